"""docs/scenes/partial_opening_exact.toml (Γ open on its left, closed on the
rest) and docs/scenes/stick_slip_exact.toml (slip on the left, stick on the
right) load and solve with the status map docs/contact-enforcement.md's
"Known limits" describes, and the transition lies in the kept set of the
agreement and the estimates: that page's "t_T is singular where Γ opens"
is about a point the exclusion does not leave out."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import discretisation, load_scene
from contactcore.estimate import far_from_singular
from contactcore.laws import OPEN, SLIP, STICK
from verification.agreement import default_exclusion
from xdolfinx.options import FE

H = 0.1
SCENES = {"partial_opening_exact": (OPEN, tol.OPEN_CLOSED_AT), "stick_slip_exact": (SLIP, tol.SLIP_STICK_AT)}


@pytest.mark.parametrize("name", SCENES)
def test_gamma_is_free_on_the_left_and_sticks_on_the_right(name):
    """fe P1 at h = 0.1: one run of free points from Γ's left end, then
    sticking points to its right end, changing within a cell of the
    reference's position."""
    free, at = SCENES[name]
    scene = load_scene(f"docs/scenes/{name}.toml")
    path = discretisation.solve(scene, FE(degree=1), H).interface
    order = np.argsort(path.points[:, 0])
    x, status = path.points[order, 0], path.final.status[order]
    first = np.argmax(status == STICK)
    assert first > 0 and np.all(status[:first] == free) and np.all(status[first:] == STICK)
    assert x[first - 1] - tol.TRANSITION_CELLS * H <= at <= x[first] + tol.TRANSITION_CELLS * H


@pytest.mark.parametrize("name", SCENES)
def test_the_transition_is_kept_by_the_exclusion(name):
    """The exclusion leaves out the domain's corners and Γ's ends only: the
    open/closed and slip/stick points are kept (the documented limit)."""
    scene = load_scene(f"docs/scenes/{name}.toml")
    at = SCENES[name][1]
    point = np.array([[at, scene.interface.point[1]]])
    assert far_from_singular(scene, point, default_exclusion(scene)).all()
