"""A profile's geometry along its parameter ``s`` (docs/scenes.md,
"Profiles and their samples"): a segment's ``s`` is the arc length from
its start; a straight Γ's, the arc length from where Γ enters the domain
along its tangent; a circular Γ's, the polar angle in rad (or the arc
length ``R θ``) anticlockwise from +x about its centre.

Contract: :func:`geometry` returns a :class:`Line` or a :class:`Circle`:
``span`` (``s`` runs from 0 to it), ``per_length`` (``s``'s units per
length unit: 1, or 1/R for an angle), ``periodic``, ``points(s)`` (the
points at ``s``, shape (n, 2)) and ``parameter(xy)`` (the ``s`` of points
projected onto the profile, and their distance off it);
:func:`taken_as` says in words what ``s`` was taken as.  No check: a
profile the scene lacks is the caller's to refuse.
"""
from __future__ import annotations

import numpy as np

from contactcore import Scene
from contactcore.geometry import CircleInterface
from contactcore.scene import LineProfile


class Line:
    """A profile's geometry: ``s`` from ``a`` along the segment to ``b``."""

    periodic = False

    def __init__(self, a, b):
        self.a, self.b = np.asarray(a, float), np.asarray(b, float)
        self.length = float(np.linalg.norm(self.b - self.a))
        self.span = self.length
        self.per_length = 1.0  # s units per length unit

    def points(self, s):
        return self.a + (np.asarray(s, float) / self.length)[:, None] * (self.b - self.a)

    def parameter(self, xy):
        t = (self.b - self.a) / self.length
        d = np.asarray(xy, float) - self.a
        s = d @ t
        return s, np.abs(d @ np.array([-t[1], t[0]]))


class Circle:
    """A circular Γ: ``s`` the polar angle (rad) or the arc length ``R θ``,
    anticlockwise from +x about the centre."""

    periodic = True

    def __init__(self, itf: CircleInterface, angle: bool):
        self.itf, self.radius = itf, float(itf.radius)
        self.per_length = 1.0 / self.radius if angle else 1.0
        self.span = 2 * np.pi * (1.0 if angle else self.radius)

    def points(self, s):
        return self.itf.points_at_angles(np.asarray(s, float) / (self.per_length * self.radius))

    def parameter(self, xy):
        d = np.asarray(xy, float) - np.asarray(self.itf.centre, float)
        theta = np.mod(np.arctan2(d[:, 1], d[:, 0]), 2 * np.pi)
        return theta * self.per_length * self.radius, np.abs(np.hypot(d[:, 0], d[:, 1]) - self.radius)


def geometry(scene: Scene, profile):
    """The geometry along which ``profile``'s ``s`` runs (docs/scenes.md,
    "Profiles and their samples")."""
    if isinstance(profile, LineProfile):
        return Line(profile.start, profile.end)
    itf = scene.interface
    if isinstance(itf, CircleInterface):
        return Circle(itf, profile.parameter == "angle")
    a, b = itf.chord(scene.domain)
    return Line(a, b)


def taken_as(scene: Scene, profile) -> str:
    """What a profile's ``s`` was taken as (unit, origin, direction), for
    an outside answer that gave ``s`` alone."""
    length, geo = scene.units.length, geometry(scene, profile)
    if isinstance(geo, Circle):
        c = ", ".join(f"{v:.4g}" for v in geo.itf.centre)
        what = "the polar angle in rad" if geo.per_length != 1.0 else f"the arc length R θ in {length}"
        return (f"s was taken as {what}, from +x anticlockwise about Γ's centre ({c}) {length}, 0 to "
                f"{geo.span:.4g}")
    a, b = (", ".join(f"{v:.4g}" for v in end) for end in (geo.a, geo.b))
    along = "along Γ from Γ's first end" if not isinstance(profile, LineProfile) else "from the profile's start"
    return f"s was taken as the arc length in {length} {along} ({a}) towards ({b}), 0 to {geo.span:.4g}"
