"""No silent garbage (issue 14): one health policy for every method.

Scene A changed in one place each is refused by every method through the
CLI (exit 2, one ``error:`` line, no traceback, no result of the method);
the policy cannot be fooled by a tiny backward error; a settled Newton step
with a large residual is not convergence; locking and condition estimates.
"""
import dataclasses
import re

import numpy as np
import pytest
import scipy.sparse as sp

from contactcore import Pin, SolverError, SolverReport, load_scene, scene_text
from contactcore import health
from contactcore.laws import LinearLaw
from contactcore.newton import solve_increments
from contactcore.system import ContactSystem, InterfaceOperator
from contactcore.tolerances import RESIDUAL_FAIL, SPRING_ENTRY_MAX
from verification import methods
from verification.__main__ import main
import tolerances as tol

H = "0.2"
A_TEXT = scene_text("A")


def _without_supports(text):
    return text[:text.index("[[supports]]")] + text[text.index("[[loads]]"):]


def _replace(old, new):
    def edit(text):
        assert old in text
        return text.replace(old, new)
    return edit


def _chain(*edits):
    def edit(text):
        for e in edits:
            text = e(text)
        return text
    return edit


LINEAR = 'type = "linear"        # the paper\'s Eq. (6)'
#: (scene A edit, a regular expression the error line must match)
BAD = {
    "no supports": (_without_supports, r"bodies − and \+ together can .*no support or pin holds it"),
    "bottom held in x only": (_replace('fix = "xy"', 'fix = "x"'), r"can .*no support or pin holds it"),
    "kT = 1e-300": (_replace("kT = 1e8", "kT = 1e-300"), r"body \+ can slide along Γ: k_T is 1e-300"),
    "coulomb mu = 0.05": (_replace(LINEAR, 'type = "coulomb"\nmu = 0.05'),
                          r"increment 1 of 20: on Γ the loads ask for shear/normal = 0\.25 of body \+, above μ = 0\.05"),
    "kN = 1e300": (_replace("kN = 1e10", "kN = 1e300"), r"^error: interface\.law\.kN: 1e\+300 Pa/m is too stiff"),
    # our own: the + block held only by unilateral points that open (tension):
    # the tie holds any shear (μ = ∞), but nothing holds it off Γ
    "open unilateral points": (_chain(_replace(LINEAR, 'type = "unilateral"'),
                                      _replace("value = [2.5e4, -1.0e5]", "value = [0.0, 1.0e5]")),
                               r"increment 1 of 20: body \+ is held by Γ alone and the loads pull it off Γ: no "
                               r"equilibrium"),
    # our own: springs of 1e-12 E/h (E = 2e11, h = 0.2) hold the + block alone
    "springs 1e-12 E/h": (_replace("kN = 1e10\nkT = 1e8", "kN = 1.0\nkT = 1.0"),
                          r"increment 20 of 20.*singular to working precision or short of the residual check \(1e-05\).*"
                          r"interface\.law\.kN = 1 Pa/m is very soft"),
    # our own: one pin and no support: both blocks can turn about the pin
    "one pin": (_chain(_without_supports, _replace("[[loads]]", "[[pins]]\npoint = [0.6, 0.8]\n\n[[loads]]")),
                r"bodies − and \+ together can rotate: no support or pin holds it"),
}


@pytest.mark.parametrize("method", methods.METHODS)
@pytest.mark.parametrize("case", list(BAD))
def test_bad_scene_is_refused_in_one_line(case, method, tmp_path, capsys):
    edit, message = BAD[case]
    path = tmp_path / "scene.toml"
    path.write_text(edit(A_TEXT))
    out = tmp_path / "out"
    assert main(["run", str(path), "--method", method, "--h", H, "--out", str(out)]) == 2
    err = capsys.readouterr().err
    lines = [line for line in err.splitlines() if line.startswith("error:")]
    assert len(lines) == 1 and "Traceback" not in err
    assert re.search(message, lines[0]), lines[0]
    assert not (out / method / "summary.json").exists()


def test_the_policy_is_not_fooled_by_a_tiny_backward_error():
    """A free-free chain of springs (null space: the constants) and a load
    with a non-zero resultant: no x solves it.  x = a particular solution
    plus 1e20 times the null vector has a backward error ~1e-20 and a
    relative residual ~1: the policy must refuse it."""
    n = 6
    A = sp.diags([-np.ones(n - 1), np.r_[1, 2 * np.ones(n - 2), 1], -np.ones(n - 1)], [-1, 0, 1]).tocsr()
    b = np.zeros(n)
    b[-1] = 1.0
    x = np.linalg.lstsq(A.toarray(), b, rcond=None)[0] + 1e20
    r = b - A @ x
    backward = health.backward_error(r, sp.linalg.norm(A, np.inf), x, b)
    residual = health.relative_residual(r, b)
    assert backward < tol.NULL_SPACE_BACKWARD and residual > tol.NULL_SPACE_RESIDUAL
    with pytest.raises(SolverError, match="relative residual .* exceeds"):
        health.check_residual(residual, "chain", backward)


def _null_space_matrix(n=6):
    """``A = Q diag(0, 1, …, n−1) Qᵀ`` (Q random orthogonal): its null space
    is Q's first column, and in floating point A is not exactly singular
    (smallest eigenvalue ~1e-16), so LU does not break down."""
    rng = np.random.default_rng(0)
    Q = np.linalg.qr(rng.standard_normal((n, n)))[0]
    return sp.csr_matrix(Q @ np.diag(np.arange(n, dtype=float)) @ Q.T), rng.standard_normal(n)


def test_efgm_solver_refuses_a_matrix_with_a_null_space():
    """Refused either by MUMPS's null-pivot detection (which the 2 × 2 block
    compression lets see it) or, where a factorisation goes through, by the
    residual of the huge answer (its backward error tiny)."""
    from efgm import sparse_solver
    A, b = _null_space_matrix()
    coords = np.column_stack([np.arange(A.shape[0], dtype=float), np.zeros(A.shape[0])])
    with pytest.raises(SolverError, match=r"singular to working precision: MUMPS found 1 null pivot|"
                                          r"relative residual \S+ exceeds 1e-05 \(backward error \S+e-1[6-9]"):
        sparse_solver.solve(A, b, coords=coords, reach=10.0)
    x, report = sparse_solver.solve(A + sp.eye(A.shape[0]), b, coords=coords, reach=10.0)  # regular: passes
    assert report.residual <= RESIDUAL_FAIL and np.allclose((A + sp.eye(A.shape[0])) @ x, b)


#: How a solver without null-pivot detection refuses a singular matrix:
#: its LU stops at an exactly zero pivot, or answers and the residual
#: refuses the huge answer (a tiny backward error).  Which of the two,
#: round-off decides (contactcore.linear_solver.PC_FAILURES); both name a
#: rigid-body mode left free.
_SINGULAR_REFUSALS = (r"singular to working precision: the factorisation met a zero pivot \(PETSc reason -11\) — "
                      r"a rigid-body mode is not removed|relative residual \S+ exceeds 1e-05 \(backward error "
                      r"\S+e-1[6-9]\) — the answer does not satisfy the equations; a rigid-body mode may be free")


def _petsc_refusal(A, b, solver):
    """The SolverError of one PETSc solve of ``A x = b`` by ``solver``'s LU (None if it answers)."""
    from efgm.petsc_matrices import to_petsc
    from petsc_once import solve_once
    M = to_petsc(A)
    bv, xv = M.createVecs()
    bv.setArray(b)
    try:
        solve_once(M, bv, xv, petsc_options={"pc_factor_mat_solver_type": solver})
    except SolverError as exc:
        return exc
    finally:
        for obj in (M, bv, xv):
            obj.destroy()
    return None


def test_petsc_solver_refuses_a_matrix_with_a_null_space():
    """PETSc with SuperLU (no null-pivot detection) refuses it: by a zero
    pivot under some OpenBLAS kernels (Nehalem, SandyBridge), by the
    residual of its huge answer under others (Haswell, Zen, Cooperlake)."""
    A, b = _null_space_matrix()
    assert re.search(_SINGULAR_REFUSALS, str(_petsc_refusal(A, b, "superlu")))


@pytest.mark.parametrize("solver", ["superlu", "petsc"])
def test_a_zero_pivot_is_refused_as_a_singular_matrix(solver):
    """A free spring ``[[1, −1], [−1, 1]]``: in any order, under any kernel,
    LU's second pivot is exactly 1 − 1 = 0, PETSc's solve reports the
    preconditioner's failure (reason −11), and the refusal names the
    singular matrix and a free rigid-body mode, not a bare PETSc reason."""
    A = sp.csr_matrix(np.array([[1.0, -1.0], [-1.0, 1.0]]))
    message = str(_petsc_refusal(A, np.array([1.0, -1.0]), solver))
    assert re.fullmatch(r"linear system is singular to working precision: the factorisation met a zero pivot "
                        r"\(PETSc reason -11\) — a rigid-body mode is not removed by the supports and pins, .*",
                        message), message


class _WrongSolve(ContactSystem):
    """One unknown, bulk K, load F, a linear spring; its solve returns half
    the step and claims success (a stand-in for a singular factorisation
    that reports a tiny backward error)."""

    def __init__(self, K, F):
        self.size, self.K, self.F = 1, K, F
        self.interface = InterfaceOperator(sp.csr_matrix([[1.0], [0.0]]), np.ones(1), np.zeros((1, 2)))
        self.fixed = np.zeros(0, int)

    def fixed_values(self, f):
        return np.zeros(0)

    def external(self, loads, supports):
        return np.array([loads[0] * self.F])

    def internal(self, u):
        return self.K * u

    def solve(self, Ki, rhs, force_scale=0.0, slot=0):
        if Ki is not None:  # else the slot's last matrix (one slot is enough here)
            self.J = self.K + Ki.toarray()[0, 0]
        return 0.5 * rhs / self.J, SolverReport("fake", residual=0.0, backward_error=0.0)


def test_a_settled_newton_step_with_a_large_residual_is_not_converged():
    scene = dataclasses.replace(load_scene("A"), law=LinearLaw(1.0, 1.0), pins=(Pin((0.2, 0.8)), Pin((0.8, 0.8))))
    with pytest.raises(SolverError) as refused:
        solve_increments(scene, _WrongSolve(K=1.0, F=-1.0))
    # the refusal names the check; the figure, round-off's in a real solve, is in its details
    assert "short of the residual check (1e-05)" in str(refused.value)
    assert "settled Newton step: relative residual 5.00e-01 exceeds" in refused.value.details


@pytest.mark.parametrize("method", methods.METHODS)
def test_plane_strain_near_incompressible_warns_about_locking(method):
    scene = load_scene("A")
    nearly = {b: dataclasses.replace(m, nu=0.4999999) for b, m in scene.materials.items()}
    warned = methods.solver(method)(scene.with_changes(plane="strain", materials=nearly), 0.2).solver.warnings
    [locking] = [w for w in warned if "lock volumetrically" in w]  # one warning, both bodies named in it
    assert "degree 2" in locking and "materials.minus.nu" in locking and "materials.plus.nu" in locking
    assert "tractions come from the same fields" in locking  # they were said not to be affected
    # plane stress does not lock; ν = 0.3 in plane strain does not either
    for quiet in (scene.with_changes(materials=nearly), scene.with_changes(plane="strain")):
        assert not any("lock" in w for w in methods.solver(method)(quiet, 0.2).solver.warnings)


@pytest.mark.parametrize("method", methods.METHODS)
def test_condition_estimate_only_when_asked(method):
    solve = methods.solver(method)
    scene = load_scene("A")
    assert solve(scene, 0.2).solver.condition is None
    assert solve(scene, 0.2, estimate_condition=True).solver.condition > 1.0


@pytest.mark.parametrize("method", methods.METHODS)
def test_a_good_solve_passes_the_policy(method):
    rep = methods.solver(method)(load_scene("A"), 0.2).solver
    assert rep.residual <= RESIDUAL_FAIL and rep.backward_error < tol.BACKWARD_STABLE and not rep.warnings


def test_springs_that_swamp_the_bulk_are_refused_before_the_solve():
    """XFEM at scene A's own h with k_N = 1e300: its residual alone is 1.5e-11
    while t_N = k_N g_N is ~1e277 Pa, so the springs are refused up front;
    just below SPRING_ENTRY_MAX the same check lets them through."""
    from xdolfinx import xfem
    scene = load_scene("A")
    with pytest.raises(SolverError, match=r"interface\.law\.kN: 1e\+300 Pa/m is too stiff .* use k_N <= "):
        xfem.solve(scene.with_changes(law=LinearLaw(1e300, scene.law.kT)), 0.025)
    weights = np.array([0.05])
    E = max(m.E for m in scene.materials.values())
    ok = 0.5 * SPRING_ENTRY_MAX * E / 0.05
    health.check_springs(scene.with_changes(law=LinearLaw(ok, ok)), weights)
    with pytest.raises(SolverError, match="interface.law.kT"):
        health.check_springs(scene.with_changes(law=LinearLaw(ok, 4 * ok)), weights)


def test_the_sweep_calls_nothing_accurate_beyond_the_residual_policy():
    """k_N from 1e-12 to 1e12 E/h on the patch (XFEM): every accurate row
    passes RESIDUAL_FAIL, and both extremes are refused naming the spring."""
    from verification.sweeps import run_sweep, sweeps
    rows = run_sweep(next(s for s in sweeps() if s.name == "kN_patch"), method_names=["xfem"])
    # accurate or warned (above CUT_PROFILE_TRACTION_WARN the profile tractions are warned of): solved
    solved = [r for r in rows if r["outcome"] in ("accurate", "warned")]
    assert all(r["residual"] <= RESIDUAL_FAIL for r in solved)
    assert len(solved) >= 10 and not [r for r in rows if r["outcome"] == "wrong"]
    for extreme in (rows[0], rows[-1]):
        assert extreme["outcome"] == "refused" and "interface.law.kN" in extreme["message"], extreme


def test_efgm_solver_survives_tiny_dense_systems():
    """A coarse EFGM run can give a small, dense system; an ordering that
    ends the process there (MUMPS's PORD: "no valid number of stages in
    multisector", then exit) would be a silent death.  Run in a child
    process, so that such an exit fails here with what it printed."""
    import subprocess
    import sys
    from pathlib import Path
    code = ("import sys; sys.path.insert(0, 'tests')\n"
            "import numpy as np, scipy.sparse as sp\n"
            "from efgm import petsc_solver\n"
            "for n in (2, 4, 6, 8, 20):\n"
            "    A = sp.csr_matrix(np.eye(n) * 4.0 + np.ones((n, n)))\n"
            "    t = petsc_solver.tangent(A, sp.csr_matrix((n, n)))\n"
            "    du, _ = t.solve(sp.csr_matrix((n, n)), np.ones(n))\n"
            "    t.close()\n"
            "    assert np.allclose(A @ du, 1.0)\n"
            "print('solved')\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                         cwd=Path(__file__).resolve().parent.parent)
    assert out.returncode == 0 and "solved" in out.stdout, out.stdout + out.stderr


def test_a_body_held_by_frictionless_contact_alone_is_refused_before_any_solve():
    """C-coulomb with μ = 0: the rod, held by Γ alone, can turn in its hole
    (frictionless contact carries no shear).  Refused by the restraint
    check, naming the motion and why, for either enforcement (before: a
    singular factorisation and advice to soften the springs)."""
    from contactcore.enforcement import make_law
    for params in ({"enforcement": "exact"}, {"kN": 1e10, "kT": 1e8}):
        scene = load_scene("C-coulomb").with_changes(law=make_law({"type": "coulomb", "mu": 0.0, **params}))
        with pytest.raises(SolverError, match=r"body − can rotate: .*frictionless \(μ = 0\)"):
            health.check_restraint(scene, np.array([[1.45, 1.5], [0.55, 1.5], [1.0, 1.95], [1.0, 1.05]]),
                                   np.full(4, 0.7))


def test_an_exact_law_that_does_not_settle_is_not_told_to_soften_springs():
    """The no-equilibrium message of an exact law (which has no springs)
    names what it can change; the residual history, round-off's, is not
    in the message and is kept whole in ``details``."""
    from contactcore.enforcement import make_law
    from contactcore.newton import _no_equilibrium
    scene = load_scene("C-coulomb").with_changes(law=make_law({"type": "coulomb", "mu": 0.2, "enforcement": "exact"}))
    history = ", ".join(f"{v:.2e}" for v in np.linspace(1.0, 0.5, 25))
    failure = f"step 0 → 1: Newton did not converge in 25 iterations; relative residual of the equilibrium rows over their forces [{history}], converged at <= 1e-08"
    error = _no_equilibrium(scene, 1, 6, [failure])
    lines = str(error).splitlines()
    assert len(lines) == 2 and "k_N" not in str(error) and "stabilisation" in lines[-1]
    assert "1.00e+00" not in str(error) and history in error.details


def test_a_body_pulled_off_against_its_weight_is_told_so():
    """grader34 F5: the + layer of tests/scenes/pulled_off_weight.toml has
    no support and its top is pulled up (2e6 N per m) harder than its
    weight holds it down (6e5 N): no equilibrium.  friction_demand did not
    judge a body under a body force, so the unilateral tie's words told it
    to use a Coulomb law with a large mu; it now counts a constant body
    force (its resultant at the part's centroid) and names the cause.  A
    pull below the weight leaves an equilibrium: no refusal.  (The run,
    `run tests/scenes/pulled_off_weight.toml --method fe --degree 1 --h
    0.1`, ends with these words, exit 2, after Newton's 6 cut-backs: 4 s,
    left to this refusal's own call.)"""
    scene = load_scene("tests/scenes/pulled_off_weight.toml")
    refusal = "body + is held by Γ alone and the loads pull it off Γ"
    assert health.friction_demand(scene, 1.0).startswith(refusal)
    light = dataclasses.replace(scene.loads[2], value=(0.0, tol.PULLED_OFF_BELOW_WEIGHT))
    assert health.friction_demand(scene.with_changes(loads=(*scene.loads[:2], light)), 1.0) == ""
    from contactcore.newton import _no_equilibrium
    error = str(_no_equilibrium(scene, 1, 6, ["step 0 → 1: Newton did not converge in 27 iterations"]))
    assert refusal in error.splitlines()[0] and "coulomb" not in error, error


def test_a_unilateral_law_that_does_not_settle_is_pointed_to_coulomb(tmp_path):
    """grader17's shear with the unilateral law (penalty, no normal load),
    fe P1 at h = 0.1: no open/closed map settles, because the law drops a
    point's tangential tie the moment it opens, and the partial search
    finds no answer either (tests/test_unilateral_partial.py).  The
    refusal's first line names that and the law that behaves (coulomb
    with a large μ, which solves scene C made unilateral); a Coulomb law's
    refusal does not mention it.  (Scene C with the unilateral law, xfem
    P2 at h = 0.1, the case this test refused until 2026-11-28, now
    answers with one partial point.)"""
    from contactcore.enforcement import make_law
    from xdolfinx.options import FE, XFEM
    from contactcore import discretisation
    from test_unilateral_partial import SHEAR_UNILATERAL
    path = tmp_path / "shear.toml"
    path.write_text(SHEAR_UNILATERAL)
    with pytest.raises(SolverError) as error:
        discretisation.solve(load_scene(path), FE(degree=1), 0.1)
    scene = load_scene("C").with_changes(law=make_law({"type": "unilateral", "enforcement": "exact"}))
    lines = str(error.value).splitlines()
    assert len(lines) == 2 and "no open/closed map of the unilateral law" in lines[0]
    assert 'type = "coulomb" with a large mu' in lines[0] and "Newton did not converge" in lines[1]
    coulomb = scene.with_changes(law=make_law({"type": "coulomb", "mu": 10.0, "enforcement": "exact"}))
    counts = discretisation.solve(coulomb, XFEM(degree=2), 0.1).interface.final.counts()
    assert counts["stick"] > counts["slip"]  # converged, and tied nearly as the unilateral law would be
    from contactcore.newton import _no_equilibrium
    assert "unilateral" not in str(_no_equilibrium(load_scene("C-coulomb"), 1, 6, ["Newton did not converge"]))


def test_coulomb_springs_at_the_limit_efgm_quotes_are_carried():
    """efgm's Coulomb spring limit, α = k h/E₋ <= EFGM_FRICTION_SPRINGS,
    checked on scene A made dimensionless, at the spacing of efgm's
    grid, as efgm sees them: springs
    exactly at the limit (k_N = 2e15 Pa/m at h = 0.1, E = 2e11 Pa, α of
    1000 plus round-off) are carried; above it the refusal quotes the
    largest spring carried, rounded down (the soft body's E/h·1e3 =
    2.4691e15 quoted 2.46e+15, not 2.47e+15), and that spring is carried."""
    from contactcore import Material, make_law
    from contactcore.scaling import Scales
    from contactcore.tolerances import EFGM_FRICTION_SPRINGS
    from efgm.nodes import grid_nodes

    def check(kN, E, E_plus=2e11):
        a = load_scene("A")
        scene = a.with_changes(law=make_law({"type": "coulomb", "kN": kN, "kT": kN / 100, "mu": 0.3}),
                               materials={"minus": Material(E, 0.3), "plus": Material(E_plus, 0.3)}).validated()
        scales = Scales.of(scene)
        dimensionless = scales.scene(scene)
        h = grid_nodes(dimensionless, 0.1 / scales.length).h
        health.check_friction_springs(dimensionless, h, EFGM_FRICTION_SPRINGS, "efgm")

    check(EFGM_FRICTION_SPRINGS["N"] * 2e11 / 0.1, 2e11)
    with pytest.raises(SolverError, match=r"use k_N <= (\S+) Pa/m") as refused:
        check(3e15, 2.4691e11, 3e11)
    quoted = float(re.search(r"use k_N <= (\S+) Pa/m", str(refused.value)).group(1))
    assert quoted == 2.46e15
    check(quoted, 2.4691e11, 3e11)


def test_a_free_motions_direction_shows_no_round_off():
    """A translation along x found with 3e-16 in y is shown as (-1, 0)."""
    from contactcore.health.restraint import _describe

    scene = load_scene("C")  # a circular Γ: a translation is named by its direction
    assert _describe(scene, np.array([0.0, 0.0, 0.0, -1.0, 3.1e-16, 0.0])) == "body + can translate along (-1, 0)"
