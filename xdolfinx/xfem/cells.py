"""XFEM's background mesh and its cells: the mesh that ignores Γ, which side
of Γ each node lies on (a node within its snap distance on Γ), and the Lagrange basis of each cell at physical
points (affine cells, or dolfinx's pull-back on a curved one)."""
from __future__ import annotations

import basix
import numpy as np
from dolfinx import fem, la, mesh
from mpi4py import MPI

from contactcore import Scene
from contactcore import tolerances as tol
from contactcore.bodies import side as side_of
from contactcore.collective import Collective
from contactcore.discretisation import check_choice
from contactcore.geometry import Rectangle

from ..options import XFEM_CELLS, cell_counts


def background_cell(scene: Scene, cell: str) -> str:
    """The background cells that run for the requested ``cell``: structured
    quads or triangles on a rectangle, gmsh triangles otherwise (a disc)."""
    check_choice("xfem", "cell", cell, XFEM_CELLS)
    return cell if isinstance(scene.domain, Rectangle) else "gmsh"


def background_mesh(scene: Scene, h: float, cell: str, counts=None, comm=MPI.COMM_WORLD, order: int = 1,
                    cut_on_one_rank: bool = False):
    """A mesh of the outer domain that ignores Γ, cells of size ≈ h (or
    ``counts`` cells per side): structured quadrilaterals or triangles on a
    rectangle, or ``cell="gmsh"`` triangles of the outer domain (the only
    choice for a disc), pins embedded as nodes, with geometry of ``order``
    1 or 2 (curved cells on a curved outer boundary: a polygonal rim caps
    degree 2 at an O(h²) error).  ``cut_on_one_rank``: under mpirun the
    cells near Γ on one rank (:func:`cut_partitioner`), for the reaction
    flux (:mod:`xdolfinx.reaction`); dolfinx's partition otherwise."""
    near = cut_on_one_rank and comm.size > 1
    if background_cell(scene, cell) == "gmsh":
        import meshes
        from xdolfinx.fitted_mesh import gmshio
        from xdolfinx.gamma_partition import partitioned

        with meshes.gmsh_session() as model:
            if comm.rank == 0:
                meshes.build_model(scene, h, order=order, fitted=False)
            io = gmshio()
            with partitioned(io, cut_partitioner(scene, _gmsh_inputs(model, comm)) if near else None):
                return io.model_to_mesh(model, comm, 0, gdim=2)[0]
    (x0, y0), (a, b) = scene.domain.corner, scene.domain.size
    n = list(counts) if counts is not None else cell_counts(scene, h)
    kind = mesh.CellType.quadrilateral if cell == "quad" else mesh.CellType.triangle
    corners = [np.array([x0, y0]), np.array([x0 + a, y0 + b])]
    if not near:
        return mesh.create_rectangle(comm, corners, n, kind)
    whole = mesh.create_rectangle(MPI.COMM_SELF, corners, n, kind) if comm.rank == 0 else None
    inputs = np.zeros((0, 2)) if whole is None else _by_input(whole.geometry.input_global_indices,
                                                               whole.geometry.x[:, :2])
    return mesh.create_rectangle(comm, corners, n, kind, partitioner=cut_partitioner(scene, inputs))


def cut_partitioner(scene: Scene, inputs: np.ndarray):
    """dolfinx's partitioner with every cell within
    :data:`~contactcore.tolerances.REACTION_GAMMA_LAYERS` of the cells Γ
    may cross on one rank (:func:`xdolfinx.gamma_partition.near_cells_partitioner`),
    ``inputs`` the input nodes' coordinates (on the rank that holds the
    cells).  A cell Γ meets has every corner within its diameter of Γ
    (:func:`diameters`, at least the largest distance between corners):
    those cells, a few more than the cut ones, seed the layers."""
    from xdolfinx.gamma_partition import near_cells_partitioner

    def seeds(vertices: np.ndarray) -> np.ndarray:
        corners = inputs[vertices]
        distance = np.abs(scene.interface.signed_distance(corners.reshape(-1, 2))).reshape(vertices.shape)
        met = np.all(distance <= diameters(corners)[:, None], axis=1)
        return np.unique(vertices[met])

    return near_cells_partitioner(seeds, "xfem", "dolfinx's rectangle or gmsh's")


def _gmsh_inputs(model, comm) -> np.ndarray:
    """The coordinates of gmsh's nodes by input index (node tag − 1, as
    ``gmshio`` numbers them) on the rank that holds the model."""
    if comm.rank != 0:
        return np.zeros((0, 2))
    tags, coords, _ = model.mesh.getNodes()
    return _by_input(np.asarray(tags, np.int64) - 1, np.asarray(coords).reshape(-1, 3)[:, :2])


def _by_input(indices: np.ndarray, coords: np.ndarray) -> np.ndarray:
    """(inputs, 2): ``coords`` placed at their input ``indices``."""
    out = np.zeros((int(np.max(indices, initial=-1)) + 1, 2))
    out[np.asarray(indices, np.int64)] = coords
    return out


def node_sides(scene: Scene, coords: np.ndarray, snap) -> np.ndarray:
    """The side (±1) of mesh nodes, a node within ``snap`` (one distance,
    or one per node) of Γ on Γ (+1): XFEM's one rule near a node
    (:data:`contactcore.tolerances.XFEM_SNAP`, :attr:`CellBasis.node_snap`),
    the same for every cell and rank that computed its coordinates.  The
    distance is |φ|/|∇φ| (φ itself for a line or a circle)."""
    itf = scene.interface
    return np.where(on_gamma(scene, coords, snap), 1, side_of(itf, coords))


def on_gamma(scene: Scene, coords: np.ndarray, snap) -> np.ndarray:
    """(points,) bool: the points within ``snap`` (one distance, or one per
    point) of Γ (|φ|/|∇φ|), which XFEM snaps Γ to
    (:data:`contactcore.tolerances.XFEM_SNAP`)."""
    return np.abs(scene.interface.signed_distance(coords)) <= snap


def diameters(corners: np.ndarray) -> np.ndarray:
    """(cells,): each cell's diameter, twice its corners' largest distance
    from their mean."""
    centre = corners.mean(axis=1)
    return 2 * np.max(np.linalg.norm(corners - centre[:, None], axis=2), axis=1)


class CellBasis:
    """The cells of ``msh`` and dolfinx's vector Lagrange space V of
    ``degree`` on them (block size 2, one block per node), with what the
    cut-cell kernels need per cell: its corners counter-clockwise, its
    affine map ``x = origin + J X`` (from the first three geometry nodes),
    whether it is curved, its nodes (V's blocks) and each node's side of Γ.

    Local numbering is dolfinx's: owned nodes and cells first, then the
    ghosts this rank sees under mpirun (:attr:`owned_nodes`,
    :attr:`owned_cells`)."""

    def __init__(self, msh, degree: int, scene: Scene):
        self.msh, self.degree = msh, degree
        self.V = fem.VectorFunctionSpace(msh, ("Lagrange", degree), dim=2)
        name = msh.topology.cell_name()
        cell_type = basix.cell.string_to_type(name)
        self.element = basix.create_element(basix.ElementFamily.P, cell_type, degree, basix.LagrangeVariant.gll_warped)
        tdim = msh.topology.dim
        self.owned_cells = msh.topology.index_map(tdim).size_local
        self.num_cells = self.owned_cells + msh.topology.index_map(tdim).num_ghosts
        geom = msh.geometry.dofmap.array.reshape(self.num_cells, -1)
        x = msh.geometry.x[:, :2]
        self.cell_geometry = x[geom]
        self.origin = x[geom[:, 0]]
        self.jacobian = np.stack([x[geom[:, 1]] - self.origin, x[geom[:, 2]] - self.origin], axis=2)
        self.inverse = np.linalg.inv(self.jacobian)
        self.cmap = msh.geometry.cmap
        self.geometry_element = basix.create_element(basix.ElementFamily.P, cell_type, self.cmap.degree,
                                                     basix.LagrangeVariant.equispaced)
        self.curved = self._curved_cells()
        # corners counter-clockwise (dolfinx orders a quadrilateral's as 0, 1, 3, 2)
        corners = x[geom[:, [0, 1, 3, 2]]] if name == "quadrilateral" else x[geom[:, :3]]
        area2 = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        flip = (area2 < 0)[:, None]
        self.corners = np.where(flip[:, :, None], corners[:, ::-1], corners)
        self.cell_dofs = self.V.dofmap.list.array.reshape(self.num_cells, -1)  # block (node) indices
        # V's first dofs of a cell are its vertices, in the geometry's order
        vertices = self.cell_dofs[:, [0, 1, 3, 2]] if name == "quadrilateral" else self.cell_dofs[:, :3]
        #: (cells, corners): V's node at each of :attr:`corners`
        self.corner_nodes = np.where(flip, vertices[:, ::-1], vertices)
        self.owned_nodes = self.V.dofmap.index_map.size_local  # the others are ghosts (mpirun)
        self.ranks = Collective(msh.comm)
        #: (cells,): XFEM_SNAP of each cell's own diameter (:data:`contactcore.tolerances.XFEM_SNAP`)
        self.cell_snap = tol.XFEM_SNAP * diameters(self.corners)
        #: (nodes,): XFEM's snap distance at each node, XFEM_SNAP of the
        #: largest diameter of the cells that hold it (over every rank): a
        #: node this close to Γ lies on it, and Γ is snapped to it.  Local,
        #: so that a graded mesh's small cells are snapped by 1e-5 of
        #: themselves and not of the mesh's largest cell; the largest of
        #: the node's cells, so that no cell holding it keeps a part thinner
        #: than 1e-5 of itself beside it.
        self.node_snap = self._node_max(self.cell_snap)
        coords = self.V.tabulate_dof_coordinates()[:, :2]
        #: (nodes,) bool: the nodes on Γ (within :attr:`node_snap`)
        self.node_on = on_gamma(scene, coords, self.node_snap)
        self.node_side = np.where(self.node_on, 1, side_of(scene.interface, coords))
        #: (nodes,): how far off Γ each node on it lies, a share of its
        #: snap's cell diameter (0 off Γ): how far XFEM moved Γ there
        self.node_moved = np.where(self.node_on, np.abs(scene.interface.signed_distance(coords))
                                   * tol.XFEM_SNAP / self.node_snap, 0.0)

    def snap_warnings(self) -> list[str]:
        """A warning where XFEM moved Γ onto mesh nodes by more than
        ``XFEM_SNAP_WARN`` of their cells' diameter (:attr:`node_moved`,
        over every rank): the answer moves with Γ, by about that share."""
        owned = self.node_moved[:self.owned_nodes]
        moved = self.ranks.max(float(np.max(owned, initial=0.0)))
        if not moved > tol.XFEM_SNAP_WARN:
            return []
        count = int(self.ranks.sum(int(np.count_nonzero(owned > tol.XFEM_SNAP_WARN))))
        return [f"Γ passes {moved:.1e} of a cell's diameter or less from {count} mesh node(s), and XFEM moved it onto "
                f"them (XFEM_SNAP = {tol.XFEM_SNAP:g} of a cell): the answer moves with Γ, by about that share (a "
                "uniform stress's t_N by 2.5 times it, grader24); to have it exact, put Γ on the nodes or more "
                f"than {tol.XFEM_SNAP:g} of a cell off them"]

    def _node_max(self, cell_values: np.ndarray) -> np.ndarray:
        """(nodes,): the largest of ``cell_values`` over the cells that
        hold each node, on every rank that holds a cell of it (each rank
        sends its ghosts' values to their owners, which send the result
        back)."""
        out = np.zeros(len(self.V.dofmap.index_map.ghosts) + self.owned_nodes)
        np.maximum.at(out, self.cell_dofs, cell_values[:, None])
        if not self.ranks.parallel:
            return out
        imap, n = self.V.dofmap.index_map, self.owned_nodes
        ghosts = self.ranks.gather(imap.ghosts.astype(np.int64))
        values = self.ranks.gather(out[n:])
        start, stop = imap.local_range
        mine = (ghosts >= start) & (ghosts < stop)
        np.maximum.at(out, ghosts[mine] - start, values[mine])
        vector = la.vector(imap, 1)
        vector.array[:n] = out[:n]
        vector.scatter_forward()
        return vector.array.copy()

    def _curved_cells(self) -> np.ndarray:
        """Cells whose geometry nodes are not the affine image (from the
        first three) of the reference nodes: curved cells on a curved rim,
        or quadrilaterals that are not parallelograms."""
        X = np.einsum("cpa,cda->cpd", self.cell_geometry - self.origin[:, None], self.inverse)
        gap = np.max(np.abs(X - self.geometry_element.points[None]), axis=(1, 2))
        return gap > tol.GEOMETRY

    def tabulate(self, cell: int, points: np.ndarray):
        """Values (P, n) and physical gradients (P, n, 2) of the cell's
        basis functions at physical points: ``∇N = ∇_X N · J⁻¹`` with
        ``X = F⁻¹(x)``, affine or, on a curved cell, dolfinx's Newton
        pull-back and ``J(X) = Σ_i x_i ⊗ ∇_X φ_i(X)`` of the geometry."""
        if not self.curved[cell]:
            X = (points - self.origin[cell]) @ self.inverse[cell].T
            tab = self.element.tabulate(1, X)
            return tab[0, :, :, 0], np.stack([tab[1, :, :, 0], tab[2, :, :, 0]], axis=-1) @ self.inverse[cell]
        nodes = np.ascontiguousarray(self.cell_geometry[cell])
        X = self.cmap.pull_back(np.ascontiguousarray(points, dtype=float), nodes)
        dphi = self.geometry_element.tabulate(1, X)[1:3, :, :, 0]            # (2, P, nodes)
        inverse = np.linalg.inv(np.einsum("ia,dpi->pad", nodes, dphi))      # (P, 2, 2): ∂X_d/∂x_a
        tab = self.element.tabulate(1, X)
        dN = np.stack([tab[1, :, :, 0], tab[2, :, :, 0]], axis=-1)
        return tab[0, :, :, 0], np.einsum("pnd,pda->pna", dN, inverse)

    def affine_gradients(self, cells: np.ndarray, X: np.ndarray) -> np.ndarray:
        """(cells, P, n, 2): the physical gradients of the basis of affine
        ``cells`` at reference points X (P, 2), ``∇_X N · J⁻¹`` of each cell."""
        dN_ref = np.moveaxis(self.element.tabulate(1, X)[1:3, :, :, 0], 0, -1)    # (P, n, 2)
        return np.einsum("pnd,cda->cpna", dN_ref, self.inverse[cells])
