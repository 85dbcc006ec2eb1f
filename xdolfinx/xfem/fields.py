"""XFEM's displacement and stress of either body at arbitrary points, and
the recovered stress at degree 1."""
from __future__ import annotations

import numpy as np

from contactcore.bodies import sign_of_index
from contactcore.recovery import PatchRecovery
from contactcore.result import check_points

from ..evaluation import BodyCellLocator
from .kernels import enriched_basis, heaviside_shift, voigt_stress
from .space import EnrichedFunctionSpace

#: Points evaluated together by :meth:`XFEMFields._affine` (its arrays are
#: about 50 doubles a point per basis function: 0.25 GB at 65 536 points, Q2).
_CHUNK = 65536


class XFEMFields:
    """Displacement and stress of either body at arbitrary points; under
    mpirun a collective call (:meth:`BodyCellLocator.choose`).

    Degree 1: a body's stress is recovered (:meth:`_recovered`, after
    Zienkiewicz and Zhu's patch recovery), not read from the cell's own
    constant or bilinear field (:mod:`contactcore.recovery`)."""

    def __init__(self, space: EnrichedFunctionSpace, x: np.ndarray):
        self.space, self.blocks = space, space.node_values(x)
        self.D = space.scene.voigt_matrices()
        self.locator = BodyCellLocator(space.msh, [space.cells_resolving(side) for side in (-1, 1)])
        self._recoveries = {body: None for body in (0, 1)}

    def _eval(self, points, bodies, gradient: bool, recovered: bool = True) -> np.ndarray:
        points, bodies = check_points(points, bodies)  # the arrays; the geometry is the Result's (ScaledFields)
        cells, mine = self.locator.choose(points, bodies)
        out = np.zeros((len(points), 3 if gradient else 2))
        if gradient and recovered and self.space.degree == 1:
            for body in np.flatnonzero(np.bincount(bodies)):  # np.unique(bodies), without a sort
                self._recovery(int(body))  # collective: every rank, whatever points it evaluates
                sel = np.flatnonzero(mine & (bodies == body))
                out[sel] = self._recovered(cells[sel], int(body), points[sel])
            return self.locator.combine(out)
        if mine.all():  # every point this rank's (serial): no copies
            return self.locator.combine(self._at(cells, bodies, points, gradient))
        sel = np.flatnonzero(mine)
        out[sel] = self._at(cells[sel], bodies[sel], points[sel], gradient)
        return self.locator.combine(out)

    def _at(self, cells: np.ndarray, bodies: np.ndarray, points: np.ndarray, gradient: bool) -> np.ndarray:
        """u (P, 2) or Voigt σ (P, 3) of body ``bodies[i]``'s polynomial in
        cell ``cells[i]`` at ``points[i]``: :meth:`_local` of every point.
        Affine cells (cut or not) all at once: each point pulled back by its
        cell's affine map, the basis tabulated once on all the reference
        points, contracted with each point's cell coefficients; a cut cell
        differs only in its enrichment factors ``H − H_J`` (the body's side
        against each node's own, snapped, side: :func:`heaviside_shift`).
        Curved cells one by one (Newton's pull-back, :meth:`CellBasis.tabulate`),
        grouped by one sort."""
        out = np.zeros((len(points), 3 if gradient else 2))
        basis = self.space.cells
        curved = basis.curved[cells]
        flat = np.flatnonzero(~curved)
        for sel in np.array_split(flat, -(-len(flat) // _CHUNK)) if len(flat) else ():  # bounded memory
            if len(flat) == len(cells):  # no curved cell: each chunk a range of the points, read as a view
                sel = slice(sel[0], sel[-1] + 1)
            out[sel] = self._affine(cells[sel], bodies[sel], points[sel], gradient)
        bent = np.flatnonzero(curved)
        if len(bent):
            order = bent[np.lexsort((bodies[bent], cells[bent]))]
            key = np.stack([cells[order], bodies[order]], axis=1)
            starts = np.flatnonzero(np.r_[True, np.any(key[1:] != key[:-1], axis=1)])
            for sel in np.split(order, starts[1:]):
                out[sel] = self._local(int(cells[sel[0]]), int(bodies[sel[0]]), points[sel], gradient)
        return out

    def _affine(self, cells: np.ndarray, bodies: np.ndarray, points: np.ndarray, gradient: bool) -> np.ndarray:
        """:meth:`_at` on affine cells, vectorised over the points."""
        space, basis = self.space, self.space.cells
        take = lambda a, i: np.take(a, i, axis=0)  # noqa: E731 - a row gather, several times numpy's fancy index
        J = take(basis.inverse, cells)
        X = np.einsum("pa,pda->pd", points - take(basis.origin, cells), J)
        tab = basis.element.tabulate(1 if gradient else 0, X)
        if not gradient:
            dofs = take(basis.cell_dofs, cells)
            U = take(self.blocks, dofs)                                         # (P, n, 4)
            shift = heaviside_shift(space, dofs, sign_of_index(bodies))         # (P, n)
            vec = U[..., :2] + shift[..., None] * U[..., 2:]                    # (P, n, 2)
            return np.einsum("pn,pnk->pk", tab[0, :, :, 0], vec)
        # node by node along the points, (n, P): vec_k = u_k + shift a_k, dN_d = Σ_e ∂N/∂X_e J_ed, and
        # du_kd = Σ_j dN_jd vec_jk summed in j's order, the same bits as the (P, n, 2) broadcasts they
        # replace, which numpy ran several times slower over their short last axes.  vec is a cell's
        # and body's: computed once for each run of points in one cell and body (the energy estimate's
        # Gauss points come cell by cell, 4 to a run) and repeated over its points
        new = np.r_[True, (cells[1:] != cells[:-1]) | (bodies[1:] != bodies[:-1])]
        first = np.flatnonzero(new)
        dofs = take(basis.cell_dofs, cells[first])
        U = take(self.blocks, dofs)                                             # (runs, n, 4)
        shift = heaviside_shift(space, dofs, sign_of_index(bodies[first]))      # (runs, n)
        vec = [U[..., k].T + shift.T * U[..., 2 + k].T for k in range(2)]      # (n, runs) each
        if len(first) < len(cells):
            run = np.cumsum(new) - 1
            vec = [np.take(v, run, axis=1) for v in vec]                        # (n, P) each
        dN = [tab[1, :, :, 0].T * J[:, 0, d] + tab[2, :, :, 0].T * J[:, 1, d] for d in range(2)]
        du = np.empty((len(points), 2, 2))
        for k in range(2):
            for d in range(2):
                acc = dN[d][0] * vec[k][0]
                for j in range(1, len(vec[k])):
                    acc = acc + dN[d][j] * vec[k][j]
                du[:, k, d] = acc
        out = np.zeros((len(points), 3))
        for body in np.flatnonzero(np.bincount(bodies)):  # np.unique(bodies), without a sort
            sel = bodies == body
            out[sel] = voigt_stress(du[sel], self.D[int(body)])
        return out

    def _local(self, c: int, body: int, points: np.ndarray, gradient: bool) -> np.ndarray:
        """u (P, 2) or Voigt σ (P, 3) of ``body``'s polynomial in cell ``c`` at ``points``."""
        N, dN, shift = enriched_basis(self.space, c, points, sign_of_index(body))
        U = self.blocks[self.space.cells.cell_dofs[c]]
        vec = U[:, :2] + shift[:, None] * U[:, 2:]
        if not gradient:
            return N @ vec
        return voigt_stress(np.einsum("pjd,jk->pkd", dN, vec), self.D[body])

    def _recovery(self, body: int):
        """``body``'s :class:`~contactcore.recovery.PatchRecovery` over every
        rank's cells, and the row of each of this rank's owned cells (a
        collective call under mpirun), built on first use.  Its samples are
        the body's resolving cells that this rank owns: the centroid and
        area of the body's part, and the cell's own σ there; a node's key
        is its global block."""
        if self._recoveries[body] is None:
            space = self.space
            cells = space.cells_resolving(sign_of_index(body))
            cells = cells[cells < space.cells.owned_cells]  # each cell sampled by its owner
            centroids, areas, sig = self._samples(cells, body)
            owned = np.arange(space.cells.owned_cells)
            sample = np.full(space.cells.owned_cells, -1)
            sample[cells] = np.arange(len(cells))
            keys = space.numbering.global_blocks[space.cells.cell_dofs[owned]]
            self._recoveries[body] = PatchRecovery.gather(space.cells.ranks, keys, sample, centroids, areas, sig)
        return self._recoveries[body]

    def _samples(self, cells: np.ndarray, body: int):
        """Centroids (m, 2), areas (m,) and Voigt σ (m, 3) of ``body``'s part
        of each of ``cells``: whole (uncut, affine) cells at once, from the
        reference rule's centroid mapped; cut and curved cells one by one."""
        space, side = self.space, sign_of_index(body)
        basis, cut = space.cells, space.cut
        centroids, areas, sig = np.zeros((len(cells), 2)), np.zeros(len(cells)), np.zeros((len(cells), 3))
        whole = np.array([c not in cut.regions and not basis.curved[c] for c in cells], dtype=bool)
        X, w = cut.reference_rule
        Xc = w @ X / w.sum()
        c = cells[whole]
        centroids[whole] = basis.origin[c] + basis.jacobian[c] @ Xc
        areas[whole] = w.sum() * np.abs(np.linalg.det(basis.jacobian[c]))
        dN = basis.affine_gradients(c, Xc[None])[:, 0]     # (cells, n, 2)
        dofs = basis.cell_dofs[c]
        U = self.blocks[dofs]
        vec = U[..., :2] + heaviside_shift(space, dofs, side)[..., None] * U[..., 2:]
        sig[whole] = voigt_stress(np.einsum("cjd,cjk->ckd", dN, vec), self.D[body])
        for n in np.flatnonzero(~whole):
            c = cells[n]
            parts = [(pts, wt) for s, pts, wt, *_ in cut.cell_values(c) if s == side]
            pts, wt = np.vstack([p for p, _ in parts]), np.concatenate([q for _, q in parts])
            areas[n], centroids[n] = wt.sum(), wt @ pts / wt.sum()
            sig[n] = self._local(c, body, centroids[n:n + 1], True)[0]
        return centroids, areas, sig

    def _recovered(self, cells: np.ndarray, body: int, points: np.ndarray) -> np.ndarray:
        """Voigt σ (P, 3) of ``body`` at ``points`` (located in ``cells``,
        owned): the recovered stress, or the cell's own where its patch
        fits no line (:mod:`contactcore.recovery`)."""
        recovery, rows = self._recovery(body)
        out = recovery.at(rows[cells], points)
        sel = np.flatnonzero(np.isin(cells, cells[np.isnan(out[:, 0])]))
        out[sel] = self._at(cells[sel], np.full(len(sel), body), points[sel], True)
        return out

    def displacement(self, points, bodies) -> np.ndarray:
        """``u`` (m, 2) of body ``bodies[i]`` (0 = −, 1 = +) at ``points[i]``
        ((m, 2)) on the method's dimensionless scene.  Only the arrays are
        checked here (shape, finite, bodies 0 or 1: FieldsError); where a
        point lies is checked by the Result's :class:`~contactcore.scaling.ScaledFields`
        before it arrives.  Under mpirun a collective call."""
        return self._eval(points, bodies, False)

    def stress(self, points, bodies) -> np.ndarray:
        """``(σxx, σyy, σxy)`` (m, 3) of body ``bodies[i]`` at ``points[i]``,
        dimensionless (degree 1: the recovered stress, class doc); the
        arrays checked as for :meth:`displacement`."""
        return self._eval(points, bodies, True)

    def direct_stress(self, points, bodies) -> np.ndarray:
        """The stress of the computed displacement itself, ``σ(u_h)``, where
        :meth:`stress` reads it (the cell's own field, not recovered: at
        degree 1 constant per triangle and body part, linear in x and in y
        apart on a quadrilateral); as :meth:`stress` at degree 2.  What the
        energy norm of the error measures (:mod:`contactcore.estimate.energy`)."""
        return self._eval(points, bodies, True, recovered=False)
