"""The scene model: one description of a problem that feeds every method.

A scene is built in code from the dataclasses below or read from a TOML file
(:func:`contactcore.scene_files.load_scene`, schema in docs/scenes.md), and
holds to the rules of :func:`validate` either way: an error is a
:class:`SceneError` whose message starts with the field's dotted path.
Conventions (signs, normals, profiles) are those of ``docs/scenes.md``.
"""
from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass, field, replace

import numpy as np

from . import tolerances as tol
from .bodies import Body, symbol_of
from .elasticity import voigt_matrix
from .errors import DiscretisationError, SceneError, quoted
from .geometry import (CircleInterface, Disc, Domain, Interface, LevelSetInterface, LineInterface, Rectangle,
                       domain_cells)
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
    """Quantities sampled along Γ against the polar angle or the arc length;
    ``parameter`` None takes Γ's own, as a scene file does: the angle on a
    circle, the arc length otherwise (the :class:`Scene` resolves it)."""

    id: str
    quantities: tuple[str, ...]
    parameter: str | None = None
    side: str = "plus"
    title: str = ""


Profile = LineProfile | InterfaceProfile

#: The longest unit name a scene may give (docs/scenes.md, "Units"): a
#: label such as "mm", "MPa" or "N/mm²", not a sentence.
MAX_UNIT_NAME = 16


@dataclass(frozen=True)
class Units:
    """The names of a scene's length and stress units: labels only.

    A scene may be given in any consistent set of units (docs/scenes.md,
    "Units"): lengths in ℓ, forces in F, stresses F/ℓ².  The numbers are
    never converted; these names label the results (plots, tables,
    ``units.json``): a spring stiffness in ``stress/length``, a
    displacement or a gap in ``length``.
    """

    length: str = "m"
    stress: str = "Pa"


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
    #: The names of the units the scene's numbers are in (labels only).
    units: Units = Units()
    #: The scene as the user gave it, when this one is its dimensionless
    #: form (contactcore.scaling): messages name the user's values.
    source: "Scene | None" = field(default=None, compare=False, repr=False)

    def __post_init__(self):
        """An interface profile without its parameter takes Γ's own
        (:class:`InterfaceProfile`)."""
        along = "angle" if isinstance(self.interface, CircleInterface) else "arclength"
        if not isinstance(self.profiles, (tuple, list)):
            return  # refused by validate(), naming the field
        object.__setattr__(self, "profiles", tuple(
            replace(p, parameter=along) if isinstance(p, InterfaceProfile) and p.parameter is None else p
            for p in self.profiles))

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
        """A validated copy with some fields replaced (parameter studies); a
        name that is no field of a Scene, or a value of the wrong kind
        (``law="x"``: :func:`validate`), is refused with a
        :class:`SceneError` naming it."""
        fields = [f.name for f in dataclasses.fields(self) if f.name != "source"]
        for name in changes:
            if name not in fields:
                raise SceneError(name, f"is no field of a Scene (its fields: {', '.join(fields)})")
        return replace(self, **changes).validated()

    def voigt_matrices(self) -> np.ndarray:
        """The plane-stress or plane-strain ``D`` (σ = D ε in Voigt
        notation) of each body, (2, 3, 3) in :data:`BODIES` order: the one
        place the methods take their material matrices from."""
        return np.array([voigt_matrix(self.materials[b].E, self.materials[b].nu, self.plane) for b in BODIES])

    def ligament_warnings(self, h: float) -> list[str]:
        """A circular Γ closer to the outer boundary than ``h``: no cell or
        node spacing resolves the ligament between them, so its stresses and
        Γ's tractions there are unresolved (a disc 0.01 mm from a 100 mm
        block's edge at h = 5 mm: fe and xfem P1 44–108 % off fe P2 there)."""
        itf, dom = self.interface, self.domain
        if not isinstance(itf, CircleInterface):
            return []
        c, r = np.asarray(itf.centre, float), itf.radius
        if isinstance(dom, Rectangle):
            lo, hi = np.asarray(dom.corner, float), np.asarray(dom.corner, float) + dom.size
            gap = float(min(np.min(c - r - lo), np.min(hi - c - r)))
        else:
            gap = float(dom.radius - np.linalg.norm(c - np.asarray(dom.centre, float)) - r)
        if gap >= h:
            return []
        return [f"Γ comes within {gap / h:.2g} h of the domain's boundary (h the cell or node spacing): no cell "
                "resolves the ligament between them, so its stresses and Γ's tractions there are not resolved; "
                "refine to an h below that gap"]

    def body_thickness(self) -> dict[str, float] | None:
        """Each body's thickness across a straight Γ: the largest distance
        from Γ of its part of the domain (a rectangle's corners on its side,
        or a disc's farthest point), in the scene's length unit; None for a
        curved Γ.  A layer along an edge, or a corner cut off by Γ, is as
        thick as this everywhere or less (grader9 #5: a 2 × 3e-6 strip)."""
        itf, dom = self.interface, self.domain
        if not isinstance(itf, LineInterface):
            return None
        if isinstance(dom, Rectangle):
            phi = itf.phi(dom.corners)
            return {"minus": max(0.0, float(-phi.min())), "plus": max(0.0, float(phi.max()))}
        d = float(itf.phi(np.asarray(dom.centre, float))[0])
        return {"minus": max(0.0, float(dom.radius) - d), "plus": max(0.0, float(dom.radius) + d)}

    def small_strain_warnings(self, fields, h: float, strain_unit: float = 1.0) -> list[str]:
        """The answer's strain too large for the small-strain theory every
        method solves: the RMS over a body of its largest principal strain,
        ``ε = strain_unit · D⁻¹σ`` (``strain_unit`` U/L on a dimensionless
        scene, :mod:`contactcore.scaling`: σ'/E' is ε L/U) from ``fields``
        (:class:`contactcore.result.Fields`) at
        the centres of cells of size ``L/SMALL_STRAIN_SAMPLES`` clear of Γ
        and of the boundary by half a cell's diagonal and by h/2 (inside one
        body of any method's mesh of spacing ``h``),
        above :data:`~contactcore.tolerances.SMALL_STRAIN_LIMIT`.  An RMS,
        not a peak: a corner's stress singularity, integrable, does not
        trigger it as h falls."""
        lo, hi = domain_cells(self.domain, self.length_scale / tol.SMALL_STRAIN_SAMPLES)
        centre = (lo + hi) / 2
        clear = np.maximum(np.linalg.norm(hi - lo, axis=1) / 2, h / 2)
        inside = ((self.domain.distance_to_boundary(centre) > clear)
                  & (np.abs(self.interface.signed_distance(centre)) > clear))
        centre = centre[inside]
        bodies = (self.interface.phi(centre) >= 0).astype(int)
        if not len(centre):
            return []
        stress = np.asarray(fields.stress(centre, bodies), float)
        found = []
        for b, D in zip(range(len(BODIES)), self.voigt_matrices()):
            if not np.any(bodies == b):
                continue
            exx, eyy, gxy = np.linalg.solve(D, stress[bodies == b].T)
            largest = np.abs(exx + eyy) / 2 + np.hypot((exx - eyy) / 2, gxy / 2)
            rms = strain_unit * float(np.sqrt(np.mean(largest ** 2)))
            if not rms <= tol.SMALL_STRAIN_LIMIT:
                found.append(f"{rms:.2g} in body {BODIES[b]} (E = {self.user.materials[BODIES[b]].E:.3g} "
                             f"{self.user.units.stress})")
        if not found:
            return []
        return [f"strains far beyond small strain: the RMS of a body's largest principal strain is {' and '.join(found)}, "
                f"above {tol.SMALL_STRAIN_LIMIT:g}: the small-strain (linear) theory every method solves does not "
                "hold there (its strain omits Green's ½∇uᵀ∇u, which is ε/2 of it), so its displacements and "
                "stresses mean nothing physical; check the moduli and loads (units?)"]

    def interface_warnings(self, h: float, fitted: bool = False) -> list[str]:
        """What a method of cell or node spacing ``h`` should warn about
        before anyone trusts its interface tractions (the thresholds and
        their measurements are in contactcore.tolerances):

        Γ is curved unless its geometry is straight (``straight_in``: a
        line, or a level set whose normal is the same along Γ), whatever
        class it was given as.

        * springs stiff enough to lock the jump of an unfitted method on a
          curved Γ (not ``fitted``): ``k h / E > LOCKING_WARN``, E the softer
          modulus (the body whose deformation the springs over-constrain);
        * springs stiff enough that Γ's profile tractions ``t = k g``, the
          law at each sample's jump, amplify the jump's discretisation
          error, in every method: ``k_N h / E`` or ``k_T h / E`` above its
          PROFILE_TRACTION_WARN on a curved Γ, E the softer modulus;
        * a normal traction ``t_N = k_N g_N`` that amplifies the
          discretisation error of ``g_N`` on a circle of radius R:
          ``(k_N/k_T)(h/2R)² > FALSE_TN_WARN`` (docs/scenes.md, scene B).
        """
        warnings = []
        law, itf = self.law, self.interface
        if not hasattr(law, "kN"):  # enforced exactly: no springs
            return warnings
        soft, curved = self.softer_modulus, not itf.straight_in(self.domain)
        alpha = law.stiffness_scale * h / soft
        if not fitted and curved and alpha > tol.LOCKING_WARN:
            warnings.append(f"interface springs of {alpha:.1e}·E/h, E the softer body's (above "
                            f"{tol.LOCKING_WARN:.0e}·E/h), on a curved Γ that cuts the discretisation: penalty "
                            "locking may raise the error tenfold and lower the convergence rate; soften the springs "
                            "or refine")
        stiff = [f"k_{c} h/E = {k * h / soft:.2g} (above {tol.PROFILE_TRACTION_WARN[c]:g})"
                 for c, k in (("N", law.kN), ("T", law.kT)) if k * h / soft > tol.PROFILE_TRACTION_WARN[c]]
        if stiff and curved:
            warnings.append(f"interface springs of {' and '.join(stiff)}, E the softer body's, on a curved Γ: Γ's "
                            "profile tractions t = k g multiply the jump's discretisation error between Γ's points "
                            "by that factor and may be off by tens of per cent; the solve's own tractions at Γ's "
                            "points are in interface.csv (Result.interface); soften the springs, refine, or enforce "
                            "the law exactly")
        if isinstance(itf, CircleInterface):
            amplification = law.kN / law.kT * (h / (2 * itf.radius)) ** 2
            if amplification > tol.FALSE_TN_WARN:
                warnings.append(f"k_N/k_T = {law.kN / law.kT:.3g} on a circle at h/2R = {h / (2 * itf.radius):.3g}: "
                                f"t_N = k_N g_N amplifies the discretisation error of g_N ((k_N/k_T)(h/2R)² = "
                                f"{amplification:.3g} > {tol.FALSE_TN_WARN:g}); a false t_N of the order of t_T may "
                                "appear: refine (it falls as h²) or lower k_N/k_T")
        return warnings

    @property
    def softer_modulus(self) -> float:
        """The softer body's Young's modulus: the body whose deformation
        a stiff interface spring over-constrains."""
        return min(m.E for m in self.materials.values())

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

def finite(value, path: str) -> float:
    """``value`` as a float when it is a finite int or float; a bool, a
    string, None, NaN or ±inf is refused with a :class:`SceneError` at the
    scene field ``path`` (e.g. ``materials.minus.E``).  No unit is
    checked or converted: the value stays in the scene's own units."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SceneError(path, f"must be a finite number (got {value!r})")
    return float(value)


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


def _check_material(mat: Material, plane: str, path: str) -> None:
    if finite(mat.E, f"{path}.E") <= 0:
        raise SceneError(f"{path}.E", f"Young's modulus must be > 0 (got {mat.E!r})")
    nu = finite(mat.nu, f"{path}.nu")
    if not -1.0 < nu < 0.5:
        raise SceneError(f"{path}.nu", f"Poisson's ratio must lie in (-1, 0.5) for plane {plane} (got {nu!r})")


def _check_domain(domain: Domain) -> None:
    if isinstance(domain, Rectangle):
        for k, v in zip("xy", domain.size):
            if finite(v, f"domain.size.{k}") <= 0:
                raise SceneError("domain.size", f"the rectangle's sides must be > 0 (got {list(domain.size)})")
        for k, v in zip("xy", domain.corner):
            finite(v, f"domain.corner.{k}")
    else:
        if finite(domain.radius, "domain.radius") <= 0:
            raise SceneError("domain.radius", f"must be > 0 (got {domain.radius!r})")


def _check_interface(scene: Scene) -> None:
    itf, dom, L = scene.interface, scene.domain, scene.length_scale
    if isinstance(itf, LineInterface):
        if itf.chord(dom) is None:
            raise SceneError("interface", "the line misses the domain")
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


def _check_point_inside(scene: Scene, point, path: str) -> None:
    for k, v in zip("xy", point):
        finite(v, f"{path}.{k}")
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
        finite(f, f"{where}[1]")
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
            finite(load.value, f"{path}.value")
        elif isinstance(load, Torque):
            finite(load.torque, f"{path}.torque")
            if not isinstance(scene.interface, CircleInterface) or load.body != "minus":
                raise SceneError(f"{path}.body", "a torque acts on the disc inside a circular interface: "
                                 "it needs a circle interface and body = 'minus'")
        else:
            for k, v in zip("xy", load.value):
                finite(v, f"{path}.value.{k}")


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


def check_fitted_thickness(scene: Scene) -> None:
    """A :class:`DiscretisationError` for a body no fitted mesh can hold:
    at most :data:`~contactcore.tolerances.THINNEST_FITTED_BODY` of the
    domain's diameter thick across a straight Γ
    (:meth:`Scene.body_thickness`), where gmsh could not tell its edges
    apart and failed with a message about a curve, or lost Γ (grader9 #5).
    Named in the user's units; a dimensionless ``scene`` names its source's."""
    user = scene.user
    for body, t in (scene.body_thickness() or {}).items():
        floor = tol.THINNEST_FITTED_BODY * scene.length_scale
        if t <= floor:
            scale, unit = user.length_scale / scene.length_scale, user.units.length
            raise DiscretisationError(
                f"body {symbol_of(body)} is at most {t * scale:.3g} {unit} thick across Γ, not "
                f"above {tol.THINNEST_FITTED_BODY:g} of the domain's diameter ({floor * scale:.3g} {unit}): a "
                "fitted mesh cannot tell its edges apart (gmsh names each edge by the boundary it lies on), and "
                "xfem and efgm need a cell or node spacing finer than its thickness: make it thicker")


def check_resolution(scene: Scene, h, field: str = "--h") -> float:
    """A resolution ``h`` that can discretise the scene: finite, > 0 and no
    larger than the domain's smallest dimension (a coarser h gives a
    one-cell mesh whose answer is meaningless)."""
    if isinstance(h, bool) or not isinstance(h, (int, float)) or not math.isfinite(h) or h <= 0:
        raise SceneError(field, f"must be a finite number > 0 (got {h!r})")
    top = smallest_dimension(scene.domain)
    if h > top:
        raise SceneError(field, f"{quoted(h, top)} exceeds the domain's smallest dimension {top:g}: the mesh would be one "
                         "cell across")
    if h < tol.GEOMETRY * top:
        raise SceneError(field, f"{quoted(h, tol.GEOMETRY * top)} is below the geometric tolerance, {tol.GEOMETRY:g} of the domain's "
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


def _check_contrast(materials: dict) -> None:
    """Refuse moduli so far apart (softer/stiffer below
    :data:`~contactcore.tolerances.MODULUS_CONTRAST_MIN`) that the softer
    body's stiffness is lost in the round-off of the stiffer's: the system
    is singular at double precision, whatever the springs or the method."""
    (soft, Es), (stiff, Eh) = sorted(((b, materials[b].E) for b in BODIES), key=lambda item: item[1])
    if Es / Eh < tol.MODULUS_CONTRAST_MIN:  # finite and > 0 both: _check_material
        raise SceneError(f"materials.{soft}.E", f"{Es:g} is {Es / Eh:.2g} of materials.{stiff}.E ({Eh:g}), below "
                         f"the {tol.MODULUS_CONTRAST_MIN:g} double precision can solve: the softer body's "
                         "stiffness is lost in the round-off of the stiffer's (every method's system is singular "
                         "or fails its residual check); bring the moduli closer, e.g. treat the stiffer body as "
                         "rigid with supports on Γ, or the softer as absent")


#: What each of a Scene's parts must be, and how a message names it.
_KINDS = {"domain": ((Rectangle, Disc), "a Rectangle or a Disc"),
          "interface": ((LineInterface, CircleInterface, LevelSetInterface),
                        "a LineInterface, a CircleInterface or a LevelSetInterface")}
_SEQUENCES = {"supports": ((Support,), "Support"), "pins": ((Pin,), "Pin"),
              "loads": ((Traction, Pressure, BodyForce, Torque), "Traction, Pressure, BodyForce or Torque"),
              "profiles": ((LineProfile, InterfaceProfile), "LineProfile or InterfaceProfile")}


def _check_kinds(scene: Scene) -> None:
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
        items = getattr(scene, name)
        if not isinstance(items, (tuple, list)):
            raise SceneError(name, f"must be a tuple of {what} (got {items!r})")
        for i, item in enumerate(items):
            if not isinstance(item, kinds):
                raise SceneError(f"{name}[{i}]", f"must be a {what} (got {item!r})")


def validate(scene: Scene) -> None:
    """Raise :class:`SceneError` at the first invalid field of ``scene``."""
    _check_kinds(scene)
    if not isinstance(scene.name, str) or not scene.name:
        raise SceneError("name", "must be a non-empty string")
    check_file_name(scene.name, "name")
    if scene.plane not in ("stress", "strain"):
        raise SceneError("plane", f"must be 'stress' or 'strain' (got {scene.plane!r})")
    _check_units(scene.units)
    _check_domain(scene.domain)
    _check_interface(scene)
    if scene.law is not None:  # a law built in code meets the file's rules (a negative k_N was refused late, as a rigid mode)
        type(scene.law).from_params({k: getattr(scene.law, k) for k in scene.law.parameters}, "interface.law")
    for body in BODIES:
        if body not in scene.materials:
            raise SceneError(f"materials.{body}", "missing")
        _check_material(scene.materials[body], scene.plane, f"materials.{body}")
    _check_contrast(scene.materials)
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
            finite(v, f"supports[{i}].value.{k}")
            if v != 0 and k not in sup.fix:
                raise SceneError(f"supports[{i}].value", f"gives u_{k} = {v:g}, but fix = {sup.fix!r} does not "
                                 f"hold u_{k}: add {k} to fix, or give 0")
        _check_path(scene, sup.path, f"supports[{i}].path")
    for i, pin in enumerate(scene.pins):
        _check_point_inside(scene, pin.point, f"pins[{i}].point")
        _check_fix(pin.fix, f"pins[{i}].fix")
    _check_loads(scene)
    _check_profiles(scene)
