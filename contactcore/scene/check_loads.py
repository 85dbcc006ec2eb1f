"""The rules of what holds and loads a scene: supports on named boundaries
holding the components they prescribe (:func:`check_supports`), pins
inside the domain (:func:`check_pins`), loads on named boundaries or
bodies (:func:`check_loads`), and each one's load path: increasing
integer increments up to the scene's ``increments``, finite factors."""
from __future__ import annotations

from ..errors import SceneError
from ..geometry import CircleInterface
from .loads import EDGE, Torque, load_contract, place_of
from .values import check_body, check_point_inside, finite
from .vocabulary import COMPONENTS


def check_supports(scene: "Scene") -> None:
    """Each support on a boundary of the domain, holding the components its
    non-zero values prescribe, with a valid path."""
    for i, sup in enumerate(scene.supports):
        _check_boundary(scene, sup.boundary, f"supports[{i}].boundary")
        _check_fix(sup.fix, f"supports[{i}].fix")
        for k, v in zip("xy", sup.value):
            finite(v, f"supports[{i}].value.{k}")
            if v != 0 and k not in sup.fix:
                raise SceneError(f"supports[{i}].value", f"gives u_{k} = {v:g}, but fix = {sup.fix!r} does not "
                                 f"hold u_{k}: add {k} to fix, or give 0")
        _check_path(scene, sup.path, f"supports[{i}].path")


def check_pins(scene: "Scene") -> None:
    """Each pin a point inside the domain, holding valid components."""
    for i, pin in enumerate(scene.pins):
        check_point_inside(scene, pin.point, f"pins[{i}].point")
        _check_fix(pin.fix, f"pins[{i}].fix")


def check_loads(scene: "Scene") -> None:
    """Each load on a boundary of the domain or in a body, as its class
    declares (:func:`~contactcore.scene.loads.place_of`; a torque: on the
    disc of a circular Γ), every declared parameter finite, with a valid
    path."""
    for i, load in enumerate(scene.loads):
        path = f"loads[{i}]"
        _check_path(scene, load.path, f"{path}.path")
        if place_of(load) == EDGE:
            _check_boundary(scene, load.boundary, f"{path}.boundary")
        else:
            check_body(load.body, f"{path}.body")
        for name in load_contract(type(load)):
            value = getattr(load, name)
            if isinstance(value, tuple):
                if len(value) != 2:
                    raise SceneError(f"{path}.{name}", f"must have 2 components (x, y), got {len(value)}")
                for k, v in zip("xy", value):
                    finite(v, f"{path}.{name}.{k}")
            else:
                finite(value, f"{path}.{name}")
        if isinstance(load, Torque) and (not isinstance(scene.interface, CircleInterface) or load.body != "minus"):
            raise SceneError(f"{path}.body", "a torque acts on the disc inside a circular interface: "
                             "it needs a circle interface and body = 'minus'")


def _check_boundary(scene: "Scene", name: str, path: str) -> None:
    """``name`` one of the domain's boundaries."""
    if name not in scene.domain.boundary_names:
        raise SceneError(path, f"no boundary named {name!r} on this domain "
                         f"(it has: {', '.join(scene.domain.boundary_names)})")


def _check_fix(fix: str, path: str) -> None:
    """``fix`` one of :data:`~contactcore.scene.vocabulary.COMPONENTS`."""
    if fix not in COMPONENTS:
        raise SceneError(path, f"must be one of {', '.join(COMPONENTS)} (got {fix!r})")


def _check_path(scene: "Scene", keys, path: str) -> None:
    """A load path: (increment, factor) pairs, increments strictly increasing
    integers in 0 … scene.increments, factors finite."""
    previous = -1
    for j, pair in enumerate(keys):
        where = f"{path}[{j}]"
        if not isinstance(pair, (tuple, list)) or len(pair) != 2:
            raise SceneError(where, f"must be a pair [increment, factor] (got {pair!r})")
        k, f = pair
        if isinstance(k, bool) or not isinstance(k, int) or not previous < k <= scene.increments:
            raise SceneError(where, f"the increment must be an integer in {previous + 1} … {scene.increments} "
                             f"(increasing, at most 'increments'); got {k!r}")
        finite(f, f"{where}[1]")
        previous = k
