"""Where xfem P1 reads each body's stress for Nitsche's traction between
equal moduli, and the weights that interpolate it to Γ's point.

At degree 1 a body's stress in a cut cell is constant (triangles) or
constant across Γ's direction (quadrilaterals), close to the exact one
near its part's centroid ``x_k``.  Annavarapu's average with weights
``w_k ∝ |Ω_kᵉ|`` (equal moduli, :mod:`contactcore.traction`) reads the
stress at the cell's centroid ``Σ_k w_k x_k``, an O(h) distance from Γ's
point that jumps by a cell where Γ crosses a grid line: the read jumps by
``h ∂σ/∂n`` there, and Nitsche's traction ``t = τ + γ g``, whose jump
``g`` is continuous along Γ, spikes on either side (a block under its
weight, Γ at 10°, h = 0.05: ±1.9 % of |t_N| at Γ's points; 0.2 % elsewhere).

Here each body k's stress is read from a cell it fills at least
:data:`~contactcore.tolerances.XFEM_READ_FILL_SHARE` of: the point's cell
``e`` itself, or where its part of ``e`` is smaller, the neighbour across
an edge of ``e`` that it fills most, if it fills at least
:data:`~contactcore.tolerances.XFEM_READ_LEAST_SHARE` of it (else ``e``
keeps Annavarapu's read): a sliver's barely determined field never
reaches the traction.  With ``d_k = |(x_p − x_k)·n|`` the distance
along the normal from the point ``x_p`` to the centroid ``x_k`` of body
k's part of its reading cell, the weights

    w₋ = d₊ / (d₋ + d₊),   w₊ = d₋ / (d₋ + d₊)

interpolate the two reads linearly along ``n`` to Γ, so a stress linear
across Γ (with a continuous normal derivative of ``n·σn``, as equilibrium
gives under one body force) is read at Γ's point, whatever the cut.  Any
convex weights keep the method consistent, and skew-symmetric Nitsche
(θ = −1) is stable for every one; ``γ₀`` stays Annavarapu's.  Between
different moduli the traction keeps Annavarapu's weights (their
robustness under contrast, Annavarapu et al. 2012), and at degree 2 each
body's linear stress is read at the point already.

Only on a straight Γ (``scene.interface.straight_in``).  On a curved Γ
(C-coulomb made exact, xfem P1 against fe P2 at h = 0.0125) the read
moved C4's t_N by no more than the curved Γ's own point-to-point scatter,
with either sign, and lost on balance (RMS 1.95 → 2.29 % of max|t_N| on
triangles at h = 0.05, worst sample 8.6 → 11.4 %): a neighbour's part
centroid lies up to 0.76 of a cell's diameter along Γ from the cell's
points there (at most 0.48 on the straight block), which reads
``∂σ/∂s`` times that offset where t_N falls steeply towards the opening,
and even the point's own cell, interpolated along n, lost on triangles
(a stress not linear across Γ within a cell).  A curved Γ keeps
Annavarapu's read (docs/contact-enforcement.md, "A curved Γ keeps
Annavarapu's read").
"""
from __future__ import annotations

import numpy as np

from contactcore import BODIES
from contactcore import tolerances as tol


def part_centroid(space, cell: int, body: int) -> tuple[float, np.ndarray]:
    """The area and the centroid (2,) of body ``body``'s (0 = −, 1 = +) part
    of ``cell`` (a cut cell's rule, or the whole cell on its side); area 0
    and the origin where the body has none."""
    area, moment = 0.0, np.zeros(2)
    for side, points, weights, *_ in space.cut.cell_values(cell):
        if (side + 1) // 2 == body:
            area += float(np.sum(weights))
            moment += weights @ points
    return area, (moment / area if area > 0 else moment)


def _share(space, cell: int, body: int) -> float:
    """The share of ``cell``'s area that body ``body`` fills."""
    parts = [part_centroid(space, cell, b)[0] for b in (0, 1)]
    return parts[body] / sum(parts)


def _node_cells(space) -> tuple[np.ndarray, np.ndarray]:
    """``(start, cells)``: the local cells holding local corner node ``n``
    are ``cells[start[n]:start[n + 1]]``, in cell order; made once per
    space (each cut cell asks for its neighbours)."""
    kept = getattr(space, "_node_cells", None)
    if kept is None:
        nodes = np.asarray(space.cells.corner_nodes)
        order = np.argsort(nodes.ravel(), kind="stable")
        start = np.concatenate([[0], np.cumsum(np.bincount(nodes.ravel()))])
        kept = space._node_cells = (start, order // nodes.shape[1])
    return kept


def _edge_neighbours(space, cell: int) -> list[int]:
    """The local cells sharing an edge (two corner nodes) with ``cell``,
    in cell order."""
    start, cells = _node_cells(space)
    near = np.concatenate([cells[start[n]:start[n + 1]] for n in np.asarray(space.cells.corner_nodes[cell])])
    found, counts = np.unique(near, return_counts=True)
    return [int(d) for d in found[counts >= 2] if d != cell]


def applies(space) -> bool:
    """Whether the space's traction is read here: degree 1, equal moduli,
    a straight Γ (module doc: on a curved one the read lost to
    Annavarapu's)."""
    scene = space.scene
    moduli = [scene.materials[b].E for b in BODIES]
    return space.degree == 1 and max(moduli) == min(moduli) and scene.interface.straight_in(scene.domain)


def readers(space, cell: int) -> tuple[int, int] | None:
    """The cells (−, +) whose fields give each body's stress at cell
    ``cell``'s Γ points (module doc), or None where the cell is not cut
    into two parts or a body fills no edge neighbour by
    :data:`~contactcore.tolerances.XFEM_READ_LEAST_SHARE` (the cell then
    keeps Annavarapu's read)."""
    if _share(space, cell, 0) in (0.0, 1.0):
        return None
    out = []
    for body in (0, 1):
        if _share(space, cell, body) >= tol.XFEM_READ_FILL_SHARE:
            out.append(cell)
            continue
        shares = {d: _share(space, d, body) for d in _edge_neighbours(space, cell)}
        best = max(shares, key=shares.get, default=None)
        if best is None or shares[best] < tol.XFEM_READ_LEAST_SHARE:
            return None
        out.append(best)
    return out[0], out[1]


def all_readers(space) -> dict:
    """``{cell: (−, +)}`` of :func:`readers` over the owned cells holding
    Γ's rule, empty where the read does not apply; made once per space
    (its traction operator and its matrix's couplings both ask)."""
    kept = getattr(space, "_readers", None)
    if kept is not None:
        return kept
    out = {}
    if applies(space):
        for c in space.owned_band:
            found = readers(space, c) if c in space.cut.gamma_rules else None
            if found is not None:
                out[c] = found
    space._readers = out
    return out


def interpolation_weights(space, points: np.ndarray, normals: np.ndarray, pair: tuple[int, int]) -> np.ndarray:
    """(P, 2): ``w₋ = d₊/(d₋ + d₊)``, ``w₊ = d₋/(d₋ + d₊)`` at ``points``
    with unit ``normals`` (module doc), ``pair`` the reading cells; 1/2
    each where both centroids lie on Γ's point's line along Γ."""
    dist = np.stack([np.abs(np.sum((points - part_centroid(space, pair[b], b)[1]) * normals, axis=1))
                     for b in (0, 1)], axis=1)
    total = dist.sum(axis=1)
    safe = np.where(total > 0, total, 1.0)
    return np.where(total[:, None] > 0, dist[:, ::-1] / safe[:, None], 0.5)
