"""The enriched approximation and the sparse operators built from it.

The paper's Eq. (19): ``u(x) = Σ_I Φ_I(x) u_I + Σ_J Φ_J(x) (H(x) − H(x_J)) a_J``,
``H = +1`` on the + side (φ ≥ 0), −1 on the − side, on the nodes J whose
support reaches across Γ by more than ENRICH_MIN_DEPTH of its reach; the
shape functions of body b are fitted on the nodes b sees (its own and the
enriched ones, :attr:`Enrichment.seen_from`), so a node left out gives the
other body nothing.  Within body b, ``H(x) = H_b`` is constant, so an enriched
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
from scipy.spatial import cKDTree

from contactcore.assembly import Triplets, blocks_to_csr, point_rows_to_csr, sum_csr
from contactcore.bodies import index_of_sign, sign_of_index, side

from .shape import CHUNK, MLS, ShapeValues, matmul, parallel_map

#: A node is enriched (it carries Heaviside unknowns and takes part in the
#: other body's fit) when its support reaches across Γ deeper than this
#: fraction of the support's reach along Γ's normal; a node that reaches
#: less far is not seen from across Γ at all (visibility, efgm.shape), so
#: each body keeps its own field.  An enriched function lives only in the
#: lens between Γ and the edge of the support, where the weight is at most
#: w(1 − δ) ≈ 2δ³ of its peak: its unknown is set by that lens alone, and
#: the thinner the lens the worse (a lens h/32 deep, δ = 0.015, puts σxy
#: on Γ 35 % off).  Measured over 24 seeded inclined placements of
#: scene A (tests/inclined_efgm.py), worst sample of any profile against
#: fe P2 at h/2, linear / quadratic basis at h = 0.05: enriching every node
#: whose support holds a point across Γ (δ = 1e-9) 4.0 / 2.8;
#: with visibility, δ = 0.1: 0.16 / 0.12, 0.2: 0.12 / 0.13, 0.25: 0.11 /
#: 0.091, 0.4: 0.12 / 0.11 (the rest is resolution near Γ's ends: the
#: same placement at h = 0.025 is 0.019).  δ = 0 leaves free unknowns.
ENRICH_MIN_DEPTH = 0.25

#: The systems built here are symmetric by construction, as fe's and
#: xfem's are by their weak form: ``K = Bᵀ W D B`` (Bubnov–Galerkin: the
#: same functions on both sides), bordered by the multipliers' ``s Cᵀ``
#: and ``s C`` (:mod:`efgm.method`).  Known, not tested: the test cost 0.2 s
#: of a 2.5 s solve on scene C at h = 0.0125; the solve's residual, taken
#: with the whole matrix, would catch a system that is not.
SYMMETRIC = True


def heaviside(bodies: np.ndarray) -> np.ndarray:
    """H = +1 in the + body (1), −1 in the − body (0)."""
    return sign_of_index(np.asarray(bodies))


@dataclass
class Enrichment:
    """Which nodes carry Heaviside dofs, their numbering and their side."""

    index: np.ndarray  # (N,) enriched number of each node, −1 if none
    node_side: np.ndarray  # (N,) H(x_J)

    @property
    def count(self) -> int:
        return int(np.sum(self.index >= 0))

    @property
    def seen_from(self) -> np.ndarray:
        """(N, 2): node I takes part in body b's fit if it lies in b or is enriched."""
        own = index_of_sign(self.node_side)
        return (own[:, None] == np.arange(2)[None, :]) | (self.index >= 0)[:, None]


def crossing_depth(scene, nodes: np.ndarray, radii: np.ndarray, points: np.ndarray, bodies: np.ndarray) -> np.ndarray:
    """How far each node's support reaches across Γ inside the domain,
    relative to its reach along Γ's normal ``n`` at the node:
    ``max |φ(q)| / ρ_I`` over the quadrature points q of the other body in
    the support (0 if none), φ the signed distance to Γ, ``ρ_I = r_I``
    (circular) or ``r_x|n_x| + r_y|n_y|`` (rectangular).  Taken over the
    points that are integrated, it is 0 for a support whose crossing lies
    outside the domain or holds no point, whose unknowns would be free."""
    node_body = (scene.interface.phi(nodes) >= 0).astype(int)
    rect = radii.ndim == 2
    if rect:
        with np.errstate(invalid="ignore", divide="ignore"):
            n = np.nan_to_num(scene.interface.normals(nodes), nan=1.0)  # a node at a circle's centre
        reach = np.sum(radii * np.abs(n), axis=1)
    else:
        reach = radii
    depth = np.zeros(len(nodes))
    near = np.abs(scene.interface.phi(nodes)) < reach  # the others cannot reach across
    for body in (0, 1):
        mine = np.flatnonzero(near & (node_body != body))
        pts = points[bodies == body]
        if len(mine) == 0 or len(pts) == 0:
            continue
        dist = np.abs(scene.interface.phi(pts))
        size = radii[mine].max(axis=1) if rect else radii[mine]
        hits = cKDTree(pts).query_ball_point(nodes[mine], size, p=np.inf if rect else 2)
        for k, (i, q) in enumerate(zip(mine, hits)):
            q = np.asarray(q, int)
            if rect:
                q = q[np.all(np.abs(pts[q] - nodes[i]) < radii[i], axis=1)]
            depth[i] = dist[q].max(initial=0.0) / reach[i]
    return depth


def find_enrichment(scene, nodes: np.ndarray, radii: np.ndarray, points: np.ndarray, bodies: np.ndarray
                    ) -> Enrichment:
    """Enrich the nodes whose support reaches across Γ by more than
    ENRICH_MIN_DEPTH of its reach (:func:`crossing_depth` over the
    quadrature ``points`` of ``bodies``)."""
    node_side = side(scene.interface, nodes)
    enriched = crossing_depth(scene, nodes, np.asarray(radii, float), points, bodies) > ENRICH_MIN_DEPTH
    index = np.full(len(nodes), -1)
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

    def _enriched(self, index: np.ndarray, bodies: np.ndarray):
        """The enriched functions of the nodes ``index`` (P, K) that are
        non-zero, at the points (or groups) that have any: (points (Q,),
        first dof (Q, K) or −1, coefficient ±2 (Q, K))."""
        safe = np.maximum(index, 0)
        e = self.enr.index[safe]
        enriched = (index >= 0) & (e >= 0)
        rows = np.flatnonzero(np.any(enriched, axis=1))  # only these can have any (most points have none)
        coeff = np.where(enriched[rows], heaviside(bodies[rows])[:, None] - self.enr.node_side[safe[rows]], 0)
        keep = np.any(coeff != 0, axis=1)
        rows, coeff = rows[keep], coeff[keep]
        return rows, np.where(coeff != 0, 2 * (self.n_nodes + e[rows]), -1), coeff

    def displacement_operator(self, sv: ShapeValues, bodies) -> sp.csr_matrix:
        """``N`` with rows ``2p, 2p+1`` = ``u_x, u_y`` at point p."""
        bodies = np.asarray(bodies)
        node = 2 * np.maximum(sv.index, 0)  # padding: column 0 with a zero value
        K = node.shape[1]
        N = point_rows_to_csr(self.ndofs, (K, K), np.concatenate([node, node + 1], axis=1),
                              np.concatenate([sv.phi, sv.phi], axis=1))
        rows, base, coeff = self._enriched(sv.index, bodies)
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
        rows, base, coeff = self._enriched(sv.index, bodies)
        trip = Triplets(B.shape)
        ex, ey = np.where(base >= 0, base, -1), np.where(base >= 0, base + 1, -1)
        egx, egy = coeff * gx[rows], coeff * gy[rows]
        r3 = 3 * rows[:, None]
        trip.add(r3, ex, egx)
        trip.add(r3 + 1, ey, egy)
        trip.add(r3 + 2, ex, egy)
        trip.add(r3 + 2, ey, egx)
        return B + trip.to_csr()

    def stiffness(self, rule, origin: np.ndarray, step: np.ndarray, D: np.ndarray) -> sp.csr_matrix:
        """``K = Σ_q w_q B_qᵀ D_b(q) B_q`` over the quadrature ``rule``
        (points, weights, bodies), ``D`` (2, 3, 3) by body, accumulated per
        background cell (squares of side ``step`` from ``origin``) and body:
        shape functions on the union of the group's supports, one dense
        block per group to the sink (:func:`~contactcore.assembly.blocks_to_csr`).
        Equal to the per-point ``Bᵀ W D B`` of :meth:`strain_operator`."""
        return self.stiffness_and_forces(rule, origin, step, D, np.zeros((len(rule.weights), 0, 2)))[0]

    def stiffness_and_forces(self, rule, origin: np.ndarray, step: np.ndarray, D: np.ndarray, forces: np.ndarray
                             ) -> tuple[sp.csr_matrix, np.ndarray]:
        """:meth:`stiffness`, and in the same pass over the cells (the shape
        functions at the volume points made once) ``Nᵀ v`` for L values
        ``forces`` (P, L, 2) at the rule's points (body forces times the
        weights): ``K`` and the vectors (ndofs, L)."""
        chunks = []
        for members, body in cell_groups(rule.points, rule.bodies, origin, step):
            size = max(1, CHUNK // members.shape[1])
            chunks += [(members[i:i + size], body[i:i + size]) for i in range(0, len(members), size)]
        tensor = strain_energy_tensor(D)
        shape = (self.ndofs, self.ndofs)

        def chunk(c):
            dofs, blocks, vectors = self._cell_stiffness(rule.points[c[0]], rule.weights[c[0]], c[1], tensor,
                                                         forces[c[0]])
            return blocks_to_csr(shape, dofs, blocks), vectors

        parts, vectors = [], np.zeros((self.ndofs, forces.shape[1]))
        for part, f in parallel_map(chunk, chunks):
            parts.append(part)
            vectors += f
        return sum_csr(shape, parts), vectors

    def _cell_functions(self, idx: np.ndarray, body: np.ndarray, grad: np.ndarray):
        """The functions of groups of one body each whose candidate nodes are
        ``idx`` (G, U), with gradients ``grad`` (G, Q, U, c) at their points
        (c = 2, or 3 with the values Φ last): the first dof of each (G, F)
        (−1 = padding) and its gradients (G, Q, F, c): the U nodes, then the
        non-zero enriched functions ``(H_b − H(x_J)) Φ_J``."""
        dofs = np.where(idx >= 0, 2 * idx, -1)
        rows, base, c = self._enriched(idx, body)
        if len(rows) == 0:
            return dofs, grad
        width = int(np.max(np.sum(c != 0, axis=1)))
        order = np.argsort(c == 0, axis=1, kind="stable")[:, :width]  # the non-zero ones first
        e_dofs = np.full((len(idx), width), -1)
        e_dofs[rows] = np.take_along_axis(base, order, axis=1)
        e_grad = np.zeros(grad.shape[:2] + (width, grad.shape[3]))
        e_grad[rows] = (np.take_along_axis(grad[rows], order[:, None, :, None], axis=2)
                        * np.take_along_axis(c, order, axis=1)[:, None, :, None])
        return np.concatenate([dofs, e_dofs], axis=1), np.concatenate([grad, e_grad], axis=2)

    def _cell_stiffness(self, points: np.ndarray, weights: np.ndarray, body: np.ndarray, tensor: np.ndarray,
                        forces: np.ndarray):
        """Dofs (G, F, 2) and dense stiffness blocks (G, F, 2, F, 2) of G groups of
        points (G, Q, 2), weights (G, Q), one body each:
        ``K_ab[i, j] = Σ_de T_b[i, j, d, e] S_de[a, b]``,
        ``S_de = Σ_q w_q ∂_d Φ_a ∂_e Φ_b`` (:func:`strain_energy_tensor`);
        and ``Σ_q Φ_a v`` of the values ``forces`` (G, Q, L, 2) (:meth:`_cell_forces`)."""
        idx = self.mls.cell_candidates(points.min(axis=1), points.max(axis=1), body)
        phi, grad = self.mls.cell_shape(points, idx)
        L = forces.shape[2]
        dofs, f = self._cell_functions(idx, body, np.concatenate([grad, phi[..., None]], axis=-1) if L else grad)
        vectors = self._cell_forces(dofs, f[..., 2], forces) if L else np.zeros((self.ndofs, 0))
        # contiguous: numpy's matmul calls BLAS only on operands with a unit
        # stride, and on these strided views it was 16x slower (measured,
        # 168 groups of 108 points and 23 functions: 7.3 ms against 0.45 ms)
        gx, gy = np.ascontiguousarray(f[..., 0]), np.ascontiguousarray(f[..., 1])
        wgx, wgy = weights[..., None] * gx, weights[..., None] * gy
        wgx, wgy = wgx.transpose(0, 2, 1), wgy.transpose(0, 2, 1)
        G, F = dofs.shape
        S = np.empty((G, 2, 2, F, F))  # S[:, d, e] = Σ_q w_q ∂_d Φ_a ∂_e Φ_b
        S[:, 0, 0], S[:, 0, 1], S[:, 1, 1] = matmul(wgx, gx), matmul(wgx, gy), matmul(wgy, gy)
        S[:, 1, 0] = S[:, 0, 1].transpose(0, 2, 1)
        blocks = matmul(tensor[body].reshape(G, 4, 4), S.reshape(G, 4, F * F)).reshape(G, 2, 2, F, F)
        dofs = np.where(dofs[:, :, None] >= 0, dofs[:, :, None] + np.arange(2), -1)
        return dofs, blocks.transpose(0, 3, 1, 4, 2), vectors  # (G, F, 2) and (G, F, 2, F, 2): [a, i, b, j]

    def _cell_forces(self, dofs: np.ndarray, phi: np.ndarray, forces: np.ndarray) -> np.ndarray:
        """``Σ_q Φ_a(q) v(q)`` summed into the unknowns (ndofs, L), from the
        functions' first dofs (G, F) (−1 = padding), their values (G, Q, F)
        and the values ``forces`` (G, Q, L, 2) at the points."""
        G, Q, L, _ = forces.shape
        sums = matmul(np.ascontiguousarray(phi.transpose(0, 2, 1)), np.ascontiguousarray(forces.reshape(G, Q, 2 * L)))
        used = dofs >= 0
        out = np.zeros((self.ndofs, L))
        for k in range(2 * L):  # k = 2 l + i: load l, component i
            out[:, k // 2] += np.bincount((dofs + k % 2)[used], sums[..., k][used], self.ndofs)
        return out


#: ``E[k, i, d]``: the strain component k (ε_xx, ε_yy, γ_xy) of the
#: displacement component i per unit ``∂_d Φ``, ``B_a[k, i] = Σ_d E[k, i, d] ∂_d Φ_a``.
_STRAIN = np.zeros((3, 2, 2))
_STRAIN[0, 0, 0] = _STRAIN[1, 1, 1] = _STRAIN[2, 0, 1] = _STRAIN[2, 1, 0] = 1.0


def strain_energy_tensor(D: np.ndarray) -> np.ndarray:
    """``T[b, i, j, d, e] = Σ_kl E[k, i, d] D_b[k, l] E[l, j, e]`` for the
    Voigt matrices ``D`` (nb, 3, 3): ``B_aᵀ D_b B_c = Σ_de T[b, :, :, d, e] ∂_d Φ_a ∂_e Φ_c``."""
    return np.einsum("kid,bkl,lje->bijde", _STRAIN, D, _STRAIN)


def cell_groups(points: np.ndarray, bodies: np.ndarray, origin: np.ndarray, step: np.ndarray):
    """The points grouped by background cell (squares of side ``step`` from
    ``origin``) and body, in buckets of equal size: ``(members (G, Q), body
    (G,))`` per size Q.  Any grouping gives the same sums; the cells make
    the unions of supports small."""
    cell = np.maximum(np.floor((points - origin) / step), 0).astype(np.int64)
    key = (cell[:, 0] * (cell[:, 1].max(initial=0) + 1) + cell[:, 1]) * 2 + bodies
    order = np.argsort(key, kind="stable")
    _, starts, counts = np.unique(key[order], return_index=True, return_counts=True)
    buckets = []
    for Q in np.unique(counts):
        members = order[starts[counts == Q][:, None] + np.arange(Q)]
        buckets.append((members, bodies[members[:, 0]]))
    return buckets


def block_diagonal(blocks: np.ndarray) -> sp.csr_matrix:
    """A sparse block-diagonal matrix from (P, b, b) dense blocks."""
    P, b, _ = blocks.shape
    trip = Triplets((P * b, P * b))
    base = b * np.arange(P)[:, None, None]
    trip.add(base + np.arange(b)[None, :, None], base + np.arange(b)[None, None, :], blocks)
    return trip.to_csr()
