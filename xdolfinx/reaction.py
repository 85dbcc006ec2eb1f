"""xfem's ``flux="reaction"`` on PETSc: Γ's multiplier mesh and the
least-squares reaction (:mod:`contactcore.reaction_flux`) from ``K``, and
the matrix whose pattern holds its tangent beside ``K``'s.

Under mpirun (as fe's nodal reaction, :mod:`xdolfinx.nodal`) the
background mesh keeps every cell within two layers of the cut cells on
one rank (:func:`xdolfinx.xfem.cells.cut_partitioner`).  Layer 1 holds
each cell that touches a cut cell's corner, layer 2 each that shares a
vertex with layer 1.  ``G``'s and ``B``'s columns (hence ``L``'s) are the
enriched unknowns of the cut cells' nodes; their rows of ``A`` reach the
unknowns of every cell holding such a node (and of the cells across a
cut cell's edges, whose stress the default flux reads: layer 1 too), so
``S = L A`` and ``SᵀWΓ⁻¹S`` couple the nodes of layer 1.  Every cell
holding one of those is in layer 2, owned by that rank, so it owns and
assembles whole each row the reaction reads and each row its tangent
reaches; the Gauss points (in the cut cells, its own) and the multiplier
nodes are all there, the other ranks hold none.  Columns are in xfem's
local numbering (:class:`~xdolfinx.xfem.space.EnrichedFunctionSpace`:
nodes, then enriched nodes), which ``K``'s local-to-global map reads."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import scipy.sparse as sp

from contactcore import DiscretisationError
from contactcore import tolerances as tol
from contactcore.collective import SERIAL, Collective
from contactcore.reaction_flux import multiplier_chain, multiplier_operator
from contactcore.system import InterfaceOperator

from .nodal import _local_columns

#: Why the reaction cannot be read on one rank (the partition of
#: :func:`xdolfinx.xfem.cells.cut_partitioner` was not taken).
NOT_ON_ONE_RANK = ('xfem: flux = "reaction": Γ\'s points, or a row of an unknown they read, are not held whole '
                   'by one rank (the mesh must keep the cells within two layers of the cut cells on one rank)')


def multiplier_spacing(cell: str, degree: int, h: float) -> float:
    """Γ's multiplier spacing for xfem P``degree`` on ``cell``:
    :data:`~contactcore.tolerances.MULTIPLIER_SPACING_TRIANGLES_P1` ``h``
    for P1 on triangles (``"triangle"``, ``"gmsh"``), else
    :data:`~contactcore.tolerances.MULTIPLIER_SPACING` ``h``."""
    triangles_p1 = cell != "quad" and degree == 1
    return (tol.MULTIPLIER_SPACING_TRIANGLES_P1 if triangles_p1 else tol.MULTIPLIER_SPACING) * h


def reaction_interface(scene, K, fixed: np.ndarray, operator: InterfaceOperator, spacing: float, space,
                       method: str):
    """``(interface, work)``: the multiplier nodes at ``spacing``
    (:func:`multiplier_spacing`) with the
    least-squares reaction of the bulk ``K`` (PETSc; ``fixed`` its
    prescribed owned rows) from the method's Gauss-point ``operator`` on
    ``space``'s unknowns, and :func:`working_pattern` (module doc)."""
    indptr, indices, values = K.getValuesCSR()
    owned = sp.csr_matrix((values, indices, indptr), shape=(K.getLocalSize()[0], K.getSize()[1]))
    l2g = (2 * space.numbering.global_blocks[:, None] + np.arange(2)).ravel()
    start, stop = K.getOwnershipRange()
    rows = np.where((l2g >= start) & (l2g < stop), l2g - start, -1)  # each local unknown's owned row, or −1
    ranks = space.cells.ranks
    total = ranks.sum(operator.size)
    interface = ranks.alike(_interface, scene, operator, owned, l2g, rows, fixed, total, spacing, method)
    return interface, working_pattern(K, owned, l2g, rows, interface, ranks)


def _interface(scene, operator: InterfaceOperator, owned: sp.csr_matrix, l2g: np.ndarray, rows: np.ndarray,
               fixed: np.ndarray, total: int, spacing: float, method: str) -> InterfaceOperator:
    """This rank's share of :func:`reaction_interface`'s operator: all of
    Γ's ``total`` points or none of them (else :data:`NOT_ON_ONE_RANK`)."""
    if operator.size not in (0, total):
        raise DiscretisationError(NOT_ON_ONE_RANK)
    if operator.size == 0:
        return _empty(operator, len(l2g))
    chain = multiplier_chain(scene.interface, scene.domain, spacing, method)
    local_fixed = np.flatnonzero(np.isin(rows, np.asarray(fixed, np.int64)))
    return replace(multiplier_operator(operator, _reaction_rows(owned, l2g, rows, operator.G), local_fixed,
                                       chain, method), exchange=operator.exchange)


def _reaction_rows(owned: sp.csr_matrix, l2g: np.ndarray, rows: np.ndarray, G: sp.csr_matrix) -> sp.csr_matrix:
    """``A``'s rows of the unknowns ``G`` reads (the only ones ``L A``
    reads), local numbering (the other rows empty): each owned whole
    (``rows``, its owned row) and reaching local unknowns only, else
    :data:`NOT_ON_ONE_RANK`."""
    reads = np.unique(G.indices)
    if np.any(rows[reads] < 0):
        raise DiscretisationError(NOT_ON_ONE_RANK)
    taken = owned[rows[reads]]
    columns = _local_columns(taken.indices, l2g, NOT_ON_ONE_RANK)
    counts = np.zeros(len(l2g), np.int64)
    counts[reads] = np.diff(taken.indptr)
    indptr = np.concatenate([[0], np.cumsum(counts)])
    return sp.csr_matrix((taken.data, columns, indptr), shape=(len(l2g), len(l2g)))


def _empty(operator: InterfaceOperator, n: int) -> InterfaceOperator:
    """The interface of a rank that holds none of Γ's points (module doc)."""
    none = sp.csr_matrix((0, n))
    return InterfaceOperator(none, np.zeros(0), np.zeros((0, 2)), operator.exchange, S=none,
                             stabilisation=np.zeros(0), pieces=np.zeros((0, 2)), load_flux=none)


def working_pattern(K, owned: sp.csr_matrix, l2g: np.ndarray, rows: np.ndarray, interface: InterfaceOperator,
                    ranks: Collective = SERIAL):
    """A PETSc matrix distributed as ``K`` (its block size) with the
    bulk's pattern (its ``owned`` rows, global columns) and every entry
    the interface's tangent can reach
    (:meth:`~contactcore.system.InterfaceOperator.pattern`, local
    numbering: ``rows`` each one's owned row, ``l2g`` its global index),
    values zero: ``SᵀWΓ⁻¹S`` couples every unknown near Γ, beyond ``K``'s
    pattern.  A collective call over ``ranks`` (the matrix's): a row not
    owned is refused on every rank alike."""
    from petsc4py import PETSc
    ones = sp.csr_matrix((np.ones_like(owned.data), owned.indices, owned.indptr), shape=owned.shape)
    reach = interface.pattern().tocoo()
    ranks.raise_any(DiscretisationError(NOT_ON_ONE_RANK) if np.any(rows[reach.row] < 0) else None)
    both = (ones + sp.csr_matrix((np.abs(reach.data), (rows[reach.row], l2g[reach.col])), shape=owned.shape)).tocsr()
    both.sort_indices()
    both.data[:] = 0.0
    sizes = (K.getLocalSize()[0], K.getSize()[0]), (K.getLocalSize()[1], K.getSize()[1])
    return PETSc.Mat().createAIJ(sizes, bsize=K.getBlockSize(), csr=(both.indptr.astype(PETSc.IntType),
                                                                     both.indices.astype(PETSc.IntType), both.data),
                                 comm=K.getComm())
