"""Per-body meshes with their fields, for visual output (ParaView, meshio).

Each body gets its own first-order mesh: the vertices of the cells that hold
it (a cell cut by Γ, in XFEM, belongs to both bodies' meshes, each showing
its own field there).  On it:

* ``u``: the displacement at every vertex (P1 in the vertices, whatever the
  method's degree);
* ``sigma``: ``(σxx, σyy, σxy)`` per cell, the value at the cell's vertex
  centroid: the cell's own value for P1 (constant stress), its mean for P2
  on a straight triangle (linear stress).  True cell data, not per vertex.

The mesh is the method's own (``locator.msh`` of the fields behind any
wrapper, :func:`contactcore.result.method_fields`), mapped into the user's
frame by the wrappers' placement; the values are those of the Result's
public fields at the mapped points, so they are in the user's units and
equal to what the profiles sample.  Numbers only: the caller writes them.

Under mpirun every rank contributes the cells it owns and every rank gets
the whole body (a collective call): vertices are keyed by dolfinx's input
index of the geometry node and cells ordered by their sorted vertex keys,
an order no partition changes, so rank 0 writes the serial run's files.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contactcore import DiscretisationError
from contactcore.result import method_fields

#: dolfinx's vertex order -> a cycle around the cell (VTK/meshio order), per cell type.
_CCW = {"triangle": [0, 1, 2], "quadrilateral": [0, 1, 3, 2]}
#: meshio's name of each dolfinx cell type.
MESHIO_CELL = {"triangle": "triangle", "quadrilateral": "quad"}


@dataclass
class BodyMesh:
    """One body's first-order mesh in the user's frame, with its fields."""

    points: np.ndarray  # (n, 2) vertices
    cells: np.ndarray  # (m, k) vertex indices, counter-clockwise
    cell_type: str  # dolfinx's name: "triangle" or "quadrilateral"
    u: np.ndarray  # (n, 2) displacement at the vertices
    sigma: np.ndarray  # (m, 3) (σxx, σyy, σxy) at the cells' vertex centroids


def body_mesh(fields, body: int) -> BodyMesh:
    """Body ``body`` (0 = −, 1 = +) of a Result's ``fields`` (see module doc)."""
    inner, placement = method_fields(fields)
    if not hasattr(inner, "locator"):
        raise DiscretisationError(f"fields: {type(inner).__name__} has no mesh to write")
    msh = inner.locator.msh
    cell_name = msh.topology.cell_name()
    order = _CCW[cell_name]
    dofmap = msh.geometry.dofmap
    per_cell = int(np.diff(dofmap.offsets)[0])
    conn = dofmap.array.reshape(-1, per_cell)[inner.locator.body_cells[body]][:, order]  # vertices come first
    keys = np.asarray(msh.geometry.input_global_indices, np.int64)[conn]  # the same on every partition
    coords = msh.geometry.x[conn][..., :2]
    if msh.comm.size > 1:
        keys, coords = (np.concatenate(msh.comm.allgather(a)) for a in (keys, coords))
    keys, coords = _in_key_order(keys, coords)
    nodes, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    cells = inverse.reshape(keys.shape)
    points = placement.to_user(coords.reshape(-1, 2)[first])
    clockwise = signed_areas(points, cells) < 0  # a mapping or mesh generator may mirror cells
    cells[clockwise] = cells[clockwise, ::-1]
    centroids = points[cells].mean(axis=1)
    fields = getattr(fields, "extended", fields)  # an XFEM cut cell's vertices lie beyond Γ: its polynomial there
    return BodyMesh(points=points, cells=cells, cell_type=cell_name,
                    u=fields.displacement(points, np.full(len(points), body)),
                    sigma=fields.stress(centroids, np.full(len(cells), body)))


def _in_key_order(keys: np.ndarray, coords: np.ndarray):
    """Cells (rows of vertex ``keys``, with their ``coords``) sorted by
    their sorted vertex keys: an order that no numbering or partition of
    the mesh changes."""
    order = np.lexsort(np.sort(keys, axis=1).T[::-1])
    return keys[order], coords[order]


def signed_areas(points: np.ndarray, cells: np.ndarray) -> np.ndarray:
    """Shoelace area of each polygon ``points[cells[i]]``: positive when
    its vertices run counter-clockwise."""
    x, y = points[cells, 0], points[cells, 1]
    return 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
