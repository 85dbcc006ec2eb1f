"""tests/registered.py's skip: a registered method whose documented check
refuses a scene is skipped by name and reason; fe, xfem and efgm never are,
even where their check refuses (their test then fails)."""
import dataclasses
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pytest

import registered
from contactcore import DiscretisationError, load_scene
from contactcore.geometry import CircleInterface, LevelSetInterface
from xdolfinx.options import FE, XFEM


@dataclass(frozen=True)
class StraightOnly(XFEM):
    """A stand-in new method (takeover33's kind): xfem that refuses a
    circular Γ by its own check."""

    name: ClassVar[str] = "straightonly"

    def check(self, scene) -> None:
        super().check(scene)
        if isinstance(scene.interface, CircleInterface):
            raise DiscretisationError(f"{self.name}: Γ must be a straight line")


def _not_skipped(scene, disc, h) -> None:
    """skip_unless_solvable must let the test run on: a skip here would
    only mark this test skipped, so it is turned into a failure."""
    try:
        registered.skip_unless_solvable(scene, disc, h)
    except pytest.skip.Exception as skipped:
        pytest.fail(f"skipped: {skipped}")


def test_a_new_method_that_refuses_a_scene_is_skipped_by_name_and_reason():
    disc = StraightOnly(degree=1)
    _not_skipped(load_scene("A"), disc, 0.1)  # a straight Γ: taken
    with pytest.raises(pytest.skip.Exception, match="straightonly refuses the disc: straightonly: Γ must be a "
                                                    "straight line"):
        registered.skip_unless_solvable(load_scene("B"), disc, 0.1, what="the disc")


def test_a_shipped_method_is_never_skipped_even_where_its_check_refuses():
    scene = load_scene("A")
    level_set = dataclasses.replace(scene, interface=LevelSetInterface(lambda x: x[:, 1] - 0.5,
                                                                       lambda x: np.tile([0.0, 1.0], (len(x), 1))))
    fe = FE(degree=1)
    assert "level set" in registered.refusal(level_set, fe, 0.1)  # fe's check refuses it ...
    _not_skipped(level_set, fe, 0.1)  # ... and the test runs on (and fails there), never skipped
