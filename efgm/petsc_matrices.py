"""EFGM's scipy matrices as PETSc's, for MUMPS (:mod:`contactcore.linear_solver`):
in one process (:func:`to_petsc`), or split in contiguous rows over the
ranks of an mpi4py communicator (:func:`ownership`, :func:`owned_rows`,
:func:`distributed_aij`) with the ghost exchange of the unknowns
(:class:`ScatterExchange`), on PETSc alone, so EFGM runs under mpirun
without dolfinx.  petsc4py is imported inside the functions that use it,
so :func:`ownership` and :func:`owned_rows` (numpy alone) need none: EFGM
runs with numpy and scipy alone unless it solves by PETSc
(:mod:`efgm.petsc_solver`, :mod:`efgm.distributed`).
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from contactcore.assembly import sum_csr
from contactcore.exchange import Exchange


def to_petsc(A: sp.spmatrix) -> PETSc.Mat:
    """A serial PETSc AIJ matrix with the entries of a scipy sparse matrix
    (the PETSc side of :mod:`contactcore.assembly`'s one sink), made on
    copies of its CSR arrays, which PETSc then uses as its own (its
    ``MatCreateSeqAIJWithArrays``; petsc4py keeps them alive with the
    matrix): no insertion row by row.  Measured on EFGM's matrix of scene C
    at h = 0.0125 (7.2e6 entries): 0.011 s against 0.15 s through ``createAIJ``."""
    from petsc4py import PETSc
    A = sp.csr_matrix(A)
    A.sort_indices()
    return PETSc.Mat().createAIJWithArrays(size=A.shape, csr=(A.indptr.astype(PETSc.IntType),
                                                              A.indices.astype(PETSc.IntType), A.data.copy()),
                                           comm=PETSc.COMM_SELF)


def ownership(size: int, parts: int) -> np.ndarray:
    """The first row of each of ``parts`` ranks, and ``size`` last: PETSc's
    own split of ``size`` rows (PetscSplitOwnership), contiguous in rank
    order, the first ``size % parts`` ranks one row more."""
    counts = size // parts + (np.arange(parts) < size % parts)
    return np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)


def owned_rows(local: sp.spmatrix, starts: np.ndarray, comm) -> sp.csr_matrix:
    """The rows this rank owns (``starts[rank]`` to ``starts[rank + 1]``, in
    global numbering) of the sum over the ranks of every rank's ``local``
    contributions (global shape and numbering), canonical CSR: each rank
    sends every other the rows it owns (one ``alltoall`` of CSR slices over
    the mpi4py ``comm``) and sums what it receives in rank order, so the
    sum does not depend on timing.  Entries summing to exactly zero are
    dropped (:func:`~contactcore.assembly.sum_csr`)."""
    local = sp.csr_matrix(local)
    rank = comm.rank
    received = comm.alltoall([(piece.indptr, piece.indices, piece.data) for piece in
                              (local[starts[r]:starts[r + 1]] for r in range(comm.size))])
    shape = (int(starts[rank + 1] - starts[rank]), local.shape[1])
    return sum_csr(shape, [sp.csr_matrix((data, indices, indptr), shape=shape)
                           for indptr, indices, data in received])


def distributed_aij(owned: sp.csr_matrix, starts: np.ndarray, comm) -> PETSc.Mat:
    """A PETSc MPIAIJ matrix on ``comm`` whose rows ``starts[rank]`` to
    ``starts[rank + 1]`` are ``owned`` (global columns, :func:`owned_rows`),
    columns split as the rows: preallocated exactly from that CSR, explicit
    zeros kept (a pattern to refill)."""
    from petsc4py import PETSc
    owned = sp.csr_matrix(owned)
    owned.sort_indices()
    n, N = owned.shape[0], owned.shape[1]
    return PETSc.Mat().createAIJ(size=((n, N), (n, N)), csr=(owned.indptr.astype(PETSc.IntType),
                                                            owned.indices.astype(PETSc.IntType), owned.data),
                                 comm=comm)


class ScatterExchange(Exchange):
    """The ghost exchange of unknowns split in contiguous rows over the
    mpi4py ``comm`` (``starts`` as :func:`ownership`), on PETSc alone: this
    rank's local numbering is its owned unknowns, then ``ghosts`` (global
    indices it reads but does not own, in the order given).  ``forward``:
    owned values -> local values; ``reverse``: local contributions -> their
    sums on the owners (owned values).  One :class:`PETSc.Scatter` between
    the distributed vector and a sequential one of the local unknowns does
    both; :meth:`local_to_global` gives the map for ``setValuesLocal``.
    The caller destroys it (:meth:`destroy`)."""

    def __init__(self, comm, starts: np.ndarray, ghosts: np.ndarray):
        from petsc4py import PETSc
        rank = comm.rank
        first, last = int(starts[rank]), int(starts[rank + 1])
        self.indices = np.concatenate([np.arange(first, last), np.asarray(ghosts, np.int64)])
        self.owned_size, self.local_size = last - first, len(self.indices)
        self._global = PETSc.Vec().createMPI((self.owned_size, int(starts[-1])), comm=comm)
        self._local = PETSc.Vec().createSeq(self.local_size, comm=PETSc.COMM_SELF)
        self._is = PETSc.IS().createGeneral(self.indices.astype(PETSc.IntType), comm=PETSc.COMM_SELF)
        self._scatter = PETSc.Scatter().create(self._global, self._is, self._local, None)
        self._map = PETSc.LGMap().create(self.indices.astype(PETSc.IntType), comm=comm)

    def forward(self, owned: np.ndarray) -> np.ndarray:
        from petsc4py import PETSc
        self._global.setArray(np.ascontiguousarray(owned, float))
        self._scatter.scatter(self._global, self._local, PETSc.InsertMode.INSERT_VALUES, PETSc.ScatterMode.FORWARD)
        return self._local.getArray(readonly=True).copy()

    def reverse(self, local: np.ndarray) -> np.ndarray:
        from petsc4py import PETSc
        self._local.setArray(np.ascontiguousarray(local, float))
        self._global.set(0.0)
        self._scatter.scatter(self._local, self._global, PETSc.InsertMode.ADD_VALUES, PETSc.ScatterMode.REVERSE)
        return self._global.getArray(readonly=True).copy()

    def local_to_global(self) -> PETSc.LGMap:
        """The local numbering's map to the global one (owned by this object)."""
        return self._map

    def destroy(self) -> None:
        for obj in (self._scatter, self._is, self._local, self._global, self._map):
            obj.destroy()
