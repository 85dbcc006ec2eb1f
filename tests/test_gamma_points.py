"""A method's Γ points lie on the scene's Γ (contactcore.system.check_points_on_gamma,
called by every solve): takeover33's fourth method put every Γ point 0.17 m
off a tilted Γ by a sign, solved without complaint, and the fields' "on Γ"
tolerance (``gamma_reach``) widened to match.  A deliberately shifted
operator is refused, naming the method, the worst point and its distance."""
from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest

from contactcore import discretisation, load_scene
from contactcore import tolerances as lib
from contactcore.errors import DiscretisationError
from contactcore.system import InterfaceOperator, check_points_on_gamma
from xdolfinx.options import XFEM

#: takeover33's offset (m, scene A's 1 m square): the sign bug's.
TAKEOVER33_OFFSET = 0.17
H = 0.2
#: Offsets of the second test, shares of the bound: half of it (taken) and twice (refused).
WITHIN, BEYOND = 0.5, 2.0


@dataclasses.dataclass(frozen=True)
class ShiftedXFEM(XFEM):
    """xfem whose Γ points are moved ``shift`` (dimensionless) along y after its build."""

    shift: float = 0.0

    def build(self, scene, resolution, timings):
        built = super().build(scene, resolution, timings)
        built.system.interface.points = built.system.interface.points + np.array([0.0, self.shift])
        return built


def test_a_shifted_operator_is_refused_naming_method_point_and_distance():
    scene = load_scene("A")
    with pytest.raises(DiscretisationError, match="xfem: a method's Γ points must lie on Γ") as caught:
        discretisation.solve(scene, ShiftedXFEM(degree=1, shift=TAKEOVER33_OFFSET), H)
    x, y, d = map(float, re.search(r"Γ point \(([-\d.e]+), ([-\d.e]+)\) is ([\d.e-]+) from", str(caught.value)).groups())
    assert y == pytest.approx(0.5 + TAKEOVER33_OFFSET) and d == pytest.approx(TAKEOVER33_OFFSET)


def test_a_point_within_the_tolerance_is_taken_and_one_beyond_is_not():
    """The bound is GAMMA_POINT_OFFSET of the domain's length scale, both sides of Γ."""
    scene = load_scene("A")
    allowed = lib.GAMMA_POINT_OFFSET * scene.domain.length_scale
    for side in (-1.0, 1.0):
        on = InterfaceOperator(G=None, weights=np.ones(2), points=np.array([[0.3, 0.5], [0.6, 0.5 + side * WITHIN * allowed]]))
        check_points_on_gamma(on, scene, "any")
        off = dataclasses.replace(on, points=on.points + [0.0, side * (BEYOND - WITHIN) * allowed])
        with pytest.raises(DiscretisationError, match=r"any: .* \(0\.6, "):
            check_points_on_gamma(off, scene, "any")
