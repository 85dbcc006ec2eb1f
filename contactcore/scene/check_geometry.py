"""The rules of a scene's geometry: a domain of positive, finite size
(:func:`check_domain`), and a Γ that cuts it into two bodies any method
can resolve (:func:`check_interface`)."""
from __future__ import annotations

from .. import tolerances as tol
from ..errors import SceneError, quoted
from ..geometry import Domain, LevelSetInterface, LineInterface, Rectangle
from .values import finite


def check_domain(domain: Domain) -> None:
    """A rectangle of finite corner and sides > 0, or a disc of radius > 0."""
    if isinstance(domain, Rectangle):
        for k, v in zip("xy", domain.size):
            if finite(v, f"domain.size.{k}") <= 0:
                raise SceneError("domain.size", f"the rectangle's sides must be > 0 (got {list(domain.size)})")
        for k, v in zip("xy", domain.corner):
            finite(v, f"domain.corner.{k}")
    else:
        if finite(domain.radius, "domain.radius") <= 0:
            raise SceneError("domain.radius", f"must be > 0 (got {domain.radius!r})")


def _point(p) -> str:
    return f"({p[0]:g}, {p[1]:g})"


def _extent(domain) -> str:
    """Where ``domain`` lies, for a refusal: a rectangle's corners, a disc's centre and radius."""
    if isinstance(domain, Rectangle):
        return f"x from {domain.corner[0]:g} to {domain.corner[0] + domain.size[0]:g}, " \
               f"y from {domain.corner[1]:g} to {domain.corner[1] + domain.size[1]:g}"
    return f"a disc of centre {_point(domain.centre)} and radius {domain.radius:g}"


def check_interface(scene: "Scene") -> None:
    """A line that cuts off no less than MIN_BODY_AREA_FRACTION of the
    domain's area on either side, a level set that changes sign in it, or
    a circle of radius > 0 strictly inside it."""
    itf, dom, L = scene.interface, scene.domain, scene.length_scale
    if isinstance(itf, LineInterface):
        if itf.chord(dom) is None:
            raise SceneError("interface", f"the line through {_point(itf.point)} with normal {_point(itf.normal)} "
                                          f"misses the domain ({_extent(dom)})")
        a_minus = itf.minus_area(dom)
        smaller = min(a_minus, dom.area - a_minus) / dom.area
        if smaller <= tol.MIN_BODY_AREA_FRACTION:
            touches = smaller <= tol.GEOMETRY ** 2  # an area of round-off
            raise SceneError("interface", "the line only touches the domain: one body would be empty" if touches
                             else f"the line cuts off a body of {quoted(smaller, tol.MIN_BODY_AREA_FRACTION, least=2)} of the domain's area, below the "
                                  f"{tol.MIN_BODY_AREA_FRACTION:g} any method can resolve")
    elif isinstance(itf, LevelSetInterface):
        a_minus = itf.minus_area(dom)
        if min(a_minus, dom.area - a_minus) <= tol.MIN_BODY_AREA_FRACTION * dom.area:
            raise SceneError("interface", "the level set does not change sign in the domain: Γ misses it")
    else:
        if finite(itf.radius, "interface.radius") <= 0:
            raise SceneError("interface.radius", f"must be > 0 (got {itf.radius!r})")
        clearance = float(dom.distance_to_boundary([itf.centre])[0]) - itf.radius
        if clearance <= tol.GEOMETRY * L:
            where = "misses the domain" if not dom.contains([itf.centre])[0] and clearance < -2 * itf.radius \
                else "is not strictly inside the domain (it must not touch or cross the outer boundary)"
            raise SceneError("interface", f"the circle {where}")
