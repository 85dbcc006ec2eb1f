"""Solver health is reported, and a singular system is a clear error."""
import subprocess
import sys

import numpy as np
import pytest

from contactcore import DiscretisationError, SolverError, load_scene, scene_text
from contactcore.tolerances import RESIDUAL_FAIL
from xdolfinx import conforming
import tolerances as tol


def test_floating_body_is_refused_with_a_clear_message():
    scene = load_scene("A").with_changes(supports=())
    with pytest.raises(SolverError, match=r"bodies − and \+ together can .*: no support or pin holds it"):
        conforming.solve(scene, 0.2)


def test_floating_body_cli_exits_non_zero_without_traceback(tmp_path):
    bad = tmp_path / "floating.toml"
    text = scene_text("A")
    start = text.index("[[supports]]")
    bad.write_text(text[:start] + text[text.index("[[loads]]"):])
    proc = subprocess.run([sys.executable, "-m", "verification", "run", str(bad), "--h", "0.2",
                           "--out", str(tmp_path / "out")], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 2
    # every method runs (the default), so the method that met it is named first
    assert proc.stderr.strip().splitlines()[-1].startswith("error: fe: scene A: bodies − and + together can")
    assert "Traceback" not in proc.stderr


def test_report_carries_residual_backward_error_and_condition():
    res = conforming.solve(load_scene("A"), 0.2, estimate_condition=True)
    rep = res.solver
    assert rep.solver == "preonly+cholesky (mumps)"  # the linear law's tangent is symmetric: LDLᵀ
    assert 0 < rep.backward_error < tol.BACKWARD_STABLE and rep.residual <= RESIDUAL_FAIL
    assert rep.condition is not None and rep.condition > 1.0
    assert rep.iterations == [1] and rep.increments == 1 and rep.solves == 1  # one solve, recorded as one


def test_petsc_options_override_the_solver():
    scene = load_scene("A")
    mumps = conforming.solve(scene, 0.2)
    superlu = conforming.solve(scene, 0.2, petsc_options={"pc_factor_mat_solver_type": "superlu"})
    assert superlu.solver.solver == "preonly+lu (superlu)" and superlu.solver.condition is None
    pts = np.array([[0.3, 0.9], [0.7, 0.2]])
    bodies = scene.body_of(pts)
    u1, u2 = mumps.fields.displacement(pts, bodies), superlu.fields.displacement(pts, bodies)
    assert np.max(np.abs(u1 - u2)) <= tol.SOLVER_AGREEMENT * np.max(np.abs(u1))


def test_bad_discretisation_is_named():
    with pytest.raises(DiscretisationError, match="degree must be 1 or 2"):
        conforming.solve(load_scene("A"), 0.2, degree=3)
    with pytest.raises(DiscretisationError, match="h must be > 0"):
        conforming.solve(load_scene("A"), -1.0)
