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
from contactcore.reaction_flux import multiplier_chain, multiplier_operator
from contactcore.system import InterfaceOperator

from .nodal import owned_rows, reaction_rows, working_pattern

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
    rows = owned_rows(K, l2g)
    ranks = space.cells.ranks
    total = ranks.sum(operator.size)
    interface = ranks.alike(_interface, scene, operator, owned, l2g, rows, fixed, total, spacing, method)
    return interface, working_pattern(K, owned, l2g, rows, interface, ranks, NOT_ON_ONE_RANK)


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
    A = reaction_rows(owned, l2g, rows, operator.G.indices, NOT_ON_ONE_RANK)
    return replace(multiplier_operator(operator, A, local_fixed, chain, method), exchange=operator.exchange)


def _empty(operator: InterfaceOperator, n: int) -> InterfaceOperator:
    """The interface of a rank that holds none of Γ's points (module doc)."""
    none = sp.csr_matrix((0, n))
    return InterfaceOperator(none, np.zeros(0), np.zeros((0, 2)), operator.exchange, S=none,
                             stabilisation=np.zeros(0), pieces=np.zeros((0, 2)), load_flux=none)
