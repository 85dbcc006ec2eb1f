"""Per-body dolfinx meshes and functions for visual output (ParaView).

Each body gets its own first-order mesh (the vertices of the cells that hold
it), its displacement at those vertices and its stress at cell midpoints
(DG0), evaluated through the body-aware point evaluation of any method with
a :class:`~xdolfinx.evaluation.BodyCellLocator` (fe, xfem).  For XFEM a cell
cut by Γ belongs to both bodies' meshes, each showing its own field there.
The caller writes them (e.g. XDMFFile).  Serial only.
"""
from __future__ import annotations

import numpy as np
import ufl
from dolfinx import fem
from dolfinx.mesh import compute_midpoints, create_mesh
from mpi4py import MPI



def body_functions(fields, body: int):
    """``(mesh, u, sigma)`` of body ``body`` (0 = −, 1 = +) on its own mesh,
    in the user's units (a :class:`contactcore.scaling.ScaledFields` maps
    the method's dimensionless mesh back)."""
    scales = getattr(fields, "scales", None)  # a Result's fields: the method's own mesh is dimensionless
    locator = (fields if scales is None else fields.inner).locator
    msh, cells = locator.msh, locator.body_cells[body]
    cell_name = msh.topology.cell_name()
    nverts = {"triangle": 3, "quadrilateral": 4}[cell_name]
    dofmap = msh.geometry.dofmap
    per_cell = np.diff(dofmap.offsets)[0]
    conn = dofmap.array.reshape(-1, per_cell)[cells, :nverts]  # vertices come first
    nodes, inverse = np.unique(conn, return_inverse=True)
    domain = ufl.Mesh(ufl.VectorElement("Lagrange", cell_name, 1))
    x = msh.geometry.x[nodes, :2]
    sub = create_mesh(MPI.COMM_SELF, inverse.reshape(-1, nverts).astype(np.int64),
                      x if scales is None else scales.to_user(x), domain)
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
