"""The scales of a scene and the map to its dimensionless form and back.

Contract: :class:`Scales` maps a scene (its points, law, loads, supports,
profiles) to the dimensionless scene every method solves, and the answer
(points, profile samples, Γ's history, a discretisation record) back to the
user's units, by the map below; a value that leaves the floating-point range
on the way is refused as a SceneError naming its place in the scene.

A scene may be drawn in any units (µm for micro-contact, km for geology)
and anywhere in the plane.  So that no tolerance of any method (gmsh's, point
location, cut cells, quadrature) is absolute, the one ``solve`` of every
method (:mod:`contactcore.discretisation`) is decorated with
:func:`contactcore.scaling.solve.dimensionless`: it solves the scene mapped by

    x' = (x − o)/L,   u' = u/U,   E' = E/S,   σ' = σ/(S U/L),

``o`` the lower-left corner of the domain's bounding box, ``L`` its larger
side, ``S`` the largest Young's modulus and ``U`` the displacement the loads
cause, ``U = max(L τ/S, |prescribed displacements|)`` with ``τ`` the largest
load as a stress (or ``U = L`` with no load), and maps the answer back.  The
rest of the scene follows from the dimensions of its fields (SI units as in
``contactcore.scene``, thickness 1), with the stress unit ``Σ = S U/L``:

* a load's parameters by the dimension its class declares
  (:func:`contactcore.scene.loads.load_contract`, :meth:`Scales.load_units`),
  never by its type: tractions, pressures (Pa) ``t' = t/Σ``; body forces
  (N/m³) and a pressure's gradient (Pa/m) ``b' = b L/Σ``; torques (N·m
  per unit thickness, i.e. N) ``T' = T/(Σ L²)``, since ``b = (T/J) r``
  with ``J = πR⁴/2``; points ``(x − o)/L``.  A load that is no registered
  load, or declares too little, is refused here, naming its type;
* penalty springs (Pa/m):                       ``k' = k L/S``;
* prescribed displacements, the slip history of a law (m): ``/U``;
* h (m): ``/L``; points (pins, profile ends, Γ, nodes): ``(x − o)/L``;
  ν, μ and load paths are dimensionless already;
* a law's parameters by the dimension its class declares
  (:func:`contactcore.laws.law_contract`, :meth:`Scales.parameter_unit`),
  never by name: springs (Pa/m) ``× L/S``, stresses ``/Σ``,
  displacements (a gap compared with a jump) ``/U``, lengths ``/L``,
  dimensionless ones unchanged.  A law that declares no dimension for a
  parameter is refused here, by name.

Equilibrium ``∇·σ + b = 0`` and the laws hold in the primed quantities
exactly when they hold in the original ones (a law's response is
dimensionally consistent and every parameter is scaled by its dimension:
``t = k g``, ``t_N = k_N min(g_N + g0, 0)`` alike; positive homogeneity is
not needed here), so the discrete answer is the same up to round-off
whatever the units and the placement, and gmsh meshes the same
dimensionless geometry at every scale.  ``U`` keeps the unknowns of order one however soft the material:
E = 1e-300 Pa under 1e5 Pa is a strain of 1e305 that ``σ = D ε`` would
overflow, but an ordinary problem once made dimensionless.
"""
from __future__ import annotations

import math
import sys
from dataclasses import dataclass, replace

import numpy as np

from .. import tolerances as tol
from ..errors import ContactError, SceneError, require_finite
from ..geometry import CircleInterface, Disc, LevelSetInterface, LineInterface, Rectangle
from ..interface_path import InterfacePath
from ..laws import DIMENSIONLESS, DISPLACEMENT, LENGTH, STIFFNESS, STRESS, law_contract
from ..profile_data import ProfileData
from ..scene import DISPLACEMENT_QUANTITIES, STRESS_QUANTITIES, LineProfile, Scene, place_of
from ..scene.loads import FORCE_DENSITY, MAGNITUDES, MOMENT, POINT, STRESS as LOAD_STRESS, load_contract


def _scaled(value: float, unit: float, path: str, least: float = 0.0) -> float:
    """``value / unit``, refused if it leaves the floating-point range: not
    finite, or a non-zero value made zero, or below ``least`` (a modulus:
    ``sys.float_info.min``, below which it is subnormal and its digits are
    lost: E = 1e-300 beside 7e10 ended in NaN; a spring or load that small
    is left to the health checks, which name what it fails to hold)."""
    out = float(value) / unit if math.isfinite(unit) and unit > 0 else math.nan
    if not math.isfinite(out) or (value != 0 and (out == 0 or abs(out) < least)):
        raise SceneError(path, f"{value!r} is out of floating-point range once made dimensionless "
                         f"(over {unit:.3g}); choose units closer to the problem's scale (docs/scenes.md, 'Units')")
    return out


def load_stress(scene: Scene) -> float:
    """``τ``: the largest load as a stress (Pa): of each parameter of a
    magnitude a load declares, its largest component as a stress (|t|, p,
    |b| L or a pressure's |gradient| L, |T|/L²).

    Load paths are left out: ``U`` only has to keep the unknowns within a
    few orders of one, since every tolerance is relative."""
    L = Scales.extent(scene.domain)[1]
    sizes = [0.0]
    for i, load in enumerate(scene.loads):
        for name, dim in _declared(load, i).items():
            if dim not in MAGNITUDES:
                continue
            size = float(max(abs(v) for v in np.ravel(getattr(load, name))))  # a Python float: overflow is inf, refused below, not a numpy warning
            sizes.append(size * L if dim == FORCE_DENSITY else size / L / L if dim == MOMENT else size)
    return max(sizes)


def _declared(load, i: int) -> dict[str, str]:
    """The declared dimension of each parameter of ``load`` (the ``i``-th of
    its scene), or a SceneError at ``loads[i]`` naming its type: no
    registered load, or one that declares too little."""
    try:
        place_of(load)
        return load_contract(type(load))
    except ContactError as exc:
        raise SceneError(f"loads[{i}]", str(exc)) from None


@dataclass(frozen=True)
class Scales:
    """The length ``L``, origin ``o``, modulus ``S`` and displacement ``U``
    of a scene (module doc)."""

    length: float
    origin: tuple[float, float]
    modulus: float
    displacement: float

    @property
    def stress(self) -> float:
        """The stress unit ``Σ = S U/L`` (Pa)."""
        return self.modulus * (self.displacement / self.length)

    @property
    def strain(self) -> float:
        """The strain unit ``U/L``: a strain is ``(U/L) σ'/E'``."""
        return self.displacement / self.length

    @staticmethod
    def extent(dom) -> tuple[tuple[float, float], float]:
        """The lower-left corner of the domain's bounding box and its larger side."""
        if isinstance(dom, Rectangle):
            return (float(dom.corner[0]), float(dom.corner[1])), float(max(dom.size))
        return (float(dom.centre[0] - dom.radius), float(dom.centre[1] - dom.radius)), 2.0 * float(dom.radius)

    @classmethod
    def of(cls, scene: Scene) -> "Scales":
        """The scales of ``scene`` (module doc); SceneError if the
        displacement its loads cause is out of floating-point range."""
        origin, L = cls.extent(scene.domain)
        S = float(max(m.E for m in scene.materials.values()))
        if not 0.0 < S < math.inf:
            raise SceneError("materials", f"Young's moduli must be finite and > 0 (the largest is {S!r})")
        prescribed = max((abs(v) for s in scene.supports for v in s.value), default=0.0)
        U = max(L * (load_stress(scene) / S), prescribed) or L
        if not 0.0 < U < math.inf or not 0.0 < S * (U / L) < math.inf:
            raise SceneError("loads", f"the displacement the loads cause, about {U:.3g} (L τ/E), is out of "
                             "floating-point range; choose units closer to the problem's scale (docs/scenes.md, 'Units')")
        return cls(L, origin, S, U)

    # ----- points -------------------------------------------------------

    def to_dimensionless(self, points) -> np.ndarray:
        """``x' = (x − o)/L`` of points (m, 2)."""
        return (np.asarray(points, float)[..., :2] - self.origin) / self.length

    def to_user(self, points) -> np.ndarray:
        """``x = o + L x'`` of points (m, 2)."""
        return np.asarray(self.origin) + self.length * np.asarray(points, float)[..., :2]

    def _point(self, point, path: str) -> tuple[float, float]:
        """A point of the scene, rounded to multiples of
        :data:`~contactcore.tolerances.DIMENSIONLESS_GRID`: the round-off of
        the change of units and of the move (~eps |x|/L) then vanishes, so
        the same scene in any units is the same dimensionless scene, bit
        for bit (the same mesh, the same profile samples)."""
        grid = tol.DIMENSIONLESS_GRID
        return tuple(round(_scaled(x - o, self.length, f"{path}.{k}") / grid) * grid
                     for k, x, o in zip("xy", point, self.origin))

    # ----- the scene ----------------------------------------------------

    def _domain(self, dom):
        if isinstance(dom, Rectangle):
            return Rectangle(self._point(dom.corner, "domain.corner"), tuple(s / self.length for s in dom.size))
        return Disc(self._point(dom.centre, "domain.centre"), dom.radius / self.length)

    def _interface(self, itf):
        if isinstance(itf, LineInterface):
            return LineInterface(self._point(itf.point, "interface.point"), itf.normal)
        if isinstance(itf, CircleInterface):
            return CircleInterface(self._point(itf.centre, "interface.centre"), itf.radius / self.length)
        # φ'(x') = φ(x)/L keeps |∇φ'| = |∇φ|; the normal is unchanged
        return LevelSetInterface(lambda p: np.asarray(itf.phi_fn(self.to_user(p)), float) / self.length,
                                 lambda p: itf.grad_fn(self.to_user(p)))

    def load_units(self, dimension: str) -> tuple[float, ...]:
        """What a load's parameter of ``dimension`` (:data:`contactcore.scene.loads.LOAD_DIMENSIONS`,
        not a point) is divided by, in turn, in the dimensionless scene
        (module doc): Σ for a stress, Σ/L for a force per volume, Σ then L²
        for a moment, nothing for a dimensionless one."""
        L, S = self.length, self.stress
        return {LOAD_STRESS: (S,), FORCE_DENSITY: (S / L,), MOMENT: (S, L * L)}.get(dimension, ())

    def _load(self, load, i: int):
        """The load with each parameter made dimensionless by its declared
        dimension (:func:`_declared`)."""
        path = f"loads[{i}]"
        changes = {}
        for name, dim in _declared(load, i).items():
            value, where = getattr(load, name), f"{path}.{name}"
            if dim == POINT:
                changes[name] = self._point(value, where)
                continue
            units = self.load_units(dim)
            if not units:
                continue

            def scaled(v):
                for unit in units:
                    v = _scaled(v, unit, where)
                return v
            changes[name] = tuple(scaled(v) for v in value) if isinstance(value, tuple) else scaled(value)
        return replace(load, **changes)

    def profile(self, prof, path: str = "profile"):
        """A profile of the dimensionless scene."""
        if isinstance(prof, LineProfile):
            return replace(prof, start=self._point(prof.start, f"{path}.start"),
                           end=self._point(prof.end, f"{path}.end"))
        return prof

    def profile_data(self, data: ProfileData) -> ProfileData:
        """Samples of a profile of the dimensionless scene in the user's
        units: x, y and an arc length (×L), an angle as it is, displacements
        and gaps (×U), stresses and tractions (×Σ)."""
        unit = {**dict.fromkeys(DISPLACEMENT_QUANTITIES + ("gN", "gT"), self.displacement),
                **dict.fromkeys(STRESS_QUANTITIES + ("tN", "tT"), self.stress),
                "s": 1.0 if data.parameter == "angle" else self.length}
        xy = self.to_user(np.column_stack([data.columns["x"], data.columns["y"]]))
        columns = {q: xy[:, "xy".index(q)] if q in ("x", "y") else unit[q] * v for q, v in data.columns.items()}
        return replace(data, columns=columns)

    def parameter_unit(self, dimension: str) -> float:
        """What a law's parameter of ``dimension`` (:data:`contactcore.laws.DIMENSIONS`)
        is divided by in the dimensionless scene (module doc)."""
        L, S, U = self.length, self.modulus, self.displacement
        return {STIFFNESS: S / L, STRESS: self.stress, DISPLACEMENT: U, LENGTH: L, DIMENSIONLESS: 1.0}[dimension]

    def law(self, law):
        """The law with every parameter made dimensionless by the dimension
        its class declares (:func:`contactcore.laws.law_contract`, which
        refuses a law that declares none, as a SceneError at
        ``interface.law``); a dimensionless one unchanged."""
        try:
            dims = law_contract(type(law))
        except ContactError as exc:
            raise SceneError("interface.law", str(exc)) from None
        return replace(law, **{k: _scaled(getattr(law, k), self.parameter_unit(d), f"interface.law.{k}")
                               for k, d in dims.items() if d != DIMENSIONLESS})

    def scene(self, scene: Scene) -> Scene:
        """The dimensionless scene (module doc); SceneError if a value leaves
        the floating-point range."""
        L, S, U = self.length, self.modulus, self.displacement
        law = self.law(scene.law)
        return replace(
            scene, domain=self._domain(scene.domain), interface=self._interface(scene.interface), law=law,
            materials={b: replace(m, E=_scaled(m.E, S, f"materials.{b}.E", sys.float_info.min))
                       for b, m in scene.materials.items()},
            supports=tuple(replace(s, value=tuple(_scaled(v, U, f"supports[{i}].value") for v in s.value))
                           for i, s in enumerate(scene.supports)),
            pins=tuple(replace(p, point=self._point(p.point, f"pins[{i}].point")) for i, p in enumerate(scene.pins)),
            loads=tuple(self._load(ld, i) for i, ld in enumerate(scene.loads)),
            profiles=tuple(self.profile(p, f"profiles[{i}]") for i, p in enumerate(scene.profiles)),
            h=None if scene.h is None else scene.h / L, source=scene.user)

    # ----- the answer ---------------------------------------------------

    def path(self, path: InterfacePath | None) -> InterfacePath | None:
        """The interface history in the user's units: points and weights
        (m, ×L), jumps and the slip history (m, ×U), tractions (Pa, ×Σ)."""
        if path is None:
            return None
        L, U = self.length, self.displacement
        steps = [self.step(st) for st in path.steps]
        return InterfacePath(self.to_user(path.points), L * path.weights, steps,
                             None if path.state is None else U * path.state,
                             None if path.pieces is None else self.to_user(path.pieces))

    def step(self, st):
        """One converged increment in the user's units: jumps (m, ×U),
        tractions (Pa, ×Σ); refused if they leave the floating-point range."""
        out = replace(st, jump=self.displacement * st.jump, traction=self.stress * st.traction)
        require_finite(f"interface jumps of step {st.step:g}", out.jump)
        require_finite(f"interface tractions of step {st.step:g}", out.traction)
        return out

    def path_in(self, path: InterfacePath | None) -> InterfacePath | None:
        """The reverse of :meth:`path`: a user's interface history over the
        dimensionless scene."""
        if path is None:
            return None
        L, U = self.length, self.displacement
        steps = [replace(st, jump=st.jump / U, traction=st.traction / self.stress) for st in path.steps]
        return InterfacePath(self.to_dimensionless(path.points), path.weights / L, steps,
                             None if path.state is None else path.state / U,
                             None if path.pieces is None else self.to_dimensionless(path.pieces))

    def discretisation(self, record: dict) -> dict:
        """A method's discretisation record with its lengths (h, a grading's
        distance) back in the user's units."""
        out = dict(record)
        if out.get("h") is not None:
            out["h"] = out["h"] * self.length
        if isinstance(out.get("grading"), dict):
            out["grading"] = {**out["grading"], "distance": out["grading"]["distance"] * self.length}
        return out


def user_points(scene: Scene, points) -> np.ndarray:
    """``points`` (…, 2) of a dimensionless ``scene`` (one :meth:`Scales.scene`
    made) in its user's coordinates and length unit, as a message names
    them; a user's own scene's unchanged.  The tilted block, 2 × 1 m, had
    its partial point named at (0.2835, 0.25), half its (0.567, 0.5), and
    a pin-held pull at (3, −1.63) mm its pivot at (−1.1e-16, 0.185)."""
    source = getattr(scene, "source", None)
    return np.asarray(points, float) if source is None else Scales.of(source).to_user(points)

