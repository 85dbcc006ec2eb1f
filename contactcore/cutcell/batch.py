"""Many axis-aligned cells cut at once by a line or a circle, bit for bit as one by one.

Contract: :func:`cut_squares` is :func:`~contactcore.cutcell.cut_cell` of
every axis-aligned cell of a grid, by a line or a circle, as array
operations over the cells (the rim and Γ cells of
:func:`contactcore.quadrature.volume_rule`).  The same arithmetic, in the
same order, as :func:`~contactcore.cutcell.cut_cell`'s scalar path: each
point and weight is the bits :func:`~contactcore.cutcell.cut_cell` gives
(a test compares them).  A cell whose cut is not the plain one (no
crossing, or two crossings on two different edges fanned from a corner),
or whose decision lies within
:data:`~contactcore.tolerances.CUT_BATCH_MARGIN` of a threshold, is left
to :func:`~contactcore.cutcell.cut_cell`; ``done`` says which cells it
settled.
"""
from __future__ import annotations

import numpy as np

from contactcore import tolerances as tol
from contactcore.bodies import sign_of
from contactcore.geometry import CircleInterface, LineInterface, polygon_area

from .crossings import _BELOW_ONE
from .gauss import gauss01, tensor_cells
from .polygons import _rectangle_test


def _square_vertices(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """(C, 4, 2): the corners of each cell counter-clockwise from ``lo``, as :func:`cut_cell` builds them."""
    return np.stack([lo, np.column_stack([hi[:, 0], lo[:, 1]]), hi, np.column_stack([lo[:, 0], hi[:, 1]])], axis=1)


def _batch_crossings(itf, a: np.ndarray, b: np.ndarray, fa: np.ndarray, fb: np.ndarray):
    """:func:`edge_crossings` of the segments a→b (E, 2) with level-set
    values ``fa``, ``fb``: the parameter of the one crossing (NaN: none),
    and where the segment may hold two (a circle dipping in: left to the
    scalar path)."""
    sa, sb = sign_of(fa), sign_of(fb)
    one = sa != sb
    t = np.full(len(a), np.nan)
    if isinstance(itf, LineInterface):
        with np.errstate(divide="ignore", invalid="ignore"):
            t[one] = fa[one] / (fa[one] - fb[one])
        return t, np.zeros(len(a), bool)
    cx, cy = (float(c) for c in itf.centre)
    R = itf.radius
    dx, dy, fx, fy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1], a[:, 0] - cx, a[:, 1] - cy
    qa, qb, qc = dx * dx + dy * dy, 2 * (fx * dx + fy * dy), fx * fx + fy * fy - R * R
    sq = np.sqrt(np.maximum(qb * qb - 4 * qa * qc, 0.0))
    lo_root, hi_root = (-qb - sq) / (2 * qa), (-qb + sq) / (2 * qa)
    root = np.where(sa > 0, lo_root, hi_root)
    t[one] = np.minimum(np.maximum(root[one], 0.0), _BELOW_ONE)
    t_near = np.minimum(np.maximum(-qb / (2 * qa), 0.0), 1.0)
    depth = R - np.hypot(fx + t_near * dx, fy + t_near * dy)
    two = ~one & (sa > 0) & (depth > tol.GEOMETRY * R * (1 - tol.CUT_BATCH_MARGIN)) & (0.0 <= lo_root) & (hi_root < 1.0)
    return t, two


def _batch_gamma(itf, p: np.ndarray, q: np.ndarray, g: np.ndarray):
    """:func:`_gamma_curve` from p to q (B, 2) at the parameters g: C and C′ (B, n, 2)."""
    if isinstance(itf, LineInterface):
        d = q - p
        return p[:, None, :] + g[None, :, None] * d[:, None, :], np.broadcast_to(d[:, None, :], (len(p), len(g), 2))
    c, R = np.asarray(itf.centre, float), itf.radius
    a0, a1 = np.arctan2(p[:, 1] - c[1], p[:, 0] - c[0]), np.arctan2(q[:, 1] - c[1], q[:, 0] - c[0])
    da = (a1 - a0 + np.pi) % (2 * np.pi) - np.pi
    ang = a0[:, None] + g[None, :] * da[:, None]
    cos, sin = np.cos(ang), np.sin(ang)
    C = c + R * np.stack([cos, sin], axis=-1)
    Rda = (R * da)[:, None]
    return C, np.stack([Rda * -sin, Rda * cos], axis=-1)


def _batch_fan(vertex: np.ndarray, C: np.ndarray, dC: np.ndarray, n: int):
    """:func:`_fan` of many cells: vertex (B, 2), curve C, C′ (B, n, 2) →
    points (B, n·n, 2), signed weights (B, n·n)."""
    g, gw = gauss01(n)
    s = g[:, None, None]
    pts = vertex[:, None, None, :] + s[None] * (C[:, None, :, :] - vertex[:, None, None, :])
    r = C - vertex[:, None, :]
    det = r[..., 0] * dC[..., 1] - r[..., 1] * dC[..., 0]
    w = (gw[:, None] * g[:, None])[None] * (gw[None, :][None] * det[:, None, :])
    return pts.reshape(len(vertex), -1, 2), w.reshape(len(vertex), -1)


def _batch_region(itf, chain: list[np.ndarray], n: int, size2: np.ndarray):
    """:func:`_region_rule` of one chain of points (each (B, 2): a crossing,
    the corners, a crossing) closed by Γ, for B cells: points (B, K, 2),
    weights (B, K), and which cells it could not settle (no corner sees the
    region whole, or the first that does is within round-off of the fold
    test)."""
    g, _ = gauss01(n)
    m = len(chain) - 2
    curves = []
    for k in range(m + 1):
        p, q = chain[k], chain[k + 1]
        d = q - p
        curves.append((p[:, None, :] + g[None, :, None] * d[:, None, :],
                       np.broadcast_to(d[:, None, :], (len(p), n, 2))))
    curves.append(_batch_gamma(itf, chain[-1], chain[0], g))
    B = len(size2)
    pts, wts = np.zeros((B, m * n * n, 2)), np.zeros((B, m * n * n))
    todo = np.ones(B, bool)
    unsure = np.zeros(B, bool)
    floor = -tol.FAN_FOLD * size2
    for k in range(1, m + 1):
        if not todo.any():
            break
        rows = np.flatnonzero(todo)
        fans = [_batch_fan(chain[k][rows], C[rows], dC[rows], n) for j, (C, dC) in enumerate(curves)
                if j not in (k - 1, k)]
        p = np.concatenate([f[0] for f in fans], axis=1)
        w = np.concatenate([f[1] for f in fans], axis=1)
        low = np.minimum(w.min(axis=1), 0.0)
        f = floor[rows]
        ok = low >= f * (1 - tol.CUT_BATCH_MARGIN)
        near = ~ok & (low >= f * (1 + tol.CUT_BATCH_MARGIN))
        unsure[rows[near]] = True
        todo[rows[near]] = False
        pts[rows[ok]], wts[rows[ok]] = p[ok], np.maximum(w[ok], 0.0)
        todo[rows[ok]] = False
    return pts, wts, unsure | todo


def _batch_polygon_rule(V: np.ndarray, n: int, rectangle: bool):
    """:func:`polygon_rule` of quadrilaterals V (B, 4, 2) that all pass
    (``rectangle``) or all fail :func:`_rectangle_test`: the tensor rule,
    or the fans from the first vertex; points (B, K, 2), weights (B, K)."""
    B = len(V)
    if rectangle:
        pts, w = tensor_cells(np.minimum(V[:, 0], V[:, 2]), np.maximum(V[:, 0], V[:, 2]), n)
        return pts.reshape(B, n * n, 2), w.reshape(B, n * n)
    g, _ = gauss01(n)
    fans = []
    for k in (1, 2):
        p, q = V[:, k], V[:, k + 1]
        d = q - p
        fans.append(_batch_fan(V[:, 0], p[:, None, :] + g[None, :, None] * d[:, None, :],
                               np.broadcast_to(d[:, None, :], (B, n, 2)), n))
    return np.concatenate([f[0] for f in fans], axis=1), np.concatenate([f[1] for f in fans], axis=1)


def cut_squares(itf, lo: np.ndarray, hi: np.ndarray, n: int, tensor: bool = True):
    """:func:`cut_cell` of the cells [lo, hi] (C, 2) at once, where a line
    or a circle cuts them plainly (section comment).  Returns ``done``
    (C,), which cells it settled, and their regions as ``(cells, slot,
    side, points, weights)`` chunks: ``cells`` (B,) the cells, ``slot`` the
    region's place among its cell's regions, ``side`` (B,) its side of
    ``itf``, points (B, K, 2) and weights (B, K) in :func:`cut_cell`'s
    order, ``tensor`` as there."""
    C = len(lo)
    done = np.zeros(C, bool)
    if not isinstance(itf, (LineInterface, CircleInterface)) or not C:
        return done, []
    V = _square_vertices(lo, hi)
    phi = itf.phi(V.reshape(-1, 2)).reshape(C, 4)
    sides = sign_of(phi)
    t, two = _batch_crossings(itf, V.reshape(-1, 2), np.roll(V, -1, axis=1).reshape(-1, 2), phi.ravel(),
                              np.roll(phi, -1, axis=1).ravel())
    t, two = t.reshape(C, 4), two.reshape(C, 4)
    crossed = ~np.isnan(t)
    count = crossed.sum(axis=1)
    fine = ~two.any(axis=1) & (count != 1) & (count <= 2)
    if isinstance(itf, CircleInterface):
        c = np.asarray(itf.centre, float)
        fine &= ~np.all((lo <= c) & (c <= hi), axis=1)  # a small circle's cell: the scalar path
    chunks = []
    # no crossing: the whole cell on the side of its corner farthest from Γ (:func:`_whole`)
    whole = np.flatnonzero(fine & (count == 0))
    rectangle = _rectangle_test(V[whole]) if tensor else np.zeros(len(whole), bool)
    for kind in (True, False):
        rows = whole[rectangle == kind]
        if len(rows):
            far = np.argmax(np.abs(phi[rows]), axis=1)
            chunks.append((rows, 0, sides[rows, far], *_batch_polygon_rule(V[rows], n, kind)))
            done[rows] = True
    # two crossings on two edges e1 < e2: the chains e1 → e2 and e2 → e1 (:func:`_two_regions`)
    size = np.linalg.norm(V.max(axis=1) - V.min(axis=1), axis=1)
    size2 = polygon_area(V)
    for e1 in range(4):
        for e2 in range(e1 + 1, 4):
            rows = np.flatnonzero(fine & (count == 2) & crossed[:, e1] & crossed[:, e2])
            if not len(rows):
                continue
            Vr = V[rows]
            X1 = Vr[:, e1] + t[rows, e1, None] * (Vr[:, (e1 + 1) % 4] - Vr[:, e1])
            X2 = Vr[:, e2] + t[rows, e2, None] * (Vr[:, (e2 + 1) % 4] - Vr[:, e2])
            chord = np.linalg.norm(X2 - X1, axis=1)
            rows_ok = chord > tol.TOUCH_CHORD * size[rows] * (1 + tol.CUT_BATCH_MARGIN)  # no touch, no sliver
            rows, Vr, X1, X2 = rows[rows_ok], Vr[rows_ok], X1[rows_ok], X2[rows_ok]
            if not len(rows):
                continue
            chain_a = [X1] + [Vr[:, k] for k in range(e1 + 1, e2 + 1)] + [X2]
            chain_b = [X2] + [Vr[:, k % 4] for k in range(e2 + 1, e1 + 5)] + [X1]
            regions = [_batch_region(itf, chain, n, size2[rows]) for chain in (chain_a, chain_b)]
            settled = ~regions[0][2] & ~regions[1][2]
            for slot, ((p, w, _), first) in enumerate(zip(regions, ((e1 + 1) % 4, (e2 + 1) % 4))):
                chunks.append((rows[settled], slot, sides[rows[settled], first], p[settled], w[settled]))
            done[rows[settled]] = True
    return done, chunks
