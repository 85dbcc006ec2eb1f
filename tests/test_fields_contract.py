"""The one contract of a Result's ``fields.displacement``/``stress``
(contactcore.result.Fields, check_points), the same for fe, xfem and efgm:
a point outside the domain, or outside the body named for it, or a
malformed argument is a FieldsError naming the first offending point in the
scene's own coordinates and unit, never a value extrapolated from the
nearest cell (grader2 items 1 and 6); points on Γ lie in both bodies,
points on the outer boundary (corners, a disc's rim) in the domain."""
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from contactcore import ContactError, Disc, FieldsError, load_scene
from contactcore import tolerances as core_tol
from contactcore.profiles import sample_points
from contactcore.result import check_points
from verification import methods

SCENES = Path(__file__).resolve().parent / "scenes"
METHODS = ("fe", "xfem", "efgm")
#: A coarse resolution of scene A (1 × 1 m): a second per method.
H_A = 0.25


@pytest.fixture(scope="module")
def fields_of_a():
    scene = load_scene("A")
    return scene, {name: methods.solver(name)(scene, H_A).fields for name in METHODS}


def _refusal(call, points, bodies) -> str:
    """The message of the FieldsError ``call(points, bodies)`` raises, with
    any warning an error (a numpy RuntimeWarning is no message)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(FieldsError) as info:
            call(np.asarray(points, float), np.asarray(bodies))
    return str(info.value)


@pytest.mark.parametrize("name", METHODS)
def test_a_point_outside_the_domain_is_refused_by_every_method(fields_of_a, name):
    """(2, 2) lies outside scene A's unit square: fe and xfem returned the
    nearest cell's polynomial extrapolated (u = (2.7e-4, −3.5e-5) for fe)."""
    _, fields = fields_of_a
    for call in (fields[name].displacement, fields[name].stress):
        text = _refusal(call, [[0.5, 0.25], [2.0, 2.0]], [0, 1])
        assert "points[1] = (2, 2) m lies outside the domain" in text, text


@pytest.mark.parametrize("name", METHODS)
def test_a_point_of_the_other_body_is_refused_by_every_method(fields_of_a, name):
    """(0.5, 0.75) lies in the + body; asked of the − body, fe and xfem
    returned the − body's value on Γ."""
    _, fields = fields_of_a
    for call in (fields[name].displacement, fields[name].stress):
        text = _refusal(call, [[0.5, 0.75]], [0])
        assert "points[0] = (0.5, 0.75) m lies in the plus (+) body" in text and "not in the minus body" in text, text
        text = _refusal(call, [[0.5, 0.25]], [1])
        assert "lies in the minus (−) body" in text, text


@pytest.mark.parametrize("name", METHODS)
def test_points_on_gamma_and_on_the_boundary_are_answered(fields_of_a, name):
    """Γ (y = 0.5) lies in both bodies; the corners and the edges in the
    domain: each gets a finite value, in either body on Γ."""
    _, fields = fields_of_a
    points = np.array([[0.5, 0.5], [0.5, 0.5], [0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [0.0, 0.5]])
    bodies = np.array([0, 1, 0, 0, 1, 1, 1])
    for call in (fields[name].displacement, fields[name].stress):
        assert np.all(np.isfinite(call(points, bodies)))


@pytest.mark.parametrize("name", METHODS)
@pytest.mark.parametrize("bodies, points, named", [
    ([2], [[0.5, 0.25]], "bodies[0] = 2"),
    ([0], [[np.nan, 0.25]], "points[0] = (nan, 0.25) is not finite"),
    ([0, 1], [[0.5, 0.25]], "bodies: must hold one body per point (1)"),
    ([0], [0.5, 0.25], "points: must have shape (m, 2)"),
])
def test_malformed_arguments_are_refused_by_name(fields_of_a, name, bodies, points, named):
    """bodies = [2] or a NaN point: an IndexError in fe and xfem, a numpy
    RuntimeWarning in efgm; now a FieldsError naming the argument."""
    _, fields = fields_of_a
    for call in (fields[name].displacement, fields[name].stress):
        assert named in _refusal(call, points, bodies)


def test_the_refusal_names_the_point_in_the_scenes_unit():
    """xfem on the wedge in mm at (500, 500) mm gave σ = (21360, −3863,
    −7338) MPa from the nearest cell; the domain is [10, 110] × [−5, 45] mm."""
    scene = load_scene(SCENES / "mm_wedge.toml")
    fields = methods.solver("xfem")(scene, 25.0).fields
    text = _refusal(fields.stress, [[500.0, 500.0]], [1])
    assert "(500, 500) mm lies outside the domain [10, 110] × [-5, 45] mm" in text, text
    assert issubclass(FieldsError, ContactError)


def test_the_contract_holds_within_the_geometric_tolerance_of_a_curved_boundary():
    """A disc's rim and a circular Γ: points on them (as a profile samples
    them, from cos and sin) pass; points beyond them by 10× the scene's
    geometric tolerance do not."""
    scene = load_scene("C")
    L = scene.length_scale
    for profile in scene.profiles:
        _, pts, _ = sample_points(scene, profile)
        check_points(pts, scene.body_of(pts, profile.side), scene)  # no error
    theta = np.linspace(0.0, 2 * np.pi, 17)
    on_gamma = scene.interface.points_at_angles(theta)
    check_points(np.r_[on_gamma, on_gamma], np.r_[np.zeros(17, int), np.ones(17, int)], scene)
    beyond = scene.interface.points_at_angles(theta) + 10 * core_tol.GEOMETRY * L * scene.interface.normals(on_gamma)
    with pytest.raises(FieldsError, match=r"points\[0\] = .* lies in the plus \(\+\) body"):
        check_points(beyond, np.zeros(17, int), scene)
    disc = replace(scene, domain=Disc((1.0, 1.5), 0.95))  # its geometry alone: no support to validate
    def rim(radius):
        return np.c_[1.0 + radius * np.cos(theta), 1.5 + radius * np.sin(theta)]
    check_points(rim(0.95), np.ones(17, int), disc)
    with pytest.raises(FieldsError, match=r"points\[0\] = \(1\.95, 1\.5\) m lies outside the domain the disc"):
        check_points(rim(0.95 + 10 * core_tol.GEOMETRY * disc.length_scale), np.ones(17, int), disc)
