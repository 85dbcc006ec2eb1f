"""The MLS weight functions ``w(r)``: the cubic and the quartic spline.

The weights of the element-free Galerkin method (Belytschko, Lu & Gu,
"Element-free Galerkin methods", IJNME 37, 1994), on a support of unit
radius: ``r`` is the distance to the node over its support radius,
``r = |x − x_I| / r_I`` on a circular support, or ``|x − x_I| / r_xI``
and ``|y − y_I| / r_yI`` on a rectangular one, whose weight is the product ``w(r_x) w(r_y)``
(:meth:`efgm.shape.MLS._weights`).  Both vanish with their first and
second derivatives at r = 1; the cubic's two pieces (the cubic B-spline)
join with two derivatives at r = 1/2.

Contract: a function of ``r`` (an array of any shape, ``r ≥ 0``) returns
``w`` and ``dw/dr`` of that shape, zero from r = 1 on.  :data:`WEIGHTS`
names them as the options do (``weight = "cubic"``, ``"quartic"``).  The
mixin :class:`_Weights` gives each neighbour's ``w`` and ``∇w`` at the
points; it reads :class:`efgm.shape.MLS`'s ``radii``, ``rectangular`` and
``weight`` (the function of :data:`WEIGHTS` chosen).
"""
from __future__ import annotations

import numpy as np


def cubic_spline(r):
    """``w(r)`` and ``dw/dr`` of the cubic spline (support r < 1)."""
    inner = r <= 0.5
    t = np.maximum(1.0 - r, 0.0)  # the outer piece is 4/3 (1 − r)³: zero from r = 1 on
    t2 = t * t
    w = np.where(inner, 2 / 3 - 4 * r * r * t, 4 / 3 * t2 * t)
    dw = np.where(inner, r * (12 * r - 8), -4 * t2)
    return w, dw


def quartic_spline(r):
    """``w(r) = 1 − 6r² + 8r³ − 3r⁴`` and its derivative (support r < 1)."""
    r2 = r * r
    w = 1 - 6 * r2 + 8 * r2 * r - 3 * r2 * r2
    dw = -12 * r + 24 * r2 - 12 * r2 * r
    outside = r >= 1.0
    w[outside] = 0.0
    dw[outside] = 0.0
    return w, dw


WEIGHTS = {"cubic": cubic_spline, "quartic": quartic_spline}


class _Weights:
    """Each neighbour's weight and its gradient at the points, for
    :class:`efgm.shape.MLS`."""

    def _weights(self, idx: np.ndarray, ox: np.ndarray, oy: np.ndarray):
        """``w``, ``∂w/∂x``, ``∂w/∂y`` (P, K) and each neighbour's largest radius."""
        r_node = self.radii[np.maximum(idx, 0)]
        if self.rectangular:
            rxn, ryn = r_node[..., 0], r_node[..., 1]
            wx, dwx = self.weight(np.abs(ox) / rxn)
            wy, dwy = self.weight(np.abs(oy) / ryn)
            w, wdx, wdy = wx * wy, dwx * wy * np.sign(ox) / rxn, wx * dwy * np.sign(oy) / ryn
            r_node = np.maximum(rxn, ryn)
        else:
            d = np.sqrt(ox * ox + oy * oy)  # np.hypot guards against overflow at 6x the cost (measured)
            w, dwr = self.weight(d / r_node)
            scale = dwr / (r_node * np.where(d > 0, d, 1.0))
            wdx, wdy = scale * ox, scale * oy
        used = idx >= 0
        return w * used, wdx * used, wdy * used, r_node
