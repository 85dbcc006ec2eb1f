"""Three findings of a review of Newton and its linear solver, each checked
on the code before its fix (docs/newton.md, "A load back to zero"; the
package doc of contactcore/linear_solver/)."""
import dataclasses
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore.enforcement import make_law
from contactcore.laws import OPEN, STICK
from verification import methods

ROOT = Path(__file__).resolve().parent.parent


def _exact_unloaded_to(load: float):
    """tests/scenes/unloaded.toml enforced exactly (Nitsche, μ = 0.3): loaded
    over one increment and unloaded to ``load`` times the load over the next."""
    scene = load_scene(ROOT / "tests" / "scenes" / "unloaded.toml")
    scene = scene.with_changes(law=make_law({"type": "coulomb", "mu": scene.law.mu, "enforcement": "exact"}),
                               increments=2)
    return scene.with_changes(loads=(dataclasses.replace(scene.loads[0], path=((1, 1.0), (2, load))),))


@pytest.mark.parametrize("method", ["xfem", pytest.param("fe", marks=pytest.mark.slow)])
def test_an_exact_law_unloaded_to_zero_through_its_fallbacks_stays_at_the_limit(method):
    """Finding 1.  The exact law's step to zero load fails at its approach
    (LOAD_APPROACH short of zero: a body held by Γ alone, Newton's maps
    slipping free) and falls back to β-continuation.  That fallback solved
    the zero load itself, from the committed state, where every position
    along Γ solves the step: before the fix fe P1 left every point slipping
    at 1.43e-7 m (Haswell) or 2 sticking at 1.35e-7 m (Nehalem), xfem P1
    every point slipping at 1.2e-10 m, both kernels, where the limit of the
    unloading holds the block by one point at 1.35e-7 / 1.40e-7 m.  Now
    the fallbacks serve each of the approach's two solves, and the answer is
    the limit's (docs/newton.md, "A load back to zero")."""
    at_zero, *short = (methods.solver(method)(_exact_unloaded_to(load), 0.1, estimate_condition=False)
                       for load in (0.0, *tol.UNLOADED_SHORT_LOADS))
    step, (a, b) = at_zero.interface.steps[-1], (r.interface.steps[-1] for r in short)
    assert np.count_nonzero(step.status == STICK) == 1 and not np.any(step.status == OPEN)
    assert np.array_equal(step.status, a.status) and np.array_equal(step.status, b.status)
    loaded = np.max(np.abs(at_zero.interface.steps[0].traction))
    assert np.max(np.abs(step.traction)) <= tol.UNLOADED_PROFILES * loaded
    # on one map the answer is linear in the load: the limit at zero, extrapolated
    (x, y) = tol.UNLOADED_SHORT_LOADS
    limit = b.jump[:, 1] + (b.jump[:, 1] - a.jump[:, 1]) * y / (x - y)
    assert np.max(np.abs(step.jump[:, 1] - limit)) <= tol.UNLOADED_EXTRAPOLATED * np.max(np.abs(limit))


_CHILD = """
import json, sys
sys.path.insert(0, "tests")
import numpy as np
from test_newton_review import _exact_unloaded_to
from verification import methods
r = methods.solver(sys.argv[1])(_exact_unloaded_to(0.0), float(sys.argv[3]), degree=int(sys.argv[2]),
                                estimate_condition=False)
s = r.interface.steps
print(json.dumps({"status": [x.status.tolist() for x in s], "traction": [x.traction.tolist() for x in s],
                  "jump": [x.jump.tolist() for x in s]}))
"""


def _under(coretype: str, method: str, degree: int, h: float) -> dict:
    env = {**os.environ, "OPENBLAS_CORETYPE": coretype}
    out = subprocess.run([sys.executable, "-c", _CHILD, method, str(degree), str(h)], capture_output=True,
                         text=True, cwd=ROOT, env=env, timeout=600)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


@pytest.mark.slow
@pytest.mark.parametrize("method, degree, h", [("fe", 1, 0.1), ("fe", 2, 0.05), ("xfem", 1, 0.05),
                                               ("efgm", 1, 0.05), ("efgm", 2, 0.1)])
def test_an_exact_law_unloaded_to_zero_decides_alike_under_two_kernels(method, degree, h):
    """Finding 1 under two BLAS kernels: before the fix the fallback's
    answer at zero load was round-off's (fe P2 at h = 0.05: 14 points
    sticking under Haswell, 1 under Nehalem; xfem P1 at 0.05: the block
    1.2e-10 or 5.1e-8 m along; efgm P1 at 0.05 1.7e-8 or 1.7e-9 m; efgm P2
    at 0.1 1.0e-7 or 5.0e-8 m).  Now the same map at every step, one point
    sticking at zero load, and tractions and jumps alike to round-off."""
    a, b = (_under(c, method, degree, h) for c in ("Haswell", "Nehalem"))
    assert a["status"] == b["status"]
    assert np.count_nonzero(np.array(a["status"][1]) == STICK) == 1
    for key in ("traction", "jump"):
        scale = np.max(np.abs(a[key][0]))
        for x, y in zip(a[key], b[key]):
            assert np.max(np.abs(np.array(x) - np.array(y))) <= tol.UNLOADED_PROFILES * scale, key


_ZERO_PIVOT = """
import sys
from petsc4py import PETSc
from contactcore.errors import SolverError
from contactcore.linear_solver import Factorisation
comm = PETSc.COMM_WORLD
rank = comm.getRank()
A = PETSc.Mat().createAIJ(((2, None), (2, None)), nnz=2, comm=comm)
A.setUp()
lo, _ = A.getOwnershipRange()
# rank ``argv[2]``'s diagonal block is a free spring: LU's second pivot is exactly 0
block = [1.0, -1.0, -1.0, 1.0] if rank == int(sys.argv[2]) else [2.0, -1.0, -1.0, 2.0]
A.setValues([lo, lo + 1], [lo, lo + 1], block)
A.assemble()
b, x = A.createVecs()
b.setArray([1.0, -1.0])
f = Factorisation(petsc_options={"pc_type": sys.argv[1], "sub_pc_type": "lu"})
try:
    f.factorise(A)
    f.solve(b, x)
    outcome = "solved"
except SolverError as exc:
    outcome = str(exc)
f.destroy()
with open(f"{sys.argv[3]}/rank{rank}.txt", "w") as out:
    out.write(outcome)
"""


@pytest.mark.parametrize("pc, ranks, singular", [("bjacobi", 2, 1)] + [
    pytest.param(pc, n, r, marks=pytest.mark.slow) for pc, n, r in
    [("bjacobi", 3, 0), ("bjacobi", 3, 2), ("asm", 2, 1), ("asm", 3, 0), ("asm", 3, 2)]])
def test_a_zero_pivot_on_one_rank_is_refused_alike_on_every_rank(tmp_path, ranks, singular, pc):
    """Finding 3.  PETSc 3.18's ``PCGetFailedReason`` is not reduced over
    the ranks after a ``preonly`` solve, nor is the KSP's reason: with
    block Jacobi or additive Schwarz (LU on each rank's block) and a zero
    pivot in one rank's block only, before the fix that rank refused
    (reason -11, a sub-preconditioner failed) while the others answered
    "solved" (the singular rank not rank 0) or "relative residual nan"
    (rank 0 singular).  Now every rank gives the same refusal, and none
    hangs (the timeout)."""
    launcher = [shutil.which("mpirun"), "--allow-run-as-root", "--oversubscribe", "-n", str(ranks)]
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "PMI_"))}
    out = subprocess.run(launcher + [sys.executable, "-c", _ZERO_PIVOT, pc, str(singular), str(tmp_path)],
                         capture_output=True, stdin=subprocess.DEVNULL, text=True, timeout=120, cwd=ROOT, env=env)
    assert out.returncode == 0, out.stderr
    messages = {(tmp_path / f"rank{r}.txt").read_text() for r in range(ranks)}
    assert len(messages) == 1, messages
    assert re.fullmatch(r"linear system: the factorisation failed \(PETSc reason -11: a sub-preconditioner failed\) "
                        r"— the matrix may be singular: a rigid-body mode is not removed .*", messages.pop())


def test_no_step_converges_by_a_residual_test_on_round_off(monkeypatch):
    """Finding 2.  A block pressed and pulled open (tests/scenes/presspull.toml,
    fe P1, h = 0.2) ends stress-free: at its pulled steps the equilibrium
    rows' forces and residual are round-off of ``A u`` (2.5e-17 at
    |u| = 0.5).  Newton's residual test judged them against a floor of
    RESIDUAL_FLOOR |u| of forces, whose NEWTON_RTOL, 1e-16 |u|, lies inside
    the round-off ``A u`` carries (6.6e-18 to 1.7e-15 |u| measured,
    contactcore.tolerances.PRODUCT_ROUNDOFF): the test passed there
    (2.5e-17 <= 5e-17), a decision round-off made.  The |u| floor is now
    the health check's only, and the residual test alone (the map's settling
    and a still step aside) passes no step whose forces and residual are
    both within PRODUCT_ROUNDOFF |u|; the steps converge by their settled
    maps, in as many iterations."""
    from contactcore import newton
    from contactcore import tolerances as ctol

    decisions, forces_at = [], {}
    residual, converged = newton._Newton._residual, newton._Newton._converged

    def stash(self, u, b, response):
        out = residual(self, u, b, response)
        forces_at[id(self)] = (out[1], float(np.max(np.abs(u[self.balance]), initial=0.0)))
        return out

    def judged(self, R, forces, tangent, response, du, moved):
        alone = converged(self, R, forces, None, response, None, moved)  # the residual test alone
        decisions.append((self._balance(R), *forces_at[id(self)], alone))
        return converged(self, R, forces, tangent, response, du, moved)

    monkeypatch.setattr(newton._Newton, "_residual", stash)
    monkeypatch.setattr(newton._Newton, "_converged", judged)
    result = methods.solver("fe")(load_scene(ROOT / "tests" / "scenes" / "presspull.toml"), 0.2,
                                  estimate_condition=False)
    on_round_off = [(b, f, a) for b, f, size, a in decisions
                    if max(b, f) <= ctol.PRODUCT_ROUNDOFF * size and size > 0]
    assert on_round_off  # the pulled steps are there
    assert not any(alone for _, _, alone in on_round_off), on_round_off
    assert result.solver.iterations == [1] * len(result.solver.iterations)
