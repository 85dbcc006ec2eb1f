"""The shared core: scene model, geometry, interface laws, result type.

Every method package (``xdolfinx``, ``efgm``) and the drivers in
``verification`` import this package; it imports none of them, and needs
neither dolfinx nor gmsh (numpy only).  One submodule,
:mod:`contactcore.linear_solver` (the PETSc/MUMPS solve every method shares),
imports petsc4py and is never imported by this package itself.
"""
from .errors import ContactError, DiscretisationError, FieldsError, SceneError, SolverError
from .enforcement import make_law
from .laws import LAWS, CoulombLaw, LinearLaw, UnilateralLaw
from .profiles import ProfileData, evaluate_quantities, sample_profile, sample_profiles
from .result import Result, SolverReport, Timings
from .scene import (BODIES, BodyForce, InterfaceProfile, LineProfile, Material, Pin, Pressure, Scene, Support,
                    Torque, Traction, Units)
from .scene_files import builtin_scenes, load_scene, scene_from_dict, scene_text
from .geometry import CircleInterface, Disc, LevelSetInterface, LineInterface, Rectangle

__all__ = [
    "BODIES", "BodyForce", "CircleInterface", "ContactError", "Disc", "DiscretisationError", "FieldsError", "InterfaceProfile",
    "CoulombLaw", "LAWS", "LevelSetInterface", "LineInterface", "LineProfile", "LinearLaw", "Material", "Pin", "Pressure", "ProfileData", "Rectangle",
    "Result", "Scene", "SceneError", "SolverError", "SolverReport", "Support", "Timings", "Torque", "Traction", "UnilateralLaw", "Units",
    "builtin_scenes", "evaluate_quantities", "load_scene", "make_law", "sample_profile", "sample_profiles",
    "scene_from_dict", "scene_text",
]
