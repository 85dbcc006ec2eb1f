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

from contactcore import DiscretisationError
from contactcore.constraints import Constraints
from contactcore.newton import InterfaceOperator

from contactcore import linear_solver


class PETScSystem:
    """``K`` (PETSc), loads, the prescribed unknowns (``constraints`` on
    dofs) and Γ (see module doc)."""

    def __init__(self, K, loads: list[np.ndarray], constraints: Constraints, interface: InterfaceOperator, *,
                 petsc_options=None, estimate_condition: bool = False, what: str = "linear system"):
        if K.getComm().getSize() > 1:
            raise DiscretisationError("the increment and Newton driver runs in serial only (no mpirun)")
        self.K, self.loads, self.constraints = K, loads, constraints
        self.size = K.getSize()[0]
        self.fixed = constraints.dofs
        self.free = np.setdiff1d(np.arange(self.size), self.fixed)
        self.interface = interface
        self._tangent = linear_solver.Tangent(K, self.free, petsc_options=petsc_options,
                                              estimate_condition=estimate_condition, what=what)

    def fixed_values(self, support_factors) -> np.ndarray:
        return self.constraints.at(support_factors)

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
