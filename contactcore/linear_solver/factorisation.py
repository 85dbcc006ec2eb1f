"""A direct solver kept for a run: one KSP whose operator is refilled in
place, factorised again numerically while its pattern is unchanged, each
solve judged by its own residual.

Its options are :mod:`~contactcore.linear_solver.options`'s, kept in
PETSc's options database under its owner's prefix and a number of its own
(:data:`_prefixes`); what MUMPS and PETSc say of each factorisation and
solve is read by :mod:`~contactcore.linear_solver.diagnosis`.  MUMPS's
workspace, sized by its analysis and relaxed by ICNTL(14) per cent, is
doubled and the factorisation redone where it fell short (at most
MUMPS_RELAXATIONS times).  A block of columns is solved at once with a
sparse right-hand side (:meth:`Factorisation.solve_columns`, MUMPS's
ICNTL(20)), and its cost is weighed against a factorisation's from MUMPS's
own counts (:meth:`Factorisation.columns_worth`: RINFOG(3) flops against
``2 e`` per column, ``e`` = INFOG(29) the factor's entries).
"""
from __future__ import annotations

import itertools

import numpy as np
import scipy.sparse as sp

from petsc4py import PETSc

from contactcore.errors import SolverError
from contactcore.result import SolverReport
from contactcore import health
from contactcore import tolerances as tol

from .diagnosis import (MUMPS_ERRORS, MUMPS_RELAXATIONS, MUMPS_WORKSPACE, _condition, _diverged, _measure_residual,
                        _mumps_factor, _mumps_status, _null_pivots, _outcome)
from .options import DEFAULT_PREFIX, OPTION_ERRORS, _options, _refused, check_options, unused_options


_prefixes = itertools.count()


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
        #: an iterative solver the options chose (not ``preonly`` with a
        #: factorisation), whose own tolerances may stop short of the check
        self.iterative = not (self.opts.get("ksp_type") == "preonly"
                              and self.opts.get("pc_type") in ("lu", "cholesky"))
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
        matrix's pattern, the ordering (ICNTL(7)) and LU's delayed pivots;
        the pattern (EFGM drops entries that sum to exactly zero) and the
        pivots follow round-off, so the BLAS kernel too (efgm P1, A-cyclic
        exact, h = 0.05: 75 columns under Haswell, 79 under Nehalem;
        docs/newton.md, grader10 F3); a different count moves which solves are
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
        if self.iterative and not report.residual <= tol.RESIDUAL_FAIL:
            ksp, pc = self.opts["ksp_type"], self.opts["pc_type"]
            # preonly applies the preconditioner once: no ksp_rtol to lower
            change = (f"preonly applies pc_type {pc} once and does not iterate: give an iterative ksp_type"
                      if ksp == "preonly" else "lower ksp_rtol")
            raise SolverError(f"{self.what}: {health.SHORT_OF_CHECK} ({tol.RESIDUAL_FAIL:g}; ksp_type {ksp}, "
                              f"pc_type {pc}): {change}, or use the default direct solver (no ksp_type or pc_type "
                              "option: MUMPS's LU)")
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
