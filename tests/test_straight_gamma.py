"""Whether Γ is straight is read from its geometry, not from the class it
was given as: a level set whose zero set is a line gets the line's
warnings (no penalty locking, no amplified profile tractions), a curved
one keeps the curve's (contactcore.geometry straight_in,
contactcore.tolerances.STRAIGHT_NORMAL)."""
import dataclasses

import numpy as np
import pytest

from contactcore import CircleInterface, LevelSetInterface, LineInterface, load_scene
from contactcore.laws import LinearLaw
from contactcore.tolerances import LOCKING_WARN, PROFILE_TRACTION_WARN

#: A cell size at which scene A's springs, made stiff below, pass every
#: curved-Γ threshold.
H = 0.1


def _stiff(scene):
    """``scene`` with springs past LOCKING_WARN and both PROFILE_TRACTION_WARN
    of its softer modulus at h = H."""
    k = 10 * max(LOCKING_WARN, *PROFILE_TRACTION_WARN.values()) * scene.softer_modulus / H
    return scene.with_changes(law=LinearLaw(kN=k, kT=k))


def _line():
    """Scene A's Γ tilted: through (0.5, 0.45) with normal (-0.3, 1)."""
    n = np.array([-0.3, 1.0]) / np.hypot(0.3, 1.0)
    return LineInterface((0.5, 0.45), tuple(n))


def _as_level_sets(line):
    """The same straight Γ given as level sets: n·(x − p), and the same
    times (1 + |x|²), whose gradient is not constant off Γ."""
    n, p = np.asarray(line.normal), np.asarray(line.point)

    def phi(x):
        return (x - p) @ n * (1 + np.sum(x * x, axis=1))

    def grad(x):
        d = (x - p) @ n
        return n[None] * (1 + np.sum(x * x, axis=1))[:, None] + 2 * d[:, None] * x

    return (LevelSetInterface(lambda x: (x - p) @ n, lambda x: np.tile(n, (len(x), 1))),
            LevelSetInterface(phi, grad))


def _curved():
    """Curved Γ given as level sets: a circle and a parabola."""
    c, R = np.array([0.5, 0.5]), 0.25
    return (LevelSetInterface(lambda x: np.hypot(*(x - c).T) - R, lambda x: (x - c) / np.hypot(*(x - c).T)[:, None]),
            LevelSetInterface(lambda x: x[:, 1] - 0.3 - 0.4 * x[:, 0] ** 2,
                              lambda x: np.column_stack([-0.8 * x[:, 0], np.ones(len(x))])))


def _warnings(interface, fitted=False):
    scene = _stiff(load_scene("A"))
    return dataclasses.replace(scene, interface=interface).interface_warnings(H, fitted=fitted)


@pytest.mark.parametrize("fitted", [False, True])
@pytest.mark.parametrize("which", [0, 1])
def test_a_straight_level_set_is_warned_as_its_line(which, fitted):
    line = _line()
    level_set = _as_level_sets(line)[which]
    assert level_set.straight_in(load_scene("A").domain)
    assert _warnings(level_set, fitted) == _warnings(line, fitted)
    assert not any("curved Γ" in w for w in _warnings(level_set, fitted))


@pytest.mark.parametrize("which", [0, 1])
def test_a_curved_level_set_keeps_the_curved_warnings(which):
    level_set = _curved()[which]
    assert not level_set.straight_in(load_scene("A").domain)
    found = _warnings(level_set)
    assert any("penalty locking" in w for w in found) and any("profile tractions" in w for w in found)
    circle = _warnings(CircleInterface((0.5, 0.5), 0.25))
    assert [w for w in circle if "circle" not in w] == found


def test_line_and_circle_know_their_shape():
    domain = load_scene("A").domain
    assert _line().straight_in(domain) and not CircleInterface((0.5, 0.5), 0.25).straight_in(domain)


def test_xfem_on_a_straight_level_set_warns_as_on_its_line():
    """End to end (the run's scene is made dimensionless before it is
    solved): xfem on the stiff straight level set reports the line's
    warnings (none of the curved Γ's), on the parabola the curved ones."""
    from xdolfinx import xfem

    scene = dataclasses.replace(_stiff(load_scene("A")), profiles=())

    def warned(interface):
        return xfem.solve(dataclasses.replace(scene, interface=interface).validated(), H).solver.warnings

    line = warned(_line())
    assert warned(_as_level_sets(_line())[1]) == line
    assert not any("curved Γ" in w for w in line)
    assert any("curved Γ" in w for w in warned(_curved()[1]))
