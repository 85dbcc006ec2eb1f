"""Integration on cells cut by Γ, on Γ, and on the outer boundary (exact geometry).

Shared by the methods that integrate on cells that ignore Γ (EFGM's
background cells, XFEM's mesh cells).  numpy only.

Every region is integrated as a set of *fans*: from a vertex ``V`` over a
boundary curve ``C(τ)``, ``τ ∈ [0, 1]``, the map ``P(s, τ) = V + s (C(τ) − V)``
covers the region between them, with ``det J = s (C − V) × C′``.  A straight
side gives a triangle (Duffy's collapsed square); an arc of the circle gives
the curved sector between ``V`` and the arc, exactly.  Gauss–Legendre rules
of ``n`` points in ``s`` and ``τ`` (numpy's, the same as basix's interval
rules — a test checks it).  A cell that Γ cuts into more than two pieces,
or whose pieces are not star-shaped from a corner, is split in four (up to
:data:`MAX_DEPTH` times) — this only happens when Γ bends sharply inside one
cell.  Cells are convex polygons given counter-clockwise: rectangles and
triangles.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from contactcore.errors import DiscretisationError
from contactcore import tolerances as tol
from contactcore.bodies import sign_of
from contactcore.geometry import CircleInterface, LevelSetInterface, LineInterface, clip_halfplane, polygon_area

#: Quad-tree splits of a cell before giving up on a cut that stays complicated.
MAX_DEPTH = 6



@dataclass
class Rule:
    """Quadrature points (Q, 2), weights (Q,) and the body (0 −, 1 +) of each."""

    points: np.ndarray
    weights: np.ndarray
    bodies: np.ndarray

    @staticmethod
    def concatenate(rules: list["Rule"]) -> "Rule":
        rules = [r for r in rules if len(r.weights)]
        if not rules:
            return Rule(np.zeros((0, 2)), np.zeros(0), np.zeros(0, int))
        return Rule(np.concatenate([r.points for r in rules]), np.concatenate([r.weights for r in rules]),
                    np.concatenate([r.bodies for r in rules]))


@functools.cache
def gauss01(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre points and weights on [0, 1] (cached: read-only)."""
    x, w = np.polynomial.legendre.leggauss(n)
    return (x + 1) / 2, w / 2


# ----- the level set seen from a cell ---------------------------------------

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


#: Newton steps projecting a chord point onto a general Γ (quadratic
#: convergence from a chord within O(h²) of Γ: 8 reach round-off).
PROJECTIONS = 8


def _projected_curve(itf, p: np.ndarray, q: np.ndarray):
    """Γ between two of its points as the chord projected onto φ = 0 along
    the chord's normal m: C(τ) = p + τ(q − p) + s(τ) m, with φ(C) = 0 by
    Newton and C′ = (q − p) + s′ m, s′ = −∇φ·(q − p) / ∇φ·m."""
    d = q - p
    m = np.array([-d[1], d[0]]) / np.linalg.norm(d)

    def solve(t):
        base = p + t[:, None] * d
        s = np.zeros(len(t))
        with np.errstate(divide="ignore", invalid="ignore"):  # ∇φ ⟂ m: not finite, and refused by the caller
            for _ in range(PROJECTIONS):
                x = base + s[:, None] * m
                s -= itf.phi(x) / (np.asarray(itf.grad_fn(x)) @ m)
        return base + s[:, None] * m

    def tangent(t):
        g = np.asarray(itf.grad_fn(solve(t)))
        return d + (-(g @ d) / (g @ m))[:, None] * m

    return solve, tangent


def _gamma_curve(itf, p: np.ndarray, q: np.ndarray):
    """Γ from p to q as ``(C(τ), C′(τ))`` (the short arc for a circle)."""
    if isinstance(itf, LevelSetInterface):
        return _projected_curve(itf, p, q)
    if isinstance(itf, LineInterface):
        return lambda t: p + t[:, None] * (q - p), lambda t: np.broadcast_to(q - p, (len(t), 2))
    c, R = np.asarray(itf.centre, float), itf.radius
    a0, a1 = np.arctan2(*(p - c)[::-1]), np.arctan2(*(q - c)[::-1])
    da = (a1 - a0 + np.pi) % (2 * np.pi) - np.pi
    ang = lambda t: a0 + t * da  # noqa: E731
    return (lambda t: c + R * np.column_stack([np.cos(ang(t)), np.sin(ang(t))]),
            lambda t: R * da * np.column_stack([-np.sin(ang(t)), np.cos(ang(t))]))


def _segment(p, q):
    return lambda t: p + t[:, None] * (q - p), lambda t: np.broadcast_to(q - p, (len(t), 2))


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


def cut_cell(itf, lo: np.ndarray, hi: np.ndarray, n: int, tensor: bool = True) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """``[(side, points, weights)]`` for the rectangle [lo, hi] (``tensor``: :func:`polygon_rule`'s)."""
    return cut_polygon(itf, np.array([lo, [hi[0], lo[1]], hi, [lo[0], hi[1]]], float), n, tensor=tensor)


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


def _tensor_rule(lo, hi, n):
    g, gw = gauss01(n)
    X, Y = np.meshgrid(lo[0] + g * (hi[0] - lo[0]), lo[1] + g * (hi[1] - lo[1]), indexing="ij")
    W = np.outer(gw, gw) * np.prod(hi - lo)
    return np.column_stack([X.ravel(), Y.ravel()]), W.ravel()


def tensor_cells(lo: np.ndarray, hi: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """n×n Gauss points of many cells at once: (C·n², 2) points and weights."""
    g, gw = gauss01(n)
    size = hi - lo
    gx, gy = np.meshgrid(g, g, indexing="ij")
    pts = lo[:, None, :] + np.stack([gx.ravel(), gy.ravel()], axis=-1)[None] * size[:, None, :]
    w = np.outer(gw, gw).ravel()[None] * np.prod(size, axis=1)[:, None]
    return pts.reshape(-1, 2), w.ravel()


# ----- lines: Γ and the outer boundary --------------------------------------

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


# ----- many squares at once ---------------------------------------------------
#
# :func:`cut_cell` of every axis-aligned cell of a grid, by a line or a
# circle, as array operations over the cells (the rim and Γ cells of
# :func:`contactcore.quadrature.volume_rule`).  The same arithmetic, in the
# same order, as :func:`cut_cell`'s scalar path: each point and weight is the
# bits :func:`cut_cell` gives (a test compares them).  A cell whose cut is
# not the plain one (no crossing, or two crossings on two different edges
# fanned from a corner), or whose decision lies within
# :data:`~contactcore.tolerances.CUT_BATCH_MARGIN` of a threshold, is left
# to :func:`cut_cell`.


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
