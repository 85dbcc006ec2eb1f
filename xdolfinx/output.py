"""Per-body dolfinx meshes and functions for visual output (ParaView).

Each body gets its own P1 mesh (the vertices of its cells), its displacement
at those vertices and its stress at cell midpoints (DG0), evaluated through
the body-aware point evaluation.  The caller writes them (e.g. XDMFFile).
Serial only.
"""
from __future__ import annotations

import numpy as np
import ufl
from dolfinx import fem
from dolfinx.mesh import compute_midpoints, create_mesh
from mpi4py import MPI

from .evaluation import BodyFields


def body_functions(fields: BodyFields, body: int):
    """``(mesh, u, sigma)`` of body ``body`` (0 = −, 1 = +) on its own P1 mesh."""
    msh = fields.locator.msh
    cells = fields.locator.body_cells[body]
    dofmap = msh.geometry.dofmap
    per_cell = np.diff(dofmap.offsets)[0]
    conn = dofmap.array.reshape(-1, per_cell)[cells, :3]  # vertices come first
    nodes, inverse = np.unique(conn, return_inverse=True)
    domain = ufl.Mesh(ufl.VectorElement("Lagrange", "triangle", 1))
    sub = create_mesh(MPI.COMM_SELF, inverse.reshape(-1, 3).astype(np.int64), msh.geometry.x[nodes, :2], domain)
    V = fem.VectorFunctionSpace(sub, ("Lagrange", 1))
    pts = V.tabulate_dof_coordinates()[:, :2]
    u = fem.Function(V, name="u")
    u.x.array[:] = fields.displacement(pts, np.full(len(pts), body)).ravel()
    S = fem.VectorFunctionSpace(sub, ("DG", 0), dim=3)
    ncells = sub.topology.index_map(2).size_local
    mids = compute_midpoints(sub, 2, np.arange(ncells, dtype=np.int32))[:, :2]
    sigma = fem.Function(S, name="sigma_xx_yy_xy")
    sigma.x.array[:] = fields.stress(mids, np.full(ncells, body)).ravel()
    return sub, u, sigma
