"""xfem P1 at a large stabilisation β on a curved Γ (curve36, 2026-11-29):
a stiff disc (r = 0.5) in a softer ring under outer pressure, exact
unilateral contact (closed all round: Lamé's t_N is uniform).  The P1
Heaviside jump is linear in each cut cell and cannot vanish at every point
of a curved Γ, so Nitsche's traction t = τ + γ g carries a residue γ g in
proportion to β: Γ's t_N zigzags from point to point
(contactcore.tolerances.XFEM_P1_CURVED_STABILISATION), and xfem P1 warns
above β = 5 (docs/warnings.md)."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene, make_law
from contactcore.tolerances import NITSCHE_STABILISATION
from verification import methods
from xdolfinx.xfem.traction import curved_stabilisation_warnings

DISC = """
name = "curved_beta"
plane = "strain"
increments = 1
[domain]
type = "disc"
centre = [0.0, 0.0]
radius = 1.0
[interface]
type = "circle"
centre = [0.0, 0.0]
radius = 0.5
[interface.law]
type = "unilateral"
enforcement = "exact"
stabilisation = {beta}
[materials.minus]
E = 2e11
nu = 0.3
[materials.plus]
E = 7e10
nu = 0.33
[[pins]]
point = [0.0, 0.0]
fix = "xy"
[[pins]]
point = [0.25, 0.0]
fix = "y"
[[pins]]
point = [0.75, 0.0]
fix = "y"
[[pins]]
point = [-0.75, 0.0]
fix = "y"
[[pins]]
point = [0.0, 0.75]
fix = "x"
[[loads]]
type = "pressure"
boundary = "outer"
value = 1e8
"""
H = 0.1
LARGE_BETA = 10 * NITSCHE_STABILISATION


def _disc(tmp_path, beta):
    path = tmp_path / f"disc_{beta:g}.toml"
    path.write_text(DISC.format(beta=beta))
    return load_scene(str(path))


def _zigzag(result) -> float:
    """RMS over Γ's points (in angle order, Γ closed) of t_N minus the mean
    of its two neighbours, over the median |t_N|."""
    points, tN = result.interface.points, result.interface.final.traction[:, 0]
    tN = tN[np.argsort(np.arctan2(points[:, 1], points[:, 0]))]
    zig = tN - 0.5 * (np.roll(tN, 1) + np.roll(tN, -1))
    return float(np.sqrt(np.mean(zig ** 2)) / np.median(np.abs(tN)))


def test_xfem_p1_warns_where_a_large_beta_zigzags_a_curved_gammas_traction(tmp_path):
    """At β = 30 the zigzag is 8 times β = 3's (h = 0.1), and the run warns;
    at β = 3 it does not."""
    runs = {beta: methods.solver("xfem")(_disc(tmp_path, beta), H, degree=1)
            for beta in (NITSCHE_STABILISATION, LARGE_BETA)}
    growth = _zigzag(runs[LARGE_BETA]) / _zigzag(runs[NITSCHE_STABILISATION])
    assert growth > tol.XFEM_CURVED_ZIGZAG_GROWTH, growth
    warned = [w for w in runs[LARGE_BETA].solver.warnings if "at stabilisation" in w]
    assert warned, runs[LARGE_BETA].solver.warnings
    assert not any("at stabilisation" in w for w in runs[NITSCHE_STABILISATION].solver.warnings)


@pytest.mark.parametrize("case", ["degree 2", "default beta", "penalty"])
def test_the_warning_is_for_xfem_p1_exact_above_the_threshold_only(tmp_path, case):
    """Not at degree 2, not at the default β (3, below the threshold), not for a penalty law."""
    scene = _disc(tmp_path, LARGE_BETA)
    assert curved_stabilisation_warnings(scene, 1)
    if case == "degree 2":
        assert not curved_stabilisation_warnings(scene, 2)
    elif case == "default beta":
        assert not curved_stabilisation_warnings(_disc(tmp_path, NITSCHE_STABILISATION), 1)
    else:
        springs = make_law({"type": "unilateral", "kN": 1e12, "kT": 1e12})
        assert not curved_stabilisation_warnings(scene.with_changes(law=springs), 1)
