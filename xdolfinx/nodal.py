"""fe's exact enforcement at Γ's nodes with the nodal reaction as Nitsche's
flux (``FE(flux="reaction")``; docs/contact-enforcement.md, "A β-free
exact enforcement for fe").

fe's two fields share Γ's nodes, so Nitsche's points may sit at them: at
node ``i`` the jump ``g_i = F_i (u⁺_i − u⁻_i)`` (``F_i`` the level set's
frame there, rows ``n``, ``t``) and the weight ``w_i = Σ_f ∫_f N_i dΓ``
(per facet Lobatto: ``L/2, L/2`` at degree 1, Simpson's ``L/6, 2L/3,
L/6`` at degree 2 on a straight facet; a uniform traction's consistent
nodal forces are ``w_i t``).  The flux is the node's reaction: with
``R = A u − b`` (the bulk's residual, no interface), equilibrium of the
node-to-node multipliers ``λ`` reads ``R⁺_i = −w_i F_iᵀ λ_i`` and
``R⁻_i = +w_i F_iᵀ λ_i``, so

    τ_i = F_i (a⁻ ∘ R⁻_i − a⁺ ∘ R⁺_i) / w_i = S u − L b,   S = L A,

``a^±`` per global component ``½, ½`` where both sides are free, ``1, 0``
(or ``0, 1``) where the other side's component is prescribed (its row
holds a support's reaction).  At the multipliers' answer ``u*``, ``τ = λ*``
and the law at ``y = g + τ/γ`` gives ``t = λ*`` for every γ, so ``u*``
solves Nitsche's residual at every β (:mod:`contactcore.exact`): the
answer does not move with β.  A component prescribed on both sides (a
support at Γ's end) is dropped from the law: its frame row, which must be
Γ's normal or tangent there, has ``G`` and ``L`` rows of zero.

Under mpirun a node's reaction needs its assembled rows of ``A`` and
``b`` for both bodies, and ``SᵀWΓ⁻¹S`` couples unknowns two cells apart:
fe's mesh then keeps every cell within two layers of Γ on one rank
(:mod:`xdolfinx.gamma_partition`), which owns every Γ node's rows and
each of their columns, so ``S``, ``L`` and the tangent sit in its owned
rows and columns (local numbering, as the Gauss-point interface's); the
other ranks hold no Γ node.  A Γ node's row that is not owned whole is
refused (:data:`NOT_ON_ONE_RANK`).  A refusal met on one rank (a Γ node's:
only the rank holding Γ meets it) is raised on every rank before the next
collective call, else the others would wait in it for ever.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

import meshes
from contactcore import BODIES, DiscretisationError
from contactcore import tolerances as tol
from contactcore.collective import SERIAL, Collective
from contactcore.cutcell import gauss01
from contactcore.geometry import polygon_area, tangent_of
from contactcore.interface_path import piece_centres
from contactcore.system import InterfaceOperator

#: Why a Γ node's reaction cannot be read on its rank (the partition of
#: :mod:`xdolfinx.gamma_partition` was not taken: a mesh not made by
#: :func:`xdolfinx.fitted_mesh.fitted_mesh` or ``file_mesh`` with it).
NOT_ON_ONE_RANK = ('fe: flux = "reaction": a Γ node\'s assembled row is not held whole by the rank of its node '
                   '(the mesh must keep the cells within two layers of Γ on one rank)')


def nodal_interface(scene, fm, V, reader, exchange, K, fixed: np.ndarray):
    """``(interface, work)``: :func:`nodal_operator` and the matrix whose
    pattern holds its tangent beside ``K``'s (:func:`working_pattern`).
    ``K``'s owned rows are read with their global columns, and the
    local-to-global map of its local numbering (owned, then ghosts).  A
    refusal is raised on every rank of the mesh alike (module doc)."""
    ranks = Collective(fm.mesh.comm)
    indptr, indices, values = K.getValuesCSR()
    owned = sp.csr_matrix((values, indices, indptr), shape=(K.getLocalSize()[0], K.getSize()[1]))
    l2g = _local_to_global(K, exchange.local_size)
    rows = owned_rows(K, l2g)
    interface = ranks.alike(nodal_operator, scene, fm, V, reader, exchange, owned, l2g, rows, fixed)
    return interface, working_pattern(K, owned, l2g, rows, interface, ranks)


def nodal_operator(scene, fm, V, reader, exchange, owned: sp.csr_matrix, l2g: np.ndarray, rows: np.ndarray,
                   fixed: np.ndarray) -> InterfaceOperator:
    """Γ's nodes as Nitsche's points with the reaction flux (module doc):
    ``G``, ``w``, the nodes, ``S = L A``, γ₀ (each node's facets' γ₀,
    weighted by their share of ``w_i``) and ``L``, columns in the local
    numbering; ``owned`` is the bulk's assembled matrix, this rank's rows
    with global columns (scipy CSR), ``l2g`` the local numbering's global
    indices, ``rows`` their owned rows (:func:`owned_rows`), ``fixed`` the
    prescribed unknowns and ``reader`` fe's
    ``(ReferenceCells, Gauss points a facet, _facet_sides)``
    (:mod:`xdolfinx.conforming`)."""
    ref, gauss, sides = reader
    nodes = _gamma_nodes(scene, ref, V, fm.facets_tagged(meshes.INTERFACE), gauss, sides)
    plus, minus, x, w, gamma0 = nodes
    normals = scene.interface.normals(x) if len(x) else np.zeros((0, 2))
    frames = np.stack([normals, tangent_of(normals)], axis=1)  # rows n, t, as interface_operator's
    G, L = _rows(scene, plus, minus, x, w, frames, fixed, exchange.local_size)
    A = reaction_rows(owned, l2g, rows, L.indices)
    return InterfaceOperator(G, w, x, exchange if exchange.ranks.parallel else None, S=(L @ A).tocsr(),
                             stabilisation=gamma0, pieces=piece_centres(x, w, [1] * len(w)), load_flux=L)


def _local_to_global(K, local_size: int) -> np.ndarray:
    """The global index of each local unknown (owned, then ghosts): ``K``'s
    row map, which dolfinx sets; the identity where none is set."""
    maps = K.getLGMap()[0]
    return maps.getIndices().astype(np.int64) if maps.handle else np.arange(local_size, dtype=np.int64)


def owned_rows(K, l2g: np.ndarray) -> np.ndarray:
    """Each local unknown's row among ``K``'s owned rows, or −1 where
    another rank owns it (``l2g`` the local numbering's global indices)."""
    start, stop = K.getOwnershipRange()
    return np.where((l2g >= start) & (l2g < stop), l2g - start, -1)


def reaction_rows(owned: sp.csr_matrix, l2g: np.ndarray, rows: np.ndarray, reads: np.ndarray,
                  refusal: str = NOT_ON_ONE_RANK) -> sp.csr_matrix:
    """``A``'s rows of the local unknowns ``reads`` (the only ones ``L A``
    reads), in the local numbering (the other rows empty): each owned
    whole (``rows``, :func:`owned_rows`) and reaching local unknowns only,
    else ``refusal`` (fe's :data:`NOT_ON_ONE_RANK`, or xfem's)."""
    reads = np.unique(reads)
    if np.any(rows[reads] < 0):
        raise DiscretisationError(refusal)
    taken = owned[rows[reads]]
    columns = _local_columns(taken.indices, l2g, refusal)
    counts = np.zeros(len(l2g), np.int64)
    counts[reads] = np.diff(taken.indptr)
    indptr = np.concatenate([[0], np.cumsum(counts)])
    return sp.csr_matrix((taken.data, columns, indptr), shape=(len(l2g), len(l2g)))


def _local_columns(columns: np.ndarray, l2g: np.ndarray, refusal: str = NOT_ON_ONE_RANK) -> np.ndarray:
    """The local index of each global ``columns``; ``refusal``
    (:data:`NOT_ON_ONE_RANK`) where one is not local."""
    order = np.argsort(l2g)
    at = np.searchsorted(l2g, columns, sorter=order)
    found = at < len(order)
    found[found] = l2g[order[at[found]]] == columns[found]
    if not found.all():
        raise DiscretisationError(refusal)
    return order[at]


def _gamma_nodes(scene, ref, V, facets: np.ndarray, gauss: int, sides):
    """Γ's nodes, each once: its + and − dofs (n, 2) each (x, y), its
    position, its weight ``w_i = Σ_f ∫_f N_i dΓ`` and γ₀ (module doc)."""
    xi, w_ref = gauss01(gauss)
    dofs = [[V.sub(b).sub(j).dofmap for j in range(2)] for b in range(2)]
    E = np.array([scene.materials[b].E for b in BODIES])
    index, plus, minus, x, w, gw = {}, [], [], [], [], []
    for f in facets:
        c = ref.f2c.links(f)[0]
        edge = int(np.flatnonzero(ref.c2f.links(c) == f)[0])
        X, coords, _, dx_dxi = ref.facet_map(c, f, xi)
        d_gamma = w_ref * np.linalg.norm(dx_dxi, axis=1)
        N = ref.element.tabulate(0, X)[0, :, :, 0]
        cells, side = sides(scene, ref, f)
        compliance = sum(polygon_area(ref.coords(k)[:3]) / E[s] for k, s in zip(cells, side))
        gamma_f = 2.0 * d_gamma.sum() / compliance
        for a in ref.element.entity_closure_dofs[1][edge]:
            key = int(dofs[1][0].cell_dofs(c)[a])
            weight = float(N[:, a] @ d_gamma)
            if key not in index:
                index[key] = len(plus)
                plus.append([dofs[1][j].cell_dofs(c)[a] for j in range(2)])
                minus.append([dofs[0][j].cell_dofs(c)[a] for j in range(2)])
                x.append(ref.cmap.tabulate(0, ref.element.points[a:a + 1])[0, 0, :, 0] @ coords)
                w.append(0.0)
                gw.append(0.0)
            w[index[key]] += weight
            gw[index[key]] += weight * gamma_f
    w = np.array(w)
    return (np.array(plus, np.int64).reshape(-1, 2), np.array(minus, np.int64).reshape(-1, 2),
            np.array(x, float).reshape(-1, 2), w, np.array(gw) / np.where(w > 0, w, 1.0))


def _rows(scene, plus, minus, x, w, frames, fixed, n: int):
    """``G`` and ``L`` (2m × n) of the nodes (module doc): a free side's
    rows read its reaction, a component prescribed on both sides drops
    its frame row (refused where that row is neither n nor t)."""
    held = np.zeros(n, bool)
    held[np.asarray(fixed, np.int64)] = True
    G, L = ([], [], []), ([], [], [])
    for i in range(len(w)):
        free_p, free_m = ~held[plus[i]], ~held[minus[i]]
        count = free_p.astype(float) + free_m
        a_p = np.where(count > 0, free_p / np.where(count > 0, count, 1.0), 0.0)
        a_m = np.where(count > 0, free_m / np.where(count > 0, count, 1.0), 0.0)
        kept = _kept_rows(frames[i], count == 0, x[i])
        for k in np.flatnonzero(kept):
            for j in range(2):
                _put(G, 2 * i + k, (plus[i, j], minus[i, j]), frames[i, k, j] * np.array([1.0, -1.0]))
                _put(L, 2 * i + k, (plus[i, j], minus[i, j]), frames[i, k, j] * np.array([-a_p[j], a_m[j]]) / w[i])
    shape = (2 * len(w), n)
    return tuple(sp.csr_matrix((np.array(v, float), (np.array(r, np.int64), np.array(c, np.int64))), shape=shape)
                 for r, c, v in (G, L))


def _kept_rows(frame: np.ndarray, both_held: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Which of the node's frame rows (n, t) take part in the law: each
    global component held on both sides drops the row it lies along
    (within :data:`~contactcore.tolerances.REACTION_ALIGNMENT`); one along
    neither is refused (its support's reaction would enter both)."""
    kept = np.ones(2, bool)
    for j in np.flatnonzero(both_held):
        k = int(np.argmax(np.abs(frame[:, j])))
        if abs(frame[k, j]) < 1.0 - tol.REACTION_ALIGNMENT:
            raise DiscretisationError(
                f'fe: flux = "reaction" at Γ\'s node ({x[0]:.6g}, {x[1]:.6g}): its {"xy"[j]} is prescribed on both '
                f'sides along neither Γ\'s normal nor its tangent there; use flux = "stress"')
        kept[k] = False
    return kept


def _put(sink, row: int, cols, values) -> None:
    """Append entries of ``row`` to a (rows, cols, values) sink."""
    for c, v in zip(cols, values):
        if v != 0.0:
            sink[0].append(row)
            sink[1].append(int(c))
            sink[2].append(float(v))


def working_pattern(K, owned: sp.csr_matrix, l2g: np.ndarray, rows: np.ndarray, interface: InterfaceOperator,
                    ranks: Collective = SERIAL, refusal: str = NOT_ON_ONE_RANK):
    """A PETSc matrix distributed as ``K`` (its block size) with the
    bulk's pattern (its ``owned`` rows, global columns) and every entry
    the interface's tangent can reach
    (:meth:`~contactcore.system.InterfaceOperator.pattern`, local
    numbering: ``rows`` each one's owned row, ``l2g`` its global index),
    values zero: the reaction's ``SᵀWΓ⁻¹S`` couples unknowns beyond ``K``'s
    pattern (two cells apart in fe, every unknown near Γ in xfem).  A
    collective call over ``ranks`` (the matrix's): a row not owned is
    refused (``refusal``) on every rank alike."""
    from petsc4py import PETSc
    ones = sp.csr_matrix((np.ones_like(owned.data), owned.indices, owned.indptr), shape=owned.shape)
    reach = interface.pattern().tocoo()
    ranks.raise_any(DiscretisationError(refusal) if np.any(rows[reach.row] < 0) else None)
    both = (ones + sp.csr_matrix((np.abs(reach.data), (rows[reach.row], l2g[reach.col])), shape=owned.shape)).tocsr()
    both.sort_indices()
    both.data[:] = 0.0
    sizes = (K.getLocalSize()[0], K.getSize()[0]), (K.getLocalSize()[1], K.getSize()[1])
    return PETSc.Mat().createAIJ(sizes, bsize=K.getBlockSize(), csr=(both.indptr.astype(PETSc.IntType),
                                                                     both.indices.astype(PETSc.IntType), both.data),
                                 comm=K.getComm())
