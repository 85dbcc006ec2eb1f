"""fe's patch test on a circular Γ (grader7, fault 1).

Two bodies of one material meet on a circle and carry hydrostatic
σ = −p·I (tests/scenes/circle_hydrostatic.toml).  The exact answer is
linear, u = −(1 − ν)p/E·(x, y).  A P1 mesh's domain is a polygon, but a
constant stress is the exact answer on a polygon too, so every law
enforced exactly must give u and σ to round-off at degree 1 (straight
cells) and 2 (curved cells): Nitsche's traction reads σ(u)n_h with the
mesh's own normal.  Before the fix it took the exact circle's normal on P1
chords: u off by 1.8e-4, σ by 4.2e-4 at h = 0.1.  The tractions at Γ's
points (``Result.interface``) are the polygon's σ n_h = −p n_h given in the
circle's frame: |t| = p to round-off, its direction the chord's (t_N is
−p cos φ, φ the angle between the two normals, an O(h²/R²) geometric
shortfall, not checked here).  Coulomb sticks at every point only where μ
exceeds tan φ (μ = 0.3 against tan φ ≤ 0.19 at h = 0.1); below that the
circle's frame makes it slip (docs/methods/fe.md).

A penalty law has no linear answer on a closed curve (the jump σn/k is
radial, and a radial jump changes the outer body's stress), so for it the
check is that the whole error is the penalty's: it falls as 1/k, with no
floor that a geometric inconsistency would leave.
"""
from pathlib import Path

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene, make_law
from contactcore.profiles import sample_profile
from xdolfinx import conforming

SCENE = Path(__file__).parent / "scenes" / "circle_hydrostatic.toml"

#: Cell size: 17 facets on the circle (θ ≈ 0.37 rad a facet).
H = 0.1

EXACT_LAWS = {"unilateral": {"type": "unilateral", "enforcement": "exact"},
              "coulomb": {"type": "coulomb", "mu": 0.3, "enforcement": "exact"},
              "bonded": {"type": "bonded"}}

#: Penalty laws at springs α·E/R (kN/kT = 100 for scene B's anisotropy).
PENALTY_LAWS = {"linear": lambda k: {"type": "linear", "kN": k, "kT": k / 100},
                "unilateral": lambda k: {"type": "unilateral", "kN": k, "kT": k}}

#: The springs' α = kR/E: stiff enough that the penalty error (≈ 1/α)
#: dominates the discretisation's, far from round-off.
PENALTY_ALPHAS = (1e3, 1e4)


def _exact(scene, pts):
    m = scene.materials["minus"]
    p = 1e6
    return -(1.0 - m.nu) * p / m.E * pts, p


def _grid(scene, n=19):
    g = np.linspace(0.03, 0.97, n)
    pts = np.array([(x, y) for x in g for y in g])
    return pts, scene.body_of(pts)


@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("law", sorted(EXACT_LAWS))
def test_exact_laws_pass_the_patch_test_on_a_circle(law, degree):
    scene = load_scene(SCENE).with_changes(law=make_law(EXACT_LAWS[law]))
    res = conforming.solve(scene, H, degree=degree)
    pts, bodies = _grid(scene)
    u_ex, p = _exact(scene, pts)
    u = res.fields.displacement(pts, bodies)
    assert np.max(np.abs(u - u_ex)) <= tol.PATCH_ROUNDOFF * np.max(np.abs(u_ex))
    s = res.fields.stress(pts, bodies)
    assert np.max(np.abs(s - np.array([-p, -p, 0.0]))) <= tol.PATCH_ROUNDOFF * p
    # the solve's tractions at Γ's quadrature points (Result.interface): σ n_h, |t| = p
    t = res.interface.final.traction
    assert np.max(np.abs(np.hypot(t[:, 0], t[:, 1]) - p)) <= tol.PATCH_ROUNDOFF * p
    # the profile along the exact circle: no gap
    (profile,) = [pr for pr in scene.profiles if pr.id == "G"]
    cols = sample_profile(scene, res.fields, profile, res.interface).columns
    assert np.max(np.abs(cols["gN"])) <= tol.PATCH_ROUNDOFF * np.max(np.abs(u_ex))
    assert np.max(np.abs(cols["gT"])) <= tol.PATCH_ROUNDOFF * np.max(np.abs(u_ex))


@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("law", sorted(PENALTY_LAWS))
def test_penalty_error_on_a_circle_is_the_penalty_alone(law, degree):
    base = load_scene(SCENE)
    E, R = base.materials["minus"].E, base.interface.radius
    pts, bodies = _grid(base)
    u_ex, _ = _exact(base, pts)
    errors = []
    for alpha in PENALTY_ALPHAS:
        res = conforming.solve(base.with_changes(law=make_law(PENALTY_LAWS[law](alpha * E / R))), H, degree=degree)
        errors.append(np.max(np.abs(res.fields.displacement(pts, bodies) - u_ex)) / np.max(np.abs(u_ex)))
    slope = np.log10(errors[1] / errors[0]) / np.log10(PENALTY_ALPHAS[1] / PENALTY_ALPHAS[0])
    assert abs(slope + 1.0) <= tol.PENALTY_SLOPE_TOL, errors
