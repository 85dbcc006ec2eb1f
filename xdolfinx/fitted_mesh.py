"""A scene's fitted mesh in dolfinx, built by :mod:`meshes` through gmsh."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from mpi4py import MPI

import meshes
from contactcore import Scene


@dataclass
class FittedMesh:
    """A dolfinx mesh whose cells carry body tags and facets the Γ/boundary tags."""

    mesh: object
    cell_tags: object
    facet_tags: object

    def cells_of(self, body: str) -> np.ndarray:
        t = self.cell_tags
        return t.indices[t.values == meshes.BODY[body]].astype(np.int32)

    def facets_tagged(self, tag: int) -> np.ndarray:
        t = self.facet_tags
        return t.indices[t.values == tag].astype(np.int32)

    @property
    def num_cells(self) -> int:
        """Cells over every rank."""
        return self.mesh.topology.index_map(2).size_global


def fitted_mesh(scene: Scene, h: float, *, order: int = 1, grading: meshes.Grading | None = None,
                comm=MPI.COMM_WORLD, gamma_on_one_rank: bool = False) -> FittedMesh:
    """Mesh ``scene`` with gmsh (Γ embedded, geometry of ``order``) and load it.

    ``gdim=2`` is required in dolfinx 0.5.2, whose default gives 3D vectors.
    ``gamma_on_one_rank``: under mpirun the cells near Γ on one rank
    (:mod:`xdolfinx.gamma_partition`), else dolfinx's partition.
    """
    with meshes.gmsh_session() as model:
        if comm.rank == 0:
            meshes.build_model(scene, h, order=order, grading=grading)
        return _loaded(model, comm, gamma_on_one_rank)


def _loaded(model, comm, gamma_on_one_rank: bool) -> FittedMesh:
    """The gmsh ``model`` (on rank 0) distributed by dolfinx, by its own
    partition or with Γ's neighbourhood on one rank (:func:`fitted_mesh`)."""
    from .gamma_partition import gamma_vertices, near_gamma_partitioner, partitioned
    io = gmshio()
    partitioner = None
    if gamma_on_one_rank and comm.size > 1:
        gamma = gamma_vertices(model, meshes.INTERFACE) if comm.rank == 0 else np.zeros(0, np.int64)
        partitioner = near_gamma_partitioner(gamma)
    with partitioned(io, partitioner):
        msh, cell_tags, facet_tags = io.model_to_mesh(model, comm, 0, gdim=2)
    msh.topology.create_connectivity(1, 2)
    return FittedMesh(msh, cell_tags, facet_tags)


def file_mesh(mesh, to_model, comm=MPI.COMM_WORLD, gamma_on_one_rank: bool = False) -> FittedMesh:
    """A user's mesh file (:class:`meshes.read.MeshFile`, checked by
    :func:`meshes.read.check_mesh`) loaded as :func:`fitted_mesh` loads
    fe's own: read into gmsh on rank 0 only, its nodes moved by
    ``to_model`` (the file's coordinates to the dimensionless scene's)
    and its groups renumbered to :mod:`meshes.tags` by name
    (:func:`meshes.read.load_model`), then distributed by dolfinx
    (``gamma_on_one_rank`` as in :func:`fitted_mesh`)."""
    from meshes.read import load_model
    with meshes.gmsh_session() as model:
        if comm.rank == 0:
            load_model(mesh, to_model)
        return _loaded(model, comm, gamma_on_one_rank)


def gmshio():
    """dolfinx's gmsh I/O, imported with SIGINT's handler left as it was:
    it imports gmsh, whose module sets the handler to the default
    (:func:`meshes.keeping_sigint`)."""
    with meshes.keeping_sigint():
        from dolfinx.io import gmshio
    return gmshio
