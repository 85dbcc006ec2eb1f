"""XFEM's enriched space (GetFEM's ``MeshFem('levelset', …)``): which nodes
carry the Heaviside enrichment, the numbering of their blocks of unknowns,
and the sparsity of the matrix over them.

Under mpirun every rank numbers its own blocks, as dolfinx_mpc does for its
constraints: its owned nodes' u, then its owned enriched nodes' a, from the
rank's offset, so PETSc's rows stay contiguous per rank.  Which nodes are
enriched is decided by each node's owner from the cut stiffness summed over
every rank's cells and sent to the ranks that ghost it.
"""
from __future__ import annotations

from dataclasses import dataclass

import dolfinx.cpp as _cpp
import numpy as np
from petsc4py import PETSc

from contactcore import DiscretisationError
from contactcore import tolerances as tol
from contactcore.tolerances import MIN_CUT_FRACTION  # which nodes are enriched, with its reason
from contactcore.bodies import Body, index_of_sign
from contactcore.exact import is_exact
from contactcore.geometry import Disc, LineInterface

from ..contact_system import GhostExchange
from .cells import CellBasis
from ..options import refinement
from .cut import CutIntegration
from .reading import all_readers


@dataclass(frozen=True)
class BlockNumbering:
    """A rank's blocks of XFEM unknowns in the global numbering: dolfinx's
    ``index_map`` of them (owned: the rank's nodes' u then its enriched
    nodes' a; ghosts after), ``global_blocks`` the global block of each
    local block (V's nodes, then the enriched ones), ``order`` the index
    map's local index of each local block."""

    index_map: object
    global_blocks: np.ndarray
    order: np.ndarray


def enriched_nodes(cells: CellBasis, cut: CutIntegration) -> np.ndarray:
    """(nodes,) bool: the nodes whose support's stiffness lies on both
    sides of Γ, each side's above MIN_CUT_FRACTION of it: the nodes of cut
    cells, and also nodes on Γ whose support reaches cells of both sides
    when Γ runs along edges.  Each node's owner sums the stiffness over
    every rank's cells, decides, and tells the ranks that ghost it."""
    exchange = GhostExchange(cells.V.dofmap.index_map, 1, cells.msh.comm)
    minus, plus = (exchange.reverse(s) for s in cut.stiffness)
    total = minus + plus
    owned = np.minimum(minus, plus) > MIN_CUT_FRACTION * np.where(total > 0, total, 1.0)
    if cells.ranks.sum(int(np.count_nonzero(owned))) == 0:
        raise DiscretisationError("xfem: Γ crosses no cell of the mesh")
    return exchange.forward(owned.astype(float)) > 0.5


def block_numbering(cells: CellBasis, enriched: np.ndarray) -> BlockNumbering:
    """The global numbering of this rank's local blocks: rank r owns
    ``offset_r + [0, n_r)`` for its nodes' u and ``offset_r + n_r + [0, e_r)``
    for its enriched nodes' a; a ghost takes its owner's numbers, sent by
    dolfinx's forward scatter.  In serial: u of node i is block i, a of the
    e-th enriched node is block ``nodes + e``."""
    comm, imap = cells.msh.comm, cells.V.dofmap.index_map
    n_owned, n_local = cells.owned_nodes, len(enriched)
    which = np.flatnonzero(enriched)
    e_owned = int(np.count_nonzero(which < n_owned))
    offset = (comm.exscan(n_owned + e_owned) if comm.size > 1 else 0) or 0  # exscan gives None on rank 0
    own = np.full((n_owned, 2), -1.0)
    own[:, 0] = offset + np.arange(n_owned)
    own[which[:e_owned], 1] = offset + n_owned + np.arange(e_owned)
    glob = np.rint(GhostExchange(imap, 2, comm).forward(own.ravel())).astype(np.int64).reshape(-1, 2)
    ghost_enriched = which[e_owned:]
    index_map = _cpp.common.IndexMap(
        comm, n_owned + e_owned, np.concatenate([glob[n_owned:, 0], glob[ghost_enriched, 1]]),
        np.concatenate([imap.owners, imap.owners[ghost_enriched - n_owned]]).astype(np.int32))
    n_ghosts, owned_total = n_local - n_owned, n_owned + e_owned
    order = np.concatenate([np.arange(n_owned), owned_total + np.arange(n_ghosts), n_owned + np.arange(e_owned),
                            owned_total + n_ghosts + np.arange(len(ghost_enriched))])
    return BlockNumbering(index_map, np.concatenate([glob[:, 0], glob[which, 1]]), order)


class EnrichedFunctionSpace:
    """dolfinx's vector space V of the standard part (``cells.V``),
    decorated with the Heaviside enrichment of Γ: ``enriched`` nodes (by
    default :func:`enriched_nodes`), the ``band`` of cells holding one (by
    default every such cell), and the numbering of the blocks, fixed here.

    Local unknowns (unrolled, block size 2): ``2·node + j`` for u_j of a
    node (V's own local numbering, owned nodes then ghosts),
    ``2·(nodes + e) + j`` for a_j of the e-th enriched node (in node order);
    :attr:`numbering` maps them to the global rows (the same in serial)."""

    def __init__(self, cells: CellBasis, cut: CutIntegration, enriched: np.ndarray | None = None,
                 band: np.ndarray | None = None):
        self.cells, self.cut = cells, cut
        self.scene, self.msh, self.V, self.degree = cut.scene, cells.msh, cells.V, cells.degree
        self.enriched = enriched_nodes(cells, cut) if enriched is None else np.asarray(enriched, bool)
        self.band = (np.flatnonzero(np.any(self.enriched[cells.cell_dofs], axis=1)) if band is None
                     else np.asarray(band, np.int64))
        if not cells.ranks.all(not cells.curved[self.band].any()):
            raise DiscretisationError(_curved_band_message(cut.scene, self.degree))
        for body in Body:
            self._check_resolved(body)
        #: enriched nodes this rank sees (owned and ghosts)
        self.num_enriched = int(self.enriched.sum())
        #: this rank's local blocks (pairs of unknowns): every node's u, the enriched nodes' a
        self.num_blocks = len(self.enriched) + self.num_enriched
        #: the band cells this rank owns: each cell is integrated once, by its owner
        self.owned_band = self.band[self.band < cells.owned_cells]
        #: (nodes,): the local block of each node's a, ``nodes + e`` for the
        #: e-th enriched node (owned ones first), −1 where not enriched
        self.enriched_blocks = np.full(len(self.enriched), -1, dtype=np.int64)
        self.enriched_blocks[self.enriched] = len(self.enriched) + np.arange(self.num_enriched)
        self.numbering = block_numbering(cells, self.enriched)
        #: ghost updates of the unknowns in the local block numbering
        self.exchange = GhostExchange(self.numbering.index_map, 2, self.msh.comm, self.numbering.order)

    def _check_resolved(self, body: Body) -> None:
        """A clear error where no cell, on any rank, resolves ``body``
        (:meth:`cells_resolving`): a body thinner than
        tol.SLIVER_EVAL_DEPTH of a cell wherever Γ cuts it (a strip along an
        edge, a corner, a rod smaller than a cell) could be evaluated
        nowhere, and its fields would read zero."""
        ranks, cut = self.cells.ranks, self.cut
        resolving = self.cells_resolving(body.sign)
        if ranks.sum(int(np.count_nonzero(resolving < self.cells.owned_cells))) > 0:
            return
        which = np.array(sorted(cut.regions), dtype=int)
        reach = ranks.max(float(np.max(cut.depth[which, int(body)] / cut.cell_size[which], initial=0.0)))
        raise DiscretisationError(
            f"xfem: no cell resolves body {body.symbol}: wherever Γ cuts it, it reaches at most {reach:.3g} of a "
            f"cell's diameter from Γ (at least {tol.SLIVER_EVAL_DEPTH:g} is needed to evaluate its fields); "
            f"{refinement(reach)}, or use fe (which fits a body thicker than {tol.THINNEST_FITTED_BODY:g} of the domain's "
            f"diameter)")

    def cells_resolving(self, side: int) -> np.ndarray:
        """The cells in which the field of the body on ``side`` (±1) is
        resolved, where that body's points are evaluated: the cells on its
        side, and the cut cells whose part on ``side`` reaches at least
        tol.SLIVER_EVAL_DEPTH of the cell's diameter from Γ and whose nodes
        on the other side are all enriched.  In a thinner part (a sliver)
        the body's polynomial is fitted to the sliver alone: its enriched
        unknowns are barely determined, or an unenriched node across Γ
        (MIN_CUT_FRACTION) carries the other side's value.  A point of a
        sliver is evaluated in the nearest cell that resolves the body (the
        locator's), its polynomial extended by at most the sliver's depth:
        the one-sided limit."""
        cells, cut = self.cells, self.cut
        is_cut = np.zeros(cells.num_cells, bool)
        is_cut[list(cut.regions)] = True
        dofs = cells.cell_dofs
        across_unenriched = np.any((cells.node_side[dofs] != side) & ~self.enriched[dofs], axis=1)
        thick = cut.depth[:, index_of_sign(side)] >= tol.SLIVER_EVAL_DEPTH * cut.cell_size
        return np.flatnonzero((~is_cut & (cut.cell_side == side)) | (is_cut & thick & ~across_unenriched))

    def owned_rows(self, local_flags: np.ndarray) -> np.ndarray:
        """The owned unknowns (rows) that some rank flagged among its local
        ones (``local_flags`` in the unrolled local numbering)."""
        return np.flatnonzero(self.exchange.reverse(np.asarray(local_flags, float)) > 0)

    def cell_blocks(self, cells) -> np.ndarray:
        """(..., 2n): the local blocks of cells in the kernels' layout, per node its
        u then its a (−1 where not enriched: PETSc skips negative indices)."""
        dofs = self.cells.cell_dofs[cells]
        return np.stack([dofs, self.enriched_blocks[dofs]], axis=-1).reshape(dofs.shape[:-1] + (-1,))

    def node_values(self, x: np.ndarray) -> np.ndarray:
        """(nodes, 4): ``[u_x, u_y, a_x, a_y]`` of each local node from the
        owned unknowns ``x`` (ghosts by the forward scatter; a = 0 where the
        node is not enriched)."""
        local = self.exchange.forward(x)
        n = len(self.enriched)
        out = np.zeros((n, 4))
        out[:, :2] = local[:2 * n].reshape(n, 2)
        out[self.enriched, 2:] = local[2 * n:].reshape(-1, 2)
        return out

    def edge_neighbours(self) -> dict:
        """``{(a, b): [cells]}``: the cells holding each edge whose two ends
        lie on Γ (``cells.node_on``; the only edges :meth:`across_edge`
        looks up), keyed by its two corner nodes sorted (the local mesh,
        ghosts included).  Made once per space (an exact law's build asks
        for it twice: its traction operator and its matrix's couplings);
        callers only read it."""
        kept = getattr(self, "_edge_neighbours", None)
        if kept is not None:
            return kept
        nodes = np.asarray(self.cells.corner_nodes)
        ends = np.roll(nodes, -1, axis=1)  # edge i of a cell runs from its corner i to corner i + 1
        on = np.asarray(self.cells.node_on, bool)
        both = (on[nodes] & on[ends]).ravel()
        lo, hi = np.minimum(nodes, ends).ravel()[both].tolist(), np.maximum(nodes, ends).ravel()[both].tolist()
        cells = np.repeat(np.arange(len(nodes)), nodes.shape[1])[both].tolist()
        out: dict = {}
        for key, c in zip(zip(lo, hi), cells):  # cell by cell, edge by edge, as the lists' order
            out.setdefault(key, []).append(c)
        self._edge_neighbours = out
        return out

    def across_edge(self, c: int, points: np.ndarray, edges: dict) -> np.ndarray:
        """(P,): for each of ``points`` (Γ's rule of cell ``c``) on an edge
        of ``c`` whose two ends are on Γ, the cell across that edge where it
        is whole on the + side, else −1: Γ along that edge has a body's
        cell on each side (:func:`xdolfinx.xfem.traction.cell_traction`)."""
        cells, cut = self.cells, self.cut
        nodes, corners = cells.corner_nodes[c], cells.corners[c]
        k, snap = len(nodes), cut.snap_of(c)
        out = np.full(len(points), -1)
        for i in range(k):
            a, b = int(nodes[i]), int(nodes[(i + 1) % k])
            if not (cells.node_on[a] and cells.node_on[b]):
                continue
            across = [d for d in edges.get((min(a, b), max(a, b)), []) if d != c]
            if len(across) != 1 or cut.cell_side[across[0]] <= 0 or across[0] in cut.regions:
                continue
            p, q = corners[i], corners[(i + 1) % k]
            length = float(np.linalg.norm(q - p))
            rel = points - p
            off = np.abs(rel[:, 0] * (q - p)[1] - rel[:, 1] * (q - p)[0]) / length
            along = rel @ (q - p) / length
            out[(off <= snap) & (along >= -snap) & (along <= length + snap)] = across[0]
        return out

    def edge_couplings(self) -> list[np.ndarray]:
        """The blocks of each owned whole − cell holding Γ's rule along an
        edge together with the whole + cell across it: the exact laws'
        traction there reads both cells (:meth:`across_edge`), so the
        matrix couples them; and each cut cell's with the cells its
        traction reads a body's stress from at degree 1
        (:func:`xdolfinx.xfem.reading.all_readers`)."""
        if not is_exact(self.scene.law):
            return []
        edges, out = self.edge_neighbours(), []
        for c in self.owned_band:
            rule = self.cut.gamma_rules.get(c)
            if rule is None or c in self.cut.regions or self.cut.cell_side[c] > 0:
                continue
            for d in set(int(d) for d in self.across_edge(c, rule[0], edges) if d >= 0):
                out.append(np.concatenate([self.cell_blocks(c), self.cell_blocks(d)]))
        for c, pair in all_readers(self).items():
            if pair != (c, c):
                out.append(np.concatenate([self.cell_blocks(d) for d in [c] + sorted(set(pair) - {c})]))
        return out

    def create_matrix(self) -> PETSc.Mat:
        """An AIJ matrix of block size 2 over the blocks of :attr:`numbering`,
        with room for exactly the cells' couplings (every owned cell couples
        the blocks of :meth:`cell_blocks`; dolfinx's sparsity pattern sends
        the rows other ranks own to them), addressed in the local block
        numbering, so dolfinx's assembler (V's dofmap) and the band kernels
        both write into it with ``setValuesBlockedLocal``."""
        comm, num = self.msh.comm, self.numbering
        pattern = _cpp.la.SparsityPattern(comm, [num.index_map, num.index_map], [2, 2])
        couplings = self.edge_couplings()
        for blocks in [*self.cell_blocks(np.arange(self.cells.owned_cells)), *couplings]:
            mapped = num.order[blocks[blocks >= 0]].astype(np.int32)
            pattern.insert(mapped, mapped)
        pattern.assemble()
        A = _cpp.la.petsc.create_matrix(comm, pattern)
        lgmap = PETSc.LGMap().create(num.global_blocks.astype(PETSc.IntType), bsize=2, comm=comm)
        A.setLGMap(lgmap, lgmap)
        lgmap.destroy()
        for blocks in couplings:  # stored zeros: the assembly keeps only the entries written
            idx = blocks.astype(PETSc.IntType)
            A.setValuesBlockedLocal(idx, idx, np.zeros((2 * len(idx)) ** 2), addv=PETSc.InsertMode.ADD_VALUES)
        return A


def _curved_band_message(scene, degree: int) -> str:
    """Why xfem of ``degree`` refuses enriched cells on a disc's curved rim
    (a degree-2 mesh's rim cells are curved): its cut-cell quadrature
    assumes straight cells there.  A straight Γ meets a disc's rim (a
    valid scene's line crosses its domain; a circle lies strictly inside),
    and no h can help; otherwise Γ only comes near it."""
    if isinstance(scene.domain, Disc) and isinstance(scene.interface, LineInterface):
        return (f"xfem: Γ meets the disc's rim, where a degree-{degree} mesh's cells are curved and xfem's "
                "cut-cell quadrature assumes straight cells where Γ cuts: a Γ that reaches a curved boundary is "
                f"not supported at degree {degree} at any h (xfem P1, fe and efgm solve it)")
    return "xfem: Γ reaches a curved cell of the rim (its cut-cell quadrature assumes straight cells there); refine h"
