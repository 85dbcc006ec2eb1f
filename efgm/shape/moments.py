"""The MLS moment matrix ``A(x) = Σ_I w_I(x) p̃_I p̃_Iᵀ``: summed, inverted, judged.

The moving least-squares fit at ``x`` (Lancaster & Šalkauskas, Math. Comp.
37, 1981; EFG: Belytschko, Lu & Gu, IJNME 37, 1994) solves ``A(x) a(x) =
Σ_I w_I(x) p̃_I u_I``: ``A`` is symmetric, and positive definite exactly
when no nonzero polynomial of the basis vanishes at every node whose
support holds ``x`` (the linear basis: three such nodes not on one line;
the quadratic: six not on one conic).

- :meth:`_Moments._moments` sums it from the m(m+1)/2 distinct products.
- :func:`_spd_inverse` inverts a stack of them by Gauss–Jordan elimination
  without pivoting (stable for a symmetric positive definite matrix),
  in plain numpy ufuncs: no LAPACK, whose serial OpenBLAS build fails
  when called from two threads at once (:mod:`efgm.shape.parallel`).
- :meth:`_Moments.regularity` and :func:`_scaled_determinant` measure how
  far it is from singular, ``det(A) / Π A_ii``: 1 for orthogonal moments,
  0 for a singular A, whatever the scale of the weights (the refusal's
  measure, :mod:`efgm.shape.refusal`).

Contract of the mixin: :class:`efgm.shape.MLS` gives ``self.m``, the basis
size.
"""
from __future__ import annotations

import numpy as np


def _spd_inverse(A: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Inverses of a stack of symmetric positive definite matrices (P, m, m)
    by Gauss–Jordan elimination without pivoting, and the pivots (P, m)
    (their product is the determinant).  Plain numpy ufuncs: no LAPACK,
    whose serial OpenBLAS build gives wrong answers when called from two
    threads at once (measured here), and no per-matrix call overhead.  A
    singular A gives non-finite entries, caught by the regularity check.
    """
    P, m, _ = A.shape
    aug = np.concatenate([A, np.broadcast_to(np.eye(m), A.shape)], axis=2)
    pivots = np.empty((P, m))
    with np.errstate(divide="ignore", invalid="ignore"):
        for k in range(m):
            pivots[:, k] = aug[:, k, k]
            aug[:, k, :] /= aug[:, k, k:k + 1]
            factors = aug[:, :, k].copy()
            factors[:, k] = 0.0
            aug -= factors[:, :, None] * aug[:, k:k + 1, :]
    return aug[:, :, m:], pivots


def _scaled_determinant(det, a00, a11, a22) -> np.ndarray:
    """:meth:`MLS.regularity` of 3 × 3 matrices from their determinant and diagonal."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return det / (np.where(a00 > 0, a00, 1.0) * np.where(a11 > 0, a11, 1.0) * np.where(a22 > 0, a22, 1.0))


class _Moments:
    """The moment matrices of :class:`efgm.shape.MLS` and their regularity."""

    def _moments(self, w: np.ndarray, pI: np.ndarray) -> np.ndarray:
        """``Σ_K w p̂_i p̂_j`` (P, m, m) of w (P, K), p̂ (m, P, K), from the
        m(m+1)/2 distinct products."""
        A = np.empty((w.shape[0], self.m, self.m))
        for i in range(self.m):
            wi = w * pI[i]
            for j in range(i, self.m):
                A[:, i, j] = A[:, j, i] = np.sum(wi * pI[j], axis=1)
        return A

    def regularity(self, A, pivots) -> np.ndarray:
        """``det(A) / Π A_ii``: the determinant of A scaled to a unit
        diagonal, 1 for orthogonal moments, 0 for a singular A."""
        diag = np.einsum("pii->pi", A)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            return np.prod(pivots / np.where(diag > 0, diag, 1.0), axis=1)
