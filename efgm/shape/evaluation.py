"""Φ and ∇Φ at points: the MLS shape functions evaluated (the paper's §VII).

The moving least-squares shape functions of the element-free Galerkin
method (Belytschko, Lu & Gu, IJNME 37, 1994; the paper's Eqs. 19–23): for
a point ``x`` with neighbours ``I`` (:mod:`efgm.shape.neighbours`),

    Φ_I(x) = p̃(x)ᵀ A(x)⁻¹ p̃(x_I) w_I(x),   A(x) = Σ_I w_I(x) p̃(x_I) p̃(x_I)ᵀ,

the basis shifted and scaled at the point itself (:mod:`efgm.shape.basis`:
``x̄ = x``, ``s`` the largest support radius among the neighbours), so
that ``p̃(x) = e₁``.  Derivatives hold ``x̄`` fixed: with ``γ = A⁻¹ p̃(x)``,

    ∂Φ_I = (∂γ)ᵀ p̃_I w_I + γᵀ p̃_I ∂w_I,   ∂γ = A⁻¹ (∂p̃(x) − ∂A γ),
    ∂A = Σ_I ∂w_I p̃_I p̃_Iᵀ,   ∂p̃(x)/∂x_d = e_{d+1}/s.

:meth:`_Evaluation.evaluate` takes the points in chunks over threads
(:mod:`efgm.shape.parallel`); the linear basis takes a closed form
(:meth:`_Evaluation._linear_shape`: the 3 × 3 inverse by cofactors), the
quadratic one the grouped form :meth:`efgm.shape.MLS.cell_shape` with one
point a group.  A singular ``A`` is refused by name
(:mod:`efgm.shape.refusal`).

Contract: :class:`ShapeValues` holds P points' neighbour indices (P, K)
(−1 = padding), Φ (P, K) and ∇Φ (P, K, 2), zero in the padding; a point
gets the same values whatever chunk and thread it is evaluated in, to
round-off.  The mixin reads :class:`efgm.shape.MLS`'s ``degree`` and
``seen_from`` and calls its ``neighbours``, ``_weights``, ``cell_shape``
and ``_check_regular``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .moments import _scaled_determinant
from .parallel import POINT_CHUNK, parallel_map

@dataclass
class ShapeValues:
    """Shape functions at P points: neighbour indices (P, K) (−1 = padding),
    values (P, K) and gradients (P, K, 2); padded entries are zero."""

    index: np.ndarray
    phi: np.ndarray
    grad: np.ndarray


class _Evaluation:
    """Φ and ∇Φ of :class:`efgm.shape.MLS` at points."""

    def evaluate(self, points, bodies=None) -> ShapeValues:
        """Φ and ∇Φ at ``points`` (P, 2) of ``bodies`` (P,) (needed with
        ``seen_from``); a clear error where A is singular.

        Points are taken in chunks of :data:`POINT_CHUNK` (their temporaries
        stay in cache) spread over the cores: numpy releases the GIL in these
        kernels.  A first pass finds each chunk's neighbours, which sets the
        output's width; a second writes each chunk's Φ and ∇Φ into its rows
        of the output, in place (a serial copy of the chunks after them was
        an eighth of the time).  The linear basis takes a closed form
        (:meth:`_linear_shape`), the quadratic one :meth:`cell_shape`.
        """
        points = np.asarray(points, float).reshape(-1, 2)
        if self.seen_from is not None and bodies is None:
            raise ValueError("efgm: shape functions with visibility need the body of each point")
        bodies = None if bodies is None else np.broadcast_to(np.asarray(bodies, int), (len(points),))
        starts = range(0, len(points), POINT_CHUNK)
        found = list(parallel_map(lambda i: self.neighbours(
            points[i:i + POINT_CHUNK], None if bodies is None else bodies[i:i + POINT_CHUNK]), starts))
        K = max((idx.shape[0] for idx, _, _ in found), default=1)
        out = ShapeValues(np.full((len(points), K), -1), np.zeros((len(points), K)), np.zeros((len(points), K, 2)))

        def shape(j: int) -> None:  # chunk j into its rows and first columns of out; the padding stays
            idx, ox, oy = found[j]
            found[j] = None
            rows, width = slice(starts[j], starts[j] + idx.shape[1]), idx.shape[0]
            out.index[rows, :width] = idx.T
            phi, grad = out.phi[rows, :width], out.grad[rows, :width]
            if self.degree == 1:
                self._linear_shape(points[rows], idx, ox, oy, phi.T, grad.transpose(2, 1, 0))
            else:
                values, gradients = self.cell_shape(points[rows, None, :], np.ascontiguousarray(idx.T))
                phi[:], grad[:] = values[:, 0], gradients[:, 0]

        for _ in parallel_map(shape, range(len(starts))):
            pass
        return out

    def _linear_shape(self, points, idx, ox, oy, phi: np.ndarray, grad: np.ndarray) -> None:
        """Φ into ``phi`` (K, P) and ∇Φ into ``grad`` (2, K, P) of the
        linear basis at single points, from their neighbours ``idx`` and
        offsets (K, P) (:meth:`neighbours`), by :meth:`cell_shape`'s
        formulas for groups of one point: the 3 × 3 moment matrix and its
        derivatives from their 6 distinct sums each, inverted in closed form
        (cofactors over the determinant)."""
        w, wdx, wdy, r_node = self._weights(idx, ox, oy)  # (K, P)
        s = np.max(np.where(w > 0, r_node, 0.0), axis=0, initial=0.0)
        s[s == 0] = 1.0
        s_g = np.max(np.where(idx >= 0, r_node, 0.0), axis=0, initial=0.0)
        s_g[s_g == 0] = 1.0
        xi, eta = -ox / s_g, -oy / s_g  # p̂_I = (1, ξ, η) = p((x_I − x)/s_g)

        def moments(weights):  # a00, a01, a02, a11, a12, a22 of Σ weights p̂ p̂ᵀ
            wx, wy = weights * xi, weights * eta
            return [weights.sum(axis=0), wx.sum(axis=0), wy.sum(axis=0), (wx * xi).sum(axis=0),
                    (wx * eta).sum(axis=0), (wy * eta).sum(axis=0)]

        a00, a01, a02, a11, a12, a22 = moments(w)
        c00, c01, c02 = a11 * a22 - a12 * a12, a02 * a12 - a01 * a22, a01 * a12 - a02 * a11
        c11, c12, c22 = a00 * a22 - a02 * a02, a01 * a02 - a00 * a12, a00 * a11 - a01 * a01
        det = a00 * c00 + a01 * c01 + a02 * c02
        self._check_regular(points, _scaled_determinant(det, a00, a11, a22), w.T, idx.T)
        inv = np.array([[c00, c01, c02], [c01, c11, c12], [c02, c12, c22]]) / det  # A⁻¹, (3, 3, P)
        gamma = inv[:, 0]  # A⁻¹ p̃(x), p̃(x) = e₁
        gp = gamma[0] + gamma[1] * xi + gamma[2] * eta
        for d, dw in enumerate((wdx, wdy)):
            b00, b01, b02, b11, b12, b22 = moments(dw)  # ∂A
            rhs = -np.array([b00 * gamma[0] + b01 * gamma[1] + b02 * gamma[2],
                             b01 * gamma[0] + b11 * gamma[1] + b12 * gamma[2],
                             b02 * gamma[0] + b12 * gamma[1] + b22 * gamma[2]])
            rhs[d + 1] += 1.0 / s  # ∂p̃(x)/∂x_d = e_{d+1}/s
            dgamma = np.einsum("ijp,jp->ip", inv, rhs)
            np.add((dgamma[0] + dgamma[1] * xi + dgamma[2] * eta) * w, gp * dw, out=grad[d])
        np.multiply(gp, w, out=phi)
