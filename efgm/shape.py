"""Moving-least-squares shape functions (the paper's §VII, Eqs. 19–23).

For a point ``x`` with neighbours ``I`` (nodes whose support holds ``x``),

    Φ_I(x) = p̃(x)ᵀ A(x)⁻¹ p̃(x_I) w_I(x),   A(x) = Σ_I w_I(x) p̃(x_I) p̃(x_I)ᵀ,

with the monomial basis of degree 1 (``1, ξ, η``) or 2 (``… ξ², ξη, η²``)
*shifted and scaled* at the evaluation point, ``p̃(y) = p((y − x̄)/s)``,
``x̄ = x`` and ``s`` the largest support radius among the neighbours, so that
the moment matrix stays well conditioned whatever the node spacing.  The
shape functions do not depend on ``x̄``; derivatives are taken with ``x̄``
held fixed: with ``γ = A⁻¹ p̃(x)``,

    ∂Φ_I = (∂γ)ᵀ p̃_I w_I + γᵀ p̃_I ∂w_I,   ∂γ = A⁻¹ (∂p̃(x) − ∂A γ),
    ∂A = Σ_I ∂w_I p̃_I p̃_Iᵀ.

*Visibility* (Belytschko et al. 1996, the criterion cut at Γ): with
``seen_from`` (N, 2), node I takes part in the MLS fit of body b only where
``seen_from[I, b]``; a point of body b then has the shape functions of the
nodes body b sees, which reproduce the basis in b on their own and are
smooth up to Γ from b's side.  Without it (or without bodies) every node is
seen everywhere.

Weights ``w(r)``: the cubic spline and the quartic spline of Belytschko et
al. (1994), on circular supports (``r = |x − x_I| / r_I``) or rectangular ones
(``w(r_x) w(r_y)``).  Everything is vectorised over points; neighbours come
from ``scipy.spatial.cKDTree``.
"""
from __future__ import annotations

import itertools
import os
import threading
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from contactcore import DiscretisationError
from contactcore import tolerances as tol
from contactcore.collective import launched_size


#: Gauss points whose stiffness blocks are made together
#: (:meth:`efgm.operators.Approximation.stiffness`): large enough to amortise
#: numpy's per-call cost, small enough for the (P, K) temporaries to stay in
#: cache (measured best among 2048, 8192 and 32768).
CHUNK = 32768

#: Points evaluated together by :meth:`MLS.evaluate`: its (K, P)
#: temporaries (K ≈ 16 neighbours) then stay in the cores' caches.  Measured
#: on 2 cores under a load of about 4, 101² grid, linear basis, 2e5 random
#: points, median of 3 per size, sizes alternated: 3.1e5 / 3.4e5 / 3.2e5 /
#: 2.5e5 / 2.2e5 points/s for 1024 / 2048 / 4096 / 8192 / 32768.
POINT_CHUNK = 2048

#: Support radii within this ratio share one search tree (see :meth:`MLS.cell_candidates`).
RADIUS_CLASS_RATIO = 1.5

#: Side of the buckets that collect each point's candidate neighbours, as a
#: fraction of the smallest support radius: smaller buckets hold fewer
#: candidates that miss the point but make more buckets.  Measured on the
#: 101² grid, linear basis (dmax 2), one thread, 32768 random points per
#: call: 0.5 / 0.35 / 0.25 give 20 / 19 / 16 candidates a bucket on average
#: (for ~13 neighbours) and 2.5e5 / 2.4e5 / 2.1e5 points/s.
BUCKET = 0.5

#: At most this many buckets per node: a node set with a few supports much
#: smaller than the rest (a user's clustered nodes) then gets larger buckets
#: instead of a bucket table that grows with (extent / smallest radius)².
#: A grid at BUCKET = 0.5 has about one bucket per node.
BUCKETS_PER_NODE = 4


def cubic_spline(r):
    """``w(r)`` and ``dw/dr`` of the cubic spline (support r < 1)."""
    inner = r <= 0.5
    t = np.maximum(1.0 - r, 0.0)  # the outer piece is 4/3 (1 − r)³: zero from r = 1 on
    t2 = t * t
    w = np.where(inner, 2 / 3 - 4 * r * r * t, 4 / 3 * t2 * t)
    dw = np.where(inner, r * (12 * r - 8), -4 * t2)
    return w, dw


def quartic_spline(r):
    """``w(r) = 1 − 6r² + 8r³ − 3r⁴`` and its derivative (support r < 1)."""
    r2 = r * r
    w = 1 - 6 * r2 + 8 * r2 * r - 3 * r2 * r2
    dw = -12 * r + 24 * r2 - 12 * r2 * r
    outside = r >= 1.0
    w[outside] = 0.0
    dw[outside] = 0.0
    return w, dw


WEIGHTS = {"cubic": cubic_spline, "quartic": quartic_spline}


def basis_size(degree: int) -> int:
    """The number of monomials of the MLS basis of ``degree``: 3 for the
    linear basis (1, ξ, η), 6 for the quadratic; another degree is a
    KeyError (the options refuse it first,
    :func:`contactcore.discretisation.check_degree`)."""
    return {1: 3, 2: 6}[degree]


def _basis(xi: np.ndarray, eta: np.ndarray, degree: int) -> np.ndarray:
    """The monomials of ``degree`` at (ξ, η), stacked first: (m, *ξ.shape)."""
    cols = [np.ones_like(xi), xi, eta]
    if degree == 2:
        cols += [xi * xi, xi * eta, eta * eta]
    return np.stack(cols, axis=0)


#: For m = 3, 6: the position among the distinct products ``p_i p_j``
#: (i ≤ j, row by row) of each entry of an m × m symmetric matrix.
_SYMMETRIC = {}
for _m in (3, 6):
    _SYMMETRIC[_m] = np.zeros((_m, _m), int)
    _SYMMETRIC[_m][np.triu_indices(_m)] = np.arange(_m * (_m + 1) // 2)
    _SYMMETRIC[_m] = np.maximum(_SYMMETRIC[_m], _SYMMETRIC[_m].T).ravel()


def _shift(v: np.ndarray, rho: np.ndarray, degree: int) -> np.ndarray:
    """``M`` (…, m, m) with ``p(ρ (u − v)) = M p(u)`` for the monomials of
    ``degree``: v (…, 2), ρ (…)."""
    a, b = v[..., 0], v[..., 1]
    one, zero = np.ones_like(a), np.zeros_like(a)
    rows = [[one, zero, zero], [-rho * a, rho, zero], [-rho * b, zero, rho]]
    if degree == 2:
        r2 = rho * rho
        rows = [row + [zero, zero, zero] for row in rows] + [
            [r2 * a * a, -2 * r2 * a, zero, r2, zero, zero],
            [r2 * a * b, -r2 * b, -r2 * a, zero, r2, zero],
            [r2 * b * b, zero, -2 * r2 * b, zero, zero, r2]]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


@dataclass
class ShapeValues:
    """Shape functions at P points: neighbour indices (P, K) (−1 = padding),
    values (P, K) and gradients (P, K, 2); padded entries are zero."""

    index: np.ndarray
    phi: np.ndarray
    grad: np.ndarray


def _spd_inverse(A: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Inverses of a stack of symmetric positive definite matrices (P, m, m)
    by Gauss–Jordan elimination without pivoting, and the pivots (P, m)
    (their product is the determinant).  Plain numpy ufuncs: no LAPACK,
    whose serial OpenBLAS build gives wrong answers when called from two
    threads at once (measured here), and no per-matrix call overhead.  A
    singular A gives non-finite entries, caught by the regularity check.
    """
    P, m, _ = A.shape
    aug = np.concatenate([A, np.broadcast_to(np.eye(m), A.shape)], axis=2)
    pivots = np.empty((P, m))
    with np.errstate(divide="ignore", invalid="ignore"):
        for k in range(m):
            pivots[:, k] = aug[:, k, k]
            aug[:, k, :] /= aug[:, k, k:k + 1]
            factors = aug[:, :, k].copy()
            factors[:, k] = 0.0
            aug -= factors[:, :, None] * aug[:, k:k + 1, :]
    return aug[:, :, m:], pivots


def _scaled_determinant(det, a00, a11, a22) -> np.ndarray:
    """:meth:`MLS.regularity` of 3 × 3 matrices from their determinant and diagonal."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return det / (np.where(a00 > 0, a00, 1.0) * np.where(a11 > 0, a11, 1.0) * np.where(a22 > 0, a22, 1.0))


#: One BLAS call at a time: numpy's matmul calls BLAS, and the serial
#: OpenBLAS build gives wrong answers when called from two threads at once
#: (measured here: singular moment matrices in a threaded assembly that
#: is regular serially).  The products are a small part of a chunk's work;
#: the rest runs in parallel (:func:`parallel_map`).
_BLAS = threading.Lock()


def matmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a @ b`` under :data:`_BLAS` (einsum, BLAS-free, is 5-15x slower here)."""
    with _BLAS:
        return a @ b


def threads() -> int:
    """How many threads :func:`parallel_map` uses: ``OMP_NUM_THREADS`` when
    set (the share of the cores that a study's workers and the scaling
    benchmark's ranks are given, as for BLAS); else one per rank under
    mpirun (MPI's one rank per core), one per core without it."""
    try:
        return max(1, int(os.environ["OMP_NUM_THREADS"]))
    except (KeyError, ValueError):
        return 1 if launched_size() > 1 else os.cpu_count() or 1


def parallel_map(function, items):
    """``function`` of each item, in order, on :func:`threads` threads (numpy
    releases the GIL in its kernels); a generator, so a consumer can reduce
    the results as they come."""
    items = list(items)
    if len(items) < 2 or threads() == 1:
        yield from map(function, items)
        return
    with ThreadPoolExecutor(threads()) as pool:
        yield from pool.map(function, items)


#: Bodies by index, as the messages name them (contactcore.bodies: 0 is −, 1 is +).
_BODY_NAMES = ("−", "+")


def _on_one_line(xy: np.ndarray) -> bool:
    """Whether the points ``xy`` (n, 2) lie on one line: their centred
    coordinates' second singular value is at most
    :data:`~contactcore.tolerances.EFGM_NODES_ON_ONE_LINE` of their first
    (two or fewer points always do)."""
    if len(xy) <= 2:
        return True
    s = np.linalg.svd(xy - xy.mean(axis=0), compute_uv=False)
    return bool(s[1] <= tol.EFGM_NODES_ON_ONE_LINE * s[0])


class MLS:
    """MLS shape functions of a node set.

    ``radii``: support radius of each node, shape (N,) for circular supports
    or (N, 2) for rectangular ones (half-widths in x and y).  ``seen_from``:
    (N, 2) bool, the bodies each node takes part in (module doc), or None.
    ``to_user``: maps a point to the coordinates an error message gives
    (the user's, where the nodes are those of a dimensionless scene), or None.
    """

    def __init__(self, nodes: np.ndarray, radii: np.ndarray, *, degree: int = 1, weight: str = "cubic",
                 dilation: float | None = None, seen_from: np.ndarray | None = None, to_user=None):
        if degree not in (1, 2):
            raise DiscretisationError(f"efgm: the MLS basis degree must be 1 or 2 (got {degree})")
        if weight not in WEIGHTS:
            raise DiscretisationError(f"efgm: unknown weight {weight!r} (known: {', '.join(WEIGHTS)})")
        self.nodes = np.asarray(nodes, float)
        self._x, self._y = self.nodes[:, 0].copy(), self.nodes[:, 1].copy()  # contiguous, for np.take
        self.radii = np.asarray(radii, float)
        self.rectangular = self.radii.ndim == 2
        self._radii2 = None if self.rectangular else self.radii * self.radii  # support tests on squared distances
        self.degree, self.weight, self.dilation = degree, WEIGHTS[weight], dilation
        self.seen_from = None if seen_from is None else np.asarray(seen_from, bool)
        self.to_user = to_user or (lambda p: np.asarray(p, float))
        self.m = basis_size(degree)
        self.tree = cKDTree(self.nodes)
        self.reach = float(np.max(self.radii))
        size = self.radii.max(axis=1) if self.rectangular else self.radii
        band = np.floor(np.log(size / size.min()) / np.log(RADIUS_CLASS_RATIO)).astype(int)
        self._classes = []  # (global indices, tree, largest radius) per radius class
        for b in np.unique(band):
            members = np.flatnonzero(band == b)
            self._classes.append((members, cKDTree(self.nodes[members]), float(size[members].max())))
        extent = np.ptp(self.nodes, axis=0)
        self._bucket = max(BUCKET * float(size.min()), float(np.sqrt(np.prod(extent) / (BUCKETS_PER_NODE * len(size)))))
        self._grid_origin = self.nodes.min(axis=0)
        self._grid_shape = np.floor(extent / self._bucket).astype(np.int64) + 1
        self._tables, self._tables_lock = {}, threading.Lock()

    def neighbours(self, points: np.ndarray, bodies: np.ndarray | None = None
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Neighbours (K, P), the points along the second axis — nodes whose
        own support holds the point and that the point's body sees, first
        in each column, −1 after — and offsets ``x − x_I`` as two (K, P)
        arrays (zero in the padding).  Neighbours run along the first axis
        so that a sum over them adds whole contiguous rows.

        Candidates come from the bucket each point falls in
        (:meth:`_bucket_candidates`: the nodes whose support meets the
        bucket, found once per bucket and body), then each is tested
        against its own support; no tree is searched per point.
        """
        cand = self._bucket_candidates(points, bodies)
        safe = np.maximum(cand, 0)
        ox = points[:, :1] - self._x.take(safe)
        oy = points[:, 1:] - self._y.take(safe)
        if self.rectangular:
            inside = (cand >= 0) & (np.abs(ox) < self.radii[safe, 0]) & (np.abs(oy) < self.radii[safe, 1])
        else:
            inside = (cand >= 0) & (ox * ox + oy * oy < self._radii2.take(safe))
        counts = inside.sum(axis=1)
        found = np.flatnonzero(inside)  # in (P, U), row by row
        rows = found // cand.shape[1]
        place = np.arange(len(found)) - np.repeat(np.cumsum(counts) - counts, counts)  # rank among its row's
        shape = (max(int(counts.max(initial=1)), 1), len(points))
        to = place * shape[1] + rows  # into (K, P)
        idx, out_x, out_y = np.full(shape, -1), np.zeros(shape), np.zeros(shape)
        idx.ravel()[to], out_x.ravel()[to], out_y.ravel()[to] = cand.take(found), ox.take(found), oy.take(found)
        return idx, out_x, out_y

    def _bucket_candidates(self, points: np.ndarray, bodies: np.ndarray | None) -> np.ndarray:
        """For each point, the candidate nodes (P, U), −1 after, of its
        bucket (squares of side :data:`BUCKET` × the smallest support
        radius, or larger (:data:`BUCKETS_PER_NODE`), over the nodes'
        bounding box; :meth:`cell_candidates` of each
        bucket, kept per body); a point outside every bucket gets those of
        its own position."""
        visible = self.seen_from is not None and bodies is not None
        cell = np.floor((points - self._grid_origin) / self._bucket).astype(np.int64)
        outside = np.any((cell < 0) | (cell >= self._grid_shape), axis=1)
        flat = np.where(outside, 0, cell[:, 0] * self._grid_shape[1] + cell[:, 1])
        if not visible:
            cand = self._bucket_table(-1, flat)[flat]
        else:
            b = np.asarray(bodies)
            tables = {key: self._bucket_table(key, flat[b == key]) for key in (0, 1)}
            cand = np.full((len(points), max(t.shape[1] for t in tables.values())), -1)
            for key, table in tables.items():
                mine = b == key
                cand[mine, :table.shape[1]] = table[flat[mine]]
        if outside.any():
            lone = self.cell_candidates(points[outside], points[outside], bodies[outside] if visible else None)
            if lone.shape[1] > cand.shape[1]:
                cand = np.pad(cand, [(0, 0), (0, lone.shape[1] - cand.shape[1])], constant_values=-1)
            cand[outside] = -1
            cand[outside, :lone.shape[1]] = lone
        return cand

    def _bucket_table(self, body: int, buckets: np.ndarray) -> np.ndarray:
        """The candidates (all buckets, U) for ``body`` (−1: no visibility),
        −1 after, the rows of ``buckets`` filled: each bucket's found on
        first use and kept (one thread at a time)."""
        with self._tables_lock:
            count = int(np.prod(self._grid_shape))
            table, done = self._tables.get(body) or (np.full((count, 1), -1), np.zeros(count, bool))
            new = np.unique(buckets[~done[buckets]])
            if len(new):
                lo = self._grid_origin + self._bucket * np.column_stack(np.divmod(new, self._grid_shape[1]))
                found = self.cell_candidates(lo, lo + self._bucket, None if body == -1 else np.full(len(new), body))
                if found.shape[1] > table.shape[1]:
                    table = np.pad(table, [(0, 0), (0, found.shape[1] - table.shape[1])], constant_values=-1)
                table[new, :found.shape[1]] = found
                done[new] = True
                self._tables[body] = (table, done)
            return table

    def cell_candidates(self, lo: np.ndarray, hi: np.ndarray, bodies: np.ndarray | None = None) -> np.ndarray:
        """The nodes (G, U), −1 after, whose support meets the box
        ``[lo, hi]`` (G, 2) of each group of points and that the group's body
        sees: a superset of the neighbours of every point in the box, found
        once per box instead of once per point."""
        centre, half = (lo + hi) / 2, (hi - lo) / 2
        size = np.max(half, axis=1) if self.rectangular else np.hypot(half[:, 0], half[:, 1])
        groups, found = [], []
        for members, tree, reach in self._classes:
            hits = tree.query_ball_point(centre, size + reach, p=np.inf if self.rectangular else 2)
            counts = np.fromiter(map(len, hits), int, len(hits))
            groups.append(np.repeat(np.arange(len(hits)), counts))
            found.append(members[np.fromiter(itertools.chain.from_iterable(hits), int, counts.sum())])
        g, node = np.concatenate(groups), np.concatenate(found)
        gap = np.maximum(np.abs(self.nodes[node] - centre[g]) - half[g], 0.0)  # box to node, per axis
        if self.rectangular:
            meet = np.all(gap < self.radii[node], axis=1)
        else:
            meet = np.hypot(gap[:, 0], gap[:, 1]) < self.radii[node]
        if self.seen_from is not None and bodies is not None:
            meet &= self.seen_from[node, np.asarray(bodies)[g]]
        order = np.argsort(g[meet], kind="stable")
        g, node = g[meet][order], node[meet][order]
        counts = np.bincount(g, minlength=len(lo))
        idx = np.full((len(lo), max(int(counts.max(initial=0)), 1)), -1)
        idx[g, np.arange(len(g)) - np.repeat(np.cumsum(counts) - counts, counts)] = node
        return idx

    def _weights(self, idx: np.ndarray, ox: np.ndarray, oy: np.ndarray):
        """``w``, ``∂w/∂x``, ``∂w/∂y`` (P, K) and each neighbour's largest radius."""
        r_node = self.radii[np.maximum(idx, 0)]
        if self.rectangular:
            rxn, ryn = r_node[..., 0], r_node[..., 1]
            wx, dwx = self.weight(np.abs(ox) / rxn)
            wy, dwy = self.weight(np.abs(oy) / ryn)
            w, wdx, wdy = wx * wy, dwx * wy * np.sign(ox) / rxn, wx * dwy * np.sign(oy) / ryn
            r_node = np.maximum(rxn, ryn)
        else:
            d = np.sqrt(ox * ox + oy * oy)  # np.hypot guards against overflow at 6x the cost (measured)
            w, dwr = self.weight(d / r_node)
            scale = dwr / (r_node * np.where(d > 0, d, 1.0))
            wdx, wdy = scale * ox, scale * oy
        used = idx >= 0
        return w * used, wdx * used, wdy * used, r_node

    def evaluate(self, points, bodies=None) -> ShapeValues:
        """Φ and ∇Φ at ``points`` (P, 2) of ``bodies`` (P,) (needed with
        ``seen_from``); a clear error where A is singular.

        Points are taken in chunks of :data:`POINT_CHUNK` (their temporaries
        stay in cache) spread over the cores: numpy releases the GIL in these
        kernels.  A first pass finds each chunk's neighbours, which sets the
        output's width; a second writes each chunk's Φ and ∇Φ into its rows
        of the output, in place (a serial copy of the chunks after them was
        an eighth of the time).  The linear basis takes a closed form
        (:meth:`_linear_shape`), the quadratic one :meth:`cell_shape`.
        """
        points = np.asarray(points, float).reshape(-1, 2)
        if self.seen_from is not None and bodies is None:
            raise ValueError("efgm: shape functions with visibility need the body of each point")
        bodies = None if bodies is None else np.broadcast_to(np.asarray(bodies, int), (len(points),))
        starts = range(0, len(points), POINT_CHUNK)
        found = list(parallel_map(lambda i: self.neighbours(
            points[i:i + POINT_CHUNK], None if bodies is None else bodies[i:i + POINT_CHUNK]), starts))
        K = max((idx.shape[0] for idx, _, _ in found), default=1)
        out = ShapeValues(np.full((len(points), K), -1), np.zeros((len(points), K)), np.zeros((len(points), K, 2)))

        def shape(j: int) -> None:  # chunk j into its rows and first columns of out; the padding stays
            idx, ox, oy = found[j]
            found[j] = None
            rows, width = slice(starts[j], starts[j] + idx.shape[1]), idx.shape[0]
            out.index[rows, :width] = idx.T
            phi, grad = out.phi[rows, :width], out.grad[rows, :width]
            if self.degree == 1:
                self._linear_shape(points[rows], idx, ox, oy, phi.T, grad.transpose(2, 1, 0))
            else:
                values, gradients = self.cell_shape(points[rows, None, :], np.ascontiguousarray(idx.T))
                phi[:], grad[:] = values[:, 0], gradients[:, 0]

        for _ in parallel_map(shape, range(len(starts))):
            pass
        return out

    def _linear_shape(self, points, idx, ox, oy, phi: np.ndarray, grad: np.ndarray) -> None:
        """Φ into ``phi`` (K, P) and ∇Φ into ``grad`` (2, K, P) of the
        linear basis at single points, from their neighbours ``idx`` and
        offsets (K, P) (:meth:`neighbours`), by :meth:`cell_shape`'s
        formulas for groups of one point: the 3 × 3 moment matrix and its
        derivatives from their 6 distinct sums each, inverted in closed form
        (cofactors over the determinant)."""
        w, wdx, wdy, r_node = self._weights(idx, ox, oy)  # (K, P)
        s = np.max(np.where(w > 0, r_node, 0.0), axis=0, initial=0.0)
        s[s == 0] = 1.0
        s_g = np.max(np.where(idx >= 0, r_node, 0.0), axis=0, initial=0.0)
        s_g[s_g == 0] = 1.0
        xi, eta = -ox / s_g, -oy / s_g  # p̂_I = (1, ξ, η) = p((x_I − x)/s_g)

        def moments(weights):  # a00, a01, a02, a11, a12, a22 of Σ weights p̂ p̂ᵀ
            wx, wy = weights * xi, weights * eta
            return [weights.sum(axis=0), wx.sum(axis=0), wy.sum(axis=0), (wx * xi).sum(axis=0),
                    (wx * eta).sum(axis=0), (wy * eta).sum(axis=0)]

        a00, a01, a02, a11, a12, a22 = moments(w)
        c00, c01, c02 = a11 * a22 - a12 * a12, a02 * a12 - a01 * a22, a01 * a12 - a02 * a11
        c11, c12, c22 = a00 * a22 - a02 * a02, a01 * a02 - a00 * a12, a00 * a11 - a01 * a01
        det = a00 * c00 + a01 * c01 + a02 * c02
        self._check_regular(points, _scaled_determinant(det, a00, a11, a22), w.T, idx.T)
        inv = np.array([[c00, c01, c02], [c01, c11, c12], [c02, c12, c22]]) / det  # A⁻¹, (3, 3, P)
        gamma = inv[:, 0]  # A⁻¹ p̃(x), p̃(x) = e₁
        gp = gamma[0] + gamma[1] * xi + gamma[2] * eta
        for d, dw in enumerate((wdx, wdy)):
            b00, b01, b02, b11, b12, b22 = moments(dw)  # ∂A
            rhs = -np.array([b00 * gamma[0] + b01 * gamma[1] + b02 * gamma[2],
                             b01 * gamma[0] + b11 * gamma[1] + b12 * gamma[2],
                             b02 * gamma[0] + b12 * gamma[1] + b22 * gamma[2]])
            rhs[d + 1] += 1.0 / s  # ∂p̃(x)/∂x_d = e_{d+1}/s
            dgamma = np.einsum("ijp,jp->ip", inv, rhs)
            np.add((dgamma[0] + dgamma[1] * xi + dgamma[2] * eta) * w, gp * dw, out=grad[d])
        np.multiply(gp, w, out=phi)

    def cell_shape(self, points: np.ndarray, idx: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Φ (G, Q, U) and ∇Φ (G, Q, U, 2) at the points (G, Q, 2) of G
        groups, of the nodes ``idx`` (G, U) of each (−1 = padding): a group
        of one point and its neighbours (:meth:`evaluate`), or the points of
        a cell and its candidates (:meth:`cell_candidates`; a node whose
        support misses a point has w = 0 there, so Φ = 0).

        The moments are summed in a basis common to the group,
        ``p̂_I = p((x_I − c)/s_g)`` (c the group's mean point, s_g its
        largest radius), by matrix products, then moved to each point's own (module doc):
        ``p̃ = M p̂``, ``M = Λ(s_g/s) T((x − c)/s_g)`` (:func:`_shift`),
        ``A = M Â Mᵀ`` and ``∂A = M ∂Â Mᵀ`` with ``Â = Σ_I w_I p̂_I p̂_Iᵀ``.
        For a group of one point, c = x, s_g = s and M = I."""
        G, Q, _ = points.shape
        m = self.m
        safe = np.maximum(idx, 0)
        ox = points[..., :1] - self.nodes[safe, 0][:, None, :]  # (G, Q, U)
        oy = points[..., 1:] - self.nodes[safe, 1][:, None, :]
        w, wdx, wdy, r_node = self._weights(idx[:, None, :], ox, oy)
        s = np.max(np.where(w > 0, r_node, 0.0), axis=2, initial=0.0)
        s[s == 0] = 1.0
        s_g = np.max(np.where(idx >= 0, r_node[:, 0], 0.0), axis=1, initial=0.0)
        s_g[s_g == 0] = 1.0
        centre = points.mean(axis=1)
        pI_m = _basis(*((self.nodes[safe] - centre[:, None, :]) / s_g[:, None, None]).transpose(2, 0, 1),
                      self.degree)  # p̂_I, (m, G, U)
        pI, pIt = pI_m.transpose(1, 2, 0), pI_m.transpose(1, 0, 2)
        if Q == 1:  # M = I; one point per group: no products p̂_i p̂_j kept per node
            M = Mt = None

            def moved(weights):  # Σ_I w_I p̂_I p̂_Iᵀ, (G, m, m)
                return self._moments(weights[:, 0], pI_m)
        else:
            # every operand of matmul C-contiguous: numpy loops on strided views instead of
            # calling BLAS (32768 quadratic 6 × 6 products: 26 ms against 1.2 ms)
            upper = np.triu_indices(m)
            pp = np.ascontiguousarray(pI[..., upper[0]] * pI[..., upper[1]])  # the p̂_i p̂_j, (G, U, m(m+1)/2)
            M = _shift((points - centre[:, None, :]) / s_g[:, None, None], s_g[:, None] / s, self.degree)
            M = np.ascontiguousarray(M.reshape(-1, m, m))
            Mt = np.ascontiguousarray(M.transpose(0, 2, 1))

            def moved(weights):  # M (Σ_I w_I p̂_I p̂_Iᵀ) Mᵀ, (G·Q, m, m)
                sums = np.ascontiguousarray(matmul(weights, pp)[..., _SYMMETRIC[m]].reshape(-1, m, m))
                return matmul(matmul(M, sums), Mt)

        def back(v):  # Mᵀ v for v (G·Q, m, 1), as (G, Q, m)
            return (v if M is None else matmul(Mt, v)).reshape(G, Q, m)

        A = moved(w)
        Ainv, pivots = _spd_inverse(A)
        self._check_regular(points.reshape(-1, 2), self.regularity(A, pivots), w.reshape(G * Q, -1), idx, Q)
        gamma = Ainv[:, :, :1]  # A⁻¹ p̃(x), p̃(x) = e₁
        gp = matmul(back(gamma), pIt)  # γᵀ M p̂_I
        grad = np.empty(w.shape + (2,))
        for d, dw in enumerate((wdx, wdy)):
            rhs = -matmul(moved(dw), gamma)
            rhs[:, d + 1, 0] += 1.0 / s.ravel()  # ∂p̃(x)/∂x_d = e_{d+1}/s
            grad[..., d] = matmul(back(matmul(Ainv, rhs)), pIt) * w + gp * dw  # Mᵀ ∂γ, ∂γ = A⁻¹ rhs
        return gp * w, grad

    def _moments(self, w: np.ndarray, pI: np.ndarray) -> np.ndarray:
        """``Σ_K w p̂_i p̂_j`` (P, m, m) of w (P, K), p̂ (m, P, K), from the
        m(m+1)/2 distinct products."""
        A = np.empty((w.shape[0], self.m, self.m))
        for i in range(self.m):
            wi = w * pI[i]
            for j in range(i, self.m):
                A[:, i, j] = A[:, j, i] = np.sum(wi * pI[j], axis=1)
        return A

    def regularity(self, A, pivots) -> np.ndarray:
        """``det(A) / Π A_ii``: the determinant of A scaled to a unit
        diagonal, 1 for orthogonal moments, 0 for a singular A."""
        diag = np.einsum("pii->pi", A)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            return np.prod(pivots / np.where(diag > 0, diag, 1.0), axis=1)

    def _check_regular(self, points, ratio, w, idx, per: int = 1) -> None:
        """A clear error at the first point whose moment matrix has a
        :meth:`regularity` ``ratio`` below :data:`contactcore.tolerances.MOMENT_REGULARITY`
        (``w`` (P, K) its weights, ``idx[p // per]`` the nodes of point p's
        columns).  It says whether the nodes in the support lie on one line
        (:func:`_on_one_line`), and names a body thinner than the node
        spacing where that is why (:meth:`_thin_body`)."""
        bad = ~(ratio > tol.MOMENT_REGULARITY)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            seen = np.asarray(idx[i // per])[w[i] > 0]
            count = len(seen)
            dist, _ = self.tree.query(points[i], k=min(self.m + 1, len(self.nodes)))
            radius = float(np.median(self.radii if not self.rectangular else self.radii.max(axis=1)))
            grow = 1.05 * float(np.max(dist)) / radius  # the m+1 nearest nodes inside the supports
            collinear = count >= 2 and _on_one_line(self.nodes[seen])
            thin = self._thin_body(points[i], seen) if collinear else ""
            if thin:
                need = thin
            elif grow <= 1.0:  # no reach to suggest: the nodes it sees are too few (a gap, Γ's visibility cut)
                need = ("the nodes it sees within reach are too few or on one line (a gap in the node set, a "
                        "boundary, or Γ's cut of what each side sees): add nodes there, or enlarge dmax")
            elif self.dilation:
                need = f"dmax = {self.dilation:g} is too small here: about {self.dilation * grow:.2g} is needed"
            else:
                need = f"enlarge the supports about {grow:.2g} times"
            line = ", all on one line;" if collinear else ","
            x, y = self.to_user(points[i])
            raise DiscretisationError(
                f"efgm: the moment matrix at point ({x:.6g}, {y:.6g}) is singular: "
                f"{count} node(s) in its support{line} at least {self.m} not on one line are needed "
                f"({int(bad.sum())} such point(s)); {need}")

    def _thin_body(self, point, seen) -> str:
        """Why a point's nodes ``seen`` (on one line) are all it has, if
        Γ's visibility cut is why: "" unless some nodes whose supports hold
        the point are hidden from it, hidden from one body b that sees
        every node of ``seen`` (so the point is b's), and would leave the
        line.  Then b's side sees nodes on that one line only here: a body
        thinner than the node spacing, which efgm refuses (docs/usage.md,
        docs/methods/efgm.md)."""
        if self.seen_from is None:
            return ""
        near = np.asarray(self.tree.query_ball_point(point, self.reach), int)
        offset = np.abs(self.nodes[near] - point)
        held = (np.all(offset < self.radii[near], axis=1) if self.rectangular
                else np.hypot(*offset.T) < self.radii[near])
        hidden = np.setdiff1d(near[held], seen)
        sides = [b for b in (0, 1) if self.seen_from[seen, b].all() and not self.seen_from[hidden, b].any()]
        if len(hidden) == 0 or len(sides) != 1 or _on_one_line(self.nodes[np.concatenate([seen, hidden])]):
            return ""
        b = sides[0]
        gap, _ = self.tree.query(self.nodes[seen], k=2)
        origin = self.to_user(np.zeros(2))
        spacing = float(np.median(gap[:, 1])) * float(np.linalg.norm(self.to_user(np.array([1.0, 0.0])) - origin))
        name = _BODY_NAMES[b]
        return (f"Γ cuts what each side sees, and body {name}'s side sees nodes on that one line only here: body {name} "
                f"is thinner than the node spacing ({spacing:.3g}), which efgm refuses: use fe, or a node spacing "
                f"finer than body {name}'s thickness")
