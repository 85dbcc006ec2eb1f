"""Each point's neighbours: the nodes whose support holds it, found by buckets.

The MLS fit at ``x`` (Belytschko, Lu & Gu, IJNME 37, 1994) sums over the
nodes ``I`` whose support holds ``x`` (``|x − x_I| < r_I`` on a circle,
``|x − x_I| < r_xI`` and ``|y − y_I| < r_yI`` on a rectangle) and, with
visibility, that the point's body sees (``seen_from``, :mod:`efgm.shape`).
Searching a tree per point costs more than the fit, so candidates are
found once per *bucket*: a square of the nodes' bounding box, of side
:data:`BUCKET` × the smallest support radius (or larger, at most
:data:`BUCKETS_PER_NODE` buckets per node), whose candidates are the nodes
whose support meets the square (:meth:`_Neighbours.cell_candidates`, a
superset of every point's neighbours there).  Then each candidate is
tested against its own support.  Supports of very different radii are
searched in classes (:data:`RADIUS_CLASS_RATIO`), each with its own tree
and reach, so that one large support does not widen every search.

Contract of the mixin: :class:`efgm.shape.MLS` gives ``nodes`` (N, 2),
``radii`` ((N,) or (N, 2)), ``rectangular`` and ``seen_from`` ((N, 2)
bool or None), then calls :meth:`_Neighbours._index_nodes`, which sets
``tree`` (a cKDTree of every node), ``reach`` (the largest radius) and the
buckets' state; the bucket tables fill on first use, one thread at a time.
Neighbours come back with −1 as padding, offsets ``x − x_I`` zero there.
"""
from __future__ import annotations

import itertools
import threading

import numpy as np
from scipy.spatial import cKDTree

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


class _Neighbours:
    """The neighbour search of :class:`efgm.shape.MLS`."""

    def _index_nodes(self) -> None:
        """The search's state: contiguous coordinates, squared radii, the
        tree of every node, the radius classes' trees and the buckets."""
        self._x, self._y = self.nodes[:, 0].copy(), self.nodes[:, 1].copy()  # contiguous, for np.take
        self._radii2 = None if self.rectangular else self.radii * self.radii  # support tests on squared distances
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
