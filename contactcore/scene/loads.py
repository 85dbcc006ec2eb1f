"""What holds and loads a scene: supports and pins on its boundary and
points, tractions, pressures, body forces and torques, each scaled along
the load path by the factor of its ``path`` (:meth:`Scene.factor
<contactcore.scene.Scene.factor>`).  Signs and units are docs/scenes.md's.

The contract of a load class (:class:`_Load`), checked when it is
registered in :data:`LOADS` (:func:`load_registry`, at import) and again
wherever a method meets a load (:func:`place_of`, :func:`load_contract`),
so that a load that declares too little, or an object that is no
registered load, is refused by name rather than met as a missing
attribute deep in a method:

* ``name``: its ``type`` in a scene file;
* ``acts_on``: where it acts, :data:`EDGE` (a field ``boundary`` naming a
  boundary of the domain) or :data:`BODY` (a field ``body``);
* ``parameters`` and ``dimensions``: every field but ``boundary``,
  ``body`` and ``path`` is a parameter, each of a dimension of
  :data:`LOAD_DIMENSIONS`; :mod:`contactcore.scaling` makes each
  dimensionless by its declared dimension and by nothing else, and sizes
  the scene's displacement unit from them;
* its one formula, ``field(c, x, y, n)`` for an edge load (the traction
  at points x, y of outward normal n) or ``field(c, x, y)`` for a body
  load (the body force), of the numbers ``c = load.coefficients(scene)``.
  Plain arithmetic, so that x, y, n and c may be numpy arrays (n's
  components first, ``n[0]`` the x components) or UFL expressions and
  Constants: every method calls it (:func:`edge_traction`,
  :func:`body_force`; xdolfinx builds its forms from it with the
  coefficients as Constants).  It returns the vector as a pair of
  components or as one vector (a traction's value, ``−p n``).

A new load is one class declaring these and an entry in :data:`LOADS`; a
scene file reads it once ``contactcore.scene_files`` knows its ``type``,
and docs/scenes.md gives its row (docs/architecture.md, "Where to change
what").

This module imports nothing of the scene package (the Scene imports it);
a formula takes the :class:`~contactcore.scene.Scene` it reads Γ from."""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..errors import ContactError
from ..registry import declared_dimensions, registered


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


#: Where a load acts (:attr:`_Load.acts_on`): on a named boundary, or in a body.
EDGE, BODY = "edge", "body"

#: The dimensions a load's parameter may declare (:attr:`_Load.dimensions`),
#: each made dimensionless by :mod:`contactcore.scaling` with the scene's
#: units (``L`` length, ``o`` origin, ``Σ`` the stress unit):
STRESS = "stress"  #: a traction or pressure, Pa: / Σ
FORCE_DENSITY = "force per volume"  #: a body force, N/m³, or a pressure's gradient, Pa/m: × L/Σ
MOMENT = "moment"  #: a torque per unit thickness, N·m/m: / (Σ L²)
POINT = "point"  #: a point of the plane, m: (x − o)/L
DIMENSIONLESS = "dimensionless"  #: unchanged
LOAD_DIMENSIONS = (STRESS, FORCE_DENSITY, MOMENT, POINT, DIMENSIONLESS)
#: The dimensions of a load's size: scaled with the load path's factor,
#: and the largest of them sizes the scene's displacement unit.
MAGNITUDES = (STRESS, FORCE_DENSITY, MOMENT)

#: The fields of a load that are not parameters: where it acts and its path.
_PLACES = {EDGE: "boundary", BODY: "body"}


class _Load:
    """What every load shares: its coefficients (by default its parameters'
    values).  A load class declares (module doc; :func:`load_contract`
    refuses one that does not) ``name``, ``acts_on``, ``parameters`` with
    their ``dimensions`` and its formula ``field``; none is given here, so
    that a new load cannot inherit a wrong one."""

    name: ClassVar[str]
    acts_on: ClassVar[str]
    parameters: ClassVar[tuple[str, ...]]
    dimensions: ClassVar[dict[str, str]]

    def coefficients(self, scene) -> tuple:
        """The numbers its ``field`` is made of in ``scene``'s units: its
        parameters' values, in order."""
        return tuple(getattr(self, p) for p in self.parameters)


@dataclass(frozen=True)
class Traction(_Load):
    """Constant traction vector (Pa) on a named boundary."""

    boundary: str
    value: tuple[float, float]
    path: tuple[tuple[int, float], ...] = ()

    name = "traction"
    acts_on = EDGE
    parameters = ("value",)
    dimensions = {"value": STRESS}

    @staticmethod
    def field(c, x, y, n):
        """``t̄``: its value wherever it acts."""
        return c[0]


@dataclass(frozen=True)
class Pressure(_Load):
    """Normal pressure (Pa, positive pushes inwards): traction ``−p n_out``."""

    boundary: str
    value: float
    path: tuple[tuple[int, float], ...] = ()

    name = "pressure"
    acts_on = EDGE
    parameters = ("value",)
    dimensions = {"value": STRESS}

    @staticmethod
    def field(c, x, y, n):
        """``−p n``, n the outward normal."""
        return -c[0] * n


@dataclass(frozen=True)
class BodyForce(_Load):
    """Constant body force (N/m³) in one body."""

    body: str
    value: tuple[float, float]
    path: tuple[tuple[int, float], ...] = ()

    name = "body_force"
    acts_on = BODY
    parameters = ("value",)
    dimensions = {"value": FORCE_DENSITY}

    @staticmethod
    def field(c, x, y):
        """``b``: its value wherever it acts."""
        return c[0]


@dataclass(frozen=True)
class Torque(_Load):
    """A torque (N·m, counter-clockwise positive) spread over the disc of Γ.

    Scene B's body force ``b = (T/J)(−(y−y_c), x−x_c)`` with ``J = πR⁴/2``:
    its moment about the centre is T and its resultant is zero.
    """

    body: str
    torque: float
    path: tuple[tuple[int, float], ...] = ()

    name = "torque"
    acts_on = BODY
    parameters = ("torque",)
    dimensions = {"torque": MOMENT}

    def coefficients(self, scene) -> tuple:
        """Its rate ``k = T/J`` (:func:`torque_rate`) and Γ's centre."""
        return torque_rate(scene, self), scene.interface.centre

    @staticmethod
    def field(c, x, y):
        """``b = k(−(y−y_c), x−x_c)`` (:func:`torque_field`)."""
        return torque_field(c[0], c[1], x, y)


Load = Traction | Pressure | BodyForce | Torque


def load_contract(cls) -> dict[str, str]:
    """The declared dimension of each parameter of the load class ``cls``
    (module doc), or a ContactError naming the load and what it fails to
    declare: a ``name``, where it acts, a field of it that is no declared
    parameter (unscaled, it would reach every method in the user's units
    against a dimensionless scene), a dimension outside
    :data:`LOAD_DIMENSIONS`, no parameter of a magnitude, no formula."""
    name = getattr(cls, "name", None)
    where = f"the load {cls.__module__}.{cls.__qualname__}" + (f" ('{name}')" if isinstance(name, str) else "")
    if not isinstance(name, str) or not name:
        raise ContactError(f"{where}: declares no 'name' (its type in a scene file)")
    if not dataclasses.is_dataclass(cls):
        raise ContactError(f"{where}: is not a dataclass of its fields")
    kind = getattr(cls, "acts_on", None)
    if kind not in _PLACES:
        raise ContactError(f"{where}: declares no 'acts_on' ('{EDGE}' or '{BODY}'; got {kind!r}): the methods "
                           "integrate it on a boundary or in a body by it")
    fields = [f.name for f in dataclasses.fields(cls)]
    for needed in (_PLACES[kind], "path"):
        if needed not in fields:
            raise ContactError(f"{where}: acts on {'an edge' if kind == EDGE else 'a body'} but has no field '{needed}'")
    dims = declared_dimensions(cls, where, LOAD_DIMENSIONS)
    parameters = cls.parameters
    undeclared = [f for f in fields if f not in (_PLACES[kind], "path") and f not in parameters]
    if undeclared:
        raise ContactError(f"{where}: its field '{undeclared[0]}' is not among its declared parameters "
                           f"({', '.join(parameters)}): the scaling could not make it dimensionless")
    missing = [p for p in parameters if p not in fields]
    if missing:
        raise ContactError(f"{where}: declares the parameter '{missing[0]}', which is not one of its fields")
    if not any(dims[p] in MAGNITUDES for p in parameters):
        raise ContactError(f"{where}: has no parameter of a magnitude ({', '.join(MAGNITUDES)}): its size and "
                           "its load path's factor would act on nothing")
    if not callable(getattr(cls, "field", None)):
        raise ContactError(f"{where}: declares no formula 'field' (the {'traction' if kind == EDGE else 'body force'} "
                           "at points; module doc)")
    return dims


def load_registry(*classes) -> dict:
    """``{name: class}`` of load classes, each held to :func:`load_contract`
    (at import: a load that declares too little is refused before any
    scene uses it), no name twice (:func:`contactcore.registry.registered`)."""
    return registered("load", load_contract, classes)


#: Every load type by the name a scene file gives it.
LOADS = load_registry(Traction, Pressure, BodyForce, Torque)


def place_of(load) -> str:
    """:data:`EDGE` or :data:`BODY`: where ``load`` acts, or a ContactError
    naming its type if it is no registered load (:data:`LOADS`): what every
    method dispatches on."""
    cls = type(load)
    if LOADS.get(getattr(cls, "name", None)) is not cls:
        raise ContactError(f"unknown load type {cls.__qualname__} ({load!r}): not one of the registered loads "
                           f"({', '.join(c.__qualname__ for c in LOADS.values())}; contactcore.scene.loads.LOADS)")
    return cls.acts_on


def vanishes(load) -> bool:
    """Whether every parameter of a magnitude of ``load`` is zero (then it
    loads nothing)."""
    dims = load_contract(type(load))
    return all(v == 0.0 for p, d in dims.items() if d in MAGNITUDES for v in np.ravel(getattr(load, p)))


def scaled_load(load, factor: float):
    """``load`` with each parameter of a magnitude times ``factor`` (its
    points and dimensionless parameters as they are): the load at that
    factor of its path."""
    def times(value):
        return tuple(v * factor for v in value) if isinstance(value, tuple) else value * factor
    return dataclasses.replace(load, **{p: times(getattr(load, p))
                                        for p, d in load_contract(type(load)).items() if d in MAGNITUDES})


def _rows(vector, x: np.ndarray) -> np.ndarray:
    """(P, 2): a formula's vector at the P points of ``x``, from a pair of
    components (numbers or (P,) arrays) or an array with its components
    first ((2,) or (2, P))."""
    return np.column_stack([np.broadcast_to(np.asarray(c, float), x.shape) for c in vector])


def edge_traction(scene, load, x, y, normals) -> np.ndarray:
    """(P, 2): the traction of the edge load ``load`` at the points x, y
    ((P,) each) of outward unit normals ``normals`` (P, 2), by its formula."""
    if place_of(load) != EDGE:
        raise ContactError(f"{type(load).__qualname__} acts in a body, not on an edge")
    x, y = np.asarray(x, float), np.asarray(y, float)
    return _rows(load.field(load.coefficients(scene), x, y, np.asarray(normals, float).T), x)


def body_force(scene, load, x, y):
    """The components ``(b_x, b_y)`` of the body load ``load`` at the
    coordinates x, y (numpy arrays), by its formula."""
    if place_of(load) != BODY:
        raise ContactError(f"{type(load).__qualname__} acts on an edge, not in a body")
    x, y = np.asarray(x, float), np.asarray(y, float)
    b = _rows(load.field(load.coefficients(scene), x, y), x)
    return b[:, 0], b[:, 1]


def torque_rate(scene, load: Torque) -> float:
    """A torque's ``k = T/J``, ``J = πR⁴/2`` the polar moment of Γ's disc."""
    return load.torque / (math.pi * scene.interface.radius ** 4 / 2)


def torque_field(k, centre, x, y):
    """``b = k(−(y−y_c), x−x_c)``: a torque's body force at x, y, with its
    rate ``k`` (:func:`torque_rate`) and ``centre`` given as numbers or as
    UFL Constants (xdolfinx's form multiplies these, with no copy of the
    formula)."""
    return -k * (y - centre[1]), k * (x - centre[0])
