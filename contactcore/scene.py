"""The scene model: one description of a problem that feeds every method.

A scene is built in code from the dataclasses below or read from a TOML file
(:func:`load_scene`, schema in docs/scenes.md).  Reading validates every field;
an error is a :class:`SceneError` whose message starts with the field's
dotted path.  Conventions (signs, normals, profiles) are those of
``docs/scenes.md``.
"""
from __future__ import annotations

import dataclasses
import json
import math
import re
import tomllib
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path

import numpy as np

from . import tolerances as tol
from .bodies import Body
from .elasticity import voigt_matrix
from .errors import SceneError
from .geometry import CircleInterface, Disc, Domain, Interface, LevelSetInterface, LineInterface, Rectangle
from .exact import default_enforcement
from .enforcement import make_law
from .laws import InterfaceLaw

BODIES = tuple(b.label for b in Body)
COMPONENTS = ("xy", "x", "y")
STRESS_QUANTITIES = ("sxx", "syy", "sxy")
DISPLACEMENT_QUANTITIES = ("ux", "uy")
INTERFACE_QUANTITIES = ("tN", "tT", "gN", "gT")
QUANTITIES = STRESS_QUANTITIES + DISPLACEMENT_QUANTITIES + INTERFACE_QUANTITIES


@dataclass(frozen=True)
class Material:
    """Isotropic linear elastic material (E in Pa)."""

    E: float
    nu: float


@dataclass(frozen=True)
class Support:
    """Prescribed displacement of the components ``fix`` on a named boundary.

    ``value`` (m) is multiplied by the factor of ``path`` (see :class:`Scene`).
    """

    boundary: str
    fix: str = "xy"
    value: tuple[float, float] = (0.0, 0.0)
    path: tuple[tuple[int, float], ...] = ()


@dataclass(frozen=True)
class Pin:
    """A point whose components ``fix`` are held at zero (rigid-body modes)."""

    point: tuple[float, float]
    fix: str = "xy"


@dataclass(frozen=True)
class Traction:
    """Constant traction vector (Pa) on a named boundary."""

    boundary: str
    value: tuple[float, float]
    path: tuple[tuple[int, float], ...] = ()


@dataclass(frozen=True)
class Pressure:
    """Normal pressure (Pa, positive pushes inwards): traction ``−p n_out``."""

    boundary: str
    value: float
    path: tuple[tuple[int, float], ...] = ()


@dataclass(frozen=True)
class BodyForce:
    """Constant body force (N/m³) in one body."""

    body: str
    value: tuple[float, float]
    path: tuple[tuple[int, float], ...] = ()


@dataclass(frozen=True)
class Torque:
    """A torque (N·m, counter-clockwise positive) spread over the disc of Γ.

    Scene B's body force ``b = (T/J)(−(y−y_c), x−x_c)`` with ``J = πR⁴/2``:
    its moment about the centre is T and its resultant is zero.
    """

    body: str
    torque: float
    path: tuple[tuple[int, float], ...] = ()


Load = Traction | Pressure | BodyForce | Torque


@dataclass(frozen=True)
class LineProfile:
    """Quantities sampled on a segment from ``start`` to ``end``.

    On Γ the stress is taken from ``side`` (default +, docs/scenes.md).
    """

    id: str
    start: tuple[float, float]
    end: tuple[float, float]
    quantities: tuple[str, ...]
    side: str = "plus"
    title: str = ""


@dataclass(frozen=True)
class InterfaceProfile:
    """Quantities sampled along Γ against the polar angle or the arc length."""

    id: str
    quantities: tuple[str, ...]
    parameter: str = "angle"
    side: str = "plus"
    title: str = ""


Profile = LineProfile | InterfaceProfile


@dataclass(frozen=True)
class Scene:
    """Everything a method needs to solve one interface problem."""

    name: str
    domain: Domain
    interface: Interface
    materials: dict[str, Material]
    law: InterfaceLaw
    supports: tuple[Support, ...] = ()
    pins: tuple[Pin, ...] = ()
    loads: tuple[Load, ...] = ()
    profiles: tuple[Profile, ...] = ()
    increments: int = 1
    #: Follow the increments even for a law without history, whose final
    #: state does not depend on the path: the user asks for the response
    #: along it (increments.csv, interface.csv).  A law with history always
    #: follows the path.
    follow_path: bool = False
    plane: str = "stress"
    h: float | None = None
    paper: dict[str, tuple[int, int]] = field(default_factory=dict)
    title: str = ""
    #: The scene as the user gave it, when this one is its dimensionless
    #: form (contactcore.scaling): messages name the user's values.
    source: "Scene | None" = field(default=None, compare=False, repr=False)

    @property
    def user(self) -> "Scene":
        """The scene in the user's units (itself unless dimensionless)."""
        return self.source or self

    @property
    def length_scale(self) -> float:
        return self.domain.length_scale

    def factor(self, path, k: int | float) -> float:
        """The factor of a load or support with keyframes ``path`` at
        increment ``k`` (fractional between increments, for cut-backs).

        A path is a list of ``(increment, factor)`` pairs with increasing
        increments in ``0 … increments``, linear in between, starting from
        ``(0, 0)`` unless it gives increment 0, and holding its last factor
        after its last keyframe.  No path is the ramp ``(0, 0) → (n, 1)``:
        equal increments of the full load (docs/scenes.md).
        """
        keys = tuple(path) or ((self.increments, 1.0),)
        if keys[0][0] != 0:
            keys = ((0, 0.0),) + keys
        steps, values = zip(*keys)
        return float(np.interp(k, steps, values))

    def factors(self, k: int | float) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The factor of every load and of every support at increment ``k``."""
        return (tuple(self.factor(ld.path, k) for ld in self.loads),
                tuple(self.factor(sp.path, k) for sp in self.supports))

    def validated(self) -> "Scene":
        """Check every physical and geometric rule; returns ``self``."""
        validate(self)
        return self

    def with_changes(self, **changes) -> "Scene":
        """A validated copy with some fields replaced (parameter studies)."""
        return replace(self, **changes).validated()

    def voigt_matrices(self) -> np.ndarray:
        """The plane-stress or plane-strain ``D`` (σ = D ε in Voigt
        notation) of each body, (2, 3, 3) in :data:`BODIES` order: the one
        place the methods take their material matrices from."""
        return np.array([voigt_matrix(self.materials[b].E, self.materials[b].nu, self.plane) for b in BODIES])

    def interface_warnings(self, h: float, fitted: bool = False) -> list[str]:
        """What a method of cell or node spacing ``h`` should warn about
        before anyone trusts its interface tractions (the thresholds and
        their measurements are in contactcore.tolerances):

        * springs stiff enough to lock the jump of an unfitted method on a
          curved Γ (not ``fitted``): ``k h / E > LOCKING_WARN``, E the stiffer
          modulus;
        * a normal traction ``t_N = k_N g_N`` that amplifies the
          discretisation error of ``g_N`` on a circle of radius R:
          ``(k_N/k_T)(h/2R)² > FALSE_TN_WARN`` (docs/scenes.md, scene B).
        """
        warnings = []
        law, itf = self.law, self.interface
        if not hasattr(law, "kN"):  # enforced exactly: no springs
            return warnings
        alpha = law.stiffness_scale * h / max(m.E for m in self.materials.values())
        if not fitted and not isinstance(itf, LineInterface) and alpha > tol.LOCKING_WARN:
            warnings.append(f"interface springs of {alpha:.1e}·E/h (above {tol.LOCKING_WARN:.0e}·E/h) on a curved "
                            "Γ that cuts the discretisation: penalty locking may raise the error tenfold and lower "
                            "the convergence rate; soften the springs or refine")
        if isinstance(itf, CircleInterface):
            amplification = law.kN / law.kT * (h / (2 * itf.radius)) ** 2
            if amplification > tol.FALSE_TN_WARN:
                warnings.append(f"k_N/k_T = {law.kN / law.kT:.3g} on a circle at h/2R = {h / (2 * itf.radius):.3g}: "
                                f"t_N = k_N g_N amplifies the discretisation error of g_N ((k_N/k_T)(h/2R)² = "
                                f"{amplification:.3g} > {tol.FALSE_TN_WARN:g}); a false t_N of the order of t_T may "
                                "appear: refine (it falls as h²) or lower k_N/k_T")
        return warnings

    def body_of(self, points, side: str = "plus") -> np.ndarray:
        """0 (−) or 1 (+) for each point: by the sign of φ, ``side`` within
        ON_INTERFACE of Γ, a distance: a level set's φ is scaled by |∇φ|,
        or with φ = 1e-9 (r² − R²) a whole rod would be 'on Γ', read from
        the + body."""
        phi = self.interface.phi(points)
        on = np.abs(self.interface.signed_distance(points)) <= tol.ON_INTERFACE * self.length_scale
        return np.where(on, BODIES.index(side), (phi > 0).astype(int))


def body_force(scene: "Scene", load: BodyForce | Torque, x, y):
    """The components ``(b_x, b_y)`` of a body load at coordinates x, y.

    Plain arithmetic, so x and y may be numpy arrays or UFL expressions: one
    formula for every method.  A torque is spread over the disc of the
    circular Γ as ``b = (T/J)(−(y−y_c), x−x_c)``, ``J = πR⁴/2`` (docs/scenes.md).
    """
    if isinstance(load, BodyForce):
        return load.value[0] + 0 * x, load.value[1] + 0 * y
    (xc, yc), R = scene.interface.centre, scene.interface.radius
    k = load.torque / (math.pi * R ** 4 / 2)
    return -k * (y - yc), k * (x - xc)


# --------------------------------------------------------------------------
# validation of a Scene (built in code or read from a file)
# --------------------------------------------------------------------------

def _finite(value, path: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SceneError(path, f"must be a finite number (got {value!r})")
    return float(value)


def _check_material(mat: Material, plane: str, path: str) -> None:
    if _finite(mat.E, f"{path}.E") <= 0:
        raise SceneError(f"{path}.E", f"Young's modulus must be > 0 (got {mat.E!r})")
    nu = _finite(mat.nu, f"{path}.nu")
    if not -1.0 < nu < 0.5:
        raise SceneError(f"{path}.nu", f"Poisson's ratio must lie in (-1, 0.5) for plane {plane} (got {nu!r})")


def _check_domain(domain: Domain) -> None:
    if isinstance(domain, Rectangle):
        for k, v in zip("xy", domain.size):
            if _finite(v, f"domain.size.{k}") <= 0:
                raise SceneError("domain.size", f"the rectangle's sides must be > 0 (got {list(domain.size)})")
        for k, v in zip("xy", domain.corner):
            _finite(v, f"domain.corner.{k}")
    else:
        if _finite(domain.radius, "domain.radius") <= 0:
            raise SceneError("domain.radius", f"must be > 0 (got {domain.radius!r})")


def _check_interface(scene: Scene) -> None:
    itf, dom, L = scene.interface, scene.domain, scene.length_scale
    if isinstance(itf, LineInterface):
        if abs(math.hypot(*itf.normal) - 1.0) > 1e-12:
            raise SceneError("interface.normal", "must be a unit vector (give any non-zero vector in a file)")
        if itf.chord(dom) is None:
            raise SceneError("interface", "the line misses the domain")
        a_minus = itf.minus_area(dom)
        smaller = min(a_minus, dom.area - a_minus) / dom.area
        if smaller <= tol.MIN_BODY_AREA_FRACTION:
            touches = smaller <= tol.GEOMETRY ** 2  # an area of round-off
            raise SceneError("interface", "the line only touches the domain: one body would be empty" if touches
                             else f"the line cuts off a body of {smaller:.2g} of the domain's area, below the "
                                  f"{tol.MIN_BODY_AREA_FRACTION:g} any method can resolve")
    elif isinstance(itf, LevelSetInterface):
        a_minus = itf.minus_area(dom)
        if min(a_minus, dom.area - a_minus) <= tol.MIN_BODY_AREA_FRACTION * dom.area:
            raise SceneError("interface", "the level set does not change sign in the domain: Γ misses it")
    else:
        if _finite(itf.radius, "interface.radius") <= 0:
            raise SceneError("interface.radius", f"must be > 0 (got {itf.radius!r})")
        clearance = float(dom.distance_to_boundary([itf.centre])[0]) - itf.radius
        if clearance <= tol.GEOMETRY * L:
            where = "misses the domain" if not dom.contains([itf.centre])[0] and clearance < -2 * itf.radius \
                else "is not strictly inside the domain (it must not touch or cross the outer boundary)"
            raise SceneError("interface", f"the circle {where}")


def _check_point_inside(scene: Scene, point, path: str) -> None:
    for k, v in zip("xy", point):
        _finite(v, f"{path}.{k}")
    if not scene.domain.contains([point], tol.GEOMETRY * scene.length_scale)[0]:
        raise SceneError(path, f"the point {list(point)} lies outside the domain")


def _check_boundary(scene: Scene, name: str, path: str) -> None:
    if name not in scene.domain.boundary_names:
        raise SceneError(path, f"no boundary named {name!r} on this domain "
                         f"(it has: {', '.join(scene.domain.boundary_names)})")


def _check_body(name: str, path: str) -> None:
    if name not in BODIES:
        raise SceneError(path, f"unknown body {name!r} (bodies are 'minus' and 'plus')")


def _check_fix(fix: str, path: str) -> None:
    if fix not in COMPONENTS:
        raise SceneError(path, f"must be one of {', '.join(COMPONENTS)} (got {fix!r})")


def _check_path(scene: Scene, keys, path: str) -> None:
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
        _finite(f, f"{where}[1]")
        previous = k


def _check_loads(scene: Scene) -> None:
    for i, load in enumerate(scene.loads):
        path = f"loads[{i}]"
        _check_path(scene, load.path, f"{path}.path")
        if isinstance(load, (Traction, Pressure)):
            _check_boundary(scene, load.boundary, f"{path}.boundary")
        else:
            _check_body(load.body, f"{path}.body")
        if isinstance(load, Pressure):
            _finite(load.value, f"{path}.value")
        elif isinstance(load, Torque):
            _finite(load.torque, f"{path}.torque")
            if not isinstance(scene.interface, CircleInterface) or load.body != "minus":
                raise SceneError(f"{path}.body", "a torque acts on the disc inside a circular interface: "
                                 "it needs a circle interface and body = 'minus'")
        else:
            for k, v in zip("xy", load.value):
                _finite(v, f"{path}.value.{k}")


#: A name that becomes a file name (a scene's, a profile's id): letters,
#: digits, '-', '_' and '.', starting with a letter, a digit or '_' —
#: nothing that can leave the result folder ('/', '..'), hide a file
#: ('.') or read as a command's option ('-').
FILE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]*")


def check_file_name(value, field: str) -> None:
    """Raise :class:`SceneError` unless ``value`` is a safe file name."""
    if not isinstance(value, str) or not FILE_NAME.fullmatch(value):
        raise SceneError(field, f"must be a file-safe name: letters, digits, '-', '_', '.', starting with a "
                         f"letter, a digit or '_' (got {value!r})")


def smallest_dimension(domain) -> float:
    """The domain's smallest extent: a rectangle's shorter side, a disc's diameter."""
    return float(min(domain.size)) if isinstance(domain, Rectangle) else 2.0 * float(domain.radius)


def check_resolution(scene: Scene, h, field: str = "--h") -> float:
    """A resolution ``h`` that can discretise the scene: finite, > 0 and no
    larger than the domain's smallest dimension (a coarser h gives a
    one-cell mesh whose answer is meaningless)."""
    if isinstance(h, bool) or not isinstance(h, (int, float)) or not math.isfinite(h) or h <= 0:
        raise SceneError(field, f"must be a finite number > 0 (got {h!r})")
    top = smallest_dimension(scene.domain)
    if h > top:
        raise SceneError(field, f"{h:g} exceeds the domain's smallest dimension {top:g}: the mesh would be one "
                         "cell across")
    if h < tol.GEOMETRY * top:
        raise SceneError(field, f"{h:g} is below the geometric tolerance, {tol.GEOMETRY:g} of the domain's "
                         f"smallest dimension {top:g}: no mesh or node set of it can be made or held")
    return float(h)


#: Names a profile may not take: they sit beside the profiles' ids in a
#: run's estimate record (summary.json's ``"estimate"``: the ZZ estimate,
#: the runs' h, Γ's status, the warnings and the worst estimated error),
#: where a profile of that name would be overwritten.
RESERVED_PROFILE_IDS = ("energy", "h", "status", "warnings", "worst")


def _check_profiles(scene: Scene) -> None:
    seen = set()
    L = scene.length_scale
    for i, prof in enumerate(scene.profiles):
        path = f"profiles[{i}]"
        if not prof.id or prof.id in seen:
            raise SceneError(f"{path}.id", f"must be a unique, non-empty name (got {prof.id!r})")
        if prof.id in RESERVED_PROFILE_IDS:
            raise SceneError(f"{path}.id", f"{prof.id!r} is reserved (a run's estimate record keeps "
                             f"{', '.join(RESERVED_PROFILE_IDS)} beside the profiles); choose another name")
        check_file_name(prof.id, f"{path}.id")
        seen.add(prof.id)
        if not prof.quantities:
            raise SceneError(f"{path}.quantities", "must name at least one quantity")
        for q in prof.quantities:
            if q not in QUANTITIES:
                raise SceneError(f"{path}.quantities", f"unknown quantity {q!r} (known: {', '.join(QUANTITIES)})")
        _check_body(prof.side, f"{path}.side")
        if isinstance(prof, LineProfile):
            _check_point_inside(scene, prof.start, f"{path}.start")
            _check_point_inside(scene, prof.end, f"{path}.end")
            if math.dist(prof.start, prof.end) <= tol.GEOMETRY * L:
                raise SceneError(f"{path}.end", "the segment has zero length")
            if set(prof.quantities) & set(INTERFACE_QUANTITIES):
                ends = np.array([prof.start, prof.end, np.add(prof.start, prof.end) / 2])
                if np.max(np.abs(scene.interface.phi(ends))) > tol.GEOMETRY * L:
                    raise SceneError(f"{path}.quantities", "interface quantities (tN, tT, gN, gT) need a "
                                     "segment that lies on the interface")
        else:
            if prof.parameter not in ("angle", "arclength"):
                raise SceneError(f"{path}.parameter", f"must be 'angle' or 'arclength' (got {prof.parameter!r})")
            if prof.parameter == "angle" and not isinstance(scene.interface, CircleInterface):
                raise SceneError(f"{path}.parameter", "a polar angle needs a circular interface; use 'arclength'")
            if isinstance(scene.interface, LevelSetInterface):
                raise SceneError(f"{path}.type", "profiles along a general level set are not supported; "
                                 "use line profiles")


def validate(scene: Scene) -> None:
    """Raise :class:`SceneError` at the first invalid field of ``scene``."""
    if not isinstance(scene.name, str) or not scene.name:
        raise SceneError("name", "must be a non-empty string")
    check_file_name(scene.name, "name")
    if scene.plane not in ("stress", "strain"):
        raise SceneError("plane", f"must be 'stress' or 'strain' (got {scene.plane!r})")
    _check_domain(scene.domain)
    _check_interface(scene)
    if scene.law is not None:  # a law built in code meets the file's rules (a negative k_N was refused late, as a rigid mode)
        type(scene.law).from_params({k: getattr(scene.law, k) for k in scene.law.parameters}, "interface.law")
    for body in BODIES:
        if body not in scene.materials:
            raise SceneError(f"materials.{body}", "missing")
        _check_material(scene.materials[body], scene.plane, f"materials.{body}")
    if isinstance(scene.increments, bool) or not isinstance(scene.increments, int) or scene.increments < 1:
        raise SceneError("increments", f"must be an integer >= 1 (got {scene.increments!r})")
    if not isinstance(scene.follow_path, bool):
        raise SceneError("follow_path", f"must be true or false (got {scene.follow_path!r})")
    if scene.h is not None:
        check_resolution(scene, scene.h, "h")
    for i, sup in enumerate(scene.supports):
        _check_boundary(scene, sup.boundary, f"supports[{i}].boundary")
        _check_fix(sup.fix, f"supports[{i}].fix")
        for k, v in zip("xy", sup.value):
            _finite(v, f"supports[{i}].value.{k}")
            if v != 0 and k not in sup.fix:
                raise SceneError(f"supports[{i}].value", f"gives u_{k} = {v:g}, but fix = {sup.fix!r} does not "
                                 f"hold u_{k}: add {k} to fix, or give 0")
        _check_path(scene, sup.path, f"supports[{i}].path")
    for i, pin in enumerate(scene.pins):
        _check_point_inside(scene, pin.point, f"pins[{i}].point")
        _check_fix(pin.fix, f"pins[{i}].fix")
    _check_loads(scene)
    _check_profiles(scene)


# --------------------------------------------------------------------------
# reading a TOML file
# --------------------------------------------------------------------------

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
                raise SceneError(path, "missing")
            return default
        value = self.data[key]
        if kind == "number":
            value = _finite(value, path)
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
            value = tuple(_finite(v, f"{path}[{i}]") for i, v in enumerate(value))
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
            raise SceneError(self._key(unknown[0]), "unknown key")


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
        normal = t.get("normal", "vector")
        length = math.hypot(*normal)
        if length == 0.0:
            raise SceneError(f"{t.path}.normal", "must be a non-zero vector")
        itf = LineInterface(t.get("point", "vector"), (normal[0] / length, normal[1] / length))
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


def _read_profile(t: _Table, interface: Interface) -> Profile:
    kind = t.get("type", "str", choices=("line", "interface"))
    common = dict(id=t.get("id", "str"), quantities=t.get("quantities", "strings"),
                  side=t.get("side", "str", "plus"), title=t.get("title", "str", ""))
    if kind == "line":
        prof = LineProfile(start=t.get("start", "vector"), end=t.get("end", "vector"), **common)
    else:
        along = "angle" if isinstance(interface, CircleInterface) else "arclength"  # the default s along Γ
        prof = InterfaceProfile(parameter=t.get("parameter", "str", along), **common)
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
        profiles=tuple(_read_profile(p, interface) for p in t.get("profiles", "tables", [])),
        paper=paper,
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
    """Names of the scenes shipped with the package (the paper's A, B, C)."""
    return sorted(p.name[:-5] for p in resources.files("contactcore.scenes").iterdir() if p.name.endswith(".toml"))


def scene_text(name_or_path: str | Path | Scene) -> str:
    """The TOML text of a built-in scene name, of a file path, or of a
    :class:`Scene` (:func:`scene_toml`)."""
    if isinstance(name_or_path, Scene):
        return scene_toml(name_or_path)
    if str(name_or_path) in builtin_scenes():
        return resources.files("contactcore.scenes").joinpath(f"{name_or_path}.toml").read_text()
    path = Path(name_or_path)
    if not path.is_file():
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
