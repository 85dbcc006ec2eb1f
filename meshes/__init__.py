"""gmsh functions that build the fitted mesh of any scene (Γ embedded).

Use :func:`build_model` inside :func:`gmsh_session` to hand the model to
dolfinx, or :func:`write_mesh` / ``python -m meshes`` for a ``.msh`` file.
"""
from .build import Grading, build_model, gmsh_session, write_mesh
from .tags import BODY, BOUNDARY, INTERFACE, NAMES

__all__ = ["BODY", "BOUNDARY", "Grading", "INTERFACE", "NAMES", "build_model", "gmsh_session", "write_mesh"]
