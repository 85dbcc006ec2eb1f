"""EFGM spread over the ranks of an MPI communicator.

Under ``mpirun -n N`` every rank builds the same node set, supports,
enrichment and quadrature rules (geometry only, the same on each), then
does its own share of the work that costs:

* the background cells are split into contiguous ranges, in the fixed
  order of their grid index (row by row), holding about equal numbers of
  Gauss points
  (:func:`cell_share`: no partitioner, the same split on any machine); a
  rank evaluates the shape functions and the stiffness of its cells only;
* Γ's quadrature points and each loaded boundary's are split into
  contiguous ranges in the rules' order (:meth:`Collective.share`); the law
  and its history live at the Γ points a rank holds;
* the multipliers' rows (supports and pins) are evaluated by the rank that owns
  their row.

Every rank's contributions (global indices, from the one assembly sink)
are sent to the rows' owners and summed there in rank order
(:func:`efgm.petsc_matrices.owned_rows`), and PETSc makes the MPIAIJ
matrix from the owned rows, preallocated exactly
(:func:`~efgm.petsc_matrices.distributed_aij`; rows split as PETSc
would, contiguously).  ``G``'s columns are renumbered locally (owned, then
the ghosts this rank's Γ points reach), with a PETSc scatter for the
jumps and the forces (:class:`~efgm.petsc_matrices.ScatterExchange`);
the shared Newton driver then runs unchanged on owned values, its
decisions reduced over the ranks, and MUMPS factorises the distributed
matrix through :class:`~contactcore.linear_solver.Tangent` (LDLᵀ while
symmetric, LU otherwise, as in serial).

Nothing here imports MPI or PETSc before :func:`communicator` finds more
than one rank and petsc4py; on one rank (a pool worker's ``COMM_SELF``
included) or without petsc4py, EFGM is the serial method, unchanged.
"""
from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse as sp

from contactcore.assembly import pattern_union
from contactcore.collective import Collective, launched_size
from contactcore.constraints import Constraints
from contactcore.system import ContactSystem, InterfaceOperator

from . import petsc_solver
from .operators import SYMMETRIC


def communicator(comm=None):
    """The mpi4py communicator EFGM spreads over, or None (one process):
    ``comm`` if it has more than one rank, else (``comm`` None) mpirun's
    ``COMM_WORLD`` when it started several ranks; None whenever mpi4py or
    petsc4py does not import (every rank then solves the serial system)."""
    if comm is None:
        if launched_size() <= 1:
            return None  # no MPI started for a serial run
        try:
            from mpi4py import MPI
        except ImportError:
            return None
        comm = MPI.COMM_WORLD
    return comm if comm.size > 1 and petsc_solver.available() else None


def cell_share(points: np.ndarray, origin: np.ndarray, step: np.ndarray, ranks: Collective) -> np.ndarray:
    """Which of the volume Gauss ``points`` this rank integrates: those of
    its contiguous range of background cells (squares of side ``step``
    from ``origin``, ordered row by row: y, then x), the ranges cut where
    the points before them reach ``rank/size`` of all points.  A grid's
    nodes are numbered in the same order (:func:`efgm.nodes.grid_nodes`),
    so a rank's cells mostly fill the rows it owns."""
    if not ranks.parallel:
        return np.ones(len(points), bool)
    cell = np.maximum(np.floor((points - origin) / step), 0).astype(np.int64)
    key = cell[:, 1] * (cell[:, 0].max(initial=0) + 1) + cell[:, 0]  # row by row, as a grid's nodes are numbered
    keys, counts = np.unique(key, return_counts=True)
    owner = (np.cumsum(counts) - counts) * ranks.comm.size // max(len(points), 1)
    return owner[np.searchsorted(keys, key)] == ranks.rank


def owned_multipliers(ranks: Collective, ndofs: int, count: int) -> np.ndarray:
    """The multipliers' rows (of ``count``, numbered after the ``ndofs``
    unknowns of the approximation) whose rows this rank owns."""
    from .petsc_matrices import ownership

    starts = ownership(ndofs + count, ranks.comm.size)
    first, last = starts[ranks.rank], starts[ranks.rank + 1]
    return np.arange(max(first, ndofs), max(last, ndofs)) - ndofs


class DistributedEFGMSystem(ContactSystem):
    """The saddle point ``[[K, s Cᵀ], [s C, 0]]`` of
    :class:`efgm.method.EFGMSystem`, its rows split over ``ranks`` (module
    doc): a :class:`~contactcore.system.ContactSystem` on this rank's owned
    rows.  ``K`` holds this rank's cells only, ``constraints`` the rows this
    rank owns (the others zero), ``loads`` this rank's share of each load
    (global numbering), ``interface`` its Γ points with global columns."""

    def __init__(self, K, constraints: Constraints, loads, interface: InterfaceOperator, scale: float,
                 ranks: Collective, estimate_condition: bool, what: str):
        from . import petsc_matrices as pm

        comm = ranks.comm
        self.collective, self.scale, self.constraints = ranks, scale, constraints
        self.estimate, self.what = estimate_condition, what
        n, c = K.shape[0], constraints.operator.shape[0]
        self.ndofs, total = n, n + c
        starts = pm.ownership(total, comm.size)
        first, last = int(starts[ranks.rank]), int(starts[ranks.rank + 1])
        self.size = last - first
        self.fixed = np.zeros(0, int)
        C = scale * constraints.operator
        mine = sp.bmat([[K, C.T], [C, sp.csr_matrix((c, c))]], format="csr")
        # the interface: this rank's points, G's columns local (owned, then the ghosts they reach)
        operators = [M for M in (interface.G, interface.S) if M is not None]  # Nitsche's S reaches further
        touched = np.unique(np.concatenate([M.indices for M in operators]))
        self.exchange = pm.ScatterExchange(comm, starts, touched[(touched < first) | (touched >= last)])
        where = np.argsort(self.exchange.indices)

        def local(M):
            if M is None:
                return None
            columns = where[np.searchsorted(self.exchange.indices, M.indices, sorter=where)]
            return sp.csr_matrix((M.data, columns, M.indptr), shape=(M.shape[0], self.exchange.local_size))

        self.interface = dataclasses.replace(interface, G=local(interface.G), S=local(interface.S),
                                             exchange=self.exchange)
        reach = self.interface.pattern().tocoo()  # every K_Γ entry this rank may add, in global numbering
        reach = sp.csr_matrix((np.abs(reach.data), (self.exchange.indices[reach.row],
                                                    self.exchange.indices[reach.col])), shape=(total, total))
        # owned rows: the bulk, and the pattern of K and every K_Γ (zeros, refilled by the Tangent)
        self.A = pm.distributed_aij(pm.owned_rows(mine, starts, comm), starts, comm)
        self.A.setLGMap(self.exchange.local_to_global(), self.exchange.local_to_global())
        work = pm.owned_rows(pattern_union(mine, reach, value=1.0), starts, comm)  # ones: the ranks' sum keeps them
        work.data[:] = 0.0
        self.work = pm.distributed_aij(work, starts, comm)
        f = sp.vstack([sp.csr_matrix(np.column_stack(loads)) if loads else sp.csr_matrix((n, 0)),
                       sp.csr_matrix((c, len(loads)))], format="csr")
        self.loads = pm.owned_rows(f, starts, comm).toarray().T  # (loads, owned rows)
        self.multipliers = np.arange(max(first, n), max(last, n))  # owned multiplier rows, global
        self.constraint_rows = np.arange(self.size - len(self.multipliers), self.size)  # the same, local
        self._vectors = self.A.createVecs()
        self._tangent = None

    def fixed_values(self, support_factors) -> np.ndarray:
        return np.zeros(0)

    def external(self, load_factors, support_factors) -> np.ndarray:
        b = sum((lam * v for lam, v in zip(load_factors, self.loads)), np.zeros(self.size))
        owned = self.size - len(self.multipliers)  # the multiplier rows come last among the owned
        b[owned:] += self.scale * self.constraints.at(support_factors)[self.multipliers - self.ndofs]
        return b

    def internal(self, u: np.ndarray) -> np.ndarray:
        x, y = self._vectors
        x.setArray(u)
        self.A.mult(x, y)
        return y.getArray(readonly=True).copy()

    def solve(self, interface_tangent, rhs, force_scale=0.0, slot=0):
        if self._tangent is None:
            from contactcore import linear_solver as ls
            self._tangent = ls.Tangent(self.A, np.arange(self.size), work=self.work,
                                       symmetric=SYMMETRIC, estimate_condition=self.estimate, what=self.what, ranks=self.collective,
                                       prefix=petsc_solver.PETSC_PREFIX)
        return self._tangent.solve(interface_tangent, rhs, force_scale, slot)

    def close(self) -> None:
        """Destroy every PETSc object (the Tangent owns ``A`` and the work
        matrix once made)."""
        if self.A is None:
            return
        if self._tangent is not None:
            self._tangent.close()
        else:
            self.A.destroy()
            self.work.destroy()
        for obj in self._vectors:
            obj.destroy()
        self.exchange.destroy()
        self.A = self.work = self._tangent = None
        self._vectors = ()
