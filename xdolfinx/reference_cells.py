"""fe's mesh cells as basix sees them: one idea, the reference cell of
each of the fitted mesh's triangles, its P element, its geometry map and
the connectivity of Γ's facets, so that fe's interface operators
(:mod:`xdolfinx.conforming` at Γ's Gauss points, :mod:`xdolfinx.nodal` at
its nodes) read one facet's points, geometry and shape functions alike."""
from __future__ import annotations

import basix
import numpy as np

from contactcore import BODIES

from .fitted_mesh import FittedMesh


class ReferenceCells:
    """The mesh's cells as basix sees them: the degree's P element, the
    geometry map, the reference facets and the connectivity of Γ's facets."""

    def __init__(self, fm: FittedMesh, degree: int):
        msh = fm.mesh
        tdim = msh.topology.dim
        msh.topology.create_connectivity(tdim - 1, tdim)
        msh.topology.create_connectivity(tdim, tdim - 1)
        self.f2c, self.c2f = msh.topology.connectivity(tdim - 1, tdim), msh.topology.connectivity(tdim, tdim - 1)
        cell = basix.CellType.triangle
        self.element = basix.create_element(basix.ElementFamily.P, cell, degree, basix.LagrangeVariant.gll_warped)
        gdeg = msh.ufl_domain().ufl_coordinate_element().degree()
        self.cmap = basix.create_element(basix.ElementFamily.P, cell, gdeg, basix.LagrangeVariant.gll_warped)
        self.ref, self.edges = basix.geometry(cell), basix.topology(cell)[1]
        self.geom, self.xg = msh.geometry.dofmap, msh.geometry.x[:, :2]
        # each cell's body by the mesher's tag (-1: untagged), not by where
        # its centroid falls: a straight facet cuts inside a circular Γ by
        # its sagitta, and in a ligament thinner than that the centroid of
        # a cell outside Γ lies inside it (grader13 #5)
        cells = msh.topology.index_map(tdim)
        self.body = np.full(cells.size_local + cells.num_ghosts, -1, dtype=np.int64)
        for b, name in enumerate(BODIES):
            self.body[fm.cells_of(name)] = b

    def coords(self, c: int) -> np.ndarray:
        return self.xg[self.geom.links(c)]

    def _ends(self, c: int, f: int) -> tuple[np.ndarray, np.ndarray]:
        a, b = self.ref[self.edges[int(np.flatnonzero(self.c2f.links(c) == f)[0])]]
        return a, b

    def edge(self, c: int, f: int) -> np.ndarray:
        a, b = self._ends(c, f)
        return b - a

    def facet_points(self, c: int, f: int, xi: np.ndarray) -> np.ndarray:
        """Reference points of cell ``c`` at the parameters ``xi`` of facet ``f``."""
        a, b = self._ends(c, f)
        return a + xi[:, None] * (b - a)

    def facet_map(self, c: int, f: int, xi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Facet ``f`` of cell ``c`` at its parameters ``xi``: the reference
        points ``X``, the cell's nodes, the geometry map's tabulation (value
        and first derivatives) at ``X`` and ``∂x/∂ξ`` along the facet
        (``dΓ = |∂x/∂ξ| dξ``)."""
        X = self.facet_points(c, f, xi)
        coords = self.coords(c)
        tab = self.cmap.tabulate(1, X)
        edge = self.edge(c, f)
        return X, coords, tab, (tab[1, :, :, 0] * edge[0] + tab[2, :, :, 0] * edge[1]) @ coords

    def gradients(self, X: np.ndarray, coords: np.ndarray) -> np.ndarray:
        """``∂N_a/∂x_i`` (cells, points, dofs, 2) of the P element in cells
        of nodes ``coords`` (cells, nodes, 2) at the reference points ``X``."""
        geo = self.cmap.tabulate(1, X)[1:, :, :, 0]  # (2, points, nodes): ∂ψ/∂X_k
        J = np.einsum("kpg,cgi->cpik", geo, coords)  # ∂x_i/∂X_k
        dN = self.element.tabulate(1, X)[1:, :, :, 0]  # (2, points, dofs)
        return np.einsum("kpa,cpki->cpai", dN, np.linalg.inv(J))
