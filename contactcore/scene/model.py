"""The :class:`Scene`: everything a method needs to solve one interface
problem, its load path's factors, its material matrices and which body a
point lies in.  Its parts are declared beside it (:mod:`.loads`,
:mod:`.profiles`, :mod:`.materials`, :mod:`.units`), its rules are
:func:`~contactcore.scene.validation.validate`'s, and the warnings a
method gives on it :mod:`.caveats`' (the methods of the same names
delegate there)."""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field, replace

import numpy as np

from .. import tolerances as tol
from ..elasticity import voigt_matrix
from ..errors import SceneError
from ..geometry import CircleInterface, Domain, Interface
from ..laws import InterfaceLaw
from . import caveats, resolution
from .loads import Load, Pin, Support
from .materials import Material
from .profiles import InterfaceProfile, Profile
from .units import Units
from .validation import validate
from .vocabulary import BODIES


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
        """:func:`contactcore.scene.caveats.ligament_warnings` of this scene."""
        return caveats.ligament_warnings(self, h)

    def body_thickness(self) -> dict[str, float] | None:
        """:func:`contactcore.scene.resolution.body_thickness` of this scene."""
        return resolution.body_thickness(self)

    def small_strain_warnings(self, fields, h: float, strain_unit: float = 1.0) -> list[str]:
        """:func:`contactcore.scene.caveats.small_strain_warnings` of this
        scene's answer ``fields`` (:func:`contactcore.scene.caveats.body_strains`)."""
        return caveats.small_strain_warnings(self, *caveats.body_strains(self, fields, h, strain_unit))

    def interface_warnings(self, h: float, fitted: bool = False) -> list[str]:
        """:func:`contactcore.scene.caveats.interface_warnings` of this scene."""
        return caveats.interface_warnings(self, h, fitted)

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
