"""A body held by Γ alone whose points all slip but one (contactcore/slide.py):
a steel block on an aluminium wedge under a shear below μ times its press.
The stiff springs' stick windows are far narrower than the slide Newton
must find; before the exact slide along the free rigid motion, fe, xfem
and efgm each refused it after six cut-backs (grader2's held-out
mm_wedge_edge.toml, 2026-11-27)."""
from pathlib import Path

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore.geometry import tangent_of
from contactcore.laws import OPEN, SLIP, STICK
from verification import methods

SCENE = Path(__file__).parent / "scenes" / "wedge_slide.toml"


@pytest.mark.parametrize("method", ["fe", "xfem", "efgm"])
def test_a_block_slipping_all_along_gamma_but_one_point_is_held(method):
    scene = load_scene(str(SCENE))
    result = methods.solver(method)(scene)
    step, weights = result.interface.steps[-1], result.interface.weights
    t_N, t_T = step.traction[:, 0], step.traction[:, 1]
    n = np.asarray(scene.interface.normal, float) / np.linalg.norm(scene.interface.normal)
    t = tangent_of(n[None])[0]
    load = np.asarray(scene.loads[0].value, float) * scene.domain.size[0]  # the top's traction × its length
    # Γ's tractions carry the + body's loads: shear/normal 0.0198 < μ = 0.025
    assert abs(weights @ t_T - load @ t) <= tol.SLIDE_BALANCE * np.linalg.norm(load)
    assert abs(weights @ t_N - load @ n) <= tol.SLIDE_BALANCE * np.linalg.norm(load)
    # closed everywhere; slipping both ways about a neutral point that sticks
    status = step.status
    assert not np.any(status == OPEN) and np.any(status == STICK)
    slip = status == SLIP
    assert np.count_nonzero(slip) > np.count_nonzero(status == STICK)
    assert np.any(t_T[slip] > 0) and np.any(t_T[slip] < 0)
    mu = scene.law.mu
    assert np.allclose(np.abs(t_T[slip]), -mu * t_N[slip], rtol=tol.SLIDE_BALANCE, atol=0)
