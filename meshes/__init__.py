"""gmsh functions that build the fitted mesh of any scene (Γ embedded).

Use :func:`build_model` inside :func:`gmsh_session` to hand the model to
dolfinx, or :func:`write_mesh` / ``python -m meshes`` for a ``.msh`` file.
The physical tags (:mod:`meshes.tags`) load without gmsh; the builders
import it on first use, so a method that only needs the tags (xfem on
structured cells) never loads gmsh.
"""
import importlib

from .tags import BODY, BOUNDARY, INTERFACE, NAMES

_BUILDERS = ("GMSH_MIN_CIRCLE_POINTS", "Grading", "build_model", "gmsh_session", "keeping_sigint", "polygon_warnings",
             "write_mesh")

__all__ = ["BODY", "BOUNDARY", "GMSH_MIN_CIRCLE_POINTS", "Grading", "INTERFACE", "NAMES", "build_model", "gmsh_session",
           "keeping_sigint", "polygon_warnings", "write_mesh"]


def __getattr__(name: str):
    """The gmsh builders of :mod:`meshes.build`, imported when first asked for."""
    if name in _BUILDERS:
        return getattr(importlib.import_module(".build", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
