"""Convex polygons that Γ leaves whole: their Gauss rule, the rectangle test, the quad-tree split.

Contract: :func:`polygon_rule` integrates an uncut convex polygon
(counter-clockwise): the ``n × n`` tensor rule on an axis-aligned
rectangle (``_rectangle_test``, within
:data:`~contactcore.tolerances.AXIS_RECTANGLE` of its diameter), fans from
its first vertex otherwise.  ``_split`` cuts a triangle or a
quadrilateral into four convex pieces; a cut that stays complicated is
split at most :data:`MAX_DEPTH` times.
"""
from __future__ import annotations

import numpy as np

from contactcore import tolerances as tol

from .curves import _segment
from .fans import _fan
from .gauss import _tensor_rule


#: Quad-tree splits of a cell before giving up on a cut that stays complicated.
MAX_DEPTH = 6


def _split(vertices: np.ndarray) -> list[np.ndarray]:
    """Four smaller convex pieces: a triangle by its edge midpoints, a
    quadrilateral by its edge midpoints and centre."""
    mids = (vertices + np.roll(vertices, -1, axis=0)) / 2
    if len(vertices) == 3:
        return [np.array([vertices[0], mids[0], mids[2]]), np.array([mids[0], vertices[1], mids[1]]),
                np.array([mids[2], mids[1], vertices[2]]), np.array([mids[0], mids[1], mids[2]])]
    c = vertices.mean(axis=0)
    return [np.array([vertices[i], mids[i], c, mids[i - 1]]) for i in range(4)]


def polygon_rule(vertices: np.ndarray, n: int, tensor: bool = True):
    """Gauss points of an uncut convex polygon: the n×n tensor rule on an
    axis-aligned rectangle (:func:`_rectangle_test`), exact for a degree
    2n − 1 polynomial in each coordinate; fans from the first vertex
    otherwise (2n² points a quadrilateral, exact to total degree 2n − 2),
    and on every polygon where ``tensor`` is false (the choice of
    :data:`contactcore.quadrature.WHOLE_CELL_TENSOR`)."""
    if tensor and len(vertices) == 4 and _rectangle_test(vertices[None])[0]:
        return _tensor_rule(np.minimum(vertices[0], vertices[2]), np.maximum(vertices[0], vertices[2]), n)
    pts, wts = zip(*[_fan(vertices[0], _segment(vertices[k], vertices[k + 1]), n)
                     for k in range(1, len(vertices) - 1)])
    return np.concatenate(pts), np.concatenate(wts)


def _rectangle_test(V: np.ndarray) -> np.ndarray:
    """Whether each quadrilateral V (B, 4, 2) is an axis-aligned rectangle:
    its edges alternately horizontal and vertical, from its first vertex
    (v₀y = v₁y, v₁x = v₂x, v₂y = v₃y, v₃x = v₀x) or, the vertices starting
    one corner on (a piece of :func:`_split`, a cell whose order was
    reversed), vertical and horizontal, each within
    :data:`~contactcore.tolerances.AXIS_RECTANGLE` of the polygon's
    diameter.  The one test of :func:`polygon_rule` and :func:`cut_squares`."""
    size = np.linalg.norm(V.max(axis=1) - V.min(axis=1), axis=1)
    step = np.abs(np.roll(V, -1, axis=1) - V)            # (B, 4, 2): |v_{k+1} − v_k| by coordinate
    limit = (tol.AXIS_RECTANGLE * size)[:, None]
    horizontal_first = np.all(step[:, [0, 1, 2, 3], [1, 0, 1, 0]] <= limit, axis=1)
    vertical_first = np.all(step[:, [0, 1, 2, 3], [0, 1, 0, 1]] <= limit, axis=1)
    return (horizontal_first | vertical_first) & (size > 0)
