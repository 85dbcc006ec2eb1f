"""Field files of one run for ParaView and meshio (``run --fields``).

``DIR/<method>/fields/`` holds, written through meshio as VTU (XML,
base64), which both ParaView and ``meshio.read`` open:

``minus.vtu``, ``plus.vtu``   (methods with a mesh: fe, xfem) each body's
    mesh at the final state: point data ``u`` (vertices), cell data
    ``sigma_xx_cell``, ``sigma_yy_cell``, ``sigma_xy_cell`` (the value at
    the cell's centroid, :mod:`xdolfinx.output`).
``interface_NNNN.vtu``        (every method) Γ's quadrature points as a
    point cloud at converged step NNNN: point data ``gN``, ``gT``, ``tN``,
    ``tT``, ``status`` (0 open, 1 stick, 2 slip, 3 partial: the unilateral
    law's partial answer, contactcore.newton.partial), ``s`` (along Γ), and
    at a step with partial points ``theta`` (a partial point's share θ of
    the tie's shear, NaN at the others).
``interface.pvd``             the steps as a time series (time = the step).

Bulk fields exist at the final state only (the methods keep no per-step
fields); the interface has every step.
"""
from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import quoteattr

import meshio
import numpy as np

from contactcore import BODIES
from contactcore.interface_path import InterfacePath, along_from_entry

from . import files

VOIGT = ("xx", "yy", "xy")


def _points3(points: np.ndarray) -> np.ndarray:
    """2D points padded with z = 0 (VTK's points are 3D)."""
    return np.column_stack([points, np.zeros(len(points))])


def write_body(path: Path, body) -> None:
    """One :class:`xdolfinx.output.BodyMesh` as a VTU file."""
    from xdolfinx.output import MESHIO_CELL

    mesh = meshio.Mesh(_points3(body.points), [(MESHIO_CELL[body.cell_type], body.cells)],
                       point_data={"u": _points3(body.u)},
                       cell_data={f"sigma_{c}_cell": [body.sigma[:, i]] for i, c in enumerate(VOIGT)})
    mesh.write(path, file_format="vtu")


def write_interface(folder: Path, scene, path: InterfacePath) -> list[tuple[float, str]]:
    """Γ's state at every step as VTU point clouds; ``(step, file name)``s."""
    s = along_from_entry(scene, path.points)
    vertices = [("vertex", np.arange(len(path.points))[:, None])]
    written = []
    for n, step in enumerate(path.steps):
        name = f"interface_{n:04d}.vtu"
        data = {"gN": step.jump[:, 0], "gT": step.jump[:, 1], "tN": step.traction[:, 0],
                "tT": step.traction[:, 1], "status": np.asarray(step.reported_status(), np.int32), "s": s}
        if step.partial.any():
            data["theta"] = np.asarray(step.theta, float)
        meshio.Mesh(_points3(path.points), vertices, point_data=data).write(folder / name, file_format="vtu")
        written.append((float(step.step), name))
    return written


def pvd_text(entries: list[tuple[float, str]]) -> str:
    """A ParaView collection: one dataset per ``(time, file)``."""
    rows = "".join(f'    <DataSet timestep="{t!r}" part="0" file={quoteattr(f)}/>\n' for t, f in entries)
    return ('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n'
            f"{rows}  </Collection>\n</VTKFile>\n")


def write_fields(folder: Path, result, mesh: bool) -> list[str]:
    """All field files of one Result (see module doc) in ``folder``, written
    atomically as a whole; ``mesh``: write the bodies too.  The names
    written.  Under mpirun every rank builds the bodies (a collective call,
    :func:`xdolfinx.output.body_mesh`) and rank 0 alone writes
    (:func:`files.writes_here`; the others write nothing and return [])."""
    bodies = []
    if mesh:
        from xdolfinx.output import body_mesh  # imports dolfinx: only for a method with a mesh

        bodies = [body_mesh(result.fields, b) for b in range(len(BODIES))]
    if not files.writes_here():
        return []
    with files.atomic_folder(folder) as tmp:
        for name, body in zip(BODIES, bodies):
            write_body(tmp / f"{name}.vtu", body)
        if result.interface is not None and result.interface.steps:
            entries = write_interface(tmp, result.scene, result.interface)
            (tmp / "interface.pvd").write_text(pvd_text(entries))
        return sorted(p.name for p in tmp.iterdir())

