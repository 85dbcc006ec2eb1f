"""A dolfinx-assembled bulk matrix as the shared :class:`ContactSystem`.

The conforming reference and XFEM both end with a PETSc matrix ``K`` of the
bulk (no supports applied), one load vector per load, the prescribed
unknowns and an :class:`~contactcore.system.InterfaceOperator`.  This class
hands them to :func:`contactcore.newton.solve_increments`: prescribed
unknowns are eliminated (only the free rows are factorised, by MUMPS's
LDLᵀ while the interface tangent is symmetric, as ``K`` is by its weak
form, and by LU while Coulomb points slip), and the interface tangent
``K_Γ`` (scipy CSR, from the one assembly sink) is added into a copy of
``K`` whose pattern already holds it (every cell couples all its
unknowns).  That copy, its free block and the factorisation are allocated
once and refilled (:class:`contactcore.linear_solver.Tangent`).  Under
mpirun every rank holds its owned rows: vectors are owned values, ``K``
and the solve are PETSc's distributed ones, and Newton's decisions are
reduced over the ranks (:attr:`collective`).
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from dolfinx import la

from contactcore.collective import Collective
from contactcore import linear_solver
from contactcore.constraints import Constraints
from contactcore.exchange import Exchange
from contactcore.system import ContactSystem, InterfaceOperator

#: The options prefix of the dolfinx methods' factorisations in PETSc's options database.
PETSC_PREFIX = "xdolfinx_"


class PETScSystem(ContactSystem):
    """``K`` (PETSc), loads, the prescribed unknowns (``constraints`` on
    dofs) and Γ (see module doc), distributed over ``comm`` (the mesh's);
    ``work``, where ``K``'s pattern cannot hold the interface's tangent, a
    matrix whose pattern holds both (:func:`xdolfinx.nodal.working_pattern`)."""


    def __init__(self, K, loads: list[np.ndarray], constraints: Constraints, interface: InterfaceOperator, *,
                 comm=None, petsc_options=None, estimate_condition: bool = False, what: str = "linear system",
                 work=None):
        self.K, self.loads, self.constraints = K, loads, constraints
        self.collective = Collective(comm)  # the mesh's (mpi4py): it outlives K
        self.size = K.getLocalSize()[0]  # this rank's owned rows (all of them in serial)
        self.fixed = constraints.dofs
        self.free = np.setdiff1d(np.arange(self.size), self.fixed)
        self.interface = interface
        # K is symmetric by its weak form: LDLᵀ while the law's tangent is
        self._tangent = linear_solver.Tangent(K, self.free, work=work, symmetric=True, petsc_options=petsc_options,
                                              estimate_condition=estimate_condition, what=what,
                                              ranks=self.collective, prefix=PETSC_PREFIX)

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

    def column_budget(self, slot: int) -> int | None:
        """MUMPS solves a correction's columns as one block, as many as cost
        about one factorisation (:meth:`~contactcore.linear_solver.Tangent.column_budget`)."""
        return self._tangent.column_budget(slot)

    def solve_columns(self, rhs: sp.spmatrix, slot: int) -> np.ndarray:
        return self._tangent.solve_columns(rhs, slot)

    def close(self) -> None:
        self._tangent.close()


class GhostExchange(Exchange):
    """dolfinx's ghost updates of a space's unknowns (its index map and
    block size, on ``comm``): ``forward`` owned values -> local values (owned, then the
    ghosts this rank sees), ``reverse`` local contributions -> their sums on
    the owners (owned values).  ``ranks`` reduces over the map's
    communicator.

    ``order`` (optional) gives, for each block of the caller's own local
    numbering, its local index in ``index_map`` (a permutation): XFEM's
    local blocks are V's nodes then the enriched ones, while an index map
    lists every owned block before any ghost."""

    def __init__(self, index_map, bs: int, comm, order: np.ndarray | None = None):
        self.vector = la.vector(index_map, bs)
        self.owned_size = index_map.size_local * bs
        self.local_size = (index_map.size_local + index_map.num_ghosts) * bs
        self.ranks = Collective(comm)
        self.order = None if order is None else (np.asarray(order, np.int64)[:, None] * bs + np.arange(bs)).ravel()

    def forward(self, owned: np.ndarray) -> np.ndarray:
        self.vector.array[:self.owned_size] = owned
        self.vector.scatter_forward()
        return self.vector.array.copy() if self.order is None else self.vector.array[self.order]

    def reverse(self, local: np.ndarray) -> np.ndarray:
        if self.order is None:
            self.vector.array[:] = local
        else:
            self.vector.array[self.order] = local
        self.vector.scatter_reverse(la.ScatterMode.add)
        return self.vector.array[:self.owned_size].copy()
