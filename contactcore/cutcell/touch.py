"""Whether Γ cuts a polygon or only touches it: the one walk and test shared by cells and Γ.

Contract: ``_walk`` lists the polygon's boundary counter-clockwise with
Γ's crossings (:mod:`~contactcore.cutcell.crossings`) and says whether Γ
is a circle that may lie inside it.  ``_touches_only`` (two crossings
round-off apart) and ``_sliver_cut`` (a region thinner than
:data:`~contactcore.tolerances.GAMMA_PIECE_MIN` of the diameter along a
chord shorter than :data:`~contactcore.tolerances.TOUCH_CHORD` of it)
decide a touch, so that :func:`~contactcore.cutcell.cut_polygon` and
:func:`~contactcore.cutcell.interface_rule_in` give Γ a piece in a cell
exactly where the cell has two regions.
"""
from __future__ import annotations

import numpy as np

from contactcore import tolerances as tol
from contactcore.bodies import sign_of
from contactcore.geometry import CircleInterface, LevelSetInterface, polygon_area

from .crossings import _crossings, _general_crossings
from .regions import _two_regions


def _touches_only(crossings: list[np.ndarray], vertices: np.ndarray) -> bool:
    """Whether Γ only touches the polygon: two crossings closer than
    :data:`~contactcore.tolerances.GAMMA_PIECE_MIN` of its diameter (Γ
    through a corner, the crossings on its two edges there apart by
    round-off), which make no piece of Γ and no region."""
    if len(crossings) != 2:
        return False
    size = float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))
    return float(np.linalg.norm(crossings[1] - crossings[0])) <= tol.GAMMA_PIECE_MIN * size


def _walk(itf, vertices: np.ndarray):
    """The polygon's boundary counter-clockwise with Γ's crossings,
    ``[(point, is_corner, side_after)]``, the places of the crossings in
    it, and whether Γ is a circle that may lie inside the polygon or cut it
    along an arc longer than π (the short-arc construction would then be
    wrong: the polygon is split)."""
    phi = itf.phi(vertices)
    sides = sign_of(phi)
    general = isinstance(itf, LevelSetInterface)
    walk = []
    for i in range(len(vertices)):
        j = (i + 1) % len(vertices)
        a, b = vertices[i], vertices[j]
        walk.append((a, True, sides[i]))
        for t in (_general_crossings(itf, a, b) if general else _crossings(itf, a, b, phi[i], phi[j])):
            walk.append((a + t * (b - a), False, None))
    crossings = [i for i, w in enumerate(walk) if not w[1]]
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    small_circle = (isinstance(itf, CircleInterface) and np.all((lo <= itf.centre) & (itf.centre <= hi))
                    and itf.radius < np.linalg.norm(hi - lo))
    return walk, crossings, small_circle


#: Gauss points per direction of the fans that measure a region's area
#: for :func:`_sliver` (a cap's area to a few digits is all it needs).
SLIVER_GAUSS = 2


def _sliver(regions, chord: float, vertices: np.ndarray) -> bool:
    """Whether Γ only touches the polygon although it crosses two edges:
    one of the two regions thinner than ``GAMMA_PIECE_MIN · diameter``
    (its area over Γ's ``chord`` across it) along a chord shorter than
    ``TOUCH_CHORD · diameter`` — a circle tangent to an edge at a corner,
    on one side of it or the other by round-off, cuts off a cap of
    round-off depth whose chord is √(R·round-off) long.  Γ along a whole
    edge (a region of no area, its chord the edge) stays a cut."""
    size = float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))
    thinnest = min(float(np.sum(w)) for _, _, w in regions)
    return chord <= tol.TOUCH_CHORD * size and thinnest <= tol.GAMMA_PIECE_MIN * size * chord


def _sliver_cut(itf, vertices: np.ndarray, walk, places) -> bool:
    """Whether the two regions that Γ's two crossings ``places`` of the
    ``walk`` make of a polygon include a :func:`_sliver`: the one test of
    :func:`cut_polygon` and :func:`interface_rule_in`, so that Γ has a
    piece in a cell exactly where the cell has two regions."""
    chord = float(np.linalg.norm(walk[places[1]][0] - walk[places[0]][0]))
    if chord > tol.TOUCH_CHORD * float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0))):
        return False  # no sliver whatever its regions' areas (:func:`_sliver`'s first test): not fanned
    regions = _two_regions(itf, walk, places, SLIVER_GAUSS, polygon_area(vertices))
    return regions is not None and _sliver(regions, chord, vertices)
