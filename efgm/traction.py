"""EFGM's consistent interface traction for Nitsche's method: ``S`` with
``τ = S u = [n·{σ}n, t·{σ}n]`` at Γ's points, and the stabilisation ``γ₀``
(:mod:`contactcore.traction` for the maths and its source).

EFGM has no cells of its own; the weights and ``γ₀`` of a Γ point are
taken on the background integration cell that holds it (its
``Ω₋ᵉ``, ``Ω₊ᵉ``: the areas the volume rule gives each body in that cell,
the same rule that integrates ``K``; ``Γᵉ``: the length of Γ in the cell
and the domain).  A point on an edge between two cells belongs to the cell
on its − side, the cell whose Γ rule holds it (:mod:`contactcore.cutcell`:
Γ on an edge is the + body's boundary, so the cell below it is cut and the
one above is not).  The parts' areas, not equal halves: a body thinner
than a cell near Γ (a strip along a boundary, a corner Γ clips) controls
its own stress over that small area only, and the weights then read the
traction from the other body.  (Squares of side h centred at each point,
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

#: A Γ point is placed in its cell after a shift of this fraction of the
#: cell's side towards the − body (module doc: a point on an edge goes to the
#: cell below it); far below any Gauss point's distance from an edge it is
#: not on.
EDGE_SHIFT = 1e-9


def cells_of(points: np.ndarray, origin: np.ndarray, step: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """The background cell (ix, iy) (P, 2) of each point, squares of side
    ``step`` from ``origin``, ``counts`` per direction."""
    return np.clip(np.floor((points - origin) / step), 0, counts - 1).astype(np.int64)


def cell_parts(scene, vol: Rule, origin: np.ndarray, step: np.ndarray, counts: np.ndarray, points: np.ndarray,
               normals: np.ndarray, gauss: int) -> tuple[np.ndarray, np.ndarray]:
    """The areas (P, 2) of the − and + parts of the background cell holding
    each Γ point, from the volume rule ``vol``, and the length (P,) of Γ in
    that cell (and in the domain)."""
    key = lambda ij: ij[:, 0] * counts[1] + ij[:, 1]  # noqa: E731
    size = int(counts[0] * counts[1])
    volume = np.bincount(2 * key(cells_of(vol.points, origin, step, counts)) + vol.bodies, vol.weights,
                         2 * size).reshape(size, 2)
    cells = cells_of(points - EDGE_SHIFT * np.max(step) * normals, origin, step, counts)
    unique, inverse = np.unique(key(cells), return_inverse=True)
    length = np.zeros(len(unique))
    for i, c in enumerate(unique):
        lo = origin + np.array([c // counts[1], c % counts[1]]) * step
        square = np.array([lo, lo + [step[0], 0.0], lo + step, lo + [0.0, step[1]]])
        pts, w, _ = interface_rule_in(scene.interface, square, gauss)
        length[i] = np.sum(w[scene.domain.contains(pts, tol.NODE_MATCH * scene.length_scale)])
    return volume[unique][inverse.ravel()], length[inverse.ravel()]


def traction(scene, approx, shape_values, vol: Rule, cells: tuple, points: np.ndarray, normals: np.ndarray,
             gauss: int):
    """``(S, γ₀)`` at Γ's ``points`` (module doc): ``shape_values`` the MLS
    functions there for the − and + bodies, ``cells`` the background
    cells' ``(origin, step, counts)``."""
    areas, length = cell_parts(scene, vol, *cells, points, normals, gauss)
    moduli = np.array([scene.materials[b].E for b in BODIES])
    weights, gamma = nitsche_weights(areas, moduli, length)
    m = len(points)
    strains = [approx.strain_operator(sv, np.full(m, b)) for b, sv in enumerate(shape_values)]
    return traction_operator(traction_maps(normals, scene.voigt_matrices(), weights), strains), gamma
