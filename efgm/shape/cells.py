"""Φ and ∇Φ of groups of points at once: the moments summed once per group.

The MLS fit (Belytschko, Lu & Gu, IJNME 37, 1994; formulas in
:mod:`efgm.shape.evaluation`) at the points of one background cell uses
the same candidate nodes at every point (:meth:`efgm.shape.MLS.cell_candidates`;
a node whose support misses a point has ``w = 0`` there, so ``Φ = 0``).
The moments are then summed in one basis common to the group,
``p̂_I = p((x_I − c)/s_g)`` (``c`` the group's mean point, ``s_g`` its
largest radius), as matrix products over the group's nodes, and moved to
each point's own basis by the change of basis of :func:`efgm.shape.basis._shift`:

    p̃ = M p̂,   M = Λ(s_g/s) T((x − c)/s_g),   A = M Â Mᵀ,   ∂A = M ∂Â Mᵀ,

with ``Â = Σ_I w_I p̂_I p̂_Iᵀ``.  For a group of one point (the quadratic
basis's :meth:`efgm.shape.MLS.evaluate`), ``c = x``, ``s_g = s`` and ``M = I``.

Contract of the mixin: points (G, Q, 2) and the nodes (G, U) of each
group (−1 = padding) give Φ (G, Q, U) and ∇Φ (G, Q, U, 2), zero in the
padding; every matrix product goes through :func:`efgm.shape.parallel.matmul`
(one BLAS call at a time), the inverses through
:func:`efgm.shape.moments._spd_inverse`.  It reads :class:`efgm.shape.MLS`'s
``nodes``, ``m`` and ``degree`` and calls its ``_weights``, ``_moments``,
``regularity`` and ``_check_regular``.
"""
from __future__ import annotations

import numpy as np

from .basis import _SYMMETRIC, _basis, _shift
from .moments import _spd_inverse
from .parallel import matmul


class _CellShapes:
    """Φ and ∇Φ of :class:`efgm.shape.MLS` at groups of points."""

    def cell_shape(self, points: np.ndarray, idx: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Φ (G, Q, U) and ∇Φ (G, Q, U, 2) at the points (G, Q, 2) of G
        groups, of the nodes ``idx`` (G, U) of each (−1 = padding): a group
        of one point and its neighbours (:meth:`evaluate`), or the points of
        a cell and its candidates (:meth:`cell_candidates`; a node whose
        support misses a point has w = 0 there, so Φ = 0).

        The moments are summed in a basis common to the group,
        ``p̂_I = p((x_I − c)/s_g)`` (c the group's mean point, s_g its
        largest radius), by matrix products, then moved to each point's own (module doc):
        ``p̃ = M p̂``, ``M = Λ(s_g/s) T((x − c)/s_g)`` (:func:`_shift`),
        ``A = M Â Mᵀ`` and ``∂A = M ∂Â Mᵀ`` with ``Â = Σ_I w_I p̂_I p̂_Iᵀ``.
        For a group of one point, c = x, s_g = s and M = I."""
        G, Q, _ = points.shape
        m = self.m
        safe = np.maximum(idx, 0)
        ox = points[..., :1] - self.nodes[safe, 0][:, None, :]  # (G, Q, U)
        oy = points[..., 1:] - self.nodes[safe, 1][:, None, :]
        w, wdx, wdy, r_node = self._weights(idx[:, None, :], ox, oy)
        s = np.max(np.where(w > 0, r_node, 0.0), axis=2, initial=0.0)
        s[s == 0] = 1.0
        s_g = np.max(np.where(idx >= 0, r_node[:, 0], 0.0), axis=1, initial=0.0)
        s_g[s_g == 0] = 1.0
        centre = points.mean(axis=1)
        pI_m = _basis(*((self.nodes[safe] - centre[:, None, :]) / s_g[:, None, None]).transpose(2, 0, 1),
                      self.degree)  # p̂_I, (m, G, U)
        pI, pIt = pI_m.transpose(1, 2, 0), pI_m.transpose(1, 0, 2)
        if Q == 1:  # M = I; one point per group: no products p̂_i p̂_j kept per node
            M = Mt = None

            def moved(weights):  # Σ_I w_I p̂_I p̂_Iᵀ, (G, m, m)
                return self._moments(weights[:, 0], pI_m)
        else:
            # every operand of matmul C-contiguous: numpy loops on strided views instead of
            # calling BLAS (32768 quadratic 6 × 6 products: 26 ms against 1.2 ms)
            upper = np.triu_indices(m)
            pp = np.ascontiguousarray(pI[..., upper[0]] * pI[..., upper[1]])  # the p̂_i p̂_j, (G, U, m(m+1)/2)
            M = _shift((points - centre[:, None, :]) / s_g[:, None, None], s_g[:, None] / s, self.degree)
            M = np.ascontiguousarray(M.reshape(-1, m, m))
            Mt = np.ascontiguousarray(M.transpose(0, 2, 1))

            def moved(weights):  # M (Σ_I w_I p̂_I p̂_Iᵀ) Mᵀ, (G·Q, m, m)
                sums = np.ascontiguousarray(matmul(weights, pp)[..., _SYMMETRIC[m]].reshape(-1, m, m))
                return matmul(matmul(M, sums), Mt)

        def back(v):  # Mᵀ v for v (G·Q, m, 1), as (G, Q, m)
            return (v if M is None else matmul(Mt, v)).reshape(G, Q, m)

        A = moved(w)
        Ainv, pivots = _spd_inverse(A)
        self._check_regular(points.reshape(-1, 2), self.regularity(A, pivots), w.reshape(G * Q, -1), idx, Q)
        gamma = Ainv[:, :, :1]  # A⁻¹ p̃(x), p̃(x) = e₁
        gp = matmul(back(gamma), pIt)  # γᵀ M p̂_I
        grad = np.empty(w.shape + (2,))
        for d, dw in enumerate((wdx, wdy)):
            rhs = -matmul(moved(dw), gamma)
            rhs[:, d + 1, 0] += 1.0 / s.ravel()  # ∂p̃(x)/∂x_d = e_{d+1}/s
            grad[..., d] = matmul(back(matmul(Ainv, rhs)), pIt) * w + gp * dw  # Mᵀ ∂γ, ∂γ = A⁻¹ rhs
        return gp * w, grad
