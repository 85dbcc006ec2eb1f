"""What holds and loads a scene: supports and pins on its boundary and
points, tractions, pressures, body forces and torques, each scaled along
the load path by the factor of its ``path`` (:meth:`Scene.factor
<contactcore.scene.Scene.factor>`), and the one formula of a body load
(:func:`body_force`).  Signs and units are docs/scenes.md's.

:func:`body_force` takes the :class:`~contactcore.scene.Scene` it reads Γ
from; this module does not import it (the Scene imports this module)."""
from __future__ import annotations

import math
from dataclasses import dataclass


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


def body_force(scene: "Scene", load: BodyForce | Torque, x, y):
    """The components ``(b_x, b_y)`` of a body load at coordinates x, y.

    Plain arithmetic, so x and y may be numpy arrays or UFL expressions: one
    formula for every method.  A torque is spread over the disc of the
    circular Γ as ``b = (T/J)(−(y−y_c), x−x_c)``, ``J = πR⁴/2`` (docs/scenes.md).
    """
    if isinstance(load, BodyForce):
        return load.value[0] + 0 * x, load.value[1] + 0 * y
    return torque_field(torque_rate(scene, load), scene.interface.centre, x, y)


def torque_rate(scene: "Scene", load: Torque) -> float:
    """A torque's ``k = T/J``, ``J = πR⁴/2`` the polar moment of Γ's disc."""
    return load.torque / (math.pi * scene.interface.radius ** 4 / 2)


def torque_field(k, centre, x, y):
    """``b = k(−(y−y_c), x−x_c)``: a torque's body force at x, y, with its
    rate ``k`` (:func:`torque_rate`) and ``centre`` given as numbers or as
    UFL Constants (xdolfinx's form multiplies these, with no copy of the
    formula)."""
    return -k * (y - centre[1]), k * (x - centre[0])

