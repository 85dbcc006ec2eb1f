"""Direct factorisations with PETSc/MUMPS and an honest report of their health.

Defaults: ``preonly`` with MUMPS, by LDLᵀ (:data:`SYMMETRIC`) for a matrix
its owner says is symmetric while the interface tangent is symmetric too,
by LU otherwise.  Any PETSc option may be overridden
(``{"pc_factor_mat_solver_type": "superlu"}``, ``{"ksp_type": "gmres", ...}``).
With MUMPS, two of its features are switched on: null-pivot detection
(ICNTL(24), threshold CNTL(3)), which turns a singular system into a clear
error instead of garbage, and — only when asked for (``estimate_condition``)
— its error analysis (ICNTL(11)=1), whose condition estimate (RINFOG(10), Arioli–Demmel–Duff)
is reported and warned about above :data:`~contactcore.tolerances.CONDITION_WARN`.

Options are checked before the solve: a type PETSc does not list, or an
option PETSc refuses while setting up (an unparsable value, a factorisation
package this build lacks), is a :class:`PETScOptionError` that names the
option; an option PETSc never read (misspelt, or not for this solver) is a
warning in the report.  Each factorisation keeps its options in PETSc's
options database under its owner's ``prefix`` (the method that made the
matrix) and a number of its own, and removes them when destroyed.

Under mpirun every rank judges a solve alike: its residual by PETSc's
norms over the ranks, and its KSP reason and preconditioner failure
reduced over them (:func:`_outcome`), so that a factorisation that fails
on one rank's block only (``pc_type`` ``bjacobi`` or ``asm``) is refused
with the same message on every rank.

Every PETSc object made here is destroyed here, and every petsc4py handle
on a part of one (``ksp.getPC()``, ``pc.getFactorMatrix()``) is released
before its owner is destroyed: with petsc4py 3.18 a handle that outlives the
KSP keeps the PC and the MUMPS factor alive for good (measured: 2.4 MB per
solve of a 4 900-unknown Laplacian, ~0.3 GB per solve of a 1.4e5-unknown P2
system, and flat once the factor is destroyed before the KSP).  Neither
dolfinx nor MPI is imported: the matrices come from their owners (dolfinx's
for fe and xfem; EFGM's scipy matrices made PETSc's by
:mod:`efgm.petsc_matrices`), distributed or not.
"""
from __future__ import annotations

import ctypes
import functools
import itertools
import re

import numpy as np
import scipy.sparse as sp

from petsc4py import PETSc

from contactcore.errors import SolverError
from contactcore.result import SolverReport
from contactcore.errors import SolverOptionError
from contactcore import health
from contactcore import tolerances as tol
from contactcore.collective import SERIAL, Collective

DEFAULT_OPTIONS = {"ksp_type": "preonly", "pc_type": "lu", "pc_factor_mat_solver_type": "mumps"}

#: MUMPS's fill-reducing ordering (ICNTL(7)): 2 = AMF.  Measured on the
#: 2D elasticity systems here (best of 3, solve stage): XFEM P2 on scene C
#: at 5.4e3 / 2.0e4 / 7.9e4 / 3.1e5 unknowns 0.027 / 0.100 / 0.50 / 2.52 s,
#: against 0.038 / 0.148 / 0.63 / 3.05 s with MUMPS's automatic choice
#: and 2.76 s with METIS at 3.1e5; XFEM P1 on scene A at 1.3e5: 0.70 s
#: against 0.94 s.
MUMPS_ORDERING = 2

#: The factorisation of a symmetric tangent (every method's, while its
#: interface law's tangent is symmetric): MUMPS's LDLᵀ for general symmetric
#: matrices (PETSc ``cholesky`` on an AIJ matrix not flagged SPD: MUMPS
#: SYM = 2, with two-by-two pivots, so EFGM's indefinite saddle point and
#: the positive definite fe and xfem tangents take the same code).  Half of
#: LU's operations; measured, XFEM P2 on scene B at 9.9e5 unknowns, one
#: process: solve stage 13.6 s (LU) against 8.1 s; EFGM on scene C at h =
#: 0.0125 (7.9e4 unknowns, best of 3, no condition estimate): 1.9 s against
#: LU 2.6 s and SuperLU (:mod:`efgm.sparse_solver`) 13.5 s.
SYMMETRIC = {"pc_type": "cholesky"}

#: MUMPS's analysis on the graph compressed by 2 × 2 blocks (ICNTL(15) =
#: −2: a node's x and y), used when the factorised rows come in such pairs
#: (:meth:`Tangent._paired`).  Measured: EFGM on scene C at h = 0.0125, LDLᵀ
#: 2.12 → 2.0 s (paired in one process, median of 4); XFEM P2 on scene B at
#: 9.9e5 unknowns, LDLᵀ, MUMPS's analysis 0.71 → 0.51 s on one rank and
#: 1.03–1.08 → 0.55 s on two (its serial part).  PORD (ICNTL(7) = 4) needs
#: half AMF's operations there (6.1e10 against 1.1–1.5e10) but its own
#: analysis takes 2.4 s, and it ends the whole process, without an
#: exception, on a small dense graph ("Error in function orderMinPriority:
#: no valid number of stages in multisector"; every size from 2 to 20
#: measured), which a coarse EFGM run can give: not used.
BLOCKS = {"mat_mumps_icntl_15": -2}

#: MUMPS's INFOG(1) where its workspace, sized by the analysis's estimate
#: relaxed by ICNTL(14) per cent, fell short in the factorisation (MUMPS 5.5
#: user guide, "Error diagnostics": −8, −9 its main work arrays; −11, −12,
#: −14, −15 those of the solve; −17, −20 its communication buffers).  The
#: estimate does not foresee every delayed pivot of an LDLᵀ with two-by-two
#: pivots, whose count depends on the ranks' dynamic scheduling: fe P2 on
#: scene C on 3 oversubscribed ranks failed once in a test run (−11 from
#: PETSc, not reproduced in 8 runs under load).  Such a factorisation is
#: redone with the relaxation doubled, at most MUMPS_RELAXATIONS times, and
#: the report says so.
MUMPS_WORKSPACE = (-8, -9, -11, -12, -14, -15, -17, -20)
MUMPS_RELAXATIONS = 4

#: What the other failures of MUMPS's factorisation mean (its user guide).
MUMPS_ERRORS = {-10: "the matrix is numerically singular — a rigid-body mode may be free, or a penalty so stiff "
                     "that the bulk stiffness is lost in round-off",
                -13: "a workspace could not be allocated: the machine's memory is short for this size"}

#: The options prefix of a factorisation whose maker names no owner.
DEFAULT_PREFIX = "contactcore_"

_prefixes = itertools.count()

#: Options whose value names a PETSc type, and where petsc4py lists the types.
TYPED_OPTIONS = {"ksp_type": PETSc.KSP.Type, "pc_type": PETSc.PC.Type,
                 "pc_factor_mat_solver_type": PETSc.Mat.SolverType,
                 "pc_factor_mat_ordering_type": PETSc.Mat.OrderingType}

#: PETSc error codes that mean "this option cannot be used": PETSC_ERR_SUP
#: (56), PETSC_ERR_ARG_WRONG (62), PETSC_ERR_ARG_OUTOFRANGE (63, an
#: unparsable value), PETSC_ERR_ARG_UNKNOWN_TYPE (86), PETSC_ERR_MISSING_FACTOR
#: (92, no such factorisation package or kind in this build).
OPTION_ERRORS = (56, 62, 63, 86, 92)


class PETScOptionError(SolverOptionError):
    """A PETSc option that PETSc does not know or cannot use; the message names it."""


def is_symmetric(A: sp.spmatrix) -> bool:
    """``max |A − Aᵀ| <= SYMMETRIC_TO_ROUNDOFF · max |A|``."""
    A = sp.csr_matrix(A)
    scale = abs(A).max() if A.nnz else 0.0
    return A.nnz == 0 or abs(A - A.T).max() <= tol.SYMMETRIC_TO_ROUNDOFF * scale


def _type_names(kinds) -> list[str]:
    return sorted({v for k, v in vars(kinds).items() if not k.startswith("_") and isinstance(v, str)})


def check_options(opts: dict) -> None:
    """Raise :class:`PETScOptionError` for a key that is not a plain option
    name or a type-valued option (:data:`TYPED_OPTIONS`) naming a type PETSc
    does not list."""
    for key, value in opts.items():
        if not isinstance(key, str) or not re.fullmatch(r"[A-Za-z]\w*", key):
            raise PETScOptionError(f"petsc option {key!r}: not an option name (letters, digits and _, "
                                   "without the leading -)")
        if key in TYPED_OPTIONS and str(value) not in _type_names(TYPED_OPTIONS[key]):
            raise PETScOptionError(f"petsc option {key}: unknown type {value!r}; PETSc knows "
                                   + ", ".join(_type_names(TYPED_OPTIONS[key])))


def _refused(exc: PETSc.Error, opts: dict) -> PETScOptionError:
    """The option PETSc refused while setting up: the one whose value its
    message quotes (else all of them), with PETSc's reason (its last line)."""
    reason = str(exc).strip().splitlines()[-1].removeprefix("[0] ").strip()
    words = set(re.findall(r"[\w.+-]+", reason))
    named = [f"{k}={v}" for k, v in opts.items() if str(v) in words] or [f"{k}={v}" for k, v in opts.items()]
    return PETScOptionError(f"petsc option {', '.join(named)}: PETSc cannot use it (error {exc.ierr}): {reason}")


@functools.lru_cache(maxsize=None)
def _petsc_function(name: str, *argtypes):
    """The C function ``name`` of the PETSc library petsc4py runs on, for
    what petsc4py 3.18 does not wrap, or None where it cannot be found."""
    try:
        with open("/proc/self/maps") as maps:
            paths = [line.split()[-1] for line in maps if "/libpetsc" in line]
        function = getattr(ctypes.CDLL(paths[0]), name)
    except (OSError, IndexError, AttributeError):
        return None
    function.argtypes = list(argtypes)
    function.restype = ctypes.c_int
    return function


def _options_used():
    """``PetscOptionsUsed``, or None where it cannot be found."""
    return _petsc_function("PetscOptionsUsed", ctypes.c_void_p, ctypes.c_char_p, ctypes.POINTER(ctypes.c_int))


def unused_options(prefix: str, opts: dict) -> list[str] | None:
    """The keys of ``opts`` (set under ``prefix``) that PETSc never read,
    or None if that cannot be asked."""
    used = _options_used()
    if used is None:
        return None
    flags = {key: ctypes.c_int(0) for key in opts}
    if any(used(None, (prefix + key).encode(), ctypes.byref(flag)) for key, flag in flags.items()):
        return None
    return [key for key, flag in flags.items() if not flag.value]


def _options(user: dict | None, estimate_condition: bool, paired: bool, symmetric: bool) -> dict:
    """The PETSc options: the defaults, then ``user``'s; with MUMPS, the
    :data:`SYMMETRIC` factorisation for a ``symmetric`` matrix unless the
    user chose one, :data:`BLOCKS` for a ``paired`` one, and the checks."""
    opts = {**DEFAULT_OPTIONS, **(user or {})}
    mumps = opts.get("pc_factor_mat_solver_type") == "mumps"
    if mumps and symmetric:
        opts.update({key: value for key, value in SYMMETRIC.items() if key not in (user or {})})
    if mumps and opts.get("pc_type") in ("lu", "cholesky"):
        opts.setdefault("mat_mumps_icntl_7", MUMPS_ORDERING)
        if paired:
            opts.update({key: value for key, value in BLOCKS.items() if key not in opts})
        opts.setdefault("mat_mumps_icntl_24", 1)
        opts.setdefault("mat_mumps_cntl_3", tol.NULL_PIVOT)
        if estimate_condition:
            opts.setdefault("mat_mumps_icntl_11", 1)
    return opts


def _mumps_factor(ksp):
    """The MUMPS factor of ``ksp``'s PC, or None; the caller destroys it
    before ``ksp`` (module doc)."""
    pc = ksp.getPC()
    if pc.getType() not in ("lu", "cholesky") or pc.getFactorSolverType() != "mumps":
        return None
    return pc.getFactorMatrix()


def _mumps_status(ksp) -> tuple[int, int]:
    """MUMPS's INFOG(1) after ``ksp``'s factorisation and the relaxation
    ICNTL(14) it ran with; (0, 0) for another solver."""
    factor = _mumps_factor(ksp)
    if factor is None:
        return 0, 0
    try:
        return factor.getMumpsInfog(1), factor.getMumpsIcntl(14)
    finally:
        factor.destroy()


#: The cause a singular tangent has here, named by every refusal of one.
SINGULAR = ("a rigid-body mode is not removed by the supports and pins, or a penalty is so stiff that the bulk "
            "stiffness is lost in round-off")


class NullPivots(SolverError):
    """A factorisation that completed and found the matrix singular: its
    MUMPS analysis stands for the next matrix of the same pattern."""


def _null_pivots(ksp, what: str) -> None:
    """A clear error (:class:`NullPivots`) if MUMPS found null pivots in its factorisation."""
    factor = _mumps_factor(ksp)
    if factor is None:
        return
    try:
        nulls = factor.getMumpsInfog(28)
    finally:
        factor.destroy()
    if nulls > 0:
        raise NullPivots(f"{what} is singular to working precision: MUMPS found {nulls} null pivot(s) — {SINGULAR}")


#: PETSc's ``PCFailedReason`` (petscpctypes.h) after a factorisation that
#: failed inside the solve (KSP reason DIVERGED_PCSETUP_FAILED, -11): a
#: solver without MUMPS's null-pivot detection (ICNTL(24)), SuperLU or
#: PETSc's own LU, stops at an exactly zero pivot.  Whether a numerically
#: singular matrix gives an exactly zero pivot there, or a pivot of
#: round-off size whose huge answer the residual test refuses, follows the
#: BLAS kernel: the matrix ``Q diag(0, 1, …, 5) Qᵀ`` of tests/test_health.py
#: with SuperLU, 2026-11-27, AMD EPYC, OpenBLAS 0.3.21: a zero pivot under
#: OPENBLAS_CORETYPE = Nehalem and SandyBridge, a relative residual 2.3 (default
#: Cooperlake) or 1.0 (Haswell, Zen) with a backward error ~1e-17.  Either
#: refusal names the singular matrix (:data:`SINGULAR`).
PC_FAILURES = {1: "a structurally zero pivot", 2: "a zero pivot", 3: "memory ran short",
               4: "the factorisation package failed", 6: "a sub-preconditioner failed"}


def _pc_failure(ksp) -> int | None:
    """``PCGetFailedReasonRank`` of ``ksp``'s PC (this rank's: PETSc
    3.18's ``PCGetFailedReason`` is reduced over the ranks only by a
    Krylov method's dot products or norms, never by ``preonly``), or None
    where it cannot be asked."""
    failed = _petsc_function("PCGetFailedReasonRank", ctypes.c_void_p, ctypes.POINTER(ctypes.c_int))
    if failed is None:
        return None
    pc, reason = ksp.getPC(), ctypes.c_int(0)
    try:
        return None if failed(ctypes.c_void_p(pc.handle), ctypes.byref(reason)) else reason.value
    finally:
        pc.destroy()


def _outcome(ksp) -> tuple[int, int | None]:
    """``ksp``'s converged reason and its PC's failure (:func:`_pc_failure`),
    the same on every rank: the least reason and the largest failure over
    the ranks.  With ``preonly`` a factorisation that fails on some ranks
    only (a zero pivot in one rank's block of ``bjacobi`` or ``asm``) is
    reported on those ranks alone (PETSc 3.18's KSPSolve_PREONLY), and the
    others answered as if solved: measured under ``mpirun -n 2`` and
    ``-n 3``, a zero pivot on rank 1 only gave rank 0 a solved step (and
    rank 1 the refusal), on rank 0 only the other ranks "relative residual
    nan": their Newtons then went different ways (tests/test_newton_review.py)."""
    reason, failure = ksp.getConvergedReason(), _pc_failure(ksp)
    comm = ksp.getComm()
    if comm.getSize() == 1:
        return reason, failure
    # PETSc's own reduction (no mpi4py here): the least reason is the largest -reason
    values = PETSc.Vec().createMPI((2, None), bsize=2, comm=comm)
    try:
        values.setArray([-float(reason), -1.0 if failure is None else float(failure)])
        least, largest = -int(values.strideMax(0)[1]), int(values.strideMax(1)[1])
    finally:
        values.destroy()
    return least, (None if largest < 0 else largest)


#: The KSP reasons a solve may diverge by, by their value (PETSc's names).
KSP_DIVERGED = {v: k for k, v in vars(PETSc.KSP.ConvergedReason).items() if k.startswith("DIVERGED")}


def _diverged(ksp, reason: int, what: str, failure: int | None = None) -> SolverError:
    """The refusal of a solve PETSc reports as diverged (``reason`` < 0),
    naming the singular matrix where the factorisation met a zero pivot
    (``failure``, :func:`_outcome`); else the reason by its name and what
    to do, without the solve's relative residual, whose figure follows
    round-off (the BLAS kernel, MUMPS's ordering) and tells nothing the
    reason does not."""
    if reason == PETSc.KSP.ConvergedReason.DIVERGED_PCSETUP_FAILED:
        if failure in (1, 2):
            return SolverError(f"{what} is singular to working precision: the factorisation met "
                              f"{PC_FAILURES[failure]} (PETSc reason {reason}) — {SINGULAR}")
        return SolverError(f"{what}: the factorisation failed (PETSc reason {reason}: "
                           + PC_FAILURES.get(failure, "the preconditioner's set-up failed")
                           + f") — the matrix may be singular: {SINGULAR}")
    name = KSP_DIVERGED.get(reason, "")
    more = ("raise ksp_max_it, or use the default direct solver" if name == "DIVERGED_MAX_IT" else
            "use the default direct solver")
    return SolverError(f"{what}: {health.DIVERGED} (PETSc reason {reason}{': ' + name if name else ''}); {more} "
                       "(no ksp_type or pc_type option: MUMPS's LU)")


def _condition(ksp, opts: dict) -> float | None:
    """MUMPS's condition estimate, computed with the solve that followed a
    factorisation when its error analysis is on (ICNTL(11) = 1)."""
    factor = _mumps_factor(ksp) if opts.get("mat_mumps_icntl_11") == 1 else None
    if factor is None:
        return None
    try:
        return float(factor.getMumpsRinfog(10))
    finally:
        factor.destroy()


def _measure_residual(A, b, x, report: SolverReport, force_scale: float) -> None:
    """Relative residual (the criterion, :mod:`contactcore.health`) and the
    normwise backward error (reported beside it), infinity norms."""
    r = b.duplicate()
    A.mult(x, r)
    r.aypx(-1.0, b)
    # norms over every rank (PETSc's): each rank judges the solve alike
    inf = PETSc.NormType.INFINITY
    rv, bv, xv = (np.array([v.norm(inf)]) for v in (r, b, x))
    report.residual = health.relative_residual(rv, bv, force_scale)
    report.backward_error = health.backward_error(rv, A.norm(PETSc.NormType.INFINITY), xv, bv)
    r.destroy()


class Factorisation:
    """A direct solver kept for a run, as dolfinx's ``NonlinearProblem``
    keeps its matrix: one KSP whose operator is refilled in place.

    :meth:`factorise` (re)factorises ``A`` — PETSc redoes only the numeric
    factorisation while ``A``'s nonzero pattern is unchanged, the symbolic
    analysis is kept — and checks it (null pivots, the condition estimate
    when asked for); :meth:`solve` solves with the last factorisation, as
    often as asked (a piecewise-linear law keeps its tangent for whole
    increments), each solve judged by its own residual.  ``paired`` and
    ``symmetric`` say what the matrix is, for the options (:func:`_options`);
    ``prefix`` names its owner in PETSc's options database (module doc).
    The caller destroys it (:meth:`destroy`).
    """

    def __init__(self, *, petsc_options: dict | None = None, estimate_condition: bool = False,
                 what: str = "linear system", paired: bool = False, symmetric: bool = False,
                 prefix: str = DEFAULT_PREFIX):
        self.opts = _options(petsc_options, estimate_condition, paired, symmetric)
        check_options(self.opts)
        self.what, self.count = what, 0
        self.prefix = f"{prefix}{next(_prefixes)}_"
        self.ksp, self.A, self.base = None, None, None
        db = PETSc.Options()
        for key, value in self.opts.items():
            db[self.prefix + key] = value

    def factorise(self, A) -> None:
        """Factorise ``A`` (kept by reference: refill it, then call again);
        where MUMPS's workspace fell short (:data:`MUMPS_WORKSPACE`), again
        with its relaxation doubled; any other failure of MUMPS is a
        :class:`SolverError` that gives its INFOG(1)."""
        relaxed = []
        for attempt in range(MUMPS_RELAXATIONS + 1):
            first = self._set_up(A)
            status, relaxation = _mumps_status(self.ksp)
            if status >= 0:
                break
            if status not in MUMPS_WORKSPACE or attempt == MUMPS_RELAXATIONS:
                raise SolverError(f"{self.what}: MUMPS's factorisation failed (INFOG(1) = {status}: "
                                  + MUMPS_ERRORS.get(status, "see the MUMPS user guide's error diagnostics")
                                  + (f"; its workspace relaxation was raised to {relaxation} %" if relaxed else "")
                                  + ")")
            relaxed.append(status)
            self.opts["mat_mumps_icntl_14"] = max(2 * relaxation, 1)
            PETSc.Options()[self.prefix + "mat_mumps_icntl_14"] = self.opts["mat_mumps_icntl_14"]
            self.ksp.destroy()
            self.ksp = None
        self.count += 1
        pc = self.ksp.getPC()
        base = SolverReport(solver=f"{self.ksp.getType()}+{pc.getType()}"
                            + (f" ({pc.getFactorSolverType()})" if pc.getType() in ("lu", "cholesky") else ""),
                            options=self.opts, factorisations=1)
        if relaxed:
            base.warnings.append(f"MUMPS's workspace estimate fell short (INFOG(1) = {relaxed[0]}): factorised "
                                 f"again with ICNTL(14) = {self.opts['mat_mumps_icntl_14']} %")
        _null_pivots(self.ksp, self.what)
        if first:
            unused = unused_options(self.prefix, self.opts)
            if unused is None:
                base.warnings.append("petsc options: could not ask PETSc which options it used")
            elif unused:
                base.warnings.append(f"petsc option(s) {', '.join(unused)} never used by PETSc: misspelt, "
                                     "or not for this solver")
        self.base = base

    def columns_worth(self) -> tuple[float, float] | None:
        """``(cost, memory)``: how many columns of a block solve
        (:meth:`solve_columns`) cost what the last factorisation did, and
        how many take as much memory as its factors; None for a solver
        other than MUMPS.  From MUMPS's own counts, which follow the
        matrix's pattern, the ordering (ICNTL(7)) and LU's delayed pivots,
        not the BLAS in use; a different count moves which solves are
        corrected, not the answer (each correction is held to the
        factorised solve's residual test): the factorisation's flops RINFOG(3) against
        a solve's ``2 e`` per column for the ``e`` = INFOG(29) entries of LU
        (``4 e`` for LDLᵀ, whose factor is stored once), and ``e / n``
        columns of ``n`` unknowns.  Measured (C-coulomb, exact, 2026-11-26):
        fe P1 at h = 0.05 41 by the flops against 43-70 timed, fe P1 at h =
        0.025 77 against 31-44, efgm P1 at h = 0.025 276 against 202-221."""
        factor = _mumps_factor(self.ksp)
        if factor is None:
            return None
        try:
            flops, entries = factor.getMumpsRinfog(3), factor.getMumpsInfog(29)
        finally:
            factor.destroy()
        entries = entries if entries >= 0 else -entries * 1e6  # MUMPS gives millions as a negative count
        if entries <= 0:
            return None
        per_column = (4.0 if self.ksp.getPC().getType() == "cholesky" else 2.0) * entries
        return flops / per_column, entries / self.A.getSize()[0]

    def _set_up(self, A) -> bool:
        """KSP (made on first use) and factorisation of ``A``; whether the KSP is new."""
        first = self.ksp is None
        if first:
            self.ksp = PETSc.KSP().create(A.getComm())
            self.ksp.setOptionsPrefix(self.prefix)
        self.ksp.setOperators(A)
        self.A, self.base = A, None
        try:
            if first:
                self.ksp.setFromOptions()
            self.ksp.setUp()
        except PETSc.Error as exc:
            if exc.ierr in OPTION_ERRORS:
                raise _refused(exc, self.opts) from None
            raise SolverError(f"{self.what}: PETSc failed (error {exc.ierr}); the matrix may be singular — "
                              "check that the supports remove every rigid-body mode") from None
        return first

    def solve(self, b, x, force_scale: float = 0.0) -> SolverReport:
        """Solve ``A x = b`` in place with the last factorisation; raise
        :class:`SolverError` if it fails (module doc).  The report carries
        the factorisation's checks only on the first solve after it."""
        report = SolverReport(solver=self.base.solver, options=self.opts, factorisations=self.base.factorisations,
                              warnings=list(self.base.warnings))
        self.base.warnings = []
        try:
            self.ksp.solve(b, x)
        except PETSc.Error as exc:
            if exc.ierr in OPTION_ERRORS:
                raise _refused(exc, self.opts) from None
            raise SolverError(f"{self.what}: PETSc failed in the solve (error {exc.ierr})") from None
        if self.base.factorisations:  # the first solve after a factorisation
            self.base.factorisations = 0
            report.condition = _condition(self.ksp, self.opts)
            if report.condition is not None and report.condition > tol.CONDITION_WARN:
                report.warnings.append(f"condition estimate {report.condition:.2e} exceeds "
                                       f"{tol.CONDITION_WARN:.0e}: digits may be lost (penalty too stiff for "
                                       "the mesh?)")
        report.iterations = [self.ksp.getIterationNumber()]
        reason, failure = _outcome(self.ksp)
        _measure_residual(self.A, b, x, report, force_scale)
        if reason < 0:
            raise _diverged(self.ksp, reason, self.what, failure)
        health.check_residual(report.residual, self.what, report.backward_error)
        return report

    def solve_columns(self, B: sp.spmatrix) -> np.ndarray:
        """``A⁻¹ B`` (dense) for the sparse columns of ``B`` (one process)
        with the last factorisation: MUMPS's solve phase takes them as one
        block with a sparse right-hand side (MatMatSolve with ``Bᵀ`` in AIJ:
        ICNTL(20), the forward elimination skips the elimination tree's
        branches a column does not reach); another solver column by column.
        Measured 2026-11-27, fe P1 on exact C-coulomb at h = 0.0125 (9.0e4
        unknowns, LU), columns of Γ's test operator: 16 / 64 / 128 columns
        in 38 / 126 / 250 ms, against 74 / 261 / 508 ms as a dense block,
        and a factorisation 260 ms.  Unchecked: the caller judges what it
        builds from them."""
        factor = _mumps_factor(self.ksp)
        if factor is None:
            b, x = self.A.createVecs()
            try:
                return np.column_stack([self._column(b, x, column) for column in B.T.toarray()])
            finally:
                b.destroy()
                x.destroy()
        comm = self.A.getComm()
        rows = sp.csr_matrix(B.T, dtype=PETSc.ScalarType)
        rows.sort_indices()
        transposed = PETSc.Mat().createAIJ(size=rows.shape, csr=(rows.indptr.astype(PETSc.IntType),
                                                                 rows.indices.astype(PETSc.IntType), rows.data),
                                           comm=comm)
        rhs = PETSc.Mat().createTranspose(transposed)
        out = PETSc.Mat().createDense(B.shape, comm=comm)
        out.setUp()
        try:
            factor.matSolve(rhs, out)
            return out.getDenseArray().copy(order="K")  # PETSc's column-major block, as it is
        finally:
            for obj in (rhs, transposed, out, factor):
                obj.destroy()

    def _column(self, b, x, column: np.ndarray) -> np.ndarray:
        b.setArray(column)
        self.ksp.solve(b, x)
        return x.getArray(readonly=True).copy()

    def destroy(self) -> None:
        if self.ksp is not None:
            self.ksp.destroy()
        self.ksp = self.A = None
        db = PETSc.Options()
        for key in self.opts:
            db.delValue(self.prefix + key)


def _local_to_global(K) -> tuple:
    """``K``'s row and column local-to-global maps (dolfinx sets them); the
    identity for a matrix made here (one process)."""
    maps = K.getLGMap()
    if maps[0].handle:  # a null handle: no map was set
        return maps
    identity = PETSc.LGMap().create(np.arange(K.getSize()[0], dtype=PETSc.IntType), comm=K.getComm())
    return identity, identity


class Tangent:
    """Newton's ``J = K + K_Γ`` and its factorisations, allocated once per
    run and refilled, as dolfinx's ``NonlinearProblem`` does.

    ``K`` (PETSc AIJ, owned from here on, distributed or not) is the bulk;
    ``free`` this rank's unknowns solved for, numbered from its first owned
    row (the others are prescribed: only the free block is factorised,
    MUMPS pays 3-4x for held rows otherwise); ``work`` a matrix whose
    pattern holds ``K``'s and every ``K_Γ``'s (default: a copy of ``K``,
    whose cells already couple what Γ couples); ``K_Γ`` comes in the local
    numbering of ``K``'s local-to-global map (owned, then ghosts) and is
    added where it falls, on whichever rank owns the row.  At a new
    ``K_Γ`` the work matrix is refilled with ``K`` and ``K_Γ``, its free
    block refilled into the submatrix of the slot asked for (with every row
    free, the slot's own copy is refilled directly), and that slot's
    factorisation redone (numerically only: the pattern is fixed).  Each slot keeps its
    factorisation until it is refilled.  For a ``symmetric`` ``K`` (the
    caller says so, from its method's construction: fe's and xfem's weak
    form, EFGM's Bubnov–Galerkin system) MUMPS's :data:`SYMMETRIC`
    factorisation is used while ``K_Γ`` is symmetric too on every rank (``ranks``: the reductions of ``K``'s communicator;
    each rank holds its points' part of ``K_Γ``); any other tangent takes
    the general LU.  Either compresses MUMPS's graph by :data:`BLOCKS` when
    the factorised rows come in node pairs (:meth:`_paired`).  ``prefix``
    names the owner of the factorisations (:class:`Factorisation`).
    """

    def __init__(self, K, free: np.ndarray, *, work=None, symmetric: bool = False,
                 petsc_options: dict | None = None, estimate_condition: bool = False,
                 what: str = "linear system", ranks: Collective = SERIAL, prefix: str = DEFAULT_PREFIX):
        self.K, self.free, self.symmetric, self.ranks = K, np.asarray(free), symmetric, ranks
        self.options, self.prefix = petsc_options, prefix
        self.estimate, self.what = estimate_condition, what
        self._slots = {}  # slot -> [free block, Factorisation, symmetric]
        start = K.getOwnershipRange()[0]  # free: this rank's owned rows, numbered from its first
        self._rows = PETSc.IS().createGeneral((start + self.free).astype(PETSc.IntType), comm=K.getComm())
        # every row free (EFGM's multipliers): each slot refills its own copy of J, no submatrix is cut
        self._all_free = self._rows.getSize() == K.getSize()[0]
        self.paired = self._paired(start)
        self._J, self._vectors = (K.copy() if work is None else work), None
        self._J.setLGMap(*_local_to_global(K))
        self._same_pattern = work is None  # J's pattern is K's: refilled by a copy of K's values

    def _paired(self, start: int) -> bool:
        """Whether the factorised rows, in order, pair up as the unknowns
        ``2k, 2k + 1`` of one node (x and y), the same answer on every
        rank: every row free and an even global size (EFGM, whose
        multipliers pair among themselves), or on every rank an even count
        of free rows that are whole pairs (fe and xfem without a support
        that holds one component only)."""
        if self._all_free:
            return self.K.getSize()[0] % 2 == 0
        rows = start + self.free
        return self.ranks.all(len(rows) % 2 == 0 and bool(np.all(rows[0::2] % 2 == 0))
                              and bool(np.all(rows[1::2] == rows[0::2] + 1)))

    def solve(self, interface_tangent: sp.spmatrix | None, rhs: np.ndarray, force_scale: float = 0.0,
              slot: int = 0) -> tuple[np.ndarray, SolverReport]:
        """``δu``: ``J[free, free] δu = rhs[free]``, zero elsewhere, with
        ``J = K + interface_tangent`` factorised into ``slot``, or with that
        slot's last factorisation if ``interface_tangent`` is None."""
        if interface_tangent is not None:
            self._refill(sp.csr_matrix(interface_tangent), slot)
        b, x = self._vectors
        b.setArray(rhs[self.free])
        x.set(0.0)
        report = self._slots[slot][1].solve(b, x, force_scale)
        du = np.zeros(len(rhs))
        du[self.free] = x.getArray(readonly=True)
        return du, report

    def solve_columns(self, rhs: sp.spmatrix, slot: int = 0) -> np.ndarray:
        """``δU`` (n, q): ``J[free, free] δU = rhs[free]`` for the q sparse
        columns of ``rhs`` with ``slot``'s last factorisation, zero elsewhere
        (one process; :meth:`Factorisation.solve_columns`)."""
        out = np.zeros(rhs.shape, order="F")  # column by column, as kept (contactcore.factorisations)
        if rhs.shape[1]:  # scattered along the columns, which are contiguous
            out.T[:, self.free] = self._slots[slot][1].solve_columns(sp.csr_matrix(rhs)[self.free]).T
        return out

    def column_budget(self, slot: int) -> int | None:
        """How many columns a low-rank correction of ``slot``'s
        factorisation may solve for as one block and keep
        (:class:`contactcore.factorisations._Update`): as many as cost one
        factorisation, in no more than LOW_RANK_MEMORY of its factors'
        memory (:meth:`Factorisation.columns_worth`), within
        [LOW_RANK_COLUMNS, LOW_RANK_COLUMNS_MAX]; None for a solver other
        than MUMPS, which solves them one by one."""
        worth = self._slots[slot][1].columns_worth()
        if worth is None:
            return None
        cost, memory = worth
        return int(min(max(min(cost, tol.LOW_RANK_MEMORY * memory), tol.LOW_RANK_COLUMNS), tol.LOW_RANK_COLUMNS_MAX))

    def _fill(self, J, K_Gamma: sp.csr_matrix) -> None:
        """``J = K + K_Γ`` in place (``J``'s pattern holds both).  On
        ``K``'s own pattern, ``K``'s values are copied (fe P2 on scene B at
        5.8e5 unknowns, one process: 0.57 s for PETSc's ``axpy`` on a
        subset pattern, which goes row by row, against 0.03 s)."""
        if self._same_pattern:
            self.K.copy(J, structure=PETSc.Mat.Structure.SAME_NONZERO_PATTERN)
        else:
            J.zeroEntries()
            J.axpy(1.0, self.K, structure=PETSc.Mat.Structure.SUBSET_NONZERO_PATTERN)
        J.setValuesLocalCSR(K_Gamma.indptr.astype(PETSc.IntType), K_Gamma.indices.astype(PETSc.IntType),
                            K_Gamma.data, addv=PETSc.InsertMode.ADD_VALUES)
        J.assemble()

    def _refill(self, interface_tangent: sp.csr_matrix, slot: int) -> None:
        block, factorisation, was_symmetric = self._slots.pop(slot, (None, None, None))  # back once factorised
        K_Gamma = interface_tangent.tocsr()
        K_Gamma.sort_indices()
        if self._all_free:
            if block is None:
                taken = any(b is self._J for b, _, _ in self._slots.values())
                block = self._J.duplicate() if taken else self._J
                block.setLGMap(*_local_to_global(self._J))
            self._fill(block, K_Gamma)
        else:
            self._fill(self._J, K_Gamma)
            block = self._J.createSubMatrix(self._rows, self._rows, submat=block)
        if self._vectors is None:
            self._vectors = block.createVecs()
        symmetric = self.symmetric and self.ranks.all(is_symmetric(K_Gamma))
        if factorisation is None or symmetric != was_symmetric:
            if factorisation is not None:
                factorisation.destroy()
            factorisation = Factorisation(petsc_options=self.options, estimate_condition=self.estimate,
                                          what=self.what, paired=self.paired, symmetric=symmetric,
                                          prefix=self.prefix)
        try:
            factorisation.factorise(block)
        except NullPivots:
            # refilled next (no solve reads it): MUMPS's analysis and memory are reused
            self._slots[slot] = [block, factorisation, symmetric]
            raise
        except SolverError:
            factorisation.destroy()
            if block is not self._J:
                block.destroy()
            raise
        self._slots[slot] = [block, factorisation, symmetric]

    def close(self) -> None:
        """Destroy every PETSc object made here, and ``K``."""
        for block, factorisation, _ in self._slots.values():
            factorisation.destroy()
            if block is not self._J:
                block.destroy()
        for obj in (self._J, self._rows, self.K, *(self._vectors or ())):
            obj.destroy()
        self._slots, self._J, self._vectors = {}, None, None
