"""EFGM's consistent interface traction for Nitsche's method: ``S`` with
``τ = S u = [n·{σ}n, t·{σ}n]`` at Γ's points, and the stabilisation ``γ₀``
(:mod:`contactcore.traction` for the maths and its source).

EFGM has no cells of its own; the weights and ``γ₀`` of a Γ point are
taken on the background integration cell that holds it, or, where that
cell leaves a body a sliver (less than
:data:`~contactcore.tolerances.EFGM_SLIVER_PART` of it), on the cells
around it: those that a square of side h centred at the point meets
(:data:`~contactcore.tolerances.EFGM_NITSCHE_REACH`), taken as one (its
``Ω₋ᵉ``, ``Ω₊ᵉ``: the areas the volume rule gives each body in those
cells, the same rule that integrates ``K``; ``Γᵉ``: the length of Γ in
them and the domain).  A grid line within
:data:`~contactcore.tolerances.ON_CELL_EDGE` of the square's edge counts
as inside it, so the cells do not follow round-off (Γ along a grid line,
a point at a cell's centre); a point on a grid line (within ON_CELL_EDGE)
has the cells on both sides as its own, taken as one.  (All points wide
halved γ₀ of ordinary cuts and turned two fragile exact-unilateral runs
from solved to refused: tolerances.EFGM_SLIVER_PART.)

Why more than the point's own cell: a straight Γ halves the square, so
each body has at least h²/2 in the cells, and neither part is a sliver
unless the body itself is thinner there.  With the one cell holding the
point, Γ a hair above a node row (which is a grid line) left the softer
body a sliver of every cell along Γ; both compliances were then tiny, γ₀
took the stiffer body's scale (γ₀ h/E_soft up to 2e6 at moduli 1e6
apart), and ``γ`` times the jump's discretisation error put Γ's tractions
off by up to 20 % of the pressure at every h, turning stick into slip
under exact Coulomb (grader13 #1; the same oscillation as stiff penalty
springs, docs/methods/efgm.md, "Limits").  An MLS field's trace on Γ is
set by its nodes' supports (radius ~2h) on its side, not by the sliver of
one integration cell, so a neighbourhood of a cell's size is also the
right measure of how much each body controls its stress there.

The parts' areas, not equal halves: a body thinner than a cell near Γ (a
strip along a boundary, a corner Γ clips) controls its own stress over
that small area only, and the weights then read the traction from the
other body.  (On 2026-11-26 squares of side h centred at each point, whose
areas are Γ's halves, were tried: smoother weights along Γ and the same
accuracy on the inclined placements of scene A, but Newton then cycled at
the slip reversal of the layered Coulomb closed form, linear basis; Γ on
a node row then took the one cell below it.  The cells the square meets
are whole cells, and that closed form, the thin strips and scene A's
inclined placements pass with them: tests/test_exact.py,
tests/test_thin_bodies.py, tests/test_nitsche_cuts.py.)

With ``sv`` the shape functions at the points for each body and ``B_k`` the
strain operator of body k (:meth:`efgm.operators.Approximation.strain_operator`),
``S = Σ_k blockdiag(w_k [n; t] P(n) D_k) B_k``.  numpy and scipy only.
"""
from __future__ import annotations

import numpy as np

from contactcore import BODIES
from contactcore import tolerances as tol
from contactcore.cutcell import Rule, interface_rule_in
from contactcore.traction import nitsche_weights, traction_maps, traction_operator


def cell_ranges(points: np.ndarray, origin: np.ndarray, step: np.ndarray, counts: np.ndarray,
                wide: bool = True) -> np.ndarray:
    """The first and last background cell (ix, iy) of each point's parts,
    (P, 2, 2) as ``[[ix0, iy0], [ix1, iy1]]``, squares of side ``step``
    from ``origin``, ``counts`` per direction: the cells that a square of
    side ``2 EFGM_NITSCHE_REACH step`` centred at the point meets (module
    doc), two or three in each direction inside the grid; not ``wide``,
    the point's own cell, or in a direction where it lies on a grid line
    (within ON_CELL_EDGE) the two cells on either side of it."""
    f = (points - origin) / step
    if wide:
        reach = tol.EFGM_NITSCHE_REACH + tol.ON_CELL_EDGE
        first, last = np.floor(f - reach), np.floor(f + reach)
    else:
        line = np.rint(f)
        on = np.abs(f - line) <= tol.ON_CELL_EDGE
        first, last = np.where(on, line - 1, np.floor(f)), np.where(on, line, np.floor(f))
    return np.clip(np.stack([first, last], axis=1), 0, counts - 1).astype(np.int64)


def cell_volumes(vol: Rule, origin: np.ndarray, step: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """The area (nx, ny, 2) of the − and + body in each background cell,
    from the volume rule ``vol`` (each Gauss point inside its cell)."""
    counts = np.asarray(counts)
    at = np.clip(np.floor((vol.points - origin) / step), 0, counts - 1).astype(np.int64)
    volume = np.zeros((*counts, 2))
    np.add.at(volume, (at[:, 0], at[:, 1], vol.bodies), vol.weights)
    return volume


def cell_parts(scene, volume: np.ndarray, origin: np.ndarray, step: np.ndarray, counts: np.ndarray,
               points: np.ndarray, gauss: int, wide: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """The areas (P, 2) of the − and + parts of the background cells
    around each Γ point (:func:`cell_ranges`), from the cells' ``volume``
    (:func:`cell_volumes`), and the length (P,) of Γ in those cells (and
    in the domain)."""
    counts = np.asarray(counts)
    ranges, inverse = np.unique(cell_ranges(points, origin, step, counts, wide).reshape(len(points), 4), axis=0,
                                return_inverse=True)
    areas, length = np.zeros((len(ranges), 2)), np.zeros(len(ranges))
    for i, (ix0, iy0, ix1, iy1) in enumerate(ranges):
        areas[i] = volume[ix0:ix1 + 1, iy0:iy1 + 1].sum(axis=(0, 1))
        lo, hi = origin + np.array([ix0, iy0]) * step, origin + np.array([ix1 + 1, iy1 + 1]) * step
        pts, w, _ = interface_rule_in(scene.interface, np.array([lo, [hi[0], lo[1]], hi, [lo[0], hi[1]]]), gauss)
        length[i] = np.sum(w[scene.domain.contains(pts, tol.NODE_MATCH * scene.length_scale)])
    return areas[inverse.ravel()], length[inverse.ravel()]


def traction(scene, approx, shape_values, vol: Rule, cells: tuple, points: np.ndarray, normals: np.ndarray,
             gauss: int):
    """``(S, γ₀)`` at Γ's ``points`` (module doc): ``shape_values`` the MLS
    functions there for the − and + bodies, ``cells`` the background
    cells' ``(origin, step, counts)``."""
    volume = cell_volumes(vol, *cells)
    own, length = cell_parts(scene, volume, *cells, points, gauss, wide=False)
    sliver = own.min(axis=1) < tol.EFGM_SLIVER_PART * own.sum(axis=1)
    if np.any(sliver):
        own[sliver], length[sliver] = cell_parts(scene, volume, *cells, points[sliver], gauss)
    moduli = np.array([scene.materials[b].E for b in BODIES])
    weights, gamma = nitsche_weights(own, moduli, length)
    m = len(points)
    strains = [approx.strain_operator(sv, np.full(m, b)) for b, sv in enumerate(shape_values)]
    return traction_operator(traction_maps(normals, scene.voigt_matrices(), weights), strains), gamma
