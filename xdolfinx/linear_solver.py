"""Direct solves with PETSc/MUMPS and an honest report of their health.

Defaults: ``preonly`` + LU with MUMPS.  Any PETSc option may be overridden
(``{"pc_factor_mat_solver_type": "superlu"}``, ``{"ksp_type": "gmres", ...}``).
With MUMPS, two of its features are switched on: null-pivot detection
(ICNTL(24), threshold CNTL(3)), which turns a singular system into a clear
error instead of garbage, and — only when asked for (``estimate_condition``)
— its error analysis (ICNTL(11)=1), whose condition estimate (RINFOG(10), Arioli–Demmel–Duff)
is reported and warned about above :data:`~contactcore.tolerances.CONDITION_WARN`.
"""
from __future__ import annotations

import itertools

import numpy as np

from petsc4py import PETSc

from contactcore import SolverError, SolverReport
from contactcore import health
from contactcore import tolerances as tol

DEFAULT_OPTIONS = {"ksp_type": "preonly", "pc_type": "lu", "pc_factor_mat_solver_type": "mumps"}

#: MUMPS's fill-reducing ordering (ICNTL(7)): 2 = AMF.  Measured on the
#: 2D elasticity systems here (best of 3, solve stage): XFEM P2 on scene C
#: at 5.4e3 / 2.0e4 / 7.9e4 / 3.1e5 unknowns 0.027 / 0.100 / 0.50 / 2.52 s,
#: against 0.038 / 0.148 / 0.63 / 3.05 s with MUMPS's automatic choice
#: and 2.76 s with METIS at 3.1e5; XFEM P1 on scene A at 1.3e5: 0.70 s
#: against 0.94 s.
MUMPS_ORDERING = 2

_prefixes = itertools.count()


def _options(user: dict | None, estimate_condition: bool) -> dict:
    opts = {**DEFAULT_OPTIONS, **(user or {})}
    if opts.get("pc_factor_mat_solver_type") == "mumps" and opts.get("pc_type") == "lu":
        opts.setdefault("mat_mumps_icntl_7", MUMPS_ORDERING)
        opts.setdefault("mat_mumps_icntl_24", 1)
        opts.setdefault("mat_mumps_cntl_3", tol.NULL_PIVOT)
        if estimate_condition:
            opts.setdefault("mat_mumps_icntl_11", 1)
    return opts


def _mumps_factor(ksp):
    pc = ksp.getPC()
    if pc.getType() != "lu" or pc.getFactorSolverType() != "mumps":
        return None
    return pc.getFactorMatrix()


def _measure_residual(A, b, x, report: SolverReport, force_scale: float) -> None:
    """Relative residual (the criterion, :mod:`contactcore.health`) and the
    normwise backward error (reported beside it), infinity norms."""
    r = b.duplicate()
    A.mult(x, r)
    r.aypx(-1.0, b)
    rv, bv, xv = r.getArray(readonly=True), b.getArray(readonly=True), x.getArray(readonly=True)
    report.residual = health.relative_residual(rv, bv, force_scale)
    report.backward_error = health.backward_error(rv, A.norm(PETSc.NormType.INFINITY), xv, bv)
    r.destroy()


def solve(A, b, x, *, rows=None, petsc_options: dict | None = None, estimate_condition: bool = False,
          what: str = "linear system", force_scale: float = 0.0) -> SolverReport:
    """Solve ``A x = b`` in place; raise :class:`SolverError` if it fails.

    With ``rows`` (global indices of the unknowns that are not held at zero,
    owned by this process) only that block is factorised and the other
    entries of ``x`` are left as they are: held rows are decoupled, but
    MUMPS still pays for them (3-4x slower solves on the conforming mixed
    space, measured).

    The report carries the relative residual ``‖b − A x‖/max(‖b‖, force_scale)``
    (which decides success, :func:`contactcore.health.check_residual`), the
    backward error beside it, the Krylov iterations, the condition estimate
    when ``estimate_condition`` (MUMPS only) and every warning.
    """
    if rows is not None:
        index = PETSc.IS().createGeneral(np.asarray(rows, dtype=PETSc.IntType), comm=A.getComm())
        As, bs, xs = A.createSubMatrix(index, index), b.getSubVector(index), x.getSubVector(index)
        try:
            return solve(As, bs, xs, petsc_options=petsc_options, estimate_condition=estimate_condition, what=what,
                         force_scale=force_scale)
        finally:
            x.restoreSubVector(index, xs)
            b.restoreSubVector(index, bs)
            As.destroy()
            index.destroy()
    opts = _options(petsc_options, estimate_condition)
    prefix = f"xdolfinx_{next(_prefixes)}_"
    db = PETSc.Options()
    for key, value in opts.items():
        db[prefix + key] = value
    ksp = PETSc.KSP().create(A.getComm())
    try:
        ksp.setOptionsPrefix(prefix)
        ksp.setOperators(A)
        ksp.setFromOptions()
        try:
            ksp.solve(b, x)
        except PETSc.Error as exc:
            raise SolverError(f"{what}: PETSc failed (error {exc.ierr}); the matrix may be singular — "
                              "check that the supports remove every rigid-body mode") from None
        report = SolverReport(solver=f"{ksp.getType()}+{ksp.getPC().getType()}"
                              + (f" ({ksp.getPC().getFactorSolverType()})" if ksp.getPC().getType() == "lu" else ""),
                              iterations=[ksp.getIterationNumber()], options=opts)
        factor = _mumps_factor(ksp)
        if factor is not None:
            nulls = factor.getMumpsInfog(28)
            if nulls > 0:
                raise SolverError(f"{what} is singular to working precision: MUMPS found {nulls} null pivot(s) — "
                                  "a rigid-body mode is not removed by the supports and pins, or a penalty is "
                                  "so stiff that the bulk stiffness is lost in round-off")
            if opts.get("mat_mumps_icntl_11") == 1:
                report.condition = float(factor.getMumpsRinfog(10))
        reason = ksp.getConvergedReason()
        _measure_residual(A, b, x, report, force_scale)
        if reason < 0:
            raise SolverError(f"{what}: the solver diverged (PETSc reason {reason}, "
                              f"relative residual {report.residual:.3e})")
        health.check_residual(report.residual, what, report.backward_error)
        if report.condition is not None and report.condition > tol.CONDITION_WARN:
            report.warnings.append(f"condition estimate {report.condition:.2e} exceeds {tol.CONDITION_WARN:.0e}: "
                                   "digits may be lost (penalty too stiff for the mesh?)")
        return report
    finally:
        ksp.destroy()
        for key in opts:
            db.delValue(prefix + key)
