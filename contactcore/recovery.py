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


def distinct_svd(A: np.ndarray, key: list | None = None,
                 memo: dict | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``np.linalg.svd(A, full_matrices=False)`` of a stack ``A`` (B, m, k)
    (an array, or an object with its ``shape``, ``len`` and rows ``A[rows]``:
    :class:`_Basis`), each distinct matrix factored once.  A patch's matrix is its samples'
    offsets and weights only, and on a uniform grid most patches repeat
    another's bit for bit (scene C at h = 0.025: 1 300 distinct among the
    Zienkiewicz–Zhu estimate's 9 700, 3 100 among xfem's 9 100); LAPACK
    factors each matrix of a stack on its own, so a repeat's factors are
    the bits its own factoring gives.  Matrices are told apart by their
    bits (a hash, then every word compared; a collision falls back to
    sorting the matrices' bytes), or by those of ``key``: arrays (B, ...)
    whose bits fix each matrix's (:meth:`PatchRecovery._fit`'s weights and
    offsets, from which its columns are products), fewer words to read.
    ``memo`` (a dict, kept by the caller between calls) holds the factors
    of earlier calls' distinct matrices, by their shape and words: a
    matrix factored in an earlier stack is not factored again (LAPACK's
    work for an (m, k) matrix is chosen by m and k alone, so its factors
    are the bits it had there; tilt35, xfem P1 at h = 0.003125: 5 800
    distinct matrices among 92 000 patches, 10 000 counted stack by stack)."""
    parts = [np.ascontiguousarray(part).reshape(len(A), -1).view(np.uint64) for part in (key or [A])]
    width = sum(part.shape[1] for part in parts)
    hashed = width <= len(_MIX)
    if hashed:
        # Σ_k word_k mix_k (mod 2^64) as one product per part: the sum of the products, three times faster
        code, at = parts[0] @ _MIX[:parts[0].shape[1]], parts[0].shape[1]
        for part in parts[1:]:
            code, at = code + part @ _MIX[at:at + part.shape[1]], at + part.shape[1]
        _, first, inverse = np.unique(code, return_index=True, return_inverse=True)
        hashed = all(np.array_equal(part, np.take(np.take(part, first, axis=0), inverse, axis=0)) for part in parts)
    if not hashed:
        words = np.hstack(parts)
        key = words.view(np.dtype((np.void, words.shape[1] * words.itemsize))).ravel()
        _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
    if memo is None or not hashed:
        U, S, Vt = np.linalg.svd(A[first], full_matrices=False)
        return U[inverse], S[inverse], Vt[inverse]
    words, code = np.hstack([np.take(part, first, axis=0) for part in parts]), code[first]
    known = memo.setdefault((A.shape[1:], width), _Factors())
    row = known.find(code, words)
    new = np.flatnonzero(row < 0)
    U, S, Vt = np.linalg.svd(A[first[new]], full_matrices=False)
    if len(new) < len(first):
        got = [np.empty((len(first),) + f.shape[1:]) for f in (U, S, Vt)]
        for g, f, k in zip(got, (U, S, Vt), known.factors):
            g[new], g[row >= 0] = f, np.take(k, row[row >= 0], axis=0)
        U, S, Vt = got
    known.add(code[new], words[new], (U[new], S[new], Vt[new]))
    return U[inverse], S[inverse], Vt[inverse]


class _Basis:
    """The stack of :meth:`PatchRecovery._fit`'s matrices ``quadratic_basis(d, terms) · weight`` of
    patches (their ``weight``, ``d0`` and ``d1`` (patches, samples)), built only for the patches
    asked for (``[rows]``): column by column, the same operations as on the whole stack."""

    def __init__(self, weight: np.ndarray, d0: np.ndarray, d1: np.ndarray, terms: int):
        self.weight, self.d0, self.d1, self.terms = weight, d0, d1, terms
        self.shape = weight.shape + (terms,)

    def __len__(self) -> int:
        return len(self.weight)

    def __getitem__(self, rows: np.ndarray) -> np.ndarray:
        w, d0, d1 = (np.take(v, rows, axis=0) for v in (self.weight, self.d0, self.d1))
        A = np.empty(w.shape + (self.terms,))
        A[..., 0] = w
        np.multiply(d0, w, out=A[..., 1])
        np.multiply(d1, w, out=A[..., 2])
        if self.terms > 3:
            np.multiply(d0 * d0, w, out=A[..., 3])
            np.multiply(d0 * d1, w, out=A[..., 4])
            np.multiply(d1 * d1, w, out=A[..., 5])
        return A


class _Factors:
    """:func:`distinct_svd`'s memo of one shape: the factors (U, S, Vt) of
    the distinct matrices factored so far, their words, and their hash codes
    sorted (a code met again with other words is factored anew, not kept)."""

    def __init__(self):
        self.size, self.codes, self.rows = 0, np.zeros(0, np.uint64), np.zeros(0, int)
        self.words, self.factors = None, None

    def find(self, code: np.ndarray, words: np.ndarray) -> np.ndarray:
        """Each matrix's row among the factors, −1 where not factored yet."""
        if not self.size:
            return np.full(len(code), -1)
        at = np.minimum(np.searchsorted(self.codes, code), len(self.codes) - 1)
        row = np.where(self.codes[at] == code, self.rows[at], -1)
        hit = np.flatnonzero(row >= 0)
        same = np.all(np.take(self.words, row[hit], axis=0) == words[hit], axis=1)
        row[hit[~same]] = -1
        return row

    def add(self, code: np.ndarray, words: np.ndarray, factors: tuple) -> None:
        """Keep the factors of new matrices (their codes not known yet)."""
        fresh = np.flatnonzero(~np.isin(code, self.codes))
        if not len(fresh):
            return
        if self.factors is None:
            self.words = np.empty((0,) + words.shape[1:], words.dtype)
            self.factors = [np.empty((0,) + f.shape[1:]) for f in factors]
        end = self.size + len(fresh)
        if end > len(self.words):  # room doubled: appending stays O(1) a row
            grow = lambda a: np.concatenate([a[:self.size], np.empty((max(end, 2 * len(a)),) + a.shape[1:], a.dtype)])  # noqa: E731
            self.words, self.factors = grow(self.words), [grow(f) for f in self.factors]
        self.words[self.size:end] = words[fresh]
        for k, f in zip(self.factors, factors):
            k[self.size:end] = f[fresh]
        codes = np.concatenate([self.codes, code[fresh]])
        order = np.argsort(codes, kind="stable")
        self.codes, self.rows = codes[order], np.concatenate([self.rows, np.arange(self.size, end)])[order]
        self.size = end


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
        # the samples' coordinates, areas and σ as contiguous columns, a zero appended to the areas and
        # σ (what :meth:`_fit`'s padding reads)
        self._x, self._y = np.ascontiguousarray(centroids[:, 0]), np.ascontiguousarray(centroids[:, 1])
        self._areas0 = np.append(areas, 0.0)
        self._sigma0 = [np.append(sigma[:, k], 0.0) for k in range(3)]
        self._fitted = np.zeros(len(keys), bool)
        self._factors = {}  # distinct_svd's memo
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
        todo = np.zeros(len(self._fitted), bool)
        todo[cells] = True
        todo = np.flatnonzero(todo & ~self._fitted)  # np.unique(cells[~self._fitted[cells]]), without a sort
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
        index, centroids, sig = self.sample, self.centroids, self.sigma
        sub = self.patches(targets)
        member = np.take(index, sub.indices)
        keep = member >= 0
        rows, member = np.repeat(np.arange(len(targets)), np.diff(sub.indptr))[keep], member[keep]
        count = np.bincount(rows, minlength=len(targets))
        longest = count.max(initial=0)
        # Each patch's samples in its row of a padded (targets, longest) layout, computed there: slot
        # row·longest + position.  A padding slot reads the zero area and σ appended to the samples' (so
        # its weight and values are +0, as the zeros it was padded with) and the patch's own origin (so
        # its offsets are +0); every other value is the same operations on the same numbers as the flat
        # rows scattered into that layout (the same bits), without the scatter and the copies
        slot = np.arange(len(rows)) + np.repeat(np.arange(len(targets)) * longest - (np.cumsum(count) - count), count)
        at_origin = np.take(index, targets)
        padded = np.full(len(targets) * longest, len(centroids))
        padded[slot] = member
        located = np.repeat(at_origin, longest)
        located[slot] = member
        area = np.take(self._areas0, padded).reshape(len(targets), longest)
        largest = area.max(axis=1, initial=0.0)  # a maximum: the padding's zeros change nothing, areas ≥ 0
        origin, length = np.take(centroids, at_origin, axis=0), np.sqrt(largest)
        some = count > 0  # the others have no samples (and no fit): their divisions by 1 are not used
        weight = np.sqrt(area / np.where(some, largest, 1.0)[:, None])
        scale = np.where(some, length, 1.0)[:, None]
        d0 = (np.take(self._x, located).reshape(weight.shape) - origin[:, :1]) / scale
        d1 = (np.take(self._y, located).reshape(weight.shape) - origin[:, 1:]) / scale
        Y = np.empty((len(targets), longest, 3))
        for k in range(3):
            np.multiply(np.take(self._sigma0[k], padded).reshape(weight.shape), weight, out=Y[..., k])
        coef = np.full((len(targets), 6, 3), np.nan)  # a line's: its quadratic terms 0
        for terms in (6, 3):
            todo = np.flatnonzero(np.isnan(coef[:, 0, 0]) & (count > terms))
            if not len(todo):
                continue
            every = len(todo) == len(targets)  # no copies of the stacks (the same values)
            # a matrix's columns are products of its weights and offsets: those tell the matrices apart, and
            # only the matrices factored are built
            key = [weight, d0, d1] if every else [np.take(v, todo, axis=0) for v in (weight, d0, d1)]
            U, S, Vt = distinct_svd(_Basis(*key, terms), key, self._factors)
            full = np.sum(S >= S[:, :1] * tol.RECOVERY_RANK, axis=1) == terms  # a spread, not round-off
            solved = np.swapaxes(Vt, 1, 2) @ ((np.swapaxes(U, 1, 2) @ (Y if every else Y[todo]))
                                              / np.where(S > 0, S, 1.0)[:, :, None])
            coef[todo[full]] = 0.0
            coef[todo[full], :terms] = solved[full]
        self._fitted[targets] = True
        self._origin[targets], self._length[targets], self._coef[targets] = origin, length, coef
