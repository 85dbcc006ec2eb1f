"""Exact geometry of a scene: the outer domain and the interface Γ.

Γ is the zero level of a signed function φ, positive on the ``+`` body:

* straight line through ``p`` with unit normal ``n``: ``φ(x) = n·(x − p)``;
* circle of centre ``c`` and radius ``R`` (the disc inside is the ``−`` body):
  ``φ(x) = |x − c| − R``;
* any level set (built in code): ``φ`` and ``∇φ`` given as callables.

Whether Γ is straight is read from its geometry (``straight_in``), not from
the class it was given as: a level set whose zero set is a line is straight.

The unit normal ``n = ∇φ/|∇φ|`` points from − into +; the tangent is
``t = (n_y, −n_x)`` (docs/scenes.md).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import tolerances as tol
from .errors import SceneError

Point = tuple[float, float]

#: A normal whose length is within this of 1 was normalised already: doing
#: it again moves it by an ulp in a fifth of cases (a scene and its TOML
#: twin would differ).  A few ε.
UNIT_LENGTH_ROUNDOFF = 4 * 2.0 ** -52


def _as_points(x) -> np.ndarray:
    pts = np.asarray(x, dtype=float)
    return pts.reshape(-1, pts.shape[-1])[:, :2]


def tangent_of(normal: np.ndarray) -> np.ndarray:
    """``t = (n_y, −n_x)`` for each row of ``normal``."""
    return np.column_stack([normal[:, 1], -normal[:, 0]])


@dataclass(frozen=True)
class Rectangle:
    """Axis-aligned rectangle ``[x0, x0+a] × [y0, y0+b]``.

    Its boundaries are named ``left``, ``right``, ``bottom`` and ``top``.
    """

    corner: Point
    size: Point

    boundary_names = ("left", "right", "bottom", "top")

    @property
    def length_scale(self) -> float:
        """The diameter, used to scale geometric tolerances."""
        return float(np.hypot(*self.size))

    @property
    def area(self) -> float:
        return float(self.size[0] * self.size[1])

    @property
    def corners(self) -> np.ndarray:
        (x0, y0), (a, b) = self.corner, self.size
        return np.array([[x0, y0], [x0 + a, y0], [x0 + a, y0 + b], [x0, y0 + b]])

    def contains(self, x, tol: float = 0.0) -> np.ndarray:
        """True where ``x`` lies in the closed rectangle grown by ``tol``."""
        p = _as_points(x)
        (x0, y0), (a, b) = self.corner, self.size
        return ((p[:, 0] >= x0 - tol) & (p[:, 0] <= x0 + a + tol)
                & (p[:, 1] >= y0 - tol) & (p[:, 1] <= y0 + b + tol))

    def distance_to_boundary(self, x) -> np.ndarray:
        """Distance of interior points to the nearest edge (negative outside)."""
        p = _as_points(x)
        (x0, y0), (a, b) = self.corner, self.size
        return np.min([p[:, 0] - x0, x0 + a - p[:, 0], p[:, 1] - y0, y0 + b - p[:, 1]], axis=0)

    def boundary_of(self, x, tol: float) -> list[str]:
        """Names of the edges that the point ``x`` lies on (within ``tol``)."""
        (x0, y0), (a, b) = self.corner, self.size
        px, py = float(x[0]), float(x[1])
        names = []
        for name, d in (("left", px - x0), ("right", x0 + a - px), ("bottom", py - y0), ("top", y0 + b - py)):
            if abs(d) <= tol:
                names.append(name)
        return names

    def on_boundary(self, name: str, x, tol: float) -> np.ndarray:
        """True where the points lie on the named edge (within ``tol``)."""
        p = _as_points(x)
        (x0, y0), (a, b) = self.corner, self.size
        coord, value = {"left": (0, x0), "right": (0, x0 + a), "bottom": (1, y0), "top": (1, y0 + b)}[name]
        return np.abs(p[:, coord] - value) <= tol

    def outward_normal(self, name: str) -> np.ndarray:
        return {"left": np.array([-1.0, 0.0]), "right": np.array([1.0, 0.0]),
                "bottom": np.array([0.0, -1.0]), "top": np.array([0.0, 1.0])}[name]


@dataclass(frozen=True)
class Disc:
    """Disc of centre ``c`` and radius ``R``; its boundary is named ``outer``."""

    centre: Point
    radius: float

    boundary_names = ("outer",)

    @property
    def length_scale(self) -> float:
        return 2.0 * float(self.radius)

    @property
    def area(self) -> float:
        return float(np.pi * self.radius ** 2)

    def contains(self, x, tol: float = 0.0) -> np.ndarray:
        p = _as_points(x)
        return np.hypot(p[:, 0] - self.centre[0], p[:, 1] - self.centre[1]) <= self.radius + tol

    def distance_to_boundary(self, x) -> np.ndarray:
        p = _as_points(x)
        return self.radius - np.hypot(p[:, 0] - self.centre[0], p[:, 1] - self.centre[1])

    def boundary_of(self, x, tol: float) -> list[str]:
        return ["outer"] if abs(self.distance_to_boundary([x])[0]) <= tol else []

    def on_boundary(self, name: str, x, tol: float) -> np.ndarray:
        """True where the points lie on the rim (within ``tol``)."""
        return np.abs(self.distance_to_boundary(x)) <= tol


Domain = Rectangle | Disc


def domain_cells(domain: Domain, h: float) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper corners (C, 2) of square-ish cells of size ≈ h covering
    ``domain`` (for a disc: those that meet it): the background cells of
    EFGM's quadrature (:func:`contactcore.quadrature.background_cells`) and
    the small-strain check's samples (:meth:`contactcore.scene.Scene.small_strain_warnings`)."""
    if isinstance(domain, Rectangle):
        lo0, size = np.asarray(domain.corner, float), np.asarray(domain.size, float)
    else:
        lo0, size = np.asarray(domain.centre, float) - domain.radius, np.full(2, 2 * domain.radius)
    n = np.maximum(1, np.round(size / h)).astype(int)
    step = size / n
    I, J = np.meshgrid(np.arange(n[0]), np.arange(n[1]), indexing="ij")
    lo = lo0 + np.column_stack([I.ravel(), J.ravel()]) * step
    hi = lo + step
    if isinstance(domain, Disc):
        centre_dist = np.hypot(*((lo + hi) / 2 - np.asarray(domain.centre)).T)
        keep = centre_dist < domain.radius + np.linalg.norm(step) / 2
        lo, hi = lo[keep], hi[keep]
    return lo, hi


@dataclass(frozen=True)
class LineInterface:
    """Straight Γ through ``point`` with ``normal`` (from − into +), made a
    unit vector as a scene file's is."""

    point: Point
    normal: Point

    def __post_init__(self):
        if len(self.normal) != 2 or len(self.point) != 2:
            raise SceneError("interface", f"point and normal must have two components (got {self.point!r}, "
                             f"{self.normal!r})")
        normal = tuple(float(c) for c in self.normal)
        length = math.hypot(*normal)
        if not 0.0 < length < math.inf:
            raise SceneError("interface.normal", f"must be a finite non-zero vector (got {self.normal!r})")
        if abs(length - 1.0) > UNIT_LENGTH_ROUNDOFF:  # normalised once: again would move it by an ulp
            normal = (normal[0] / length, normal[1] / length)
        object.__setattr__(self, "point", tuple(float(c) for c in self.point))
        object.__setattr__(self, "normal", normal)

    def phi(self, x) -> np.ndarray:
        """φ (m,) at points ``x`` (one point (2,) or (m, 2), the scene's
        length unit): the signed distance to the line, negative on the −
        side, positive on the + side (where ``normal`` points)."""
        p = _as_points(x)
        return (p[:, 0] - self.point[0]) * self.normal[0] + (p[:, 1] - self.point[1]) * self.normal[1]

    def normals(self, x) -> np.ndarray:
        """The unit normal ``n`` (from − into +) at each point of ``x``
        ((m, 2)): the line's own, wherever the point lies."""
        return np.tile(np.asarray(self.normal, dtype=float), (len(_as_points(x)), 1))

    def signed_distance(self, x) -> np.ndarray:
        """The distance to Γ, signed as φ: φ itself (a unit normal)."""
        return self.phi(x)

    def straight_in(self, domain: Domain) -> bool:
        """A line is straight."""
        return True

    def chord(self, domain: Domain) -> np.ndarray | None:
        """The two end points of Γ ∩ domain, ordered along ``t``; None if it
        misses (equal points if it only touches a corner or a tangent).

        The parameter along the line is ``x = p + s t``.
        """
        p = np.asarray(self.point, dtype=float)
        t = tangent_of(np.asarray([self.normal], dtype=float))[0]
        if isinstance(domain, Rectangle):
            lo, hi = -np.inf, np.inf
            (x0, y0), (a, b) = domain.corner, domain.size
            for k, (mn, mx) in enumerate(((x0, x0 + a), (y0, y0 + b))):
                if abs(t[k]) < tol.AXIS_PARALLEL:  # Γ parallel to this axis
                    if not mn <= p[k] <= mx:
                        return None
                    continue
                s1, s2 = sorted(((mn - p[k]) / t[k], (mx - p[k]) / t[k]))
                lo, hi = max(lo, s1), min(hi, s2)
            if lo > hi:
                return None
        else:
            c = np.asarray(domain.centre, dtype=float)
            s0 = float(np.dot(c - p, t))
            d2 = domain.radius ** 2 - float(np.dot(c - p, self.normal)) ** 2
            if d2 < 0.0:
                return None
            lo, hi = s0 - np.sqrt(d2), s0 + np.sqrt(d2)
        return np.array([p + lo * t, p + hi * t])

    def minus_area(self, domain: Domain) -> float:
        """Area of the − side of the domain (exact for both domain types)."""
        if isinstance(domain, Rectangle):
            return polygon_area(clip_halfplane(domain.corners, self))
        R = domain.radius
        d = float(self.phi([domain.centre])[0])  # signed distance of the centre
        d = np.clip(d, -R, R)
        segment = R * R * np.arccos(d / R) - d * np.sqrt(R * R - d * d)
        return float(segment)


@dataclass(frozen=True)
class CircleInterface:
    """Circular Γ; the disc inside is the − body, ``n`` points outwards."""

    centre: Point
    radius: float

    def phi(self, x) -> np.ndarray:
        """φ (m,) at points ``x`` (one point (2,) or (m, 2), the scene's
        length unit): distance to the centre minus the radius, negative
        inside (the − body), positive outside."""
        p = _as_points(x)
        return np.hypot(p[:, 0] - self.centre[0], p[:, 1] - self.centre[1]) - self.radius

    def normals(self, x) -> np.ndarray:
        """The unit normal ``n`` (outwards, from − into +) at each point of
        ``x`` ((m, 2)): the radial direction through the point, on Γ or off
        it; the centre itself has none (0/0 gives NaN, not refused)."""
        p = _as_points(x)
        d = p - np.asarray(self.centre, dtype=float)
        return d / np.linalg.norm(d, axis=1)[:, None]

    def signed_distance(self, x) -> np.ndarray:
        """The distance to Γ, signed as φ: φ itself."""
        return self.phi(x)

    def straight_in(self, domain: Domain) -> bool:
        """A circle is curved."""
        return False

    def points_at_angles(self, theta: np.ndarray) -> np.ndarray:
        """The points (m, 2) of Γ at polar angles ``theta`` (m,), in
        radians from the +x axis about the centre, anticlockwise."""
        return np.column_stack([self.centre[0] + self.radius * np.cos(theta),
                                self.centre[1] + self.radius * np.sin(theta)])

    def minus_area(self, domain: Domain) -> float:
        return float(np.pi * self.radius ** 2)


#: LevelSetInterface.points_in looks for Γ on this many lines each way across
#: the domain's bounding box, sampled at this many intervals (a piece of Γ
#: between two lines and two samples, 1/32 of the box across, is missed),
#: and bisects each sign change this many times (2^-52 of an interval:
#: round-off).
GAMMA_SEARCH_LINES = 32
GAMMA_SEARCH_SAMPLES = 64
GAMMA_BISECTIONS = 52


@dataclass(frozen=True)
class LevelSetInterface:
    """Γ = {φ = 0} for any smooth φ given as callables (numpy, vectorised):
    ``phi(points (m, 2)) -> (m,)`` and ``grad(points) -> (m, 2)``, positive
    on the + body.  Built in code only (a TOML file names lines and
    circles); only methods that work on a mesh ignoring Γ (XFEM) take it.
    """

    phi_fn: object
    grad_fn: object

    def phi(self, x) -> np.ndarray:
        """The user's φ at points ``x`` (one point (2,) or (m, 2)) as floats:
        negative on the − body, positive on the +; not checked here."""
        return np.asarray(self.phi_fn(_as_points(x)), float)

    def normals(self, x) -> np.ndarray:
        """``∇φ/|∇φ|`` at each point of ``x`` ((m, 2)): the unit normal from
        − into +; where ∇φ = 0 it is NaN (not refused here)."""
        g = np.asarray(self.grad_fn(_as_points(x)), float).reshape(-1, 2)
        return g / np.linalg.norm(g, axis=1)[:, None]

    def signed_distance(self, x) -> np.ndarray:
        """The distance to Γ, signed as φ, to first order: ``φ/|∇φ|`` (a
        φ scaled by any factor gives the same)."""
        p = _as_points(x)
        with np.errstate(divide="ignore"):  # |∇φ| = 0 (a centre of φ = r² − R²): infinitely far, to first order
            return self.phi(p) / np.linalg.norm(np.asarray(self.grad_fn(p), float).reshape(-1, 2), axis=1)

    def points_in(self, domain: Domain) -> np.ndarray:
        """Points of Γ inside ``domain`` (m, 2): where φ changes sign along
        GAMMA_SEARCH_LINES lines each way across the domain's bounding box
        (GAMMA_SEARCH_SAMPLES samples each), bisected to round-off."""
        lo, hi = _bounding_box(domain)
        u = lo[None] + (np.arange(GAMMA_SEARCH_LINES)[:, None] + 0.5) / GAMMA_SEARCH_LINES * (hi - lo)[None]
        a = np.concatenate([np.column_stack([np.full(len(u), lo[0]), u[:, 1]]),
                            np.column_stack([u[:, 0], np.full(len(u), lo[1])])])
        b = np.concatenate([np.column_stack([np.full(len(u), hi[0]), u[:, 1]]),
                            np.column_stack([u[:, 0], np.full(len(u), hi[1])])])
        t = np.linspace(0.0, 1.0, GAMMA_SEARCH_SAMPLES + 1)
        side = self.phi((a[:, None] + t[None, :, None] * (b - a)[:, None]).reshape(-1, 2)).reshape(len(a), -1) > 0
        line, k = np.nonzero(side[:, :-1] != side[:, 1:])
        a, d, before = a[line], (b - a)[line], side[line, k]
        t_lo, t_hi = t[k], t[k + 1]
        for _ in range(GAMMA_BISECTIONS):
            mid = (t_lo + t_hi) / 2
            same = (self.phi(a + mid[:, None] * d) > 0) == before
            t_lo, t_hi = np.where(same, mid, t_lo), np.where(same, t_hi, mid)
        x = a + t_hi[:, None] * d
        return x[domain.contains(x)]

    def straight_in(self, domain: Domain) -> bool:
        """Whether Γ ∩ ``domain`` is straight: its unit normal is the same,
        within STRAIGHT_NORMAL, at every point :meth:`points_in` finds (a
        connected curve of constant normal is a segment; one φ cannot
        keep its normal across two parallel lines, its sign alternates).
        Fewer than two points found: Γ is too small to tell, curved."""
        points = self.points_in(domain)
        if len(points) < 2:
            return False
        n = self.normals(points)
        return bool(np.all(np.isfinite(n)) and np.max(np.linalg.norm(n - n[0], axis=1)) <= tol.STRAIGHT_NORMAL)

    def minus_area(self, domain: Domain, samples: int = 400) -> float:
        """The − side's area, estimated on a grid of samples² points."""
        lo, hi = _bounding_box(domain)
        g = (np.arange(samples) + 0.5) / samples
        X, Y = np.meshgrid(lo[0] + g * (hi[0] - lo[0]), lo[1] + g * (hi[1] - lo[1]))
        pts = np.column_stack([X.ravel(), Y.ravel()])
        inside = domain.contains(pts)
        return float(np.sum(inside & (self.phi(pts) < 0)) * np.prod(hi - lo) / samples ** 2)


def _bounding_box(domain: Domain) -> tuple[np.ndarray, np.ndarray]:
    if isinstance(domain, Rectangle):
        return np.asarray(domain.corner, float), np.add(domain.corner, domain.size)
    c = np.asarray(domain.centre, float)
    return c - domain.radius, c + domain.radius


Interface = LineInterface | CircleInterface | LevelSetInterface


def clip_halfplane(poly: np.ndarray, line: LineInterface) -> np.ndarray:
    """Sutherland–Hodgman clip of a convex polygon to the side ``φ <= 0``."""
    phi = line.phi(poly)
    out = []
    for i in range(len(poly)):
        a, b, fa, fb = poly[i], poly[(i + 1) % len(poly)], phi[i], phi[(i + 1) % len(poly)]
        if fa <= 0:
            out.append(a)
        if (fa < 0 < fb) or (fb < 0 < fa):
            out.append(a + fa / (fa - fb) * (b - a))
    return np.array(out) if out else np.zeros((0, 2))


def polygon_area(poly: np.ndarray):
    """The area of a polygon (n, 2), or of each of a stack (…, n, 2), its
    vertices in order (shoelace formula); fewer than 3 vertices: 0."""
    poly = np.asarray(poly, float)
    if poly.shape[-2] < 3:
        return np.zeros(poly.shape[:-2]) if poly.ndim > 2 else 0.0
    x, y = poly[..., 0], poly[..., 1]
    area = 0.5 * np.abs(np.sum(x * np.roll(y, -1, axis=-1) - np.roll(x, -1, axis=-1) * y, axis=-1))
    return float(area) if poly.ndim == 2 else area


def polygon_centroid(poly: np.ndarray) -> np.ndarray:
    """The centroid of a polygon (n, 2), its vertices in order:
    ``Σ (p_i + p_{i+1}) (p_i × p_{i+1}) / (6 A)``, ``A`` its signed area."""
    p, q = poly, np.roll(poly, -1, axis=0)
    cross = p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]
    return ((p + q) * cross[:, None]).sum(axis=0) / (3.0 * cross.sum())
