"""XFEM's consistent interface traction for Nitsche's method: ``S`` with
``τ = S u = [n·{σ}n, t·{σ}n]`` at Γ's points, and the stabilisation ``γ₀``
(:mod:`contactcore.traction` for the maths and its source: Annavarapu,
Hautefeuille and Dolbow, CMAME 2012).

The cell of a Γ point is the mesh cell whose Γ rule holds it, ``Ω_kᵉ``
the part of that cell on side k (the cut-cell rule's weights summed; a
cell that Γ only touches along an edge is wholly on one side, the other
part empty) and ``Γᵉ`` Γ's piece in it.  ``γ₀`` is at least
:func:`gamma_floor`: where Γ clips a corner of the cell (or only passes
through it) the piece's length goes to 0 while the cell's far part keeps
its area, and ``γ₀`` with it; the exact law divides by it, and the
point's status would follow its stress alone.  The floor is the least
``γ₀`` of a piece of :data:`~contactcore.tolerances.NITSCHE_PIECE_FLOOR`
of the cell's diameter (the softer body's scale), and where the far part
is the stiffer body, its ``γ₀`` at a piece of
:data:`~contactcore.tolerances.NITSCHE_DEGENERATE_PIECE` of it.  The
far part's ``γ₀`` at NITSCHE_PIECE_FLOOR itself, the floor before, is
its modulus over h, up to E₋/E₊ times the γ of the cuts beside it, and γ
times the jump's discretisation error (set by the softer body) then
outweighed the compressive traction: points opened on a uniformly
pressed circle, a stiff disc in a ring 100 times softer.  Body
k's stress at a point of cell ``c`` is the polynomial of its side there,
``σ_k = D_k B_k u_c`` with ``B_k`` the strain matrix of the cell's block
layout (u, then the shifted Heaviside ``(H_k − H_J)`` a, per node).  A
sliver side gets a weight → 0 as the cut fraction does, so its barely
determined enriched unknowns never reach the traction, and ``γ₀`` stays
bounded (:func:`contactcore.traction.nitsche_weights`).

The rows are in the order of :func:`xdolfinx.xfem.interface_operator`
(the owned band cells that hold Γ, in order) and the columns are the same
local unrolled unknowns ``2·block + j``, so ``S`` and ``G`` share the
ghost exchange under mpirun.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from contactcore import BODIES
from contactcore import tolerances as tol
from contactcore.assembly import Triplets
from contactcore.bodies import Body
from contactcore.system import InterfaceOperator
from contactcore.exact import is_exact
from contactcore.traction import nitsche_weights, traction_maps

from .kernels import heaviside_shift, side_strains, strain_matrix
from .reading import all_readers, interpolation_weights


def cell_parts(space, c: int) -> np.ndarray:
    """(2,): the areas of the − and + parts of cell ``c``."""
    areas = np.zeros(2)
    for side, _, w, *_ in space.cut.cell_values(c):
        areas[(side + 1) // 2] += np.sum(w)
    return areas


def gamma_floor(areas: np.ndarray, moduli: np.ndarray, size) -> np.ndarray:
    """The least ``γ₀`` (module doc) of a cell of parts ``areas`` (2,),
    moduli ``moduli`` (2,) and diameter ``size`` (or of cells: ``areas``
    (C, 2), ``size`` (C,)), ``F`` =
    :data:`~contactcore.tolerances.NITSCHE_PIECE_FLOOR` and ``f`` =
    :data:`~contactcore.tolerances.NITSCHE_DEGENERATE_PIECE`: the larger of

    * ``2 F size E_min / |cell|``, the least ``γ₀ = 2|Γᵉ| / Σ_k |Ω_kᵉ|/E_k``
      that a piece ``F size`` long could have in the cell (the whole cell
      of the softer body): a cut across the cell (``|Γᵉ| >= F size``) has a
      larger ``γ₀`` whatever its parts, so it only raises clipped corners,
      to the softer body's scale, which is the cuts' beside them; for equal
      moduli it is the ``γ₀`` of a piece ``F size`` long;
    * ``2 f size / Σ_k |Ω_kᵉ|/E_k``, the cell's own ``γ₀`` at a piece ``f
      size`` long: where the piece degenerates (1e-6 of the cell and less)
      and the far part is the stiffer body, whose stress the traction then
      reads, γ at the softer body's scale lets that stress's discretisation
      error decide the status against the gap."""
    areas, moduli = np.asarray(areas, float), np.asarray(moduli, float)
    compliance = areas[..., 0] / moduli[0] + areas[..., 1] / moduli[1]
    soft = 2.0 * tol.NITSCHE_PIECE_FLOOR * size * float(np.min(moduli)) / (areas[..., 0] + areas[..., 1])
    return np.maximum(soft, 2.0 * tol.NITSCHE_DEGENERATE_PIECE * size / compliance)


def cell_traction(space, c: int, D: np.ndarray, moduli: np.ndarray, edges: dict | None = None):
    """Cell ``c``'s blocks (2n) and its rows of ``S`` (P, 2, 4n) in its
    block layout, and ``γ₀`` (P,), at the points of its Γ rule.

    Γ along an edge (the rule of a whole − cell, :func:`xdolfinx.xfem.cut._edge_rules`)
    with a whole + cell across: the traction is both cells' weighted
    average, as fe's on a facet (``w_k = (|Ω_k|/E_k) / Σ_j |Ω_j|/E_j``
    over the two cells, ``γ₀ = 2|Γᵉ| / Σ_j |Ω_j|/E_j``); the blocks and
    columns are then the − cell's followed by the + cell's (2n + 2n').
    Read from the − cell alone, a partly open Γ under shear along a node
    row opened at a node whatever h (grader16 F2: s = 0.325 at h = 0.05,
    0.025, 0.0125, P1 and P2, against 0.3156)."""
    pts, w, normals = space.cut.gamma_rules[c]
    P = len(w)
    parts = cell_parts(space, c)
    pair = all_readers(space).get(c)
    if pair is not None:
        return _read_traction(space, c, D, moduli, pair)
    across = np.full(P, -1) if parts[1] > 0 or edges is None else space.across_edge(c, pts, edges)
    if np.any(across >= 0):
        return _edge_traction(space, c, D, moduli, pts, w, normals, across)
    areas = np.broadcast_to(parts, (P, 2))
    weights, gamma = nitsche_weights(areas, moduli, np.full(P, np.sum(w)))
    gamma = np.maximum(gamma, gamma_floor(areas[0], moduli, space.cut.cell_size[c]))  # a corner clip: γ₀ bounded
    maps = traction_maps(normals, D, weights)
    blocks, strains = side_strains(space, c, pts)  # (B₋, B₊), each (P, 3, 4n)
    rows = np.zeros((P, 2, strains[0].shape[-1]))
    for body in Body:
        if weights[0, body] > 0:
            rows += maps[body] @ strains[body]
    return blocks, rows, gamma


def _read_traction(space, c: int, D: np.ndarray, moduli: np.ndarray, pair: tuple[int, int]):
    """:func:`cell_traction` where each body's stress is read from the
    cell ``pair[k]`` it fills and interpolated along n to the point
    (:mod:`xdolfinx.xfem.reading`); ``γ₀`` is the cell's own, as in
    :func:`cell_traction`.  The blocks and columns are cell ``c``'s
    followed by each other reading cell's."""
    pts, w, normals = space.cut.gamma_rules[c]
    P = len(w)
    parts = cell_parts(space, c)
    _, gamma = nitsche_weights(np.broadcast_to(parts, (P, 2)), moduli, np.full(P, np.sum(w)))
    gamma = np.maximum(gamma, gamma_floor(parts, moduli, space.cut.cell_size[c]))
    maps = traction_maps(normals, D, interpolation_weights(space, pts, normals, pair))
    reading = [c] + sorted(set(d for d in pair if d != c))
    columns, rows = [], []
    for d in reading:
        blocks, strains = side_strains(space, d, pts)
        columns.append(blocks)
        rows.append(sum(maps[body] @ strains[body] for body in Body if pair[body] == d)
                    if d in pair else np.zeros((P, 2, strains[0].shape[-1])))
    return np.concatenate(columns), np.concatenate(rows, axis=-1), gamma


def _edge_traction(space, c: int, D: np.ndarray, moduli: np.ndarray, pts, w, normals, across):
    """:func:`cell_traction` on an edge of the whole − cell ``c`` with the
    whole + cell ``across[p]`` beyond it (one edge's points each; a point
    with no such cell, −1, read from ``c`` alone)."""
    P = len(w)
    blocks, strains = side_strains(space, c, pts)
    columns, rows = [blocks], [np.zeros((P, 2, strains[0].shape[-1]))]
    gamma = np.zeros(P)
    others = sorted(set(int(d) for d in across if d >= 0))
    pieces = [(np.flatnonzero(across == d), d) for d in others] + [(np.flatnonzero(across < 0), -1)]
    for at, d in pieces:
        if not len(at):
            continue
        minus = cell_parts(space, c)[0]
        plus = 0.0 if d < 0 else float(np.sum(cell_parts(space, d)))
        areas = np.broadcast_to(np.array([minus, plus]), (len(at), 2))
        length = float(np.sum(w[at]))
        weights, g = nitsche_weights(areas, moduli, np.full(len(at), length))
        gamma[at] = np.maximum(g, gamma_floor(areas[0], moduli, space.cut.cell_size[c]))
        maps = traction_maps(normals[at], D, weights)
        rows[0][at] += maps[0] @ strains[0][at]
        if d >= 0:
            other, (_, plus_strain) = side_strains(space, d, pts[at])
            columns.append(other)
            rows.append(np.zeros((P, 2, plus_strain.shape[-1])))
            rows[-1][at] = maps[1] @ plus_strain
    return np.concatenate(columns), np.concatenate(rows, axis=-1), gamma


def traction_operator(space):
    """``(S, γ₀)`` of the space's Γ points (module doc): ``S`` (2m × local
    unknowns) in :func:`xdolfinx.xfem.interface_operator`'s rows and
    columns, ``γ₀`` (m,) in Pa/m.

    The cells read from themselves alone (:func:`cell_traction`'s first
    case, all but those with Γ along an edge and a whole + cell across it,
    and those :mod:`xdolfinx.xfem.reading` reads)
    are computed together, point by point as :func:`cell_traction` does
    (the same products per point, so the same numbers); the few others
    cell by cell (:func:`_edge_traction`).  Each row's entries reach the
    COO sink in the order the cell-by-cell loop gave them, so ``S`` sums
    any duplicates alike."""
    scene = space.scene
    D = scene.voigt_matrices()
    moduli = np.array([scene.materials[b].E for b in BODIES])
    trip = Triplets((0, 2 * space.num_blocks))
    edges = space.edge_neighbours()
    cells = [c for c in space.owned_band if c in space.cut.gamma_rules]
    sizes = np.array([len(space.cut.gamma_rules[c][1]) for c in cells], dtype=np.int64)
    starts = np.concatenate([[0], np.cumsum(sizes)])
    m = int(starts[-1])
    gamma = np.zeros(m)
    plain = []  # (cell, its parts): read from the cell alone
    read = all_readers(space)
    for i, c in enumerate(cells):
        pts, w, normals = space.cut.gamma_rules[c]
        parts = cell_parts(space, c)
        if c in read:
            blocks, rows, gamma[starts[i]:starts[i + 1]] = _read_traction(space, c, D, moduli, read[c])
            _add_rows(trip, starts[i], blocks, rows)
            continue
        across = np.full(len(w), -1) if parts[1] > 0 or edges is None else space.across_edge(c, pts, edges)
        if not np.any(across >= 0):
            plain.append((i, parts))
            continue
        blocks, rows, gamma[starts[i]:starts[i + 1]] = _edge_traction(space, c, D, moduli, pts, w, normals, across)
        _add_rows(trip, starts[i], blocks, rows)
    if plain:
        _plain_tractions(space, trip, D, moduli, [cells[i] for i, _ in plain], np.array([p for _, p in plain]),
                         starts[[i for i, _ in plain]], gamma)
    trip.shape = (2 * m, trip.shape[1])
    return trip.to_csr(), gamma


def _add_rows(trip: Triplets, first: int, blocks: np.ndarray, rows: np.ndarray) -> None:
    """Rows ``rows`` (P, 2, 4n) of the points ``first …`` on the cell's
    ``blocks`` (2n,: u, then a, −1 if none) into ``trip``."""
    P = len(rows)
    cols = np.where(blocks[:, None] >= 0, 2 * blocks[:, None] + np.arange(2), -1).ravel()  # (4n,)
    trip.add(2 * (first + np.arange(P))[:, None, None] + np.arange(2)[None, :, None], cols[None, None, :], rows)


def _plain_tractions(space, trip: Triplets, D: np.ndarray, moduli: np.ndarray, cells: list, parts: np.ndarray,
                     starts: np.ndarray, gamma: np.ndarray) -> None:
    """:func:`cell_traction`'s rows and ``γ₀`` of ``cells`` read from
    themselves alone (``parts`` (C, 2) their − and + areas, ``starts``
    their first points' rows), all points at once: into ``trip`` and
    ``gamma``."""
    rules = [space.cut.gamma_rules[c] for c in cells]
    count = np.array([len(w) for _, w, _ in rules], dtype=np.int64)
    cell_of = np.repeat(np.arange(len(cells)), count)  # each point's cell (index into cells)
    normals = np.concatenate([n for _, _, n in rules])
    areas = parts[cell_of]
    weights, g = nitsche_weights(areas, moduli, np.repeat([np.sum(w) for _, w, _ in rules], count))
    gamma_at = np.repeat(starts, count) + (np.arange(len(cell_of)) - np.repeat(np.cumsum(count) - count, count))
    gamma[gamma_at] = np.maximum(g, gamma_floor(parts, moduli, space.cut.cell_size[cells])[cell_of])
    maps = traction_maps(normals, D, weights)
    dN = np.concatenate([space.cells.tabulate(c, pts)[1] for c, (pts, _, _) in zip(cells, rules)])  # (M, n, 2)
    dofs = space.cells.cell_dofs[cells][cell_of]  # (M, n)
    rows = np.zeros((len(cell_of), 2, 4 * dofs.shape[1]))
    for body in Body:
        strain = strain_matrix(dN, heaviside_shift(space, dofs, body.sign))
        used = weights[:, body] > 0
        rows[used] += maps[body][used] @ strain[used]
    blocks = space.cell_blocks(np.asarray(cells))[cell_of]  # (M, 2n)
    cols = np.where(blocks[:, :, None] >= 0, 2 * blocks[:, :, None] + np.arange(2), -1).reshape(len(cell_of), -1)
    trip.add(2 * gamma_at[:, None, None] + np.arange(2)[None, :, None], cols[:, None, :], rows)


def contrast_warnings(scene, degree: int) -> list[str]:
    """A warning where xfem P1 enforces an exact law on a curved Γ between
    moduli :data:`~contactcore.tolerances.XFEM_P1_CONTRAST` apart or more:
    its tractions on Γ scatter (measured there)."""
    moduli = [scene.materials[b].E for b in BODIES]
    contrast = max(moduli) / min(moduli)
    if degree != 1 or not is_exact(scene.law) or scene.interface.straight_in(scene.domain) \
            or contrast < tol.XFEM_P1_CONTRAST:
        return []
    return [f"xfem P1 with an exact law on a curved Γ between moduli {contrast:.3g} times apart: where the softer "
            "body's part of a cut cell is a sliver, Nitsche's traction reads the stiffer body's stress with γ at "
            "its scale times the softer body's jump error, and Γ's tractions scatter (a uniformly pressed circle, "
            "contrast 100: piece-mean t_T up to 14-17 % of the pressure at h = R/8, 7.6 % at R/16, points slipping "
            "with μ = 0.2 where none should); use degree 2 or fe, or refine h"]


def curved_stabilisation_warnings(scene, degree: int) -> list[str]:
    """A warning where xfem P1 enforces an exact law on a curved Γ with a
    ``stabilisation`` β above
    :data:`~contactcore.tolerances.XFEM_P1_CURVED_STABILISATION`: the cells'
    linear jumps cannot vanish at every point of a curved Γ, and the
    residue ``g`` times ``γ = β γ₀`` makes Nitsche's traction ``t = τ + γ g``
    oscillate from point to point, in proportion to β (measured there)."""
    if degree != 1 or not is_exact(scene.law) or scene.interface.straight_in(scene.domain) \
            or scene.law.stabilisation <= tol.XFEM_P1_CURVED_STABILISATION:
        return []
    return [f"xfem P1 with an exact law on a curved Γ at stabilisation {scene.law.stabilisation:g}, above "
            f"{tol.XFEM_P1_CURVED_STABILISATION:g}: a cut cell's linear jump cannot vanish all along a curve, and γ "
            "times its residue makes Γ's tractions oscillate point to point in proportion to β (a stiff disc in a "
            "ring at β = 30, h = R/10: t_N 31 % off at a point, t_T up to 41 % of |t_N|, 4.9 and 5.1 % at β = 3); "
            f"use a stabilisation of {tol.XFEM_P1_CURVED_STABILISATION:g} or less, degree 2 or fe"]

def with_traction(interface: InterfaceOperator, space) -> InterfaceOperator:
    """``interface`` with ``S`` and ``γ₀`` when the scene's law is enforced
    exactly, else as it is."""
    if not is_exact(space.scene.law):
        return interface
    S, gamma = traction_operator(space)
    return dataclasses.replace(interface, S=S, stabilisation=gamma)
