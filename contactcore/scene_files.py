"""Scenes in files: a TOML file (schema in docs/scenes.md) to a validated
:class:`~contactcore.scene.Scene` and back.

Reading checks every key (unknown keys are refused, each value against its
kind) and then the scene's own rules (:func:`contactcore.scene.validate`);
an error is a :class:`SceneError` whose message starts with the field's
dotted path.  :func:`scene_toml` writes the text :func:`load_scene` reads
back, so a run's ``scene.toml`` is the scene it solved.
"""
from __future__ import annotations

import dataclasses
import json
import tomllib
from importlib import resources
from pathlib import Path

from .errors import SceneError, os_problem
from .spelling import closest as _closest
from .geometry import CircleInterface, Disc, Domain, Interface, LevelSetInterface, LineInterface, Rectangle
from .exact import default_enforcement
from .enforcement import make_law
from .laws import InterfaceLaw
from .scene import (BODIES, BodyForce, InterfaceProfile, LineProfile, Load, Material, Pin, Pressure, Profile, Scene, Support,
                    Torque, Traction, Units, finite)



class _Table:
    """A TOML table being read: typed access by key, unknown keys rejected."""

    def __init__(self, data, path: str):
        if not isinstance(data, dict):
            raise SceneError(path or "scene", "must be a table")
        self.data, self.path, self.used = data, path, set()

    def _key(self, key: str) -> str:
        return f"{self.path}.{key}" if self.path else key

    def get(self, key: str, kind: str, default=..., choices=None):
        """The value of ``key`` checked against ``kind``: number, int, str,
        vector (two numbers), numbers, strings, bool, table, tables."""
        self.used.add(key)
        path = self._key(key)
        if key not in self.data:
            if default is ...:
                given = _closest(key, set(self.data) - self.used)
                raise SceneError(path, f"missing (is {given!r}, given, a misspelling of it?)" if given else "missing")
            return default
        value = self.data[key]
        if kind == "number":
            value = finite(value, path)
        elif kind == "int":
            if isinstance(value, bool) or not isinstance(value, int):
                raise SceneError(path, f"must be an integer (got {value!r})")
        elif kind == "bool":
            if not isinstance(value, bool):
                raise SceneError(path, f"must be true or false (got {value!r})")
        elif kind == "str":
            if not isinstance(value, str):
                raise SceneError(path, f"must be a string (got {value!r})")
        elif kind == "vector":
            if not isinstance(value, list) or len(value) != 2:
                raise SceneError(path, f"must be a list of two numbers (got {value!r})")
            value = tuple(finite(v, f"{path}[{i}]") for i, v in enumerate(value))
        elif kind == "ints":
            if not isinstance(value, list) or len(value) != 2 or not all(
                    isinstance(v, int) and not isinstance(v, bool) and v > 0 for v in value):
                raise SceneError(path, f"must be a list of two positive integers (got {value!r})")
            value = tuple(value)
        elif kind == "strings":
            if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
                raise SceneError(path, f"must be a list of strings (got {value!r})")
            value = tuple(value)
        elif kind == "table":
            value = _Table(value, path)
        elif kind == "path":
            if not isinstance(value, list) or not value:
                raise SceneError(path, f"must be a non-empty list of [increment, factor] pairs (got {value!r})")
            value = tuple(tuple(v) if isinstance(v, list) else v for v in value)
        elif kind == "tables":
            if not isinstance(value, list):
                raise SceneError(path, "must be an array of tables ([[...]] in TOML)")
            value = [_Table(v, f"{path}[{i}]") for i, v in enumerate(value)]
        if choices is not None and value not in choices:
            raise SceneError(path, f"must be one of {', '.join(map(str, choices))} (got {value!r})")
        return value

    def done(self) -> None:
        """Reject any key that was not read: a typo must not pass silently."""
        unknown = sorted(set(self.data) - self.used)
        if unknown:
            known = _closest(unknown[0], self.used - set(self.data))
            given = None if known else _closest(unknown[0], self.used & set(self.data))
            hint = (f" (did you mean {known!r}?)" if known
                    else f" (like {given!r}, which is given too)" if given else "")
            raise SceneError(self._key(unknown[0]), f"unknown key{hint}")


def _read_domain(t: _Table) -> Domain:
    kind = t.get("type", "str", choices=("rectangle", "disc"))
    if kind == "rectangle":
        domain = Rectangle(t.get("corner", "vector", (0.0, 0.0)), t.get("size", "vector"))
    else:
        domain = Disc(t.get("centre", "vector"), t.get("radius", "number"))
    t.done()
    return domain


def _read_interface(t: _Table) -> tuple[Interface, InterfaceLaw]:
    kind = t.get("type", "str", choices=("line", "circle"))
    if kind == "line":
        itf = LineInterface(t.get("point", "vector"), t.get("normal", "vector"))  # the normal made a unit vector
    else:
        itf = CircleInterface(t.get("centre", "vector"), t.get("radius", "number"))
    law_table = t.get("law", "table")
    law_table.used = set(law_table.data)  # the law checks its own keys
    law = make_law(law_table.data, law_table.path)
    t.done()
    return itf, law


def _read_materials(t: _Table) -> dict[str, Material]:
    mats = {}
    for body in BODIES:
        m = t.get(body, "table")
        mats[body] = Material(m.get("E", "number"), m.get("nu", "number"))
        m.done()
    t.done()
    return mats


def _read_units(t: _Table | None) -> Units:
    """The ``[units]`` table's names (labels only), each defaulting to SI's;
    :func:`contactcore.scene.validate` checks them."""
    if t is None:
        return Units()
    units = Units(**{f.name: t.get(f.name, "str", f.default) for f in dataclasses.fields(Units)})
    t.done()
    return units


def _read_support(t: _Table) -> Support:
    s = Support(t.get("boundary", "str"), t.get("fix", "str", "xy"), t.get("value", "vector", (0.0, 0.0)),
                t.get("path", "path", ()))
    t.done()
    return s


def _read_pin(t: _Table) -> Pin:
    p = Pin(t.get("point", "vector"), t.get("fix", "str", "xy"))
    t.done()
    return p


def _read_load(t: _Table) -> Load:
    kind = t.get("type", "str", choices=("traction", "pressure", "body_force", "torque"))
    path = t.get("path", "path", ())
    if kind == "traction":
        load = Traction(t.get("boundary", "str"), t.get("value", "vector"), path)
    elif kind == "pressure":
        load = Pressure(t.get("boundary", "str"), t.get("value", "number"), path)
    elif kind == "body_force":
        load = BodyForce(t.get("body", "str"), t.get("value", "vector"), path)
    else:
        load = Torque(t.get("body", "str", "minus"), t.get("torque", "number"), path)
    t.done()
    return load


def _read_profile(t: _Table) -> Profile:
    kind = t.get("type", "str", choices=("line", "interface"))
    common = dict(id=t.get("id", "str"), quantities=t.get("quantities", "strings"),
                  side=t.get("side", "str", "plus"), title=t.get("title", "str", ""))
    if kind == "line":
        prof = LineProfile(start=t.get("start", "vector"), end=t.get("end", "vector"), **common)
    else:
        prof = InterfaceProfile(parameter=t.get("parameter", "str", None), **common)  # None: Γ's own (Scene)
    t.done()
    return prof


def scene_from_dict(data: dict) -> Scene:
    """Build and validate a scene from the parsed contents of a TOML file."""
    t = _Table(data, "")
    interface, law = _read_interface(t.get("interface", "table"))
    paper = {}
    paper_t = t.get("paper", "table", None)
    if paper_t is not None:
        paper = {k: paper_t.get(k, "ints", None) for k in ("xfem_cells", "efgm_nodes")}
        paper = {k: v for k, v in paper.items() if v is not None}
        paper_t.done()
    scene = Scene(
        name=t.get("name", "str"),
        title=t.get("title", "str", ""),
        plane=t.get("plane", "str", "stress"),
        h=t.get("h", "number", None),
        increments=t.get("increments", "int", 1),
        follow_path=t.get("follow_path", "bool", False),
        domain=_read_domain(t.get("domain", "table")),
        interface=interface,
        law=law,
        materials=_read_materials(t.get("materials", "table")),
        supports=tuple(_read_support(s) for s in t.get("supports", "tables", [])),
        pins=tuple(_read_pin(p) for p in t.get("pins", "tables", [])),
        loads=tuple(_read_load(x) for x in t.get("loads", "tables", [])),
        profiles=tuple(_read_profile(p) for p in t.get("profiles", "tables", [])),
        paper=paper,
        units=_read_units(t.get("units", "table", None)),
    )
    t.done()
    return scene.validated()


# ----- writing a scene back as TOML -------------------------------------------

_LOAD_TYPES = {Traction: "traction", Pressure: "pressure", BodyForce: "body_force", Torque: "torque"}


def scene_to_dict(scene: Scene) -> dict:
    """The TOML tables of ``scene``: :func:`scene_from_dict` of the result is
    ``scene`` again (every built-in scene round-trips, tests/test_scene_model.py)."""
    itf = scene.interface
    if isinstance(itf, LevelSetInterface):
        raise SceneError("interface", "a general level set (Python callables) has no TOML form")
    data = {"name": scene.name, "title": scene.title, "plane": scene.plane, "increments": scene.increments,
            "follow_path": scene.follow_path}
    if scene.h is not None:
        data["h"] = scene.h
    if scene.paper:
        data["paper"] = {k: list(v) for k, v in scene.paper.items()}
    if scene.units != Units():
        data["units"] = dataclasses.asdict(scene.units)
    dom = scene.domain
    data["domain"] = ({"type": "rectangle", "corner": list(dom.corner), "size": list(dom.size)}
                      if isinstance(dom, Rectangle) else {"type": "disc", "centre": list(dom.centre),
                                                          "radius": dom.radius})
    data["interface"] = ({"type": "line", "point": list(itf.point), "normal": list(itf.normal)}
                         if isinstance(itf, LineInterface) else {"type": "circle", "centre": list(itf.centre),
                                                                 "radius": itf.radius})
    data["interface"]["law"] = {"type": scene.law.name, **{k: getattr(scene.law, k) for k in scene.law.parameters}}
    if scene.law.enforcement != default_enforcement(scene.law.name):
        data["interface"]["law"]["enforcement"] = scene.law.enforcement
    data["materials"] = {b: {"E": scene.materials[b].E, "nu": scene.materials[b].nu} for b in BODIES}
    data["supports"] = [_fields(s) for s in scene.supports]
    data["pins"] = [_fields(p) for p in scene.pins]
    data["loads"] = [{"type": _LOAD_TYPES[type(x)], **_fields(x)} for x in scene.loads]
    data["profiles"] = [{"type": "line" if isinstance(p, LineProfile) else "interface", **_fields(p)}
                        for p in scene.profiles]
    return {k: v for k, v in data.items() if v != []}


def _fields(item) -> dict:
    """A scene item's fields as TOML values (tuples as lists, empty paths left out)."""
    out = {}
    for f in dataclasses.fields(item):
        value = getattr(item, f.name)
        if f.name == "path" and not value:
            continue
        out[f.name] = [list(v) if isinstance(v, tuple) else v for v in value] if isinstance(value, tuple) else value
    return out


def _toml_value(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):  # the shortest text that reads back exactly, always a TOML float
        text = next(t for t in (f"{value:.{p}g}" for p in range(1, 18)) if float(t) == value)
        return text if any(c in text for c in ".e") else text + ".0"
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    return "[" + ", ".join(_toml_value(v) for v in value) + "]"


def _toml_table(name: str, table: dict, array: bool = False) -> list[str]:
    """``table`` under the header ``name`` (``[[name]]`` for an array
    element), its scalar keys first, then its sub-tables."""
    lines = ([f"[[{name}]]" if array else f"[{name}]"] if name else [])
    tables = []
    for key, value in table.items():
        if isinstance(value, dict):
            tables.append((key, value, False))
        elif isinstance(value, list) and value and isinstance(value[0], dict):
            tables += [(key, v, True) for v in value]
        else:
            lines.append(f"{key} = {_toml_value(value)}")
    for key, value, is_array in tables:
        lines += [""] + _toml_table(f"{name}.{key}" if name else key, value, is_array)
    return lines


def scene_toml(scene: Scene) -> str:
    """``scene`` as the TOML text :func:`load_scene` reads back."""
    return "\n".join(_toml_table("", scene_to_dict(scene))) + "\n"


def builtin_scenes() -> list[str]:
    """Names of the scenes shipped with the package, sorted: the paper's
    A, B, C and the variants docs/scenes.md describes (``A-cyclic``, ...)."""
    return sorted(p.name[:-5] for p in resources.files("contactcore.scenes").iterdir() if p.name.endswith(".toml"))


def scene_text(name_or_path: str | Path | Scene) -> str:
    """The TOML text of a built-in scene name, of a file path, or of a
    :class:`Scene` (:func:`scene_toml`)."""
    if isinstance(name_or_path, Scene):
        return scene_toml(name_or_path)
    if str(name_or_path) in builtin_scenes():
        return resources.files("contactcore.scenes").joinpath(f"{name_or_path}.toml").read_text()
    path = Path(name_or_path)
    try:
        readable = path.is_file()
    except OSError as exc:  # a name too long for the file system (ENAMETOOLONG), ...
        raise SceneError("scene", f"cannot read {path}: {os_problem(path, exc)}") from None
    if not readable:
        raise SceneError("scene", f"{str(name_or_path)!r} is neither a built-in scene "
                         f"({', '.join(builtin_scenes())}) nor a readable file")
    try:
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise SceneError("scene", f"{path} is not UTF-8 text (byte {exc.start}: {exc.reason})") from None
    except OSError as exc:
        raise SceneError("scene", f"cannot read {path}: {exc.strerror}") from None


def load_scene(name_or_path: str | Path | Scene) -> Scene:
    """Read and validate a scene: a built-in name (``A``) or a TOML path; a
    :class:`Scene` (built in Python) is returned as it is, so every driver
    takes a scene or a name."""
    if isinstance(name_or_path, Scene):
        return name_or_path.validated()
    text = scene_text(name_or_path)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError("scene", f"not valid TOML: {exc}") from None
    return scene_from_dict(data)
