"""The shared core needs numpy only; laws and geometry do what they say."""
import subprocess
import sys

import numpy as np
import pytest

from contactcore import CircleInterface, Disc, LAWS, LineInterface, Rectangle, load_scene, make_law
import tolerances as tol


def test_core_imports_no_dolfinx_nor_gmsh():
    code = ("import sys, contactcore, contactcore.profiles; "
            "bad = [m for m in ('dolfinx', 'petsc4py', 'gmsh', 'ufl', 'basix', 'mpi4py') if m in sys.modules]; "
            "print(bad); sys.exit(1 if bad else 0)")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_linear_law_traction_and_tangent():
    law = make_law({"type": "linear", "kN": 2.0, "kT": 3.0})
    assert set(LAWS) >= {"linear"} and law.is_linear and law.initial_state(4) is None
    resp = law.evaluate(np.array([[1.0, -1.0], [-0.5, 2.0]]))
    assert np.allclose(resp.traction, [[2.0, -3.0], [-1.0, 6.0]])
    assert resp.tangent.shape == (2, 2, 2) and np.allclose(resp.tangent[1], np.diag([2.0, 3.0]))


def test_normals_and_tangents():
    line = LineInterface((0.0, 0.5), (0.0, 1.0))
    assert np.allclose(line.phi([[0.3, 0.7]]), 0.2)
    circle = CircleInterface((1.0, 1.0), 0.5)
    n = circle.normals([[1.0, 2.0]])
    assert np.allclose(n, [[0.0, 1.0]])


@pytest.mark.parametrize("domain,line,expected", [
    (Rectangle((0.0, 0.0), (1.0, 1.0)), LineInterface((0.0, 0.25), (0.0, 1.0)), 0.25),
    (Rectangle((0.0, 0.0), (1.0, 1.0)), LineInterface((0.5, 0.5), (np.sqrt(0.5), np.sqrt(0.5))), 0.5),
    (Disc((0.0, 0.0), 1.0), LineInterface((0.0, 0.0), (1.0, 0.0)), np.pi / 2),
])
def test_minus_area(domain, line, expected):
    assert line.minus_area(domain) == pytest.approx(expected, rel=tol.MESH_SUMS)


def test_points_on_gamma_take_the_requested_side():
    scene = load_scene("A")
    pts = np.array([[0.2, 0.5], [0.2, 0.5 + 1e-6], [0.2, 0.5 - 1e-6]])
    assert scene.body_of(pts).tolist() == [1, 1, 0]
    assert scene.body_of(pts, side="minus").tolist() == [0, 1, 0]


def test_the_history_files_parameter_is_the_profiles_arc_length_wherever_the_point_lies():
    """interface.csv's and the interface VTU files' ``s`` on a straight Γ is
    the arc length from where Γ enters the domain, as a profile's: the same
    Γ given by a point at its middle (or beyond the domain) gives the same
    ``s``, 0 at the entry and the chord's length at the exit."""
    from contactcore.interface_path import along_from_entry
    from contactcore.profiles import sample_points

    from contactcore.scene import InterfaceProfile

    scene = load_scene("A").with_changes(interface=LineInterface((0.0, 0.2), (-0.5, 1.0)),
                                         profiles=(InterfaceProfile("G", ("gN",)),))
    a, b = scene.interface.chord(scene.domain)
    s_profile, points, _ = sample_points(scene, scene.profiles[0])
    for point in (a, (a + b) / 2, b + 3.0 * (b - a)):
        moved = scene.with_changes(interface=LineInterface(tuple(point), scene.interface.normal))
        ends = along_from_entry(moved, np.array([a, b]))
        assert ends[0] == pytest.approx(0.0, abs=tol.SHAPE_ROUNDOFF) and ends[1] == pytest.approx(np.linalg.norm(b - a))
        assert np.allclose(along_from_entry(moved, points), s_profile, rtol=0.0, atol=tol.SHAPE_ROUNDOFF)


def test_a_ligament_thinner_than_h_between_a_circle_and_the_boundary_is_warned():
    """A circular Γ 0.01 from the right edge of a unit square warns at
    h = 0.05 (no cell spans the ligament) and not at h = 0.005; scenes B
    and C, whose discs keep a cell from the edge at h = 0.2, do not warn;
    nor does a straight Γ."""
    base = load_scene("B")
    near = base.with_changes(domain=Rectangle((0.0, 0.0), (1.0, 1.0)), interface=CircleInterface((0.7, 0.5), 0.29),
                             profiles=())
    assert "ligament" in " ".join(near.ligament_warnings(0.05)) and not near.ligament_warnings(0.005)
    for name in ("B", "C", "A"):
        assert not load_scene(name).ligament_warnings(0.2), name
