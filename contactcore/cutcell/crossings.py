"""Where Γ crosses a cell's edge: the parameters of the side changes of its level set.

Contract: :func:`edge_crossings` gives the parameters ``t ∈ [0, 1)`` of
the segment ``a → b`` where the side of ``itf`` (:func:`contactcore.bodies.sign_of`)
changes: in closed form for a line or a circle (a circle that dips into
the segment by no more than the geometric tolerance is no crossing), by
sampling and bisection to round-off for a general level set.  A crossing
at an edge's end belongs to the next edge (``_BELOW_ONE``).
"""
from __future__ import annotations

import math

import numpy as np

from contactcore import tolerances as tol
from contactcore.bodies import sign_of
from contactcore.geometry import LevelSetInterface, LineInterface


#: Samples per edge that detect the sign changes of a general level set
#: (two crossings closer than 1/EDGE_SAMPLES of an edge would be missed), and
#: bisection steps that locate each (2^-52: to round-off).
EDGE_SAMPLES = 16
BISECTIONS = 52


def _general_crossings(itf, a: np.ndarray, b: np.ndarray) -> list[float]:
    t = np.linspace(0.0, 1.0, EDGE_SAMPLES + 1)
    side = sign_of(itf.phi(a + t[:, None] * (b - a)))
    out = []
    for k in np.flatnonzero(side[:-1] != side[1:]):
        lo, hi = t[k], t[k + 1]
        for _ in range(BISECTIONS):
            mid = (lo + hi) / 2
            if sign_of(itf.phi([a + mid * (b - a)]))[0] == side[k]:
                lo = mid
            else:
                hi = mid
        out.append(min(float(hi), np.nextafter(1.0, 0.0)))  # hi − lo = 2^-52 of the edge
    return out


def edge_crossings(itf, a: np.ndarray, b: np.ndarray) -> list[float]:
    """Parameters t ∈ [0, 1) of the segment a→b where the side changes."""
    if isinstance(itf, LevelSetInterface):
        return _general_crossings(itf, a, b)
    return _crossings(itf, a, b, *itf.phi([a, b]))


def _crossings(itf, a: np.ndarray, b: np.ndarray, fa, fb) -> list[float]:
    """:func:`edge_crossings` of a line or a circle, its level set ``fa``,
    ``fb`` at a and b given (a polygon's corners' values, found once)."""
    sa, sb = (1 if fa >= 0 else -1), (1 if fb >= 0 else -1)  # sign_of
    if isinstance(itf, LineInterface):
        if sa == sb:
            return []
        return [float(fa / (fa - fb))]
    # scalar arithmetic: this runs for every edge of every cell near Γ
    (cx, cy), R = itf.centre, itf.radius
    dx, dy, fx, fy = b[0] - a[0], b[1] - a[1], a[0] - cx, a[1] - cy
    qa, qb, qc = dx * dx + dy * dy, 2 * (fx * dx + fy * dy), fx * fx + fy * fy - R * R
    sq = math.sqrt(max(qb * qb - 4 * qa * qc, 0.0))
    lo_root, hi_root = (-qb - sq) / (2 * qa), (-qb + sq) / (2 * qa)
    if sa != sb:  # exactly one crossing: the root between the end points
        t = lo_root if sa > 0 else hi_root
        return [float(min(max(t, 0.0), _BELOW_ONE))]
    # same side: two crossings only if the segment dips into the disc by more
    # than the geometric tolerance (a touch is no crossing)
    t_near = min(max(-qb / (2 * qa), 0.0), 1.0)
    depth = R - math.hypot(fx + t_near * dx, fy + t_near * dy)
    if sa < 0 or depth <= tol.GEOMETRY * R or not (0.0 <= lo_root and hi_root < 1.0):
        return []
    return [float(lo_root), float(hi_root)]


#: The largest parameter below 1: a crossing at an edge's end belongs to the next edge.
_BELOW_ONE = float(np.nextafter(1.0, 0.0))
