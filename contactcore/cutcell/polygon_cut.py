"""The Gauss rule of a convex polygon on each side of Γ: one entry per region.

Contract: :func:`cut_polygon` (and :func:`cut_cell` for a rectangle)
returns ``[(side, points, weights)]``: one region where Γ misses or only
touches the polygon (on the side of its corner farthest from Γ), the two
fanned regions where Γ crosses it twice, and otherwise the regions of its
four pieces (``_split``), at most :data:`MAX_DEPTH` deep, where a piece
Γ still crosses twice takes Γ as its chord; a cut that stays complicated
beyond that is a DiscretisationError.  The weights sum to the polygon's
area.
"""
from __future__ import annotations

import numpy as np

from contactcore.errors import DiscretisationError
from contactcore.bodies import sign_of
from contactcore.geometry import polygon_area

from .polygons import MAX_DEPTH, _split, polygon_rule
from .regions import _chord_regions, _two_regions
from .touch import _sliver_cut, _touches_only, _walk


def cut_cell(itf, lo: np.ndarray, hi: np.ndarray, n: int, tensor: bool = True) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """``[(side, points, weights)]`` for the rectangle [lo, hi] (``tensor``: :func:`polygon_rule`'s)."""
    return cut_polygon(itf, np.array([lo, [hi[0], lo[1]], hi, [lo[0], hi[1]]], float), n, tensor=tensor)


def _whole(itf, vertices: np.ndarray, n: int, tensor: bool):
    """The polygon as one region on the side of its corner farthest from Γ."""
    far = int(np.argmax(np.abs(itf.phi(vertices))))
    return [(int(sign_of(itf.phi(vertices[far:far + 1]))[0]), *polygon_rule(vertices, n, tensor))]


def cut_polygon(itf, vertices: np.ndarray, n: int, depth: int = 0,
                tensor: bool = True) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """``[(side, points, weights)]`` for a convex polygon (counter-clockwise)
    and level set ``itf``: one entry per region on one side of Γ; one
    region where Γ only touches the polygon (:func:`_touches_only`,
    :func:`_sliver`).  ``tensor``: whether a whole axis-aligned rectangle
    takes the tensor rule (:func:`polygon_rule`)."""
    walk, crossings, small_circle = _walk(itf, vertices)
    size2 = polygon_area(vertices)
    if not small_circle and (not crossings or _touches_only([walk[i][0] for i in crossings], vertices)
                             or len(crossings) == 2 and _sliver_cut(itf, vertices, walk, crossings)):
        return _whole(itf, vertices, n, tensor)
    if len(crossings) == 2 and not small_circle:
        result = _two_regions(itf, walk, crossings, n, size2)
        if result is not None:
            return result
    if depth >= MAX_DEPTH and len(crossings) == 2 and not small_circle:
        chord = _chord_regions(itf, vertices, walk[crossings[0]][0], walk[crossings[1]][0], n, tensor)
        if chord is not None:
            return chord
    if depth >= MAX_DEPTH:
        raise DiscretisationError(f"the cell with corners {np.round(vertices, 6).tolist()} is cut by Γ in a way "
                                  f"that {MAX_DEPTH} subdivisions do not simplify; refine")
    return [part for piece in _split(vertices) for part in cut_polygon(itf, piece, n, depth + 1, tensor)]
