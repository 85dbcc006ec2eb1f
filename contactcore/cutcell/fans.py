"""A region integrated as fans: from a vertex ``V`` over each of its boundary curves.

Contract: ``_fan(V, C, n)`` maps Gauss points of the unit square by
``P(s, τ) = V + s (C(τ) − V)``, ``det J = s (C − V) × C′``, and returns
points and *signed* weights (a triangle for a straight side, the curved
sector exactly for an arc).  ``_region_rule`` fans a region from the first
of its corners that sees all of it, i.e. whose weights fold by no more
than :data:`~contactcore.tolerances.FAN_FOLD` of the cell's area, and
returns None where no corner does.
"""
from __future__ import annotations

import numpy as np

from contactcore import tolerances as tol

from .gauss import gauss01


def _fan(vertex, curve, n) -> tuple[np.ndarray, np.ndarray]:
    """Points and signed weights of the fan from ``vertex`` over ``curve``."""
    g, gw = gauss01(n)
    C, dC = curve[0](g), curve[1](g)
    s = g[:, None, None]
    pts = vertex + s * (C[None] - vertex)                         # (n_s, n_τ, 2)
    r = C - vertex
    det = r[:, 0] * dC[:, 1] - r[:, 1] * dC[:, 0]                 # (n_τ,)
    w = (gw[:, None] * g[:, None]) * (gw[None, :] * det[None, :])
    return pts.reshape(-1, 2), w.ravel()


def _region_rule(corners_and_curves, n, size2):
    """Fan a region from the first of its corners that sees all of it.
    Curve k runs from boundary point k to point k + 1 (the last one, Γ,
    back to point 0), so a corner's two sides are curves k − 1 and k:
    straight, their fans have no area and are left out."""
    points, curves = corners_and_curves
    corners = [k for k, (_, is_corner) in enumerate(points) if is_corner]
    for k in corners or [None]:
        vertex = points[0 if k is None else k][0]
        fans = [_fan(vertex, curve, n) for j, curve in enumerate(curves) if k is None or j not in (k - 1, k)]
        w = np.concatenate([f[1] for f in fans])
        if w.min(initial=0.0) >= -tol.FAN_FOLD * size2:
            return np.concatenate([f[0] for f in fans]), np.maximum(w, 0.0)
    return None
