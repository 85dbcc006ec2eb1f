"""A scene's rules, checked in one order (:func:`validate`): each part of
the kind its field holds, then the scene's own fields (name, plane, units,
increments, follow_path, h), then its parts by the ``check_*`` modules
beside this one (geometry, law, materials, supports, pins, loads,
profiles).  The first invalid field is refused with a
:class:`~contactcore.errors.SceneError` whose message starts with the
field's dotted path.

Checks a :class:`~contactcore.scene.Scene` built in code or read from a
file; this module does not import it (the Scene imports this module)."""
from __future__ import annotations

from ..errors import SceneError
from ..geometry import CircleInterface, Disc, LevelSetInterface, LineInterface, Rectangle
from .check_geometry import check_domain, check_interface
from .check_loads import check_loads, check_pins, check_supports
from .check_materials import check_materials
from .check_profiles import check_profiles
from .loads import LOADS, Pin, Support
from .materials import Material
from .profiles import InterfaceProfile, LineProfile
from .resolution import check_resolution
from .units import MAX_UNIT_NAME, Units
from .values import check_file_name
from .vocabulary import BODIES


def validate(scene: "Scene") -> None:
    """Raise :class:`SceneError` at the first invalid field of ``scene``."""
    _check_kinds(scene)
    if not isinstance(scene.name, str) or not scene.name:
        raise SceneError("name", "must be a non-empty string")
    check_file_name(scene.name, "name")
    if scene.plane not in ("stress", "strain"):
        raise SceneError("plane", f"must be 'stress' or 'strain' (got {scene.plane!r})")
    _check_units(scene.units)
    check_domain(scene.domain)
    check_interface(scene)
    if scene.law is not None:  # a law built in code meets the file's rules (a negative k_N was refused late, as a rigid mode)
        type(scene.law).from_params({k: getattr(scene.law, k) for k in scene.law.parameters}, "interface.law")
    check_materials(scene)
    if isinstance(scene.increments, bool) or not isinstance(scene.increments, int) or scene.increments < 1:
        raise SceneError("increments", f"must be an integer >= 1 (got {scene.increments!r})")
    if not isinstance(scene.follow_path, bool):
        raise SceneError("follow_path", f"must be true or false (got {scene.follow_path!r})")
    if scene.h is not None:
        check_resolution(scene, scene.h, "h")
    check_supports(scene)
    check_pins(scene)
    check_loads(scene)
    check_profiles(scene)


def _check_units(units: Units) -> None:
    """Each unit name a non-empty printable string (no newline) of at most
    :data:`MAX_UNIT_NAME` characters."""
    if not isinstance(units, Units):
        raise SceneError("units", f"must be a Units(length=..., stress=...) (got {units!r})")
    for key in ("length", "stress"):
        value = getattr(units, key)
        if not isinstance(value, str) or not value.strip() or not value.isprintable() \
                or len(value) > MAX_UNIT_NAME:
            raise SceneError(f"units.{key}", f"must be a unit's name: a non-empty string of at most "
                             f"{MAX_UNIT_NAME} characters on one line (got {value!r})")


#: What each of a Scene's parts must be, and how a message names it.
_KINDS = {"domain": ((Rectangle, Disc), "a Rectangle or a Disc"),
          "interface": ((LineInterface, CircleInterface, LevelSetInterface),
                        "a LineInterface, a CircleInterface or a LevelSetInterface")}
_SEQUENCES = {"supports": ((Support,), "Support"), "pins": ((Pin,), "Pin"),
              "loads": (None, None),  # the registered loads (contactcore.scene.loads.LOADS) when checked
              "profiles": ((LineProfile, InterfaceProfile), "LineProfile or InterfaceProfile")}


def _check_kinds(scene: "Scene") -> None:
    """Each part of ``scene`` of the kind its field holds (a scene built in
    code, or ``with_changes(law="x")``, reached an AttributeError deep in
    the checks below, grader9 #11)."""
    for name, (kinds, what) in _KINDS.items():
        if not isinstance(getattr(scene, name), kinds):
            raise SceneError(name, f"must be {what} (got {getattr(scene, name)!r})")
    if not isinstance(scene.materials, dict):
        raise SceneError("materials", f"must be a dict of body ({', '.join(BODIES)}) to Material "
                                      f"(got {scene.materials!r})")
    for body, material in scene.materials.items():
        if not isinstance(material, Material):
            raise SceneError(f"materials.{body}", f"must be a Material(E=..., nu=...) (got {material!r})")
    law = scene.law
    if law is not None and not (callable(getattr(type(law), "from_params", None))
                                and isinstance(getattr(law, "parameters", None), tuple)):
        raise SceneError("interface.law", f"must be an interface law, as contactcore.make_law({{\"type\": ...}}) "
                                          f"builds (got {law!r})")
    for name, (kinds, what) in _SEQUENCES.items():
        if name == "loads":
            kinds = tuple(LOADS.values())
            what = ", ".join(c.__qualname__ for c in kinds[:-1]) + f" or {kinds[-1].__qualname__}"
        items = getattr(scene, name)
        if not isinstance(items, (tuple, list)):
            raise SceneError(name, f"must be a tuple of {what} (got {items!r})")
        for i, item in enumerate(items):
            if not isinstance(item, kinds):
                raise SceneError(f"{name}[{i}]", f"must be a {what} (got {item!r})")
