"""XFEM's cell kernels on the band: the enriched basis, its strains and
stresses, element matrices and load vectors, and the interface operator.

The displacement on ``side`` (±1) of Γ in a cell is (the paper's Eq. 8)

    u(x) = Σ_J N_J(x) (u_J + (H − H_J) a_J),   H = side,

with ``H_J`` the node's own side and ``a_J = 0`` where the node is not
enriched: :func:`heaviside_shift` gives the factors ``H − H_J``.  The block
layout of a cell's unknowns is, per node, ``u_x, u_y, a_x, a_y``
(:meth:`~xdolfinx.xfem.space.EnrichedFunctionSpace.cell_blocks`).
"""
from __future__ import annotations

import numpy as np

from contactcore import BODIES
from contactcore import tolerances as tol
from contactcore.assembly import Triplets
from contactcore.bodies import index_of_sign, sign_of_index
from contactcore.cutcell import edge_crossings, gauss01
from contactcore.geometry import tangent_of
from contactcore.interface_path import piece_centres
from contactcore.system import InterfaceOperator
from contactcore.scene import BODY, EDGE, body_force, edge_traction, place_of

from .space import EnrichedFunctionSpace


def heaviside_shift(space: EnrichedFunctionSpace, dofs: np.ndarray, side) -> np.ndarray:
    """The shifted Heaviside ``H − H_J`` of nodes ``dofs`` (..., n) on
    ``side`` (a sign, or one per row of ``dofs``): 0 where not enriched."""
    return np.where(space.enriched[dofs], np.expand_dims(side, -1) - space.cells.node_side[dofs], 0)


def enriched_basis(space: EnrichedFunctionSpace, cell: int, points: np.ndarray, side: int):
    """Values (P, n), gradients (P, n, 2) and enrichment factors ``H − H_J``
    (n,) of ``cell``'s basis at physical ``points`` on ``side``."""
    return (*space.cells.tabulate(cell, points), heaviside_shift(space, space.cells.cell_dofs[cell], side))


def strain_matrix(dN: np.ndarray, shift: np.ndarray) -> np.ndarray:
    """(..., P, 3, 4n): ε_xx, ε_yy, γ_xy of the block layout, from gradients
    (..., P, n, 2) and enrichment factors broadcast to (..., P, n)."""
    n = dN.shape[-2]
    B = np.zeros(dN.shape[:-2] + (3, 4 * n))
    for comp, c in ((0, 1.0), (2, shift)):
        gx, gy = dN[..., 0] * c, dN[..., 1] * c
        B[..., 0, comp::4] = gx
        B[..., 1, comp + 1::4] = gy
        B[..., 2, comp::4] = gy
        B[..., 2, comp + 1::4] = gx
    return B


def side_strains(space: EnrichedFunctionSpace, cell: int, points: np.ndarray):
    """The cell's blocks (2n, :meth:`EnrichedFunctionSpace.cell_blocks`)
    and the strain–displacement matrices ``(B₋, B₊)``, each (P, 3, 4n), of
    either side's field at physical ``points`` of ``cell`` (Γ's points of a
    cut cell: the one-sided strains there)."""
    _, dN = space.cells.tabulate(cell, points)
    dofs = space.cells.cell_dofs[cell]
    return space.cell_blocks(cell), tuple(strain_matrix(dN, heaviside_shift(space, dofs, s)) for s in (-1, 1))


def voigt_stress(du: np.ndarray, D: np.ndarray) -> np.ndarray:
    """(P, 3): ``D ε`` in Voigt form from displacement gradients du (P, 2, 2),
    ``du[p, k, d] = ∂u_k/∂x_d``."""
    return np.column_stack([du[:, 0, 0], du[:, 1, 1], du[:, 0, 1] + du[:, 1, 0]]) @ D.T


def _stiffness(B: np.ndarray, w: np.ndarray, D: np.ndarray) -> np.ndarray:
    """Σ_p w_p B_pᵀ D B_p over the points (axis −3) of B (..., P, 3, m)."""
    m = B.shape[-1]
    lead = B.shape[:-3]
    Bw = (B * w[..., None, None]).reshape(lead + (-1, m))
    return np.swapaxes(Bw, -1, -2) @ (D[..., None, :, :] @ B).reshape(lead + (-1, m))


def band_kernels(space: EnrichedFunctionSpace, D: np.ndarray):
    """Blocks (2n, :meth:`EnrichedFunctionSpace.cell_blocks`) and element
    matrices (4n × 4n) of the band cells this rank owns: the bulk of each
    region with its body's D (the interface is :func:`interface_operator`'s).
    Cells that Γ does not cut share the reference cell's rule (mapped
    affinely) and are computed together."""
    cells, cut = space.cells, space.cut
    band = space.owned_band
    whole = np.array([c for c in band if c not in cut.regions], dtype=np.int64)
    for c in (c for c in band if c in cut.regions):
        K = np.zeros((4 * cells.cell_dofs.shape[1],) * 2)
        for side, _, w, _, dN in cut.regions[c]:
            K += _stiffness(strain_matrix(dN, heaviside_shift(space, cells.cell_dofs[c], side)), w,
                            D[index_of_sign(side)])
        yield space.cell_blocks(c), K
    if len(whole):
        X, w = cut.reference_rule
        dN = cells.affine_gradients(whole, X)
        side = cut.cell_side[whole]
        shift = heaviside_shift(space, cells.cell_dofs[whole], side)[:, None, :]
        weights = w[None, :] * np.abs(np.linalg.det(cells.jacobian[whole]))[:, None]
        yield from zip(space.cell_blocks(whole), _stiffness(strain_matrix(dN, shift), weights, D[index_of_sign(side)]))


def interface_operator(space: EnrichedFunctionSpace) -> InterfaceOperator:
    """Γ's quadrature points in the band cells, on the exact Γ with the level
    set's normal, and ``G``: ``[[u]] = 2 Σ_J N_J a_J`` in the frame (n, t),
    rows ``g_N, g_T`` of each point, columns the unrolled unknowns
    ``2·block + j`` of a_j of the cell's enriched nodes."""
    trip = Triplets((0, 2 * space.num_blocks))
    points, weights = [], []
    m = 0
    for c in (c for c in space.owned_band if c in space.cut.gamma_rules):
        pts, w, normals = space.cut.gamma_rules[c]
        dofs = space.cells.cell_dofs[c]
        keep = space.enriched[dofs]
        N = space.cells.tabulate(c, pts)[0][:, keep]
        blocks = space.enriched_blocks[dofs[keep]]
        frame = np.stack([normals, tangent_of(normals)], axis=1)  # (P, 2, 2): rows n, t
        rows = 2 * (m + np.arange(len(w)))[:, None, None] + np.arange(2)[None, :, None]
        for j in range(2):
            trip.add(rows, 2 * blocks[None, None, :] + j, 2 * N[:, None, :] * frame[:, :, j:j + 1])
        points.append(pts)
        weights.append(w)
        m += len(w)
    trip.shape = (2 * m, trip.shape[1])
    sizes = [len(w) for w in weights]  # each cut cell's points: one piece of Γ
    points = np.concatenate(points) if points else np.zeros((0, 2))
    weights = np.concatenate(weights) if weights else np.zeros(0)
    return InterfaceOperator(trip.to_csr(), weights, points, space.exchange if space.cells.ranks.parallel else None,
                             pieces=piece_centres(points, weights, sizes))


def band_loads(space: EnrichedFunctionSpace, load):
    """Blocks (2n) and load vectors (4n) of one load on the band cells this
    rank owns: a body force on each region of its body, a traction or
    pressure on the cell's edges along its boundary, split where Γ crosses
    them in a cut cell (the enriched functions jump there), on its one
    side in a whole cell: as the cell's stiffness, Γ snapped to the nodes
    near it.  Split at the exact Γ instead, the piece between Γ and a
    snapped node (≤ XFEM_SNAP of a cell) loaded the other side's
    enrichment, a function that is zero in the cell: a bonded layered bar
    pulled along Γ had σ off by 0.8 and Γ's traction by 4.8 times Γ's
    distance from the node line over h.  Dispatched on where the load
    acts (:func:`contactcore.scene.place_of`, which refuses an unknown one
    by name)."""
    kind = place_of(load)
    if kind == BODY:
        yield from _band_body_loads(space, load)
    elif kind == EDGE:
        yield from _band_edge_loads(space, load)


def _band_body_loads(space: EnrichedFunctionSpace, load):
    side = sign_of_index(BODIES.index(load.body))
    for c in space.owned_band:
        f = np.zeros(4 * len(space.cells.cell_dofs[c]))
        for _, pts, w, N in (part for part in space.cut.cell_values(c) if part[0] == side):
            force = np.column_stack(body_force(space.scene, load, pts[:, 0], pts[:, 1]))
            f += _vector_load(N, heaviside_shift(space, space.cells.cell_dofs[c], side), w[:, None] * force)
        yield space.cell_blocks(c), f


def _band_edge_loads(space: EnrichedFunctionSpace, load):
    scene = space.scene
    g, gw = gauss01(space.cut.gauss)
    band = space.owned_band
    corners = space.cells.corners[band]
    count = corners.shape[1]
    on = scene.domain.on_boundary(load.boundary, corners.reshape(-1, 2), tol.NODE_MATCH * scene.length_scale)
    on = on.reshape(-1, count)
    along = on & np.roll(on, -1, axis=1)  # edge i: corner i to corner i + 1
    for k in np.flatnonzero(along.any(axis=1)):
        c = band[k]
        f = np.zeros(4 * len(space.cells.cell_dofs[c]))
        for i in np.flatnonzero(along[k]):
            a, b = corners[k, i], corners[k, (i + 1) % count]
            cut = c in space.cut.regions  # else whole on its side: Γ snapped off the edge
            knots = [0.0] + (edge_crossings(scene.interface, a, b) if cut else []) + [1.0]
            for t0, t1 in zip(knots[:-1], knots[1:]):
                pts = a + (t0 + g[:, None] * (t1 - t0)) * (b - a)
                w = gw * (t1 - t0) * np.linalg.norm(b - a)
                side = ((1 if scene.interface.phi([(pts[0] + pts[-1]) / 2])[0] >= 0 else -1) if cut
                        else int(space.cut.cell_side[c]))
                N, _, shift = enriched_basis(space, c, pts, side)
                t = _edge_traction(scene, load, a, b, corners[k].mean(axis=0), pts)
                f += _vector_load(N, shift, w[:, None] * t)
        yield space.cell_blocks(c), f


def _edge_traction(scene, load, a: np.ndarray, b: np.ndarray, inside: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """The traction (P, 2) of a boundary ``load`` at the points ``pts`` of
    the cell edge ``a``–``b`` (``inside`` a point of the cell), by the
    load's formula (:func:`contactcore.scene.edge_traction`) with ``n`` the
    edge's own outward normal (a disc's rim is the mesh's chords: uniform
    pressure then gives σ = −p I to round-off)."""
    n = np.array([b[1] - a[1], a[0] - b[0]]) / np.linalg.norm(b - a)
    n = n if n @ (a - inside) > 0 else -n
    return edge_traction(scene, load, pts[:, 0], pts[:, 1], np.tile(n, (len(pts), 1)))


def _vector_load(N: np.ndarray, shift: np.ndarray, wt: np.ndarray) -> np.ndarray:
    """Σ_p [N_j t, (shift_j N_j) t] in the block layout, for weighted loads wt (P, 2)."""
    n = N.shape[1]
    f = np.zeros(4 * n)
    f[0::4], f[1::4] = N.T @ wt[:, 0], N.T @ wt[:, 1]
    f[2::4], f[3::4] = (N * shift).T @ wt[:, 0], (N * shift).T @ wt[:, 1]
    return f
