"""Point evaluation of per-body dolfinx functions.

Each body's displacement and stress live on the whole mesh but mean
something only on that body's cells.  A point is evaluated in a cell of the
requested body that contains it; if none does (a point of the exact curved
Γ that falls just outside the polygonal body), in the nearest cell of that
body, whose polynomial is then extended a distance O(h²) — the same
convention as the + side limit on Γ (docs/scenes.md).
"""
from __future__ import annotations

import numpy as np
from dolfinx import geometry
from dolfinx.mesh import compute_midpoints
from mpi4py import MPI
from scipy.spatial import cKDTree

from contactcore import DiscretisationError
from contactcore import tolerances as tol
from contactcore.bodies import Body
from contactcore.result import check_points

#: Nearest cell midpoints examined before the exact distance decides.
_NEAREST_CANDIDATES = 8

class _Grid:
    """The owned cells of a mesh that is one axis-aligned grid of
    rectangles (dolfinx's structured quadrilaterals on a rectangle: xfem's
    background mesh), found from the cells' own corners; None otherwise
    (:meth:`of`).  :meth:`inside` gives the cell a point lies in, well
    inside it (:data:`~contactcore.tolerances.GRID_MARGIN`), by one division and no search: the
    cell dolfinx's search finds, as nothing else is near the point."""

    def __init__(self, lo: np.ndarray, hi: np.ndarray, origin: np.ndarray, step: np.ndarray, index: np.ndarray):
        self.lo, self.hi, self.origin, self.step, self.index = lo, hi, origin, step, index
        self.margin = np.maximum(tol.GRID_MARGIN * (hi - lo), tol.GRID_REACH)

    @classmethod
    def of(cls, msh, ncells: int) -> "_Grid | None":
        """The grid of the ``ncells`` owned cells of ``msh``, or None where
        they are not one (not quadrilaterals, not axis-aligned rectangles
        of one size on one lattice)."""
        if msh.topology.cell_name() != "quadrilateral" or ncells == 0:
            return None
        dofs = msh.geometry.dofmap.array.reshape(-1, msh.geometry.dofmap.offsets[1])[:ncells]
        if dofs.shape[1] != 4:
            return None
        corners = msh.geometry.x[dofs][..., :2]                    # (cells, 4, 2)
        lo, hi = corners.min(axis=1), corners.max(axis=1)
        at_hi = corners == hi[:, None]
        on_box = np.all(at_hi | (corners == lo[:, None]), axis=(1, 2))
        code = np.sort(at_hi[..., 0] + 2 * at_hi[..., 1], axis=1)
        if not (np.all(on_box) and np.all(code == np.arange(4)) and np.all(hi > lo)):
            return None
        step = hi[0] - lo[0]
        origin = lo.min(axis=0)
        if not np.all(np.abs((hi - lo) - step) <= tol.GRID_LATTICE * step):
            return None
        ij = np.round((lo - origin) / step).astype(np.int64)
        if not np.all(np.abs(origin + ij * step - lo) <= tol.GRID_LATTICE * step):
            return None
        shape = ij.max(axis=0) + 1
        index = np.full(tuple(shape), -1, dtype=np.int32)
        index[ij[:, 0], ij[:, 1]] = np.arange(ncells, dtype=np.int32)
        if np.count_nonzero(index >= 0) != ncells:  # two cells on one lattice point
            return None
        return cls(lo, hi, origin, step, index)

    def inside(self, points: np.ndarray) -> np.ndarray:
        """(P,): the owned cell each point lies well inside, −1 where none
        (outside the grid's owned cells, or within the margin of an edge)."""
        i = np.floor((points[:, 0] - self.origin[0]) / self.step[0])
        j = np.floor((points[:, 1] - self.origin[1]) / self.step[1])
        nx, ny = self.index.shape
        ok = (i >= 0) & (i < nx) & (j >= 0) & (j < ny)
        cell = np.take(self.index.ravel(), np.where(ok, i * ny + j, 0).astype(np.int64))
        cell[~ok] = -1
        c = np.maximum(cell, 0)  # row gathers by np.take, several times numpy's fancy index
        lo, hi, margin = (np.take(a, c, axis=0) for a in (self.lo, self.hi, self.margin))
        well = ((points[:, 0] > lo[:, 0] + margin[:, 0]) & (points[:, 0] < hi[:, 0] - margin[:, 0])
                & (points[:, 1] > lo[:, 1] + margin[:, 1]) & (points[:, 1] < hi[:, 1] - margin[:, 1]))
        return np.where(well, cell, -1)


class BodyCellLocator:
    """Finds, for each point, a cell of a given body to evaluate in.

    ``body_cells[b]`` lists the cells that hold body b; the lists may
    overlap (an XFEM cell cut by Γ holds both bodies)."""

    def __init__(self, msh, body_cells: list[np.ndarray]):
        self.msh = msh
        tdim = msh.topology.dim
        ncells = msh.topology.index_map(tdim).size_local
        body_cells = [np.asarray(c, dtype=np.int32) for c in body_cells]
        self.holds = np.zeros((len(body_cells), ncells), bool)
        for b, cells in enumerate(body_cells):
            self.holds[b, cells[cells < ncells]] = True
        self.tree = geometry.BoundingBoxTree(msh, tdim)
        self.all_midpoints = compute_midpoints(msh, tdim, np.arange(ncells, dtype=np.int32))[:, :2]
        self.body_cells = [c[c < ncells] for c in body_cells]
        self.midpoints = [compute_midpoints(msh, tdim, c)[:, :2] for c in self.body_cells]
        self.kdtrees = [cKDTree(m) for m in self.midpoints]
        self.grid = _Grid.of(msh, ncells)  # a structured mesh's cells found without a search
        self._last = None  # the last choose's points, bodies and answer (:meth:`choose`)

    def cells(self, points: np.ndarray, bodies: np.ndarray) -> np.ndarray:
        """A cell of body ``bodies[i]`` holding (or nearest to) ``points[i]``;
        of several cells holding it (a point on a cell edge, where a stress
        jumps), the one whose midpoint comes first in x, then y: a choice
        that no numbering or partition of the mesh changes."""
        return self.cells_and_distances(points, bodies)[0]

    def cells_and_distances(self, points: np.ndarray, bodies: np.ndarray):
        """:meth:`cells` among this rank's owned cells, the squared distance
        from each point to its cell (0 inside it; inf, with cell −1, where
        this rank owns no cell of that body) and the cell's midpoint.
        On a grid (:class:`_Grid`), a point well inside a cell of its body
        takes that cell at distance 0 without a search (the answer of the
        search: no other cell is near it); the others are searched."""
        if self.grid is None:
            return self._searched(points, bodies)
        cells = self.grid.inside(points)
        found = cells >= 0
        found &= np.take(self.holds.ravel(), np.asarray(bodies, np.int64) * self.holds.shape[1] + np.maximum(cells, 0))
        out = np.where(found, cells, -1).astype(np.int32)
        dist = np.zeros(len(points))
        key = np.take(self.all_midpoints, np.maximum(out, 0), axis=0)
        rest = np.flatnonzero(~found)
        if len(rest):
            out[rest], dist[rest], key[rest] = self._searched(points[rest], bodies[rest])
        return out, dist, key

    def _searched(self, points: np.ndarray, bodies: np.ndarray):
        """:meth:`cells_and_distances` by dolfinx's search of every point."""
        p3 = np.zeros((len(points), 3))
        p3[:, :2] = points
        colliding = geometry.compute_colliding_cells(self.msh, geometry.compute_collisions(self.tree, p3), p3)
        out = np.full(len(points), -1, dtype=np.int32)
        owner = np.repeat(np.arange(len(points)), np.diff(colliding.offsets))
        hit = colliding.array
        ok = hit < self.holds.shape[1]
        ok[ok] = self.holds[bodies[owner[ok]], hit[ok]]
        owner, hit = owner[ok], hit[ok]
        mid = self.all_midpoints[hit]
        order = np.lexsort((mid[:, 1], mid[:, 0], owner))  # per point, the first midpoint in x, then y
        first_point, first = np.unique(owner[order], return_index=True)
        out[first_point] = hit[order][first]
        dist = np.where(out >= 0, 0.0, np.inf)
        for b in np.unique(bodies[out < 0]):
            missing = np.flatnonzero((out < 0) & (bodies == b))
            k = min(_NEAREST_CANDIDATES, len(self.body_cells[b]))
            if k == 0:
                continue
            _, idx = self.kdtrees[b].query(points[missing], k=k)
            idx = idx.reshape(len(missing), k)
            for j, i in enumerate(missing):
                cand = self.body_cells[b][idx[j]]
                d2 = geometry.squared_distance(self.msh, 2, cand, np.tile(p3[i], (len(cand), 1)))
                out[i], dist[i] = cand[int(np.argmin(d2))], float(np.min(d2))
        key = np.where((out >= 0)[:, None], self.all_midpoints[np.maximum(out, 0)], np.inf)
        return out, dist, key


    def choose(self, points: np.ndarray, bodies: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The cell of each point (:meth:`cells_and_distances`) and whether
        this rank evaluates it.  Under mpirun a collective call: each point
        goes to the cell the rule picks among every rank's (holding it, else
        nearest; the first midpoint on a tie), and only that cell's rank
        evaluates it; :meth:`combine` then gives every rank the values.
        The same points and bodies as the last call (on every rank) reuse
        its answer: a stress read twice at the same points (the energy
        estimate's direct and recovered stress at 4 × 10^5 Gauss points)
        locates them once."""
        last, comm = self._last, self.msh.comm
        same = (last is not None and np.array_equal(last[0], points) and np.array_equal(last[1], bodies))
        if (same if comm.size == 1 else comm.allreduce(same, op=MPI.LAND)):
            return last[2].copy(), last[3].copy()
        cells, mine = self._choose(points, bodies)
        self._last = (np.array(points, copy=True), np.array(bodies, copy=True), cells.copy(), mine.copy())
        return cells, mine

    def _choose(self, points: np.ndarray, bodies: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`choose`, computed."""
        cells, dist, key = self.cells_and_distances(points, bodies)
        mine = cells >= 0
        comm = self.msh.comm
        dists = dist[None] if comm.size == 1 else np.array(comm.allgather(dist))
        nowhere = np.flatnonzero(np.all(np.isinf(dists), axis=0))
        if len(nowhere):  # every rank sees it: a zero would otherwise stand for the value
            i = int(nowhere[0])
            raise DiscretisationError(f"no cell of body {Body(int(bodies[i])).label} to evaluate its fields in at "
                                      f"({points[i][0]:.6g}, {points[i][1]:.6g}) ({len(nowhere)} point(s))")
        if comm.size > 1:
            keys = np.array(comm.allgather(key))
            mine &= np.lexsort((keys[..., 1], keys[..., 0], dists), axis=0)[0] == comm.rank
        return cells, mine

    def combine(self, values: np.ndarray) -> np.ndarray:
        """Every rank's evaluations (zero where it did not evaluate) summed:
        each point's value, on every rank."""
        comm = self.msh.comm
        return values if comm.size == 1 else comm.allreduce(values, op=MPI.SUM)


class BodyFields:
    """The :class:`contactcore.result.Fields` of per-body dolfinx functions.

    ``displacements[b]`` and ``stresses[b]`` (Voigt ``xx, yy, xy``) are
    dolfinx Functions of body ``b`` (0 = −, 1 = +) on the whole mesh.
    """

    def __init__(self, locator: BodyCellLocator, displacements, stresses):
        self.locator, self.displacements, self.stresses = locator, displacements, stresses

    def _eval(self, functions, points, bodies) -> np.ndarray:
        """Under mpirun a collective call (:meth:`BodyCellLocator.choose`)."""
        points, bodies = check_points(points, bodies)  # the arrays; the geometry is the Result's (ScaledFields)
        cells, mine = self.locator.choose(points, bodies)
        p3 = np.zeros((len(points), 3))
        p3[:, :2] = points
        out = np.zeros((len(points), int(np.prod(functions[0].function_space.element.value_shape))))
        for b, fn in enumerate(functions):
            sel = np.flatnonzero((bodies == b) & mine)
            if len(sel):
                out[sel] = fn.eval(p3[sel], cells[sel]).reshape(len(sel), -1)
        return self.locator.combine(out)

    def displacement(self, points, bodies) -> np.ndarray:
        """``u`` (m, 2) of body ``bodies[i]`` (0 = −, 1 = +) at ``points[i]``
        ((m, 2)) on the method's dimensionless scene.  Only the arrays are
        checked here (shape, finite, bodies 0 or 1: FieldsError); where a
        point lies is checked by the Result's :class:`~contactcore.scaling.ScaledFields`
        before it arrives."""
        return self._eval(self.displacements, points, bodies)

    def stress(self, points, bodies) -> np.ndarray:
        """``(σxx, σyy, σxy)`` (m, 3) of body ``bodies[i]`` at ``points[i]``,
        dimensionless; the arrays checked as for :meth:`displacement`."""
        return self._eval(self.stresses, points, bodies)
