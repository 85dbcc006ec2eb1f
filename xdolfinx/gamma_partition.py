"""A partition of fe's fitted mesh that keeps every cell near Γ on one
rank, for the nodal reaction (``FE(flux="reaction")``, :mod:`xdolfinx.nodal`)
under mpirun.

A Γ node's reaction is its assembled rows of ``A`` for both bodies, and
``S = L A`` then ``SᵀWΓ⁻¹S`` couple unknowns two cells apart.  With every
cell that touches Γ (layer 1) and every cell that shares a vertex with
one of those (layer 2) owned by rank 0, each Γ node's dofs and every
dof of a layer-1 cell are touched by rank 0's own cells only: rank 0 owns
them and assembles their rows whole, so ``S`` and the interface's tangent
live in rank 0's owned rows and columns (another rank's ghost cells
share a facet with its own, hence are beyond layer 1, and hold no
Γ node).  The other cells keep dolfinx's graph partition.

xfem's reaction flux takes the same partition of its background mesh
(gmsh's, or dolfinx's rectangle), seeded by its cut cells' corners in
place of Γ's vertices (:func:`near_cells_partitioner`;
:mod:`xdolfinx.reaction` says why two layers suffice there too).

Ghosts follow dolfinx's ``shared_facet`` mode (its default, which
``gmshio.model_to_mesh`` takes): a cell is also sent to the owner of
each cell across one of its facets.
"""
from __future__ import annotations

import functools
from contextlib import contextmanager

import numpy as np

from contactcore import DiscretisationError
from contactcore.tolerances import REACTION_GAMMA_LAYERS

#: the rank that owns the cells near Γ
GAMMA_RANK = 0

#: a cell's facets as pairs of its vertices, by its number of vertices:
#: a triangle's, and a quadrilateral's in dolfinx's order (0, 1, 3, 2 round it)
FACETS = {3: [(0, 1), (1, 2), (0, 2)], 4: [(0, 1), (0, 2), (1, 3), (2, 3)]}


def gamma_vertices(model, tag: int) -> np.ndarray:
    """The input indices (gmsh's node tag − 1, as dolfinx's ``gmshio``
    numbers the nodes) of the nodes of the physical group ``tag`` of
    dimension 1 (Γ), on the rank that holds the gmsh model."""
    tags, _ = model.mesh.getNodesForPhysicalGroup(1, tag)
    return np.asarray(tags, np.int64) - 1


def near_gamma_partitioner(gamma: np.ndarray):
    """dolfinx's cell partitioner (``create_mesh``'s ``partitioner``), but
    with every cell within :data:`~contactcore.tolerances.REACTION_GAMMA_LAYERS`
    of the vertices ``gamma`` (input indices, given on the rank that holds
    the cells) owned by :data:`GAMMA_RANK`, and each cell ghosted across
    its facets (``shared_facet``, the mode ``gmshio`` asks for; module doc)."""
    return near_cells_partitioner(lambda vertices: gamma, "fe", "gmsh's")


def near_cells_partitioner(seeds, method: str, source: str):
    """:func:`near_gamma_partitioner` with the seed vertices given by
    ``seeds(vertices)`` (input indices; ``vertices`` the (cells, corners)
    input indices of every cell, on the rank that holds them): xfem's are
    its cut cells' corners (:mod:`xdolfinx.xfem.cells`); ``method`` and
    the mesh's ``source`` name the refusal's.  Triangles or dolfinx's quadrilaterals."""
    from dolfinx import cpp
    from dolfinx.mesh import GhostMode
    graph = cpp.mesh.create_cell_partitioner()

    def partition(comm, nparts, tdim, cells, _ghost_mode):
        first = graph(comm, nparts, tdim, cells, GhostMode.none)
        owners = first.array[first.offsets[:-1]]  # each cell's one rank
        if comm.allreduce(int(len(owners) > 0)) > 1:
            raise DiscretisationError(f"{method}: flux = \"reaction\" under mpirun needs the mesh's cells on one "
                                      f"rank before they are distributed ({source}, as {method} reads them)")
        vertices = cells.array.reshape(len(owners), -1) if len(owners) else np.zeros((0, tdim + 1), np.int64)
        near = _near(vertices, seeds(vertices), REACTION_GAMMA_LAYERS)
        owners = np.where(near, GAMMA_RANK, owners).astype(np.int32)
        _check_every_rank_holds_cells(comm, nparts, owners, near, method)
        lists = [np.array([o, *g], np.int32) for o, g in zip(owners, _facet_ghosts(vertices, owners))]
        offsets = np.cumsum([0] + [len(v) for v in lists]).astype(np.int32)
        data = np.concatenate(lists) if lists else np.zeros(0, np.int32)
        return cpp.graph.AdjacencyList_int32(data, offsets)

    return partition


def _check_every_rank_holds_cells(comm, nparts: int, owners: np.ndarray, near: np.ndarray, method: str) -> None:
    """Refuse, on every rank alike, a partition that leaves a rank no cell
    (every cell near Γ, on a coarse mesh or many ranks): dolfinx 0.5.2
    crashes (a segmentation fault in ``DofMap.collapse``) on a rank
    without cells.  ``owners`` and ``near`` (each cell's rank, and whether
    it is near Γ) are given on the one rank holding the cells; ``method``
    names the run in the message."""
    counts = comm.allreduce(np.bincount(owners, minlength=nparts))
    empty = int(np.count_nonzero(counts == 0))
    if empty:
        raise DiscretisationError(
            f'{method}: flux = "reaction" under mpirun: rank {GAMMA_RANK} holds every cell within '
            f"{REACTION_GAMMA_LAYERS} layers of Γ ({comm.allreduce(int(near.sum()))} of the mesh's "
            f"{int(counts.sum())} cells), which leaves {empty} of the {nparts} ranks no cell; run on fewer ranks "
            "or at a smaller h")


def _near(cells: np.ndarray, gamma: np.ndarray, layers: int) -> np.ndarray:
    """(cells,) bool: the cells within ``layers`` of the vertices ``gamma``:
    layer 1 touches one of them, layer k + 1 shares a vertex with layer k."""
    near = np.zeros(len(cells), bool)
    reached = np.asarray(gamma, np.int64)
    for _ in range(layers):
        near |= np.isin(cells, reached).any(axis=1)
        reached = np.unique(cells[near])
    return near


def _facet_ghosts(cells: np.ndarray, owners: np.ndarray) -> list:
    """Each cell's ghost ranks: the owners, other than its own, of the
    cells across its facets (vertex pairs: :data:`FACETS` by corners)."""
    pairs = FACETS[cells.shape[1]]
    edges = np.sort(np.concatenate([cells[:, p] for p in pairs]), axis=1)
    which = np.tile(np.arange(len(cells)), len(pairs))
    order = np.lexsort((edges[:, 1], edges[:, 0]))
    edges, which = edges[order], which[order]
    shared = np.flatnonzero(np.all(edges[1:] == edges[:-1], axis=1))  # an inner facet's two cells
    a, b = which[shared], which[shared + 1]
    across = owners[a] != owners[b]
    ghosts = [set() for _ in range(len(cells))]
    for c, r in zip(np.concatenate([a[across], b[across]]), np.concatenate([owners[b[across]], owners[a[across]]])):
        ghosts[c].add(int(r))
    return [sorted(g) for g in ghosts]


@contextmanager
def partitioned(gmshio, partitioner):
    """``gmshio.model_to_mesh`` with ``partitioner`` (None: dolfinx's own)
    while the block runs: dolfinx 0.5.2's ``model_to_mesh`` takes none and
    calls ``create_mesh`` by its module's name, which is bound to a
    partial of it here and restored after."""
    if partitioner is None:
        yield
        return
    create = gmshio.create_mesh
    gmshio.create_mesh = functools.partial(create, partitioner=partitioner)
    try:
        yield
    finally:
        gmshio.create_mesh = create
