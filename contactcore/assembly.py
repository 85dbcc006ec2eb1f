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
