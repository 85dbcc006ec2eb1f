"""grader15 #1: efgm with stiff penalty springs of any law on a straight Γ
oscillates from point to point by about α = k h/E times its jump error;
above contactcore.tolerances.EFGM_SPRING_WARN it warns, below it is silent
and within the accuracy its docs state."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore import tolerances as lib_tol
from efgm import method

#: grader15's closed form (a): σ uniform, applied as σ·n on the four edges, Γ at −22.5°
SCENE = """name = "uniform_stress_inclined"
plane = "stress"
increments = 1
h = 0.1

[domain]
type = "rectangle"
corner = [0.0, 0.0]
size = [1.0, 1.0]

[interface]
type = "line"
point = [0.5, 0.47]
normal = [0.3826834323650898, 0.9238795325112867]

[interface.law]
type = "LAW"
kN = KN
kT = KN
MU

[materials.minus]
E = 200000000000.0
nu = 0.3
[materials.plus]
E = 200000000000.0
nu = 0.3

[[pins]]
point = [0.0, 0.0]
fix = "xy"

[[pins]]
point = [1.0, 0.0]
fix = "y"

[[loads]]
type = "traction"
boundary = "left"
value = [1000000.0, -300000.0]

[[loads]]
type = "traction"
boundary = "right"
value = [-1000000.0, 300000.0]

[[loads]]
type = "traction"
boundary = "bottom"
value = [-300000.0, 2000000.0]

[[loads]]
type = "traction"
boundary = "top"
value = [300000.0, -2000000.0]

[[profiles]]
id = "G"
type = "interface"
quantities = ["gN", "gT", "tN", "tT"]

[[profiles]]
id = "D"
type = "line"
start = [0.0, 0.0]
end = [1.0, 1.0]
quantities = ["sxx", "syy", "sxy", "ux", "uy"]
"""
SIGMA = np.array([[-1e6, 3e5], [3e5, -2e6]])
NORMAL = np.array([0.3826834323650898, 0.9238795325112867])
E, H = 2e11, 0.1


def _scene(tmp_path, alpha, law="linear"):
    k = alpha * E / H
    text = SCENE.replace("KN", f"{k!r}").replace("LAW", law).replace("MU", "mu = 2.0" if law == "coulomb" else "")
    path = tmp_path / f"s{alpha}.toml"
    path.write_text(text)
    return load_scene(path)


def _spread(result) -> float:
    """max |t_N − mean t_N| over Γ's points, relative to |σ|'s largest entry
    (the exact t_N is uniform; the mean is exact)."""
    t = np.asarray(result.interface.final.traction)[:, 0]
    exact = NORMAL @ SIGMA @ NORMAL
    return float(np.max(np.abs(t - t.mean())) / abs(t.mean()) * abs(exact) / np.max(np.abs(SIGMA)))


def _warned(result) -> bool:
    return any("efgm P" in w and "carries to about 1e-3" in w for w in result.solver.warnings)


@pytest.mark.parametrize("degree", [1, 2])
def test_springs_above_the_limit_are_warned_and_do_oscillate(tmp_path, degree):
    limit = lib_tol.EFGM_SPRING_WARN[degree]
    below = method.solve(_scene(tmp_path, limit / 3), H, degree=degree)
    above = method.solve(_scene(tmp_path, limit * 3), H, degree=degree)
    assert not _warned(below) and _spread(below) <= tol.EFGM_STATED_TRACTION, _spread(below)
    assert _warned(above) and _spread(above) > tol.EFGM_STATED_TRACTION, _spread(above)


@pytest.mark.parametrize("law", ["unilateral", "coulomb"])
def test_every_penalty_law_is_warned(tmp_path, law):
    result = method.solve(_scene(tmp_path, 3 * lib_tol.EFGM_SPRING_WARN[1], law), H, degree=1)
    assert _warned(result)
