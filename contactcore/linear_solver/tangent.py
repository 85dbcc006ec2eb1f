"""Newton's tangent ``J = K + K_Γ`` and its factorisations, allocated once
per run and refilled, as dolfinx's ``NonlinearProblem`` does.

Only the free block ``J[free, free]`` is factorised, into one of several
kept slots (:class:`Tangent`); by MUMPS's LDLᵀ while ``K`` is symmetric and
``K_Γ`` is too on every rank (:func:`is_symmetric`: ``max |A − Aᵀ| <=
SYMMETRIC_TO_ROUNDOFF · max |A|``), by LU otherwise, the graph compressed
by node pairs where the factorised rows pair up (:meth:`Tangent._paired`).
``K_Γ`` comes in the local numbering of ``K``'s local-to-global map
(:func:`_local_to_global`: dolfinx's, or the identity for a matrix made
here).
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from petsc4py import PETSc

from contactcore.errors import SolverError
from contactcore.result import SolverReport
from contactcore import tolerances as tol
from contactcore.collective import SERIAL, Collective

from .diagnosis import NullPivots
from .factorisation import Factorisation
from .options import DEFAULT_PREFIX


def is_symmetric(A: sp.spmatrix) -> bool:
    """``max |A − Aᵀ| <= SYMMETRIC_TO_ROUNDOFF · max |A|``."""
    A = sp.csr_matrix(A)
    scale = abs(A).max() if A.nnz else 0.0
    return A.nnz == 0 or abs(A - A.T).max() <= tol.SYMMETRIC_TO_ROUNDOFF * scale


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
