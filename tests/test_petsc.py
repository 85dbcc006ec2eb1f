"""PETSc objects are freed, options are checked, and EFGM solves by MUMPS
when petsc4py imports (SuperLU otherwise) with the same answer."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest
import scipy.sparse as sp
from petsc4py import PETSc

from contactcore import SolverError
from efgm import sparse_solver
from verification.files import read_profile_csv
from contactcore import linear_solver
from contactcore.linear_solver import PETScOptionError
from efgm.petsc_matrices import to_petsc
from petsc_once import solve_once

import tolerances as tol


def _laplacian(n: int) -> sp.csr_matrix:
    """The 5-point Laplacian on an n × n grid (SPD, n² unknowns)."""
    T = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(n, n))
    return (sp.kron(T, sp.identity(n)) + sp.kron(sp.identity(n), T)).tocsr()


def _resident_mb() -> float:
    with open("/proc/self/statm") as fh:
        return int(fh.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


def _left_in_database() -> list[str]:
    return [k for k in PETSc.Options().getAll() if k.startswith(linear_solver.DEFAULT_PREFIX)]


def test_factor_and_solve_cycles_keep_memory_flat():
    A = to_petsc(_laplacian(70))
    b, x = A.createVecs()
    b.set(1.0)
    try:
        solve_once(A, b, x, estimate_condition=False)  # libraries warmed up
        start = _resident_mb()
        for _ in range(30):
            report = solve_once(A, b, x, estimate_condition=False)
        growth = _resident_mb() - start
    finally:
        for obj in (A, b, x):
            obj.destroy()
    assert report.solver == "preonly+lu (mumps)" and report.backward_error < tol.BACKWARD_STABLE
    assert growth <= tol.MEMORY_CYCLE_GROWTH_MB, f"resident memory grew by {growth:.1f} MB over 30 solves"
    assert _left_in_database() == []


def _solve_small(options: dict):
    M = to_petsc(_laplacian(6))
    b, x = M.createVecs()
    b.set(1.0)
    try:
        report = solve_once(M, b, x, petsc_options=options, estimate_condition=False)
        return x.getArray().copy(), report
    finally:
        for obj in (M, b, x):
            obj.destroy()


@pytest.mark.parametrize("options, named, reason", [
    ({"pc_type": "nonexistent"}, "pc_type", "unknown type 'nonexistent'"),
    ({"ksp_type": "gmress"}, "ksp_type", "unknown type 'gmress'"),
    ({"pc_factor_mat_solver_type": "nonexistent"}, "pc_factor_mat_solver_type", "unknown type 'nonexistent'"),
    ({"pc_type": "cholesky", "pc_factor_mat_solver_type": "superlu"}, "pc_factor_mat_solver_type=superlu",
     "does not support factorization type CHOLESKY"),
    ({"mat_mumps_icntl_7": "x"}, "mat_mumps_icntl_7=x", "has no integer value"),
    ({"-pc_type": "lu"}, "'-pc_type'", "not an option name"),
])
def test_a_bad_option_is_named_before_any_solve(options, named, reason):
    with pytest.raises(PETScOptionError, match=f"^petsc option {named}") as info:
        _solve_small(options)
    assert reason in str(info.value) and "singular" not in str(info.value)
    assert isinstance(info.value, SolverError) and _left_in_database() == []


def test_a_bad_option_in_a_whole_solve_keeps_its_type_and_no_hint():
    """Through the one entry point, the option's error is the input's: it
    stays a PETScOptionError, without the springs' and rigid modes' hint
    that a failed solve gets."""
    from contactcore import discretisation, load_scene
    from xdolfinx.options import FE
    with pytest.raises(PETScOptionError, match="mat_mumps_icntl_14=abc") as info:
        discretisation.solve(load_scene("A"), FE(petsc_options={"mat_mumps_icntl_14": "abc"}), 0.5)
    assert "rigid-body" not in str(info.value)
    with pytest.raises(PETScOptionError, match="pc_type") as info:  # a law with history: no cut-back tried
        discretisation.solve(load_scene("C-coulomb"), FE(petsc_options={"pc_type": "bogus"}), 0.5)
    assert "cut-back" not in str(info.value) and "\n" not in str(info.value)


def test_options_petsc_never_read_are_warned_about():
    x, report = _solve_small({"pc_factor_shfit_type": "nonzero", "ksp_rtol": 1e-3})  # preonly reads no rtol
    assert np.allclose(_laplacian(6) @ x, 1.0, rtol=0, atol=tol.SMALL_SOLVE_RESIDUAL)
    assert report.warnings == ["petsc option(s) pc_factor_shfit_type, ksp_rtol never used by PETSc: misspelt, "
                               "or not for this solver"]
    _, clean = _solve_small({"pc_factor_mat_solver_type": "mumps", "mat_mumps_icntl_14": 40})
    assert clean.warnings == []


def test_cli_names_a_bad_option_and_exits_2(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "verification", "run", "A", "--method", "fe", "--h", "0.5",
                           "--petsc-option", "pc_factor_mat_solver_type=nonexistent", "--out", str(tmp_path)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert proc.stderr.strip().splitlines()[-1].startswith(
        "error: petsc option pc_factor_mat_solver_type: unknown type 'nonexistent'")


def _saddle_point(asymmetry: float) -> tuple[sp.csr_matrix, np.ndarray]:
    """[[K, Cᵀ], [C, 0]] with K the Laplacian plus ``asymmetry`` in one
    off-diagonal pair (a slip tangent), C pinning two unknowns."""
    K = _laplacian(5).tolil()
    K[0, 1] += asymmetry
    C = sp.csr_matrix((np.ones(2), ([0, 1], [3, 17])), shape=(2, 25))
    A = sp.bmat([[K.tocsr(), C.T], [C, None]], format="csr")
    return A, np.linspace(1.0, 2.0, 27)


@pytest.mark.parametrize("asymmetry, factor", [(0.0, "cholesky"), (0.5, "lu")])
def test_efgm_mumps_picks_ldlt_only_for_a_symmetric_system(asymmetry, factor):
    A, b = _saddle_point(asymmetry)
    coords = np.vstack([np.c_[np.arange(25) % 5, np.arange(25) // 5], [[3, 0], [2, 3]]]).astype(float)
    x, report = sparse_solver.solve(A, b, coords=coords, reach=2.0, what="saddle point", estimate_condition=True)
    ref, superlu = sparse_solver.solve_superlu(A, b, coords=coords, reach=2.0, what="saddle point")
    assert report.solver == f"preonly+{factor} (mumps)" and superlu.solver.startswith("superlu")
    assert report.backward_error < tol.BACKWARD_STABLE and report.condition > 1.0
    assert np.max(np.abs(x - ref)) <= tol.SOLVER_AGREEMENT * np.max(np.abs(ref))


@pytest.mark.parametrize("free, paired", [([0, 1, 2, 3, 6, 7], True), ([0, 1, 3, 4], False), ([1, 2], False),
                                          ([0, 1, 2], False)])
def test_mumps_compresses_only_whole_node_pairs(free, paired):
    """ICNTL(15) = −2 groups the factorised rows two by two: only right
    when they are a node's x and y (a support holding one component
    shifts them)."""
    K = to_petsc(_laplacian(3) + sp.identity(9))
    tangent = linear_solver.Tangent(K, np.array(free), symmetric=True)
    try:
        rhs = np.ones(9)
        du, report = tangent.solve(sp.csr_matrix((9, 9)), rhs)
        assert tangent.paired is paired
        assert ("mat_mumps_icntl_15" in report.options) is paired
        assert report.solver == "preonly+cholesky (mumps)"
        J = (_laplacian(3) + sp.identity(9)).toarray()[np.ix_(free, free)]
        assert np.allclose(J @ du[free], rhs[free])
    finally:
        tangent.close()


def test_a_symmetric_tangent_keeps_a_solver_the_user_chose():
    """LDLᵀ is MUMPS's: SuperLU asked for by the user is used as asked (LU)."""
    K = to_petsc(_laplacian(3) + sp.identity(9))
    tangent = linear_solver.Tangent(K, np.arange(9), symmetric=True,
                                    petsc_options={"pc_factor_mat_solver_type": "superlu"})
    try:
        _, report = tangent.solve(sp.csr_matrix((9, 9)), np.ones(9))
        assert report.solver == "preonly+lu (superlu)" and report.warnings == []
    finally:
        tangent.close()


def _run_efgm(out, block_petsc: bool) -> dict:
    """``run A --method efgm --h 0.2`` in a fresh interpreter; its summary."""
    code = ("import sys; " + ("sys.modules['petsc4py'] = None; " if block_petsc else "")
            + "from verification.__main__ import main; "
            f"code = main(['run', 'A', '--method', 'efgm', '--h', '0.2', '--out', {str(out)!r}]); "
            "sys.exit(code or ('dolfinx' in sys.modules))")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    return json.loads((out / "efgm" / "summary.json").read_text())["solver"]


def test_efgm_without_petsc4py_falls_back_to_superlu_with_the_same_profiles(tmp_path):
    superlu = _run_efgm(tmp_path / "superlu", block_petsc=True)
    mumps = _run_efgm(tmp_path / "mumps", block_petsc=False)
    assert superlu["solver"].startswith("superlu (scipy)") and mumps["solver"] == "preonly+cholesky (mumps)"
    assert superlu["backward_error"] < tol.BACKWARD_STABLE and mumps["backward_error"] < tol.BACKWARD_STABLE
    profiles = sorted(p.name for p in (tmp_path / "mumps" / "efgm" / "profiles").iterdir())
    assert profiles == sorted(p.name for p in (tmp_path / "superlu" / "efgm" / "profiles").iterdir()) != []
    for name in profiles:
        a = read_profile_csv(tmp_path / "superlu" / "efgm" / "profiles" / name)
        b = read_profile_csv(tmp_path / "mumps" / "efgm" / "profiles" / name)
        for q in set(a) - {"s", "x", "y"}:
            qa, qb = np.array(a[q]), np.array(b[q])
            assert np.max(np.abs(qa - qb)) <= tol.SOLVER_AGREEMENT * np.max(np.abs(qa)), (name, q)



def test_a_workspace_that_falls_short_is_relaxed_and_said():
    """EFGM P2's saddle point (scene A, h = 0.1) needs delayed two-by-two
    pivots; with MUMPS's workspace relaxation at 1 % its factorisation runs
    out of workspace (INFOG(1) = −9, measured 2026-11-27; P1's did while its
    supports were collocated at the nodes, not with multipliers on the
    boundary, efgm.method.support_multipliers): it is redone with the
    relaxation doubled until it fits, the report says so, and the answer is
    SuperLU's."""
    from contactcore import load_scene
    from contactcore.discretisation import Resolution
    from contactcore.result import Timings
    from efgm import method
    from efgm.options import EFGM

    scene = load_scene("A")
    system = method.build(scene, EFGM(degree=2), Resolution(0.1), Timings()).system
    springs = np.tile(np.diag([scene.law.kN, scene.law.kT]), (system.interface.size, 1, 1))
    A = (system.A + system.interface.stiffness(springs)).tocsr()
    b = np.linspace(1.0, 2.0, A.shape[0])
    factorisation = linear_solver.Factorisation(petsc_options={"mat_mumps_icntl_14": 1}, symmetric=True)
    M = to_petsc(A)
    try:
        factorisation.factorise(M)
        x, rhs = M.createVecs()
        rhs.setArray(b)
        report = factorisation.solve(rhs, x)
        got = x.getArray().copy()
        for v in (x, rhs):
            v.destroy()
    finally:
        factorisation.destroy()
        M.destroy()
    assert any("INFOG(1) = -9" in w and "ICNTL(14)" in w for w in report.warnings), report.warnings
    assert factorisation.opts["mat_mumps_icntl_14"] > 1
    want = sp.linalg.spsolve(A.tocsc(), b)
    assert np.max(np.abs(got - want)) <= tol.SOLVER_AGREEMENT * np.max(np.abs(want))


def test_to_petsc_owns_copies_of_the_entries():
    """``to_petsc`` hands PETSc copies of the CSR arrays, which PETSc then
    uses as its own: the matrix has the entries, and changing the scipy
    matrix afterwards does not change it."""
    A = (_laplacian(4) + sp.random(16, 16, density=0.1, random_state=1)).tocsr()
    M = to_petsc(A)
    try:
        want = A.toarray()
        A.data[:] = 7.0
        indptr, indices, data = M.getValuesCSR()
        got = sp.csr_matrix((data, indices, indptr), shape=A.shape).toarray()
        assert np.array_equal(got, want)
    finally:
        M.destroy()


def test_pattern_union_keeps_entries_that_a_sum_would_cancel():
    """The work matrix's pattern holds every entry of K and of every K_Γ,
    even where their values cancel (A and −A), with zero values."""
    from contactcore.assembly import pattern_union

    A = sp.random(12, 12, density=0.3, random_state=2, format="csr")
    B = sp.random(12, 12, density=0.3, random_state=3, format="csr")
    union = pattern_union(A, -A, B)
    assert union.shape == A.shape and not np.any(union.data)
    stored = set(zip(np.repeat(np.arange(12), np.diff(union.indptr)).tolist(), union.indices.tolist()))
    assert len(stored) == union.nnz  # no entry twice
    assert stored == set(zip(*A.nonzero())) | set(zip(*B.nonzero()))


@pytest.mark.parametrize("scene_name, degree, support", [("A", 1, "circular"), ("C", 2, "rectangular"),
                                                         ("C-coulomb", 1, "circular")])
def test_efgm_systems_are_symmetric_by_construction(scene_name, degree, support):
    """EFGM's bulk system is factorised as symmetric without a test
    (:data:`efgm.operators.SYMMETRIC`): it is, to round-off, for each basis,
    support shape and law (the solve's residual would catch one that is not)."""
    from contactcore import load_scene
    from contactcore.discretisation import Resolution
    from contactcore.result import Timings
    from efgm import method
    from efgm.operators import SYMMETRIC
    from efgm.options import EFGM

    system = method.build(load_scene(scene_name), EFGM(degree=degree, support=support), Resolution(0.1),
                          Timings()).system
    assert SYMMETRIC and linear_solver.is_symmetric(system.A)


@pytest.mark.parametrize("ksp, advice", [("preonly", "preonly applies pc_type jacobi once and does not iterate: "
                                                     "give an iterative ksp_type"),
                                         ("gmres", "lower ksp_rtol")])
def test_a_solve_short_of_the_residual_check_gets_advice_that_fits_its_ksp(ksp, advice):
    """review4: preonly + jacobi applies Jacobi once and stops far short of
    the residual check; its refusal advised "lower ksp_rtol", an option
    preonly does not read.  gmres stopped by a loose ksp_rtol keeps that
    advice."""
    from contactcore import health
    A = to_petsc(_laplacian(6))
    b, x = A.createVecs()
    b.set(1.0)
    options = {"ksp_type": ksp, "pc_type": "jacobi"} | ({"ksp_rtol": 0.5} if ksp == "gmres" else {})
    try:
        with pytest.raises(SolverError) as refused:
            solve_once(A, b, x, petsc_options=options)
    finally:
        for obj in (A, b, x):
            obj.destroy()
    assert health.SHORT_OF_CHECK in str(refused.value) and f"): {advice}, or use the default " \
        "direct solver" in str(refused.value), str(refused.value)
    assert _left_in_database() == []
