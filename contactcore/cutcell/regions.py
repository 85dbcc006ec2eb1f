"""The two regions of a polygon that Γ crosses twice, one on each side of it.

Contract: ``_two_regions`` closes each chain of the polygon's boundary
between Γ's two crossings with Γ itself and fans it from a corner
(``_region_rule``): ``[(side, points, weights)]``, or None where a chain
has no corner or no corner sees its region whole.  ``_chord_regions``,
the last resort at the finest split, takes Γ as its chord (convex pieces;
the area moved is at most ``|q − p|³ κ / 12``), or None.
"""
from __future__ import annotations

import numpy as np

from contactcore.geometry import LineInterface, clip_halfplane, polygon_area

from .curves import _gamma_curve, _segment
from .fans import _region_rule
from .polygons import polygon_rule


def _chord_regions(itf, vertices: np.ndarray, p: np.ndarray, q: np.ndarray, n: int, tensor: bool):
    """The two regions of a piece at the finest split that Γ crosses at
    ``p`` and ``q`` but that no corner sees whole (Γ touching a side of the
    piece between its crossings: a circle tangent to a grid line, which
    every split keeps), with Γ taken as its chord ``p → q``: convex pieces.
    The area moved, between arc and chord, is at most ``|q − p|³ κ / 12``,
    ``|q − p|`` no longer than the piece: ``2^-MAX_DEPTH`` of the cell.
    None for a chord of no length or a piece whose corners all lie on Γ."""
    t = q - p
    if not np.any(t):
        return None
    m = np.array([t[1], -t[0]]) / np.hypot(*t)
    phi = itf.phi(vertices)
    reach = np.where(phi != 0, np.abs((vertices - p) @ m), -1.0)
    far = int(np.argmax(reach))  # the corner off Γ farthest from the chord: on Γ's side as on the chord's
    if reach[far] < 0:
        return None
    if ((vertices[far] - p) @ m) * phi[far] < 0:
        m = -m
    out = []
    for side, normal in ((-1, m), (1, -m)):
        piece = clip_halfplane(vertices, LineInterface(tuple(p), tuple(normal)))
        if polygon_area(piece) > 0:
            out.append((side, *polygon_rule(piece, n, tensor)))
    return out


def _two_regions(itf, walk, crossings, n, size2):
    """The two regions of a cell that Γ crosses twice, each fanned from a corner."""
    i, j = crossings
    chains = [walk[i:j + 1], walk[j:] + walk[:i + 1]]
    out = []
    for chain in chains:
        corner_sides = [w[2] for w in chain if w[1]]
        if not corner_sides:
            return None
        start, end = chain[0][0], chain[-1][0]
        curves = [_segment(chain[k][0], chain[k + 1][0]) for k in range(len(chain) - 1)]
        curves.append(_gamma_curve(itf, end, start))
        rule = _region_rule(([(w[0], w[1]) for w in chain], curves), n, size2)
        if rule is None:
            return None
        out.append((int(corner_sides[0]), *rule))
    return out
