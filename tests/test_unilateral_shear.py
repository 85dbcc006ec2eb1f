"""The unilateral law where Γ partly opens under shear
(docs/contact-enforcement.md, "The unilateral law under shear").

A stiff block (E = 2e11 Pa) on a softer foundation (3e10 Pa), held by Γ
alone and pushed down and sideways on its top (2e5, −2e5) Pa, lifts its
left part off Γ.  The unilateral law ties a closed point tangentially and
frees it the moment it opens, so the points at the edge of the contact
zone carry the tie's shear on almost no pressure.  The discrete law then
has an open/closed map consistent at every point on coarse meshes only:
fe P1 at h = 0.05 has one (an island of three closed points, an open gap,
then the closed zone), fe P1 at h = 0.025 and efgm P1 at h = 0.05 none
among every edge position and every map of the twelve points about the
best one.  A failure says so
first and points to Coulomb's law with μ a few times the loads'
shear/normal, which solves the case.
"""
import itertools

import numpy as np
import pytest

from contactcore import SolverError, discretisation, health, load_scene, make_law
from contactcore.newton import _Newton, _no_equilibrium

TILTED = """name = "tilted"
plane = "stress"
h = 0.05
[domain]
type = "rectangle"
size = [2.0, 1.0]
[interface]
type = "line"
point = [0.0, 0.5]
normal = [0.0, 1.0]
[interface.law]
type = "unilateral"
enforcement = "exact"
[materials.minus]
E = 3e10
nu = 0.2
[materials.plus]
E = 2e11
nu = 0.3
[[supports]]
boundary = "bottom"
fix = "xy"
[[loads]]
type = "traction"
boundary = "top"
value = [2e5, -2e5]
"""

#: How many points about the best edge position the search of consistent
#: maps tries every open/closed pattern of (2^12 maps, one solve each).
WINDOW = 12


def _tilted(tmp_path, **law):
    path = tmp_path / "tilted.toml"
    path.write_text(TILTED)
    scene = load_scene(path)
    if law:
        scene = scene.with_changes(law=make_law({"type": "unilateral", **law}))
    return scene


@pytest.mark.parametrize("law", [{"enforcement": "exact"}, {"kN": 1e12, "kT": 1e12}])
def test_a_unilateral_failure_names_the_tie_first(tmp_path, law):
    """The refusal's first line names the tie and the Coulomb law with a μ
    above the loads' shear/normal on the block (1 here); the tie holds any
    shear, so the block pressed onto Γ is not refused as sliding off."""
    scene = _tilted(tmp_path, **law)
    assert health.friction_demand(scene, 1.0) == ""
    failure = "step 0 → 1: Newton did not converge in 25 iterations; relative residual of the equilibrium rows over their forces [1.00e+00], converged at <= 1e-08"
    first, second = str(_no_equilibrium(scene, 1, 6, [failure], from_rest=True)).splitlines()
    assert first.startswith("scene tilted: increment 1 of 1: Newton found no open/closed map of the unilateral law")
    assert "type = \"coulomb\" with mu a few times the loads' shear/normal (1 on body +)" in first
    assert "more increments do not help" in first and "Newton did not converge" in second
    assert ("soften k_N, k_T" in first) == ("kN" in law) and ("stabilisation" in first) != ("kN" in law)


def test_a_unilateral_solve_that_fails_is_not_blamed_on_the_tie(tmp_path):
    """Only Newton running out of iterations is the tie's: a failed linear
    solve of the same law keeps the general two-line refusal."""
    failure = "step 0 → 1: scene tilted (fe) is singular to working precision: MUMPS found 1 null pivot(s)"
    first, _ = str(_no_equilibrium(_tilted(tmp_path), 1, 6, [failure])).splitlines()
    assert first.startswith("scene tilted: increment 1 of 1 failed after 6 cut-backs") and "unilateral" not in first


@pytest.mark.slow
@pytest.mark.parametrize("law", [{"enforcement": "exact"}, {"kN": 1e12, "kT": 1e12}])
def test_the_tilted_block_is_refused_and_coulomb_solves_it(tmp_path, law):
    """efgm P1 at h = 0.05, exact and on springs: the unilateral law is
    refused naming its tie; Coulomb's law with μ = 2, twice the loads'
    shear/normal on the block, solves the same case: Γ partly open, its
    closed points part sticking, part slipping."""
    from efgm.options import EFGM
    scene = _tilted(tmp_path, **law)
    with pytest.raises(SolverError, match=r"increment 1 of 1: Newton found no open/closed map of the unilateral"):
        discretisation.solve(scene, EFGM(degree=1), 0.05)
    coulomb = scene.with_changes(law=make_law({**law, "type": "coulomb", "mu": 2.0}))
    counts = discretisation.solve(coulomb, EFGM(degree=1), 0.05).interface.final.counts()
    assert min(counts.values()) > 0, counts


def _maps(scene, method, h, monkeypatch):
    """Every edge position of the contact zone (closed where x > a) and
    every pattern of the WINDOW points about the best one (open left of
    them, closed right): the number of points where the solve of each map
    contradicts it (a closed point whose augmented gap y_N is open beyond
    the decision band, or the reverse), for ``method`` (a
    Discretisation) at ``h``.  The
    search runs on the system the method built, inside its solve (the
    system is closed after it)."""
    from contactcore import discretisation as disc
    found = {}

    def search(scene, system, progress=None, guess=None):
        found["maps"] = _search(_Newton(scene, system))
        raise SolverError("searched")
    monkeypatch.setattr(disc, "solve_increments", search)
    with pytest.raises(SolverError, match="searched"):
        disc.solve(scene, method, h)
    return found["maps"]


def _search(newton):
    """:func:`_maps` on the system and law of ``newton``."""
    from contactcore.tolerances import DECISION_BAND
    loads, supports = newton.scene.factors(1.0)
    b = newton.system.external(loads, supports)
    u0 = np.zeros(newton.system.size)
    u0[newton.system.fixed] = newton.system.fixed_values(supports)
    R0, forces, _ = newton._residual(u0, b, newton.itf.respond(newton.law, u0, newton.state))
    scale = max(forces, float(np.max(np.abs(R0[newton.free]))))
    x, gamma = newton.itf.points[:, 0], newton.itf.gamma

    def contradicted(closed):
        tangent = np.zeros((len(x), 2, 2))
        tangent[closed] = gamma[closed, None, None] * np.eye(2)
        u = u0 + newton.factorisations.solve(tangent, -R0, scale)[0]
        y_N = (newton.itf.augmented @ u).reshape(-1, 2)[:, 0]
        band = DECISION_BAND * np.max(np.abs(y_N))
        return int(np.sum(np.where(closed, y_N > band, y_N < -band)))

    order = np.argsort(x, kind="stable")
    edges = []
    for i in range(len(x) // 2):  # the contact zone spans the right half at least (the block is pressed)
        closed = np.zeros(len(x), bool)
        closed[order[i:]] = True
        edges.append(contradicted(closed))
    first = int(np.argmin(edges)) - WINDOW // 2
    patterns = {}
    for bits in itertools.product((False, True), repeat=WINDOW):
        closed = np.zeros(len(x), bool)
        closed[order[first + WINDOW:]] = True
        closed[order[first:first + WINDOW]] = bits
        patterns[bits] = contradicted(closed)
    return edges, patterns


@pytest.mark.slow
def test_the_discrete_law_has_a_consistent_map_on_a_coarse_mesh_only(tmp_path, monkeypatch):
    """Exact fe P1: at h = 0.05, where Newton converges, the search finds
    exactly one consistent map, and it is not an edge but an island of
    closed points ahead of the contact zone; at h = 0.025, where Newton
    fails, no edge position and no pattern of the window is consistent,
    nor for efgm P1 at h = 0.05, where Newton fails too."""
    from efgm.options import EFGM
    from xdolfinx.options import FE
    scene = _tilted(tmp_path)
    edges, patterns = _maps(scene, FE(degree=1), 0.05, monkeypatch)
    consistent = [bits for bits, n in patterns.items() if n == 0]
    assert min(edges) > 0 and len(consistent) == 1
    switches = np.diff(np.array([*consistent[0], True], int))  # the points right of the window are closed
    assert np.sum(switches != 0) >= 3  # open, closed, open, closed again
    for method, h in ((FE(degree=1), 0.025), (EFGM(degree=1), 0.05)):
        edges, patterns = _maps(scene, method, h, monkeypatch)
        assert min(edges) > 0 and min(patterns.values()) > 0, (method.name, h)


@pytest.mark.parametrize("a, b, c", [(0.097, 1.224, 766100.0), (0.139, 1.048, 455000.0), (0.317, 0.801, 450900.0)])
def test_a_load_along_a_tilted_gamma_is_judged_alike_whatever_the_round_off(tmp_path, a, b, c):
    """The block on Γ tilted to the normal (−a, b), pushed along Γ by
    c (b, a): F·n is round-off, of either sign or zero by a, b, c.  Either
    law is told that the loads do not press the block onto Γ, never that
    they pull it off, nor asked for a shear/normal of 1e16."""
    from contactcore.laws import CoulombLaw
    text = (TILTED.replace("normal = [0.0, 1.0]", f"normal = [{-a!r}, {b!r}]")
            .replace("point = [0.0, 0.5]", "point = [1.0, 0.5]")
            .replace("value = [2e5, -2e5]", f"value = [{b * c!r}, {a * c!r}]"))
    path = tmp_path / "along.toml"
    path.write_text(text)
    scene = load_scene(path)
    along = "body + is held by Γ alone and the loads lie along Γ and do not press it onto Γ: no equilibrium"
    assert health.friction_demand(scene, 1.0).startswith(along)
    assert health.friction_demand(scene.with_changes(law=CoulombLaw(1e10, 1e8, 0.5)), 1.0).startswith(along)
    assert 'with a large mu' in health.tie_cause(scene, 1.0, "Newton did not converge in 25 iterations", True)
