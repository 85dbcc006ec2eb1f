"""Every shipped scene solves with the reference, and its answer obeys the
global balances that hold whatever the mesh."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene, sample_profiles
from xdolfinx import conforming


def _profiles(name, h, degree=1):
    scene = load_scene(name)
    result = conforming.solve(scene, h, degree=degree)
    assert result.dofs > 0 and result.solver.backward_error < tol.BACKWARD_STABLE_SCENES
    return scene, result, {p.id: p.columns for p in sample_profiles(scene, result.fields, result.interface)}


def test_scene_a_interface_carries_the_load():
    """Equilibrium of the upper block: ∫_Γ t_N = ∫_top t_y and ∫_Γ t_T = ∫_top t_x."""
    scene, _, prof = _profiles("A", 0.1)
    a5 = prof["A5"]
    tx, ty = scene.loads[0].value
    assert np.trapz(a5["gN"] * scene.law.kN, a5["s"]) == pytest.approx(ty, rel=tol.RESULTANT)
    assert np.trapz(a5["gT"] * scene.law.kT, a5["s"]) == pytest.approx(tx, rel=tol.RESULTANT)


@pytest.mark.parametrize("degree,h", [(1, 0.05), (2, 0.1)])
def test_scene_b_interface_carries_the_torque(degree, h):
    """Mean t_T = −T/(2πR²) (docs/scenes.md) and t_N ≈ 0: no false normal traction."""
    scene, _, prof = _profiles("B", h, degree)
    R, T = scene.interface.radius, -scene.loads[0].torque
    expected = -T / (2 * np.pi * R ** 2)
    mean = np.mean(prof["B5"]["tT"][:-1])  # 100 equal angle steps: the last sample repeats the first
    assert mean == pytest.approx(expected, rel=tol.TORQUE_BALANCE[degree])
    assert np.max(np.abs(prof["B6"]["tN"])) <= tol.FALSE_TN[degree] * abs(expected)


def test_scene_c_rod_is_in_equilibrium():
    """No load acts on the rod, so the interface tractions on it cancel."""
    scene, _, prof = _profiles("C", 0.1)
    c4, R = prof["C4"], scene.interface.radius
    n = np.column_stack([np.cos(c4["s"]), np.sin(c4["s"])])
    t = np.column_stack([n[:, 1], -n[:, 0]])
    traction = c4["tN"][:, None] * n + c4["tT"][:, None] * t
    resultant = np.trapz(traction, c4["s"], axis=0) * R
    scale = np.trapz(np.linalg.norm(traction, axis=1), c4["s"]) * R
    assert np.linalg.norm(resultant) <= tol.RESULTANT * scale
    # C2 honours the applied traction on the loaded edge, on average
    assert np.trapz(prof["C2"]["syy"], prof["C2"]["s"]) / 2.0 == pytest.approx(scene.loads[0].value[1],
                                                                              rel=10 * tol.RESULTANT)


def test_paper_resolution_is_the_xfem_cell_size():
    from contactcore.discretisation import resolution
    assert resolution(load_scene("C"), None, True, "xfem_cells").h == pytest.approx(0.1)
    assert resolution(load_scene("A"), 0.3, False, "xfem_cells").h == 0.3
    assert resolution(load_scene("A"), None, False, "xfem_cells").h == load_scene("A").h
    nodes = load_scene("A").paper["efgm_nodes"]
    assert resolution(load_scene("A"), None, True, "efgm_nodes").h == pytest.approx(max(
        s / (n - 1) for s, n in zip(load_scene("A").domain.size, nodes)))
