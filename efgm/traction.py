"""EFGM's consistent interface traction for Nitsche's method: ``S`` with
``τ = S u = [n·{σ}n, t·{σ}n]`` at Γ's points, and the stabilisation ``γ₀``
(:mod:`contactcore.traction` for the maths and its source).

EFGM has no cells of its own; the weights and ``γ₀`` of a Γ point are
taken on the background integration cell that holds it (its
``Ω₋ᵉ``, ``Ω₊ᵉ``: the areas the volume rule gives each body in that cell,
the same rule that integrates ``K``; ``Γᵉ``: the length of Γ in the cell
and the domain).  A point on a grid line between cells (within
:data:`~contactcore.tolerances.ON_CELL_EDGE` of it) belongs to the cells on
both sides, taken as one: Γ along the line then has a whole cell of each
body as its parts and its length in them, whether round-off puts Γ on the
line, just left of it or just right (one cell alone would hold Γ along
its edge or not by that round-off, and its Γ length be 0).  The parts'
areas, not equal halves: a body thinner than a cell near Γ (a strip along
a boundary, a corner Γ clips) controls its own stress over that small area
only, and the weights then read the traction from the other body.  (Squares of side h centred at each point,
which a straight Γ halves, gave smoother weights along Γ and the same
accuracy on the inclined placements of scene A, but Newton then cycled
at the slip reversal of the layered Coulomb closed form, linear basis.)

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


def cell_ranges(points: np.ndarray, origin: np.ndarray, step: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """The first and last background cell (ix, iy) holding each point,
    (P, 2, 2) as ``[[ix0, iy0], [ix1, iy1]]``, squares of side ``step``
    from ``origin``, ``counts`` per direction: the point's cell, or in a
    direction where it lies on a grid line (module doc) the two cells on
    either side of it."""
    f = (points - origin) / step
    line = np.rint(f)
    on = np.abs(f - line) <= tol.ON_CELL_EDGE
    first, last = np.where(on, line - 1, np.floor(f)), np.where(on, line, np.floor(f))
    return np.clip(np.stack([first, last], axis=1), 0, counts - 1).astype(np.int64)


def cell_parts(scene, vol: Rule, origin: np.ndarray, step: np.ndarray, counts: np.ndarray, points: np.ndarray,
               gauss: int) -> tuple[np.ndarray, np.ndarray]:
    """The areas (P, 2) of the − and + parts of the background cells
    holding each Γ point (:func:`cell_ranges`), from the volume rule
    ``vol``, and the length (P,) of Γ in those cells (and in the domain)."""
    counts = np.asarray(counts)
    at = np.clip(np.floor((vol.points - origin) / step), 0, counts - 1).astype(np.int64)  # inside its cell
    volume = np.zeros((*counts, 2))
    np.add.at(volume, (at[:, 0], at[:, 1], vol.bodies), vol.weights)
    ranges, inverse = np.unique(cell_ranges(points, origin, step, counts).reshape(len(points), 4), axis=0,
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
    areas, length = cell_parts(scene, vol, *cells, points, gauss)
    moduli = np.array([scene.materials[b].E for b in BODIES])
    weights, gamma = nitsche_weights(areas, moduli, length)
    m = len(points)
    strains = [approx.strain_operator(sv, np.full(m, b)) for b, sv in enumerate(shape_values)]
    return traction_operator(traction_maps(normals, scene.voigt_matrices(), weights), strains), gamma
