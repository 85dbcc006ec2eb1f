"""Gauss points on lines: Γ inside a polygon, and any parametrised curve (Γ, the outer boundary).

Contract: :func:`interface_rule_in` gives Γ's points, arc-length weights
and the level set's unit normals inside a convex polygon, following the
same walk, touch test and splits as
:func:`~contactcore.cutcell.cut_polygon`, so that cells and Γ are
integrated alike (no points where Γ only touches).  :func:`curve_rule`
gives points, arc-length weights and unit tangents on a curve ``x(τ)`` in
pieces no longer than ``h``, broken at given parameters.
"""
from __future__ import annotations

import numpy as np

from contactcore.errors import DiscretisationError

from .curves import _gamma_curve
from .gauss import gauss01
from .polygons import MAX_DEPTH, _split
from .touch import _sliver_cut, _touches_only, _walk


def curve_rule(points_of, tangent_of, length: float, h: float, n: int, breaks=()) -> tuple[np.ndarray, ...]:
    """Gauss points on a curve ``x(τ)``, τ ∈ [0, 1], of total ``length``, in
    pieces no longer than h and broken at the parameters ``breaks``.
    Returns points, weights (arc length) and unit tangents."""
    knots = sorted(set([0.0, 1.0] + [b for b in breaks if 0.0 < b < 1.0]))
    taus, wts = [], []
    g, gw = gauss01(n)
    for a, b in zip(knots[:-1], knots[1:]):
        m = max(1, int(np.ceil((b - a) * length / h)))
        edges = np.linspace(a, b, m + 1)
        taus.append((edges[:-1, None] + g[None] * np.diff(edges)[:, None]).ravel())
        wts.append((np.diff(edges)[:, None] * gw[None]).ravel())
    tau, w = np.concatenate(taus), np.concatenate(wts)
    tang = tangent_of(tau)
    speed = np.linalg.norm(tang, axis=1)
    return points_of(tau), w * speed, tang / speed[:, None]


def interface_rule_in(itf, vertices: np.ndarray, n: int, depth: int = 0):
    """Gauss points of Γ inside a convex polygon: points, weights (arc
    length) and the level set's unit normals, following the same splits as
    :func:`cut_polygon` so that cells and Γ are integrated alike."""
    walk, places, small_circle = _walk(itf, vertices)
    crossings = [walk[i][0] for i in places]
    if not small_circle and (not crossings or _touches_only(crossings, vertices)
                             or len(crossings) == 2 and _sliver_cut(itf, vertices, walk, places)):
        return np.zeros((0, 2)), np.zeros(0), np.zeros((0, 2))
    if len(crossings) == 2 and not small_circle:
        curve, tangent = _gamma_curve(itf, crossings[0], crossings[1])
        g, gw = gauss01(n)
        pts = curve(g)
        return pts, gw * np.linalg.norm(tangent(g), axis=1), itf.normals(pts)
    if depth >= MAX_DEPTH:
        raise DiscretisationError(f"the cell with corners {np.round(vertices, 6).tolist()} is cut by Γ in a way "
                                  f"that {MAX_DEPTH} subdivisions do not simplify; refine")
    parts = [interface_rule_in(itf, piece, n, depth + 1) for piece in _split(vertices)]
    return tuple(np.concatenate([p[k] for p in parts]) for k in range(3))
