"""The enriched approximation and the sparse operators built from it.

The paper's Eq. (19): ``u(x) = Σ_I Φ_I(x) u_I + Σ_J Φ_J(x) (H(x) − H(x_J)) a_J``,
``H = +1`` on the + side (φ ≥ 0), −1 on the − side, on the nodes J whose
support Γ cuts.  Within body b, ``H(x) = H_b`` is constant, so an enriched
function is ``(H_b − H(x_J)) Φ_J``: zero in J's own body, ``±2 Φ_J`` in the
other.  Unknowns: ``(u_x, u_y)`` of node I at ``2I, 2I+1``, then ``a_J`` at
``2N + 2e(J) + {0, 1}``.

Every integral and every output is a product of two operators built here:
``N`` (2 rows per point: ``u_x, u_y``) and ``B`` (3 rows per point:
``ε_xx, ε_yy, γ_xy``), assembled from COO triplets.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from contactcore.assembly import Triplets, point_rows_to_csr

from .shape import MLS, ShapeValues

#: A node is enriched when the part of its shape function's integral lying
#: on the other side of Γ exceeds this fraction of the whole.  A sliver of
#: relative depth δ holds ~δ⁴ of the integral but gradients ~δ², so leaving
#: the node out costs ~fraction^(1/2) in stress: 1e-6 showed as a 1e-3 stress
#: floor in the patch test (measured), 1e-9 (δ ~ 5e-3, ~3e-5) gives the same
#: answers as enriching every node that Γ reaches; the equilibrated solver
#: keeps such small functions well scaled.
ENRICH_MIN_FRACTION = 1e-9


def heaviside(bodies: np.ndarray) -> np.ndarray:
    """H = +1 in the + body (1), −1 in the − body (0)."""
    return 2 * np.asarray(bodies) - 1


@dataclass
class Enrichment:
    """Which nodes carry Heaviside dofs, their numbering and their side."""

    index: np.ndarray  # (N,) enriched number of each node, −1 if none
    node_side: np.ndarray  # (N,) H(x_J)

    @property
    def count(self) -> int:
        return int(np.sum(self.index >= 0))


def find_enrichment(scene, mls: MLS, sv: ShapeValues, weights: np.ndarray, bodies: np.ndarray) -> Enrichment:
    """Enrich the nodes whose support reaches across Γ (see ENRICH_MIN_FRACTION)."""
    N = len(mls.nodes)
    node_side = np.where(scene.interface.phi(mls.nodes) >= 0, 1, -1)
    idx = np.maximum(sv.index, 0)
    mass = weights[:, None] * np.abs(sv.phi)
    other = heaviside(bodies)[:, None] != node_side[idx]
    total = np.bincount(idx.ravel(), mass.ravel(), minlength=N)
    across = np.bincount(idx.ravel(), (mass * other).ravel(), minlength=N)
    enriched = across > ENRICH_MIN_FRACTION * np.where(total > 0, total, 1.0)
    index = np.full(N, -1)
    index[enriched] = np.arange(int(enriched.sum()))
    return Enrichment(index, node_side)


class Approximation:
    """Shape functions plus enrichment: the unknowns and their operators."""

    def __init__(self, mls: MLS, enrichment: Enrichment):
        self.mls, self.enr = mls, enrichment
        self.n_nodes = len(mls.nodes)
        self.ndofs = 2 * (self.n_nodes + enrichment.count)

    def dof_points(self) -> np.ndarray:
        """The node of each unknown (ndofs, 2): where it couples."""
        nodes = self.mls.nodes
        enriched = np.flatnonzero(self.enr.index >= 0)[np.argsort(self.enr.index[self.enr.index >= 0])]
        return np.repeat(np.vstack([nodes, nodes[enriched]]), 2, axis=0)

    def _enriched(self, sv: ShapeValues, bodies: np.ndarray):
        """The enriched functions that are non-zero, at the points that have
        any: (points (Q,), first dof (Q, K) or −1, coefficient ±2 (Q, K))."""
        safe = np.maximum(sv.index, 0)
        e = self.enr.index[safe]
        coeff = np.where((sv.index >= 0) & (e >= 0), heaviside(bodies)[:, None] - self.enr.node_side[safe], 0)
        rows = np.flatnonzero(np.any(coeff != 0, axis=1))
        coeff = coeff[rows]
        return rows, np.where(coeff != 0, 2 * (self.n_nodes + e[rows]), -1), coeff

    def displacement_operator(self, sv: ShapeValues, bodies) -> sp.csr_matrix:
        """``N`` with rows ``2p, 2p+1`` = ``u_x, u_y`` at point p."""
        bodies = np.asarray(bodies)
        node = 2 * np.maximum(sv.index, 0)  # padding: column 0 with a zero value
        K = node.shape[1]
        N = point_rows_to_csr(self.ndofs, (K, K), np.concatenate([node, node + 1], axis=1),
                              np.concatenate([sv.phi, sv.phi], axis=1))
        rows, base, coeff = self._enriched(sv, bodies)
        trip = Triplets(N.shape)
        for c in range(2):
            trip.add((2 * rows + c)[:, None], np.where(base >= 0, base + c, -1), coeff * sv.phi[rows])
        return N + trip.to_csr()

    def strain_operator(self, sv: ShapeValues, bodies) -> sp.csr_matrix:
        """``B`` with rows ``3p, 3p+1, 3p+2`` = ``ε_xx, ε_yy, γ_xy`` at point p."""
        bodies = np.asarray(bodies)
        node = 2 * np.maximum(sv.index, 0)
        K = node.shape[1]
        gx, gy = sv.grad[..., 0], sv.grad[..., 1]
        B = point_rows_to_csr(self.ndofs, (K, K, 2 * K), np.concatenate([node, node + 1, node, node + 1], axis=1),
                              np.concatenate([gx, gy, gy, gx], axis=1))
        rows, base, coeff = self._enriched(sv, bodies)
        trip = Triplets(B.shape)
        ex, ey = np.where(base >= 0, base, -1), np.where(base >= 0, base + 1, -1)
        egx, egy = coeff * gx[rows], coeff * gy[rows]
        r3 = 3 * rows[:, None]
        trip.add(r3, ex, egx)
        trip.add(r3 + 1, ey, egy)
        trip.add(r3 + 2, ex, egy)
        trip.add(r3 + 2, ey, egx)
        return B + trip.to_csr()


def block_diagonal(blocks: np.ndarray) -> sp.csr_matrix:
    """A sparse block-diagonal matrix from (P, b, b) dense blocks."""
    P, b, _ = blocks.shape
    trip = Triplets((P * b, P * b))
    base = b * np.arange(P)[:, None, None]
    trip.add(base + np.arange(b)[None, :, None], base + np.arange(b)[None, None, :], blocks)
    return trip.to_csr()
