"""A dolfinx-assembled bulk matrix as the shared :class:`ContactSystem`.

The conforming reference and XFEM both end with a PETSc matrix ``K`` of the
bulk (no supports applied), one load vector per load, the prescribed
unknowns and an :class:`~contactcore.newton.InterfaceOperator`.  This class
hands them to :func:`contactcore.newton.solve_increments`: prescribed
unknowns are eliminated (only the free rows are factorised, by MUMPS LU,
which assumes no symmetry), and the interface tangent ``K_Γ`` (scipy CSR,
from the one assembly sink) is added into a copy of ``K`` whose pattern
already holds it (every cell couples all its unknowns).  That copy, its
free block and the factorisation are allocated once and refilled
(:class:`contactcore.linear_solver.Tangent`).  Serial only.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from petsc4py import PETSc

from contactcore import DiscretisationError
from contactcore.newton import InterfaceOperator

from contactcore import linear_solver


class PETScSystem:
    """``K`` (PETSc), loads, prescribed unknowns and Γ (see module doc).

    ``fixed`` are the prescribed unknowns; ``fixed_full`` their values at a
    factor of 1 and ``owner`` the support each follows (−1: always zero);
    ``active`` the unknowns that take part at all (the others are fixed at
    zero too).
    """

    def __init__(self, K, loads: list[np.ndarray], fixed, fixed_full, owner, interface: InterfaceOperator, *,
                 petsc_options=None, estimate_condition: bool = False, what: str = "linear system"):
        if K.getComm().getSize() > 1:
            raise DiscretisationError("the increment and Newton driver runs in serial only (no mpirun)")
        self.K, self.loads = K, loads
        self.size = K.getSize()[0]
        self.fixed = np.asarray(fixed, dtype=np.int64)
        self.fixed_full, self.owner = np.asarray(fixed_full, float), np.asarray(owner)
        self.free = np.setdiff1d(np.arange(self.size), self.fixed)
        self.interface = interface
        self._tangent = linear_solver.Tangent(K, self.free, petsc_options=petsc_options,
                                              estimate_condition=estimate_condition, what=what)

    def fixed_values(self, support_factors) -> np.ndarray:
        factor = np.asarray(tuple(support_factors) + (0.0,))[self.owner]
        return self.fixed_full * np.where(self.owner >= 0, factor, 0.0)

    def external(self, load_factors, support_factors) -> np.ndarray:
        return sum((lam * v for lam, v in zip(load_factors, self.loads)), np.zeros(self.size))

    def internal(self, u: np.ndarray) -> np.ndarray:
        x, y = self.K.createVecs()
        x.setArray(u)
        self.K.mult(x, y)
        out = y.getArray().copy()
        x.destroy()
        y.destroy()
        return out

    def solve(self, interface_tangent, rhs: np.ndarray, force_scale: float = 0.0, slot: int = 0):
        return self._tangent.solve(interface_tangent, rhs, force_scale, slot)

    def close(self) -> None:
        self._tangent.close()
