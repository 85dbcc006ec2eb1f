"""The two bodies in GetFEM: meshes from gmsh, displacement spaces, Γ's multiplier space.

The − and the + body are two GetFEM meshes, from the same gmsh model as
our fe method (:func:`meshes.build.build_model`): triangles of size h,
geometry of the elements' degree (curved on a circle at degree 2), the
two meshes conforming along Γ but separate objects, so each body has its
own displacement ``u1`` (−) and ``u2`` (+), ``FEM_PK(2, k)``.  The
multiplier λ of the contact (Alart & Curnier, CMAME 92, 1991; Renard,
CMAME 256, 2013) is a ``FEM_PK(2, 1)`` field on the − body's side of Γ,
the mortar pair of GetFEM's contact demos.  Each mesh carries the region
of its faces on Γ (:data:`_GAMMA`) and one region per named edge of the
rectangle (:data:`_EDGES`), found by position to within
:data:`FACE_MATCH` of the scene's length.

Contract: :class:`_Bodies` holds per body (``"minus"``, ``"plus"``) the
mesh, its ``MeshFem`` and ``MeshIm``, its edges' region numbers, Γ's
facets in gmsh's order and the multiplier's ``MeshFem``; ``keep`` holds
every GetFEM object that must outlive its Python name.
"""
from __future__ import annotations

import numpy as np

from contactcore import Scene
from contactcore.geometry import CircleInterface
from meshes.build import build_model, gmsh_session
from meshes.tags import BODY, INTERFACE

#: Degree of the multiplier on Γ: P1 against P1 or P2 displacements (a
#: stable mortar pair on the − body's trace; GetFEM's contact demos' choice).
MULTIPLIER_DEGREE = 1

#: Relative tolerance of a face's position on a named edge or on Γ.
FACE_MATCH = 1e-6

#: gmsh's element types: 3- and 6-node triangles, 2- and 3-node lines.
_GMSH_TRIANGLE = {1: 2, 2: 9}
_GMSH_LINE = {1: 1, 2: 8}

#: GetFEM's node order of a ``GT_PK(2, 2)`` triangle from gmsh's (vertices,
#: then the midpoints of edges 01, 12, 20).
_GMSH_TO_GETFEM = {1: [0, 1, 2], 2: [0, 3, 1, 5, 4, 2]}

#: GetFEM region numbers: Γ, then one per named edge.
_GAMMA = 1
_EDGES = {"left": 11, "right": 12, "bottom": 13, "top": 14}


def _gmsh_meshes(scene: Scene, h: float, degree: int) -> tuple[dict, np.ndarray]:
    """Each body's triangles as node coordinates (2, nodes per cell, cells)
    in GetFEM's order, and Γ's facets (facets, nodes, 2) in gmsh's order
    (end points, then the midpoint at degree 2)."""
    import gmsh
    with gmsh_session():
        build_model(scene, h, order=degree)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        xy = np.zeros((int(tags.max()) + 1, 2))
        xy[tags.astype(int)] = coords.reshape(-1, 3)[:, :2]
        cells = {}
        for body, tag in BODY.items():
            nodes = [gmsh.model.mesh.getElementsByType(_GMSH_TRIANGLE[degree], s)[1]
                     for s in gmsh.model.getEntitiesForPhysicalGroup(2, tag)]
            conn = np.concatenate(nodes).astype(int).reshape(-1, len(_GMSH_TO_GETFEM[degree]))
            cells[body] = xy[conn[:, _GMSH_TO_GETFEM[degree]]].transpose(2, 1, 0)
        lines = [gmsh.model.mesh.getElementsByType(_GMSH_LINE[degree], c)[1]
                 for c in gmsh.model.getEntitiesForPhysicalGroup(1, INTERFACE)]
        facets = xy[np.concatenate(lines).astype(int).reshape(-1, degree + 1)]
    return cells, facets


def _getfem_mesh(gf, cells: np.ndarray, degree: int):
    m = gf.Mesh("empty", 2)
    m.add_convex(gf.GeoTrans(f"GT_PK(2,{degree})"), np.asfortranarray(cells))
    return m


def _gamma_faces(scene: Scene, m, body: str) -> np.ndarray:
    """The outer faces of a body's mesh on Γ: inside the circle's ball, or
    along the line's normal (outward: n for −, −n for +)."""
    itf, L = scene.interface, scene.length_scale
    if isinstance(itf, CircleInterface):
        return m.outer_faces_in_ball(np.asarray(itf.centre, float), itf.radius + FACE_MATCH * L)
    n = np.asarray(itf.normal, float) * (1 if body == "minus" else -1)
    return m.outer_faces_with_direction(n, FACE_MATCH)


def _edge_faces(scene: Scene, m) -> dict[str, np.ndarray]:
    """The outer faces of a body's mesh on each named edge of the rectangle."""
    (x0, y0), (a, b) = scene.domain.corner, scene.domain.size
    e = FACE_MATCH * scene.length_scale
    boxes = {"left": ([x0 - e, y0 - e], [x0 + e, y0 + b + e]), "right": ([x0 + a - e, y0 - e], [x0 + a + e, y0 + b + e]),
             "bottom": ([x0 - e, y0 - e], [x0 + a + e, y0 + e]), "top": ([x0 - e, y0 + b - e], [x0 + a + e, y0 + b + e])}
    return {name: m.outer_faces_in_box(*map(np.array, box)) for name, box in boxes.items()}


class _Bodies:
    """GetFEM's meshes, spaces and integration methods of the two bodies."""

    VARS = {"minus": "u1", "plus": "u2"}

    def __init__(self, gf, scene: Scene, h: float, degree: int):
        cells, self.facets = _gmsh_meshes(scene, h, degree)
        self.mesh, self.mfu, self.mim, self.edges = {}, {}, {}, {}
        for body in BODY:
            m = _getfem_mesh(gf, cells[body], degree)
            m.set_region(_GAMMA, _gamma_faces(scene, m, body))
            self.edges[body] = {}
            for name, faces in _edge_faces(scene, m).items():
                if faces.size:
                    m.set_region(_EDGES[name], faces)
                    self.edges[body][name] = _EDGES[name]
            mfu = gf.MeshFem(m, 2)
            mfu.set_fem(gf.Fem(f"FEM_PK(2,{degree})"))
            self.mesh[body], self.mfu[body] = m, mfu
            self.mim[body] = gf.MeshIm(m, gf.Integ(f"IM_TRIANGLE({4 * degree})"))
        m1 = self.mesh["minus"]
        base = gf.MeshFem(m1, 2)
        base.set_fem(gf.Fem(f"FEM_PK(2,{MULTIPLIER_DEGREE})"))
        self.mflambda = gf.MeshFem("partial", base, base.basic_dof_on_region(_GAMMA))
        self.keep = [base]  # GetFEM frees an object with its last Python reference

    def dofs(self) -> int:
        return int(sum(mf.nbdof() for mf in self.mfu.values()) + self.mflambda.nbdof())
