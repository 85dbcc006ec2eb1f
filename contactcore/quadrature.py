"""The scene's quadrature on its exact geometry: the domain split along Γ,
its named boundaries, and Γ itself.

Background cells of size ≈ h cover the domain; a cell that Γ (or a disc's
rim) crosses is integrated piecewise by :mod:`contactcore.cutcell`'s fans,
so every quadrature point knows its body exactly and

    ∫_{Ω_b} f dx ≈ Σ_{q: body(q) = b} w_q f(x_q)

holds to the rule's order whatever a method's mesh does.  EFGM integrates
its weak form with these rules (the paper's background cells) and
:mod:`verification.norms` measures every method's error with them, so
neither depends on the other.  numpy only.
"""
from __future__ import annotations

import numpy as np

from contactcore.scene import Scene
from contactcore.cutcell import Rule, curve_rule, cut_cell, cut_squares, edge_crossings, tensor_cells
from contactcore.geometry import CircleInterface, Disc, Rectangle, domain_cells


def background_cells(scene: Scene, h: float) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper corners (C, 2) of square-ish cells of size ≈ h covering
    the scene's domain (:func:`contactcore.geometry.domain_cells`)."""
    return domain_cells(scene.domain, h)


def _outer_circle(scene: Scene) -> CircleInterface | None:
    dom = scene.domain
    return CircleInterface(dom.centre, dom.radius) if isinstance(dom, Disc) else None


#: Quad-tree splits of a background cell that both Γ and a disc's rim
#: cross (where a straight Γ leaves the disc), until each piece is crossed
#: by one of them; a piece still crossed by both after the last split reads
#: each Gauss point's body from its side of Γ, an error in area of at most
#: the piece, 4^-RIM_SPLITS of the cell (the − body of a straight Γ across
#: a disc: 3e-10 of its area at 10 cells across, measured 2026-11-27).
RIM_SPLITS = 10


#: Whether a whole cell near Γ or the rim (one they come near but do not
#: cut) takes the n×n tensor rule here, as a plain cell does, or the fans
#: of its two triangles (2n² points) that it took while
#: contactcore.cutcell.polygon_rule's rectangle test held for no rectangle.
#: Kept on the fans, by choice: this rule integrates efgm's stiffness (MLS
#: shape functions, rational: no rule is exact) and the estimates' and
#: norms' integrands (fields of other meshes, a mask about singular points),
#: so the switch moves their answers by their quadrature error, not by
#: round-off, and did not shrink it (2026-11-28: efgm's σ against a rule of
#: 3× the points per direction, scenes A-C at h = 0.05, P1/P2: rms error
#: 9.7e-5 → 1.3e-4 on A P1, max 1.3e-3 → 1.7e-3 on B P1, 5.2e-5 → 4.0e-5
#: rms on B P2, C within 5 %; the interface patches' errors moved both
#: ways; docs/error-estimates-log.md).  xfem's cells take the tensor rule
#: (its integrands are polynomials on its axis-aligned cells).
WHOLE_CELL_TENSOR = False


def _centre_value(level_set, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each cell's (lower ``lo``, upper ``hi`` corners, (C, 2)) level-set
    value at its centre and its half-diagonal: the cell may meet the curve
    where |value| < half, lies on its − side where value ≤ −half."""
    return level_set.phi((lo + hi) / 2), np.linalg.norm(hi - lo, axis=1) / 2


def _near(level_set, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Whether each cell may meet the level set's curve (:func:`_centre_value`)."""
    value, half = _centre_value(level_set, lo, hi)
    return np.abs(value) < half


def _gamma_cell(scene: Scene, lo: np.ndarray, hi: np.ndarray, n: int) -> list[Rule]:
    """A cell inside the domain that Γ may cross: its pieces on each side."""
    return [Rule(p, wt, np.full(len(wt), int(s > 0))) for s, p, wt in cut_cell(scene.interface, lo, hi, n, WHOLE_CELL_TENSOR)]


def _quarters(lo: np.ndarray, mid: np.ndarray, hi: np.ndarray):
    """The four quarters (lower, upper corners) of the cell [lo, hi] about ``mid``."""
    corners = [(lo, mid), ((mid[0], lo[1]), (hi[0], mid[1])), (mid, hi), ((lo[0], mid[1]), (mid[0], hi[1]))]
    return [(np.asarray(a, float), np.asarray(b, float)) for a, b in corners]


def _rim_cell(scene: Scene, outer, lo: np.ndarray, hi: np.ndarray, n: int, near_gamma: bool,
              depth: int = 0) -> list[Rule]:
    """A cell that a disc's rim crosses: its part inside the rim, each Gauss
    point's body from its side of Γ; where Γ comes within the cell too
    (``near_gamma``), split in four (up to :data:`RIM_SPLITS` times) and
    each quarter taken as the rim's, Γ's or neither's."""
    if not near_gamma or depth >= RIM_SPLITS:
        return [Rule(p, wt, (scene.interface.phi(p) >= 0).astype(int))
                for s, p, wt in cut_cell(outer, lo, hi, n, WHOLE_CELL_TENSOR) if s < 0]
    out = []
    for a, b in _quarters(lo, (lo + hi) / 2, hi):
        (rim,), (half,) = _centre_value(outer, a[None], b[None])
        if rim <= -half:
            out += _gamma_cell(scene, a, b, n)
        elif rim < half:
            out += _rim_cell(scene, outer, a, b, n, _near(scene.interface, a[None], b[None])[0], depth + 1)
    return out


def volume_rule(scene: Scene, h: float, n: int) -> Rule:
    """Gauss points of the domain with the body of each, Γ followed exactly.

    The cells that Γ or the rim crosses plainly are cut all at once
    (:func:`contactcore.cutcell.cut_squares`), the others one by one
    (:func:`_gamma_cell`, :func:`_rim_cell`); the points come in the order
    of the cells, plain cells first, as the cell-by-cell rule gives them."""
    lo, hi = background_cells(scene, h)
    centre = (lo + hi) / 2
    near_gamma = _near(scene.interface, lo, hi)
    outer = _outer_circle(scene)
    near_rim = _near(outer, lo, hi) if outer else np.zeros(len(lo), bool)
    plain = ~near_gamma & ~near_rim
    pts, w = tensor_cells(lo[plain], hi[plain], n)
    body = np.repeat((scene.interface.phi(centre[plain]) >= 0).astype(int), n * n)
    # (cell, slot) of each chunk's points: the cut cells' pieces are put in cell order
    points, weights, bodies, keys = [pts], [w], [body], [np.full(len(w), -1)]

    def add(cells, slot, p, wt, b):
        points.append(p.reshape(-1, 2))
        weights.append(wt.ravel())
        bodies.append(b.ravel())
        keys.append(np.repeat(cells * 4 + slot, wt.shape[1] if wt.ndim == 2 else 1))

    gamma_only = np.flatnonzero(near_gamma & ~near_rim)
    done, chunks = cut_squares(scene.interface, lo[gamma_only], hi[gamma_only], n, WHOLE_CELL_TENSOR)
    for cells, slot, side, p, wt in chunks:
        add(gamma_only[cells], slot, p, wt, np.broadcast_to((side > 0).astype(int)[:, None], wt.shape))
    left = list(gamma_only[~done])
    rim_only = np.flatnonzero(near_rim & ~near_gamma)
    if len(rim_only):
        done, chunks = cut_squares(outer, lo[rim_only], hi[rim_only], n, WHOLE_CELL_TENSOR)
        for cells, slot, side, p, wt in chunks:
            inside = side < 0
            if inside.any():
                q = p[inside]
                add(rim_only[cells[inside]], slot, q, wt[inside],
                    (scene.interface.phi(q.reshape(-1, 2)) >= 0).astype(int).reshape(wt[inside].shape))
        left += list(rim_only[~done])
    left += list(np.flatnonzero(near_rim & near_gamma))
    for c in left:
        rule = Rule.concatenate(_rim_cell(scene, outer, lo[c], hi[c], n, near_gamma[c]) if near_rim[c]
                                else _gamma_cell(scene, lo[c], hi[c], n))
        points.append(rule.points)
        weights.append(rule.weights)
        bodies.append(rule.bodies)
        keys.append(np.full(len(rule.weights), c * 4))
    # the plain cells' points (key −1, the lowest) first as they are, the rest sorted stably by key: the
    # order of a stable sort of all the keys, without sorting or gathering the plain cells' (most) points
    order = np.argsort(np.concatenate(keys[1:]), kind="stable") if len(keys) > 1 else np.zeros(0, int)
    rule = Rule(*(np.concatenate([a[0], np.concatenate(a[1:])[order]]) if len(a) > 1 else a[0]
                  for a in (points, weights, bodies)))
    keep = rule.weights > 0
    return rule if keep.all() else Rule(rule.points[keep], rule.weights[keep], rule.bodies[keep])


def _edge(scene: Scene, name: str):
    """End points of a rectangle edge, in the direction of +x (or +y)."""
    c = scene.domain.corners
    return {"bottom": (c[0], c[1]), "top": (c[3], c[2]), "left": (c[0], c[3]), "right": (c[1], c[2])}[name]


def boundary_rule(scene: Scene, name: str, h: float, n: int):
    """Gauss points on a named boundary: points, weights, outward normals,
    bodies; pieces of length ≤ h broken where Γ meets the boundary."""
    dom, itf = scene.domain, scene.interface
    if isinstance(dom, Rectangle):
        a, b = _edge(scene, name)
        breaks = edge_crossings(itf, a, b)
        pts, w, _ = curve_rule(lambda t: a + t[:, None] * (b - a), lambda t: np.broadcast_to(b - a, (len(t), 2)),
                               float(np.linalg.norm(b - a)), h, n, breaks)
        normals = np.tile(dom.outward_normal(name), (len(w), 1))
    else:
        c, R = np.asarray(dom.centre, float), dom.radius
        chord = itf.chord(dom) if not isinstance(itf, CircleInterface) else None
        breaks = [] if chord is None else list((np.arctan2(*(chord - c).T[::-1]) / (2 * np.pi)) % 1.0)
        ring = lambda t: c + R * np.column_stack([np.cos(2 * np.pi * t), np.sin(2 * np.pi * t)])  # noqa: E731
        pts, w, _ = curve_rule(ring, lambda t: 2 * np.pi * R * np.column_stack([-np.sin(2 * np.pi * t),
                                                                              np.cos(2 * np.pi * t)]),
                               2 * np.pi * R, h, n, breaks)
        normals = (pts - c) / R
    return pts, w, normals, scene.body_of(pts)


def interface_rule(scene: Scene, h: float, n: int):
    """Gauss points on Γ inside the domain: points, weights, normals."""
    itf = scene.interface
    if isinstance(itf, CircleInterface):
        R = itf.radius
        pts, w, _ = curve_rule(lambda t: itf.points_at_angles(2 * np.pi * t),
                               lambda t: 2 * np.pi * R * np.column_stack([-np.sin(2 * np.pi * t),
                                                                        np.cos(2 * np.pi * t)]),
                               2 * np.pi * R, h, n)
    else:
        a, b = itf.chord(scene.domain)
        pts, w, _ = curve_rule(lambda t: a + t[:, None] * (b - a), lambda t: np.broadcast_to(b - a, (len(t), 2)),
                               float(np.linalg.norm(b - a)), h, n)
    return pts, w, itf.normals(pts)
