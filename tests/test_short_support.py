"""A support holds each body along its part of the edge, however short
(review5): Γ crossing the left edge 0.03 below its top left body +'s part
of the left support between the restraint check's samples, so the body was
taken for held by Γ alone and a shear/normal above μ refused before Newton
as "no equilibrium", though the clamp holds it."""
import dataclasses
from pathlib import Path

import numpy as np
import pytest

from contactcore import health, load_scene
from contactcore import tolerances as core_tol
from contactcore.errors import SolverError
from contactcore.laws import SLIP
from verification import methods

SCENE = Path(__file__).resolve().parent / "scenes" / "short_clamp.toml"


def test_a_body_clamped_on_a_short_part_of_an_edge_is_not_refused_as_free():
    scene = load_scene(SCENE)
    assert health.beyond_cone(scene, 1.0) == ""
    result = methods.solver("fe")(scene, None, degree=1, estimate_condition=False)
    final = result.interface.final
    assert np.all(final.status == SLIP)  # the loads ask 0.57 > μ: Γ slips, the clamp carries the rest
    t = final.traction
    assert np.max(np.abs(t[:, 1]) + scene.law.mu * t[:, 0]) <= core_tol.TRACTION_ROUNDOFF * np.max(-t[:, 0])


def test_without_the_clamp_the_same_load_is_refused_before_newton():
    scene = load_scene(SCENE)
    bare = scene.with_changes(supports=tuple(s for s in scene.supports if s.boundary != "left"))
    assert "slides off" in health.beyond_cone(bare, 1.0)
    with pytest.raises(SolverError, match="slides off"):
        methods.solver("fe")(bare, None, degree=1, estimate_condition=False)
