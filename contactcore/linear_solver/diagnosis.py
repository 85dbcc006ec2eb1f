"""What MUMPS and PETSc say of a factorisation and a solve, and how a
failure is named.

A factorisation: MUMPS's INFOG(1) (:func:`_mumps_status`; its workspace
errors :data:`MUMPS_WORKSPACE`, redone with a larger relaxation, its other
errors :data:`MUMPS_ERRORS`, MUMPS 5.5 user guide, "Error diagnostics"),
its null pivots INFOG(28) (ICNTL(24) on: :class:`NullPivots`, the singular
matrix named by :data:`SINGULAR`), and its condition estimate RINFOG(10)
(Arioli–Demmel–Duff, ICNTL(11) = 1: :func:`_condition`).  A solve: its KSP
reason (:data:`KSP_DIVERGED`) and its PC's failure (:data:`PC_FAILURES`,
for a solver without null-pivot detection that stops at a zero pivot),
named by :func:`_diverged`, and its relative residual and normwise
backward error (:func:`_measure_residual`, judged by the policy of
:mod:`contactcore.health`).

Under mpirun every rank judges a solve alike: its residual by PETSc's
norms over the ranks, and its KSP reason and preconditioner failure
reduced over them (:func:`_outcome`), so that a factorisation that fails
on one rank's block only (``pc_type`` ``bjacobi`` or ``asm``) is refused
with the same message on every rank.

A handle on a KSP's factor (:func:`_mumps_factor`) or PC is destroyed
here before the KSP is (:mod:`contactcore.linear_solver`).
"""
from __future__ import annotations

import ctypes

import numpy as np

from petsc4py import PETSc

from contactcore.errors import SolverError
from contactcore.result import SolverReport
from contactcore import health

from .library import _petsc_function


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
