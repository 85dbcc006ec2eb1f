"""Γ's profile past its end pieces' centres (contactcore.interface_path).

An exact law's traction in a profile is its mean over each piece of Γ,
read linearly between the pieces' centres.  Between a straight Γ's end and
its end piece's centre the sample reads the line through the two end
pieces' means, up to Γ's end and never past it, where both pieces lie
wholly in one status; holding the end piece's mean flat was off by
``|t'| L/2``, O(h), where the field is exact (grader33 F4: 0.37 % of
|t_N| at h = 0.05 on a block under its own weight, every method).
"""
import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene, sample_profiles
from contactcore.geometry import LineInterface
from contactcore.interface_path import Increment, InterfacePath, piece_centres
from contactcore.laws import OPEN, STICK
from test_xfem_sliver_read import SCENE, exact_tn
from xdolfinx import conforming, xfem

#: a straight Γ along x at y = 0.5 from x = 0 to 1: five pieces of 0.2,
#: two Gauss points each (ξ = ±1/√3)
_EDGES = np.linspace(0.0, 1.0, 6)
_X = np.concatenate([(a + b) / 2 + (b - a) / 2 * np.array([-1, 1]) / np.sqrt(3) for a, b in zip(_EDGES, _EDGES[1:])])
_LINE = LineInterface((0.0, 0.5), (0.0, 1.0))


def _path(traction: np.ndarray, status: np.ndarray) -> InterfacePath:
    points, weights = np.column_stack([_X, np.full(len(_X), 0.5)]), np.full(len(_X), 0.1)
    step = Increment(1.0, (), 1, [], np.zeros((len(_X), 2)), traction, status.astype(np.int8))
    return InterfacePath(points, weights, [step], pieces=piece_centres(points, weights, [2] * 5))


def _read(path: InterfacePath, x) -> np.ndarray:
    x = np.asarray(x, float)
    return path.piece_means(_LINE, np.column_stack([x, np.full(len(x), 0.5)]), path.final.traction)


def _linear(x):
    return np.column_stack([-1.0 - np.asarray(x), 0.1 * np.asarray(x)])


def test_a_linear_traction_is_read_exactly_up_to_gammas_ends_and_no_further():
    """Samples at Γ's ends read the linear traction itself (the end pieces'
    means held flat were off by t' L/2 = 0.1); a point past Γ's end reads
    Γ's end."""
    path = _path(_linear(_X), np.full(len(_X), STICK))
    x = np.array([0.0, 0.05, 0.5, 0.95, 1.0])
    assert np.allclose(_read(path, x), _linear(x), rtol=0, atol=tol.PATCH_ROUNDOFF)
    assert np.allclose(_read(path, [-0.3, 1.3]), _linear([0.0, 1.0]), rtol=0, atol=tol.PATCH_ROUNDOFF)


def test_never_across_a_status_change():
    """A point of the last piece open: that end holds its piece's mean (the
    old reading), the other end is still extrapolated."""
    status = np.full(len(_X), STICK)
    status[-1] = OPEN
    path = _path(_linear(_X), status)
    read = _read(path, [0.0, 1.0])
    assert np.allclose(read[0], _linear([0.0])[0], rtol=0, atol=tol.PATCH_ROUNDOFF)
    assert np.allclose(read[1], _linear([0.9])[0], rtol=0, atol=tol.PATCH_ROUNDOFF)


def test_the_line_keeps_the_sign_both_means_share():
    """t_N = −(1 − x)² closes to zero at Γ's end: the line through the last
    two means (−0.0933, −0.0133) reaches +0.027 there; the profile reads 0,
    never a tension on a closed Γ."""
    traction = np.column_stack([-(1.0 - _X) ** 2, np.zeros(len(_X))])
    read = _read(_path(traction, np.full(len(_X), STICK)), [1.0])
    assert read[0, 0] <= 0.0


@pytest.mark.parametrize("solve", [conforming.solve, xfem.solve], ids=["fe", "xfem"])
def test_end_samples_follow_the_closed_form_where_the_field_is_exact(solve):
    """A block under its own weight, cut by a tilted Γ that sticks: t_N
    linear along Γ, degree 2 exact.  Profile G's first and last two samples
    were off by 3.7e-3 of max|t_N| (fe P2) and 3.8e-3 (xfem P2) at h = 0.05."""
    scene = load_scene(SCENE)
    result = solve(scene, 0.05, degree=2)
    g = sample_profiles(scene, result.fields, result.interface)[0].columns
    exact = exact_tn(np.column_stack([g["x"], g["y"]]))
    ends = np.abs(g["tN"] - exact)[[0, 1, -2, -1]]
    assert np.max(ends) / np.max(np.abs(exact)) < tol.PROFILE_END_ROUNDOFF


def test_a_singular_end_holds_its_piece_mean():
    """t ~ r^−0.3 from Γ's end at x = 1 (a singular end): the end slopes
    differ by 0.76 of the end one, so the end piece's mean is held (the
    line would carry the singularity's steepness past the piece, and the
    profile's mean along Γ would no longer be the force across it)."""
    traction = np.column_stack([-(1.0 - _X) ** -0.3, np.zeros(len(_X))])
    path = _path(traction, np.full(len(_X), STICK))
    held = path.piece_means(_LINE, np.array([[0.9, 0.5]]), traction)
    assert np.allclose(_read(path, [1.0]), held, rtol=0, atol=tol.PATCH_ROUNDOFF)
