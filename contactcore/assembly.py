"""The one assembly sink: element routines emit COO triplets, one helper
turns them into a sparse matrix (scipy CSR here; a PETSc AIJ builder can be
added beside it for the dolfinx-side methods).  When every point emits the
same pattern of rows (fixed widths, explicit zeros for padding),
:func:`point_rows_to_csr` writes the CSR arrays directly: no sorting, no
duplicate summation — 2x faster than the triplets for EFGM operators.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp


class Triplets:
    """Accumulates ``(row, col, value)`` blocks; duplicates are summed."""

    def __init__(self, shape: tuple[int, int]):
        self.shape = shape
        self.rows, self.cols, self.vals = [], [], []

    def add(self, rows, cols, vals) -> None:
        """Add entries; ``rows``, ``cols``, ``vals`` broadcast together.
        Entries whose row or column is negative are dropped (padding)."""
        r, c, v = np.broadcast_arrays(np.asarray(rows), np.asarray(cols), np.asarray(vals, float))
        keep = (r >= 0) & (c >= 0) & (v != 0)
        self.rows.append(r[keep].ravel())
        self.cols.append(c[keep].ravel())
        self.vals.append(v[keep].ravel())

    def to_csr(self) -> sp.csr_matrix:
        if not self.rows:
            return sp.csr_matrix(self.shape)
        return sp.csr_matrix((np.concatenate(self.vals), (np.concatenate(self.rows), np.concatenate(self.cols))),
                             shape=self.shape)


def point_rows_to_csr(ncols: int, widths: tuple[int, ...], cols: np.ndarray, vals: np.ndarray) -> sp.csr_matrix:
    """CSR whose rows come in groups of ``len(widths)`` per point: point p
    owns rows ``p·r … p·r + r − 1`` with ``widths`` entries each, given as
    ``cols``/``vals`` of shape (P, Σ widths) in row order."""
    P = cols.shape[0]
    indptr = np.concatenate([[0], np.cumsum(np.tile(np.asarray(widths), P))])
    return sp.csr_matrix((vals.ravel(), cols.ravel(), indptr), shape=(P * len(widths), ncols))



def blocks_to_csr(shape: tuple[int, int], dofs: np.ndarray, blocks: np.ndarray) -> sp.csr_matrix:
    """``Σ_e P_eᵀ K_e P_e`` of dense element blocks ``blocks`` (E, n, n) on
    the dofs ``dofs`` (E, n) (``P_e`` picks them; a negative dof is padding:
    its row and column are left out).  The local dofs may have any shape s,
    dofs (E, *s) and blocks (E, *s, *s), e.g. (node, component): a strided
    view is then read once, not copied to (E, n, n) first.  Summed by one
    sparse product ``Pᵀ M``: ``M`` holds the blocks' rows with global
    columns, ``P`` one 1 per block row at its dof, and the product's dense
    row accumulator sums the duplicates without sorting them (entries that
    sum to zero are dropped)."""
    E = dofs.shape[0]
    local = dofs.shape[1:]
    vals = np.where((dofs >= 0).reshape((E,) + (1,) * len(local) + local), blocks, 0.0).ravel()
    dofs = dofs.reshape(E, -1)
    n = dofs.shape[1]
    index = np.int32 if E * n * n < np.iinfo(np.int32).max else np.int64  # scipy's own choice: no conversion
    cols = np.broadcast_to(np.maximum(dofs, 0).astype(index)[:, None, :], (E, n, n)).ravel()
    M = sp.csr_matrix((vals, cols, np.arange(0, E * n * n + 1, n, dtype=index)), shape=(E * n, shape[1]))
    used = np.flatnonzero(dofs.ravel() >= 0)
    PT = sp.csr_matrix((np.ones(len(used)), (dofs.ravel()[used], used)), shape=(shape[0], E * n))
    return PT @ M  # both CSR: a CSC factor would convert M first


def pattern_union(*matrices: sp.spmatrix, value: float = 0.0) -> sp.csr_matrix:
    """``value`` on every entry stored in any of ``matrices`` (of one
    shape): with explicit zeros, the pattern a matrix refilled with any of
    their sums needs; with ones, a pattern that a further sum keeps.  Summed
    as ones, which cannot cancel, on the matrices' own index arrays (no copy
    of their values)."""
    ones = []
    for A in matrices:
        A = sp.csr_matrix(A)
        ones.append(sp.csr_matrix((np.ones(len(A.indices)), A.indices, A.indptr), shape=A.shape))
    union = sum(ones[1:], ones[0]).tocsr()
    union.data[:] = value
    return union


def sum_csr(shape: tuple[int, int], parts: list[sp.csr_matrix]) -> sp.csr_matrix:
    """The sum of sparse matrices of one ``shape``, by one product
    ``[I … I] · [A₁; …; A_k]`` (no pairwise additions), canonical."""
    if not parts:
        return sp.csr_matrix(shape)
    stacked = sp.vstack(parts, format="csr")
    k = len(parts)
    ones = sp.csr_matrix((np.ones(k * shape[0]), np.arange(k * shape[0]).reshape(k, -1).T.ravel(),
                          np.arange(0, k * shape[0] + 1, k)), shape=(shape[0], k * shape[0]))
    total = (ones @ stacked).tocsr()
    total.sort_indices()
    return total
