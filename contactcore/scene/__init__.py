"""The scene model: one description of a problem that feeds every method.

A scene is built in code from the dataclasses below or read from a TOML file
(:func:`contactcore.scene_files.load_scene`, schema in docs/scenes.md), and
holds to the rules of :func:`validate` either way: an error is a
:class:`SceneError` whose message starts with the field's dotted path.
Conventions (signs, normals, profiles) are those of ``docs/scenes.md``.

One idea a module:

- :mod:`~contactcore.scene.vocabulary`: the bodies, components and
  quantities a scene names (:data:`BODIES`, :data:`QUANTITIES`, ...);
- :mod:`~contactcore.scene.materials`, :mod:`~contactcore.scene.units`:
  a body's :class:`Material`, the names of the scene's :class:`Units`;
- :mod:`~contactcore.scene.loads`: supports, pins and loads, the load
  contract (:data:`LOADS`, :func:`place_of`) and each load's one formula
  (:func:`edge_traction`, :func:`body_force`);
- :mod:`~contactcore.scene.profiles`: what a scene samples
  (:class:`LineProfile`, :class:`InterfaceProfile`);
- :mod:`~contactcore.scene.model`: the :class:`Scene` itself (its load
  path's factors, material matrices, the body of a point);
- :mod:`~contactcore.scene.caveats`: what a method of spacing h warns
  about on a scene (ligament, small strain, stiff springs);
- :mod:`~contactcore.scene.resolution`: what a discretisation can resolve
  (:func:`check_resolution`, :func:`check_fitted_thickness`);
- :mod:`~contactcore.scene.validation`: :func:`validate`, the rules in
  their order, from :mod:`~contactcore.scene.values` (one value:
  :func:`finite`, :func:`check_file_name`) and the rules of each part:
  :mod:`~contactcore.scene.check_geometry`,
  :mod:`~contactcore.scene.check_materials`,
  :mod:`~contactcore.scene.check_loads`,
  :mod:`~contactcore.scene.check_profiles`.

The arrows: ``model`` → ``validation`` → ``check_*`` → ``values`` →
``vocabulary``; ``model`` → ``caveats``, ``resolution`` (its delegates);
``validation`` → ``resolution``.  The declarations (``loads``,
``profiles``, ``materials``, ``units``) import nothing of the package, and
no module but this ``__init__`` imports ``model``: a function of a scene
takes the :class:`Scene` as its argument.

The package's public names, imported here as ``contactcore.scene.NAME``,
are those the scene model has always had: its dataclasses, vocabulary,
:func:`validate` and the checks the drivers call; the types of a scene's
fields (the geometry's, :class:`~contactcore.laws.InterfaceLaw`) and its
errors stay importable from here too.  A module's private helpers, and
the parts of :func:`validate`, stay in their home.
"""
from ..errors import DiscretisationError, SceneError
from ..geometry import CircleInterface, Disc, Domain, Interface, LevelSetInterface, LineInterface, Rectangle
from ..laws import InterfaceLaw
from .check_profiles import RESERVED_PROFILE_IDS
from .loads import (BODY, EDGE, LOADS, BodyForce, Load, Pin, Pressure, Support, Torque, Traction, body_force,
                    edge_traction, place_of)
from .materials import Material
from .model import Scene
from .profiles import InterfaceProfile, LineProfile, Profile
from .resolution import check_fitted_thickness, check_resolution, smallest_dimension
from .units import MAX_UNIT_NAME, Units
from .validation import validate
from .values import FILE_NAME, check_file_name, finite
from .vocabulary import (BODIES, COMPONENTS, DISPLACEMENT_QUANTITIES, INTERFACE_QUANTITIES, MEAN_SIDE,
                         PROFILE_SIDES, QUANTITIES, STRESS_QUANTITIES)

__all__ = [
    # vocabulary
    "BODIES", "COMPONENTS", "DISPLACEMENT_QUANTITIES", "INTERFACE_QUANTITIES", "MEAN_SIDE", "PROFILE_SIDES",
    "QUANTITIES", "STRESS_QUANTITIES",
    # materials, units
    "MAX_UNIT_NAME", "Material", "Units",
    # loads
    "BODY", "BodyForce", "EDGE", "LOADS", "Load", "Pin", "Pressure", "Support", "Torque", "Traction",
    "body_force", "edge_traction", "place_of",
    # profiles
    "InterfaceProfile", "LineProfile", "Profile",
    # model
    "Scene",
    # resolution
    "check_fitted_thickness", "check_resolution", "smallest_dimension",
    # validation, values, check_profiles
    "FILE_NAME", "RESERVED_PROFILE_IDS", "check_file_name", "finite", "validate",
    # the types of a scene's fields and its errors
    "CircleInterface", "Disc", "DiscretisationError", "Domain", "Interface", "InterfaceLaw", "LevelSetInterface",
    "LineInterface", "Rectangle", "SceneError",
]
