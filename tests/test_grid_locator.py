"""The cell locator's grid (estcost, 2026-11-29): on a mesh that is one
axis-aligned grid of quadrilaterals (xfem's background mesh on a
rectangle) a point well inside a cell of its body takes that cell without
dolfinx's search; every answer (cell, distance, midpoint) must be the
search's, on cell edges, corners, just off them, outside the domain and
for a body whose cells are a part of the mesh, in serial and under mpirun."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from dolfinx import mesh
from mpi4py import MPI

ROOT = Path(__file__).resolve().parent.parent

#: Offsets from cell edges the points are put at (in the mesh's units,
#: cells of side 0.1 and 0.05): on the edge, far below dolfinx's collision
#: reach, about it, about the grid's margin (1e-7 of a cell here) and well
#: inside.
OFFSETS = (0.0, 1e-16, 1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 5e-8, 2e-7, 1e-6, 1e-3)


def _points(lo, hi, nx, ny, rng) -> np.ndarray:
    """Random points of the box, the grid's nodes, points on and off its
    lines by :data:`OFFSETS`, and some outside the box."""
    xs, ys = np.linspace(lo[0], hi[0], nx + 1), np.linspace(lo[1], hi[1], ny + 1)
    inner = lo + rng.random((400, 2)) * (hi - lo)
    nodes = np.array(np.meshgrid(xs, ys)).reshape(2, -1).T
    near = []
    for d in OFFSETS:
        for s in (-1, 1):
            t = lo[1] + rng.random(len(xs)) * (hi[1] - lo[1])
            near.append(np.column_stack([xs + s * d, t]))
            t = lo[0] + rng.random(len(ys)) * (hi[0] - lo[0])
            near.append(np.column_stack([t, ys + s * d]))
            near.append(nodes + s * d)
    outside = np.array([[lo[0] - 0.01, lo[1] + 0.3], [hi[0] + 0.2, hi[1] + 0.2], [lo[0] + 0.5, hi[1] + 1e-12]])
    return np.vstack([inner, nodes, *near, outside])


def _compare(comm, kind=mesh.CellType.quadrilateral) -> int:
    """The locator's answers with and without its grid on a 10 × 20 mesh
    of [0.2, 1.2] × [-0.5, 0.5] (cells 0.1 × 0.05), two bodies: all cells,
    and the cells left of x = 0.7 whose midpoint's y is below 0.1; returns
    how many points the grid answered (asserts equality)."""
    from xdolfinx.evaluation import BodyCellLocator

    lo, hi = np.array([0.2, -0.5]), np.array([1.2, 0.5])
    msh = mesh.create_rectangle(comm, [lo, hi], [10, 20], kind)
    n = msh.topology.index_map(2).size_local
    mid = mesh.compute_midpoints(msh, 2, np.arange(n, dtype=np.int32))
    some = np.flatnonzero((mid[:, 0] < 0.7) & (mid[:, 1] < 0.1)).astype(np.int32)
    locator = BodyCellLocator(msh, [np.arange(n, dtype=np.int32), some])
    pts = _points(lo, hi, 10, 20, np.random.default_rng(3))
    pts = pts[np.all((pts >= lo - 0.3) & (pts <= hi + 0.3), axis=1)]
    bodies = np.tile([0, 1], len(pts))[:len(pts)]
    grid = locator.cells_and_distances(pts, bodies)
    searched = locator._searched(pts, bodies)
    for a, b in zip(grid, searched):
        assert np.array_equal(a, b)
    if locator.grid is None:
        return 0
    return int(np.count_nonzero(locator.grid.inside(pts) >= 0))


def test_grid_gives_the_search_answer():
    """Serial: the grid answers most points, and every answer is the search's."""
    answered = _compare(MPI.COMM_WORLD)
    assert answered > 300


def test_no_grid_on_triangles():
    """Triangles are no grid: the locator searches, as before."""
    from xdolfinx.evaluation import _Grid

    msh = mesh.create_rectangle(MPI.COMM_WORLD, [np.zeros(2), np.ones(2)], [4, 4], mesh.CellType.triangle)
    assert _Grid.of(msh, msh.topology.index_map(2).size_local) is None
    assert _compare(MPI.COMM_WORLD, mesh.CellType.triangle) == 0


def test_xfem_background_mesh_is_a_grid():
    """xfem's background mesh on a rectangle (tests/scenes or scene A) is found as a grid."""
    from contactcore import load_scene
    from xdolfinx.evaluation import _Grid
    from xdolfinx.xfem.cells import background_mesh

    msh = background_mesh(load_scene("A"), 0.1, "quad")
    assert _Grid.of(msh, msh.topology.index_map(2).size_local) is not None


def test_grid_under_mpirun():
    """Two ranks, each with its owned part of the mesh: each rank's grid
    answers as its search does."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "PMI_"))}
    # one line from rank 0: two ranks' prints may share a line of mpirun's forwarded output
    code = ("import sys; sys.path.insert(0, 'tests'); from mpi4py import MPI; import test_grid_locator as t; "
            "c = MPI.COMM_WORLD; counts = c.gather(t._compare(c)); "
            "c.rank == 0 and print('answered', *counts, flush=True)")
    out = subprocess.run([shutil.which("mpirun"), "--allow-run-as-root", "-n", "2", sys.executable, "-c", code],
                         capture_output=True, text=True, timeout=120, cwd=ROOT, env=env, stdin=subprocess.DEVNULL)
    assert out.returncode == 0, out.stderr[-2000:]
    (line,) = [line for line in out.stdout.splitlines() if line.startswith("answered")]
    answered = [int(a) for a in line.split()[1:]]
    assert len(answered) == 2 and all(a > 0 for a in answered)
