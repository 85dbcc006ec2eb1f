"""Sparse direct solves of EFGM's systems, with the same health report as
the others: PETSc + MUMPS when petsc4py imports (:mod:`efgm.petsc_solver`,
the solver of fe and xfem), else SuperLU (:func:`solve_superlu`); the
report's ``solver`` says which ran.

SuperLU: the system is equilibrated first (symmetric scaling by the inverse square
root of each row's largest entry), which removes the scale gap between the
stiffness (~E) and the constraint rows, then factorised by SuperLU.  The
report: relative residual (which decides success, as for the dolfinx
methods: :mod:`contactcore.health`), normwise backward error and, when asked
for, Higham's 1-norm estimate of the condition number of the equilibrated
matrix.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from contactcore import SolverError, SolverReport, health
from contactcore import tolerances as tol

from . import petsc_solver

#: Nested-dissection leaves below this many unknowns are kept in their order.
ND_LEAF = 64


def nested_dissection(coords: np.ndarray, reach: float) -> np.ndarray:
    """A fill-reducing order of unknowns located at ``coords`` whose
    couplings do not reach further than ``reach``: bisect at the median of
    the longer side, number both halves first (recursively) and the band of
    width ``reach`` around the cut last.  On 2D node sets this gives the
    O(N^1.5) factorisation of nested dissection (George 1973), where
    SuperLU's own orderings varied 5-8x from one EFGM system to another.
    """
    order = []
    stack = [(np.arange(len(coords)), False)]
    while stack:
        idx, emit = stack.pop()
        if emit or len(idx) <= ND_LEAF:
            order.append(idx)
            continue
        pts = coords[idx]
        axis = int(np.argmax(np.ptp(pts, axis=0)))
        cut = np.median(pts[:, axis])
        offset = pts[:, axis] - cut
        band = np.abs(offset) < reach / 2
        left, right = idx[(offset < 0) & ~band], idx[(offset >= 0) & ~band]
        if len(left) == 0 or len(right) == 0:
            order.append(idx)
            continue
        # last pushed is processed first: left, right, then the separator
        stack += [(idx[band], True), (right, False), (left, False)]
    return np.concatenate(order)


#: Partial pivoting threshold in symmetric mode: a diagonal pivot is kept
#: unless smaller than this fraction of its column's largest entry, which
#: still pivots away from the zero diagonal of the constraint rows.
PIVOT_THRESHOLD = 0.1


def _equilibrate(A: sp.csr_matrix) -> np.ndarray:
    row_max = abs(A).max(axis=1).toarray().ravel()
    if np.any(row_max == 0):
        i = int(np.flatnonzero(row_max == 0)[0])
        raise SolverError(f"the system is singular: unknown {i} appears in no equation")
    return 1.0 / np.sqrt(row_max)


def solve(A: sp.csr_matrix, b: np.ndarray, *, coords: np.ndarray, reach: float, estimate_condition: bool = False,
          what: str = "linear system", force_scale: float = 0.0) -> tuple[np.ndarray, SolverReport]:
    """Solve ``A x = b`` once, on the path Newton takes (:func:`tangent`
    with no interface term): MUMPS if petsc4py imports, else SuperLU
    (module doc; ``coords`` and ``reach`` as for :class:`SuperLU`)."""
    none = sp.csr_matrix(A.shape)
    solver = tangent(A, none, coords=coords, reach=reach, estimate_condition=estimate_condition, what=what)
    try:
        return solver.solve(none, b, force_scale)
    finally:
        solver.close()


def tangent(A: sp.csr_matrix, interface_pattern: sp.spmatrix, *, coords: np.ndarray, reach: float,
            symmetric: bool | None = None, estimate_condition: bool = False, what: str = "linear system"):
    """Newton's ``J = A + K_Γ`` of a run: on MUMPS if petsc4py imports
    (:func:`efgm.petsc_solver.tangent`, ``symmetric`` as there), else on
    SuperLU (:class:`SuperLUTangent`)."""
    if petsc_solver.available():
        return petsc_solver.tangent(A, interface_pattern, symmetric=symmetric, estimate_condition=estimate_condition,
                                    what=what)
    return SuperLUTangent(A, coords=coords, reach=reach, estimate_condition=estimate_condition, what=what)


def solve_superlu(A: sp.csr_matrix, b: np.ndarray, *, coords: np.ndarray, reach: float,
                  estimate_condition: bool = False, what: str = "linear system",
                  force_scale: float = 0.0) -> tuple[np.ndarray, SolverReport]:
    """Solve ``A x = b`` once by :class:`SuperLU`; ``coords`` and ``reach``
    as there."""
    return SuperLU(A, coords=coords, reach=reach, estimate_condition=estimate_condition, what=what).solve(
        b, force_scale)


class SuperLU:
    """``A`` equilibrated and factorised by SuperLU, unknown i located at
    ``coords[i]`` and coupled to unknowns within ``reach`` (for the
    ordering); raise :class:`SolverError` if it is singular.  Each
    :meth:`solve` is judged by its relative residual
    ``‖b − A x‖/max(‖b‖, force_scale)`` (:func:`contactcore.health.check_residual`),
    the backward error reported beside it.  SuperLU's equilibrated factors
    of a singular matrix rarely break down (round-off leaves a tiny pivot,
    hence a huge ``x`` and a tiny backward error), so the residual is the
    check that catches them."""

    def __init__(self, A: sp.csr_matrix, *, coords: np.ndarray, reach: float, estimate_condition: bool = False,
                 what: str = "linear system"):
        self.A, self.what = A, what
        self.s = _equilibrate(A)
        self.perm = nested_dissection(coords, reach)
        As = (sp.diags(self.s) @ A @ sp.diags(self.s))[self.perm][:, self.perm]
        try:
            self.lu = spla.splu(As.tocsc(), permc_spec="NATURAL", diag_pivot_thresh=PIVOT_THRESHOLD,
                                options={"SymmetricMode": True})
        except RuntimeError as exc:
            raise SolverError(f"{what} is singular ({exc}) — a rigid-body mode is not removed by the supports "
                              "and pins, or a penalty is so stiff that the bulk stiffness is lost in round-off") from None
        self.base = SolverReport(solver="superlu (scipy), equilibrated, nested dissection", factorisations=1)
        if estimate_condition:
            inv = spla.LinearOperator(As.shape, matvec=self.lu.solve, rmatvec=lambda v: self.lu.solve(v, trans="T"))
            self.base.condition = float(spla.onenormest(inv) * spla.norm(As, 1))
            if self.base.condition > tol.CONDITION_WARN:
                self.base.warnings.append(f"condition estimate {self.base.condition:.2e} exceeds "
                                          f"{tol.CONDITION_WARN:.0e}: digits may be lost (penalty too stiff, or "
                                          "supports too small?)")

    def solve(self, b: np.ndarray, force_scale: float = 0.0) -> tuple[np.ndarray, SolverReport]:
        x = np.empty_like(b)
        x[self.perm] = self.lu.solve((self.s * b)[self.perm])
        x *= self.s
        report = SolverReport(solver=self.base.solver, iterations=[1], factorisations=self.base.factorisations,
                              condition=self.base.condition, warnings=list(self.base.warnings))
        self.base.factorisations, self.base.warnings = 0, []
        r = b - self.A @ x
        report.residual = health.relative_residual(r, b, force_scale)
        report.backward_error = health.backward_error(r, spla.norm(self.A, np.inf), x, b)
        health.check_residual(report.residual if np.all(np.isfinite(x)) else float("nan"), self.what,
                              report.backward_error)
        return x, report


class SuperLUTangent:
    """Newton's ``J = A + K_Γ`` for :class:`SuperLU` (every unknown free),
    with the interface of :class:`contactcore.linear_solver.Tangent`: one
    factorisation per slot, a ``K_Γ`` of None solves with the slot's last."""

    def __init__(self, A: sp.csr_matrix, *, coords: np.ndarray, reach: float, estimate_condition: bool = False,
                 what: str = "linear system"):
        self.A, self.slots = A, {}
        self.kwargs = dict(coords=coords, reach=reach, estimate_condition=estimate_condition, what=what)

    def solve(self, interface_tangent, rhs: np.ndarray, force_scale: float = 0.0, slot: int = 0):
        if interface_tangent is not None:
            self.slots.pop(slot, None)  # until the factorisation succeeds
            self.slots[slot] = SuperLU((self.A + interface_tangent).tocsr(), **self.kwargs)
        return self.slots[slot].solve(rhs, force_scale)

    def close(self) -> None:
        self.slots = {}
