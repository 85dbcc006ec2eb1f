"""Nodes, support sizes and background integration cells of an EFGM model."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from contactcore import DiscretisationError, Scene
from contactcore import tolerances as tol
from contactcore.geometry import Disc, Rectangle
from contactcore.scaling import Scales

#: A node's spacing ``c_I`` is its distance to its SPACING_NEIGHBOUR-th
#: nearest other node: on a regular grid the 4th nearest is one grid step
#: away, so ``c_I = h`` and ``r_I = dmax·h``; on an irregular set it adapts.
SPACING_NEIGHBOUR = 4


@dataclass
class NodeSet:
    """Node coordinates (N, 2) and the nominal spacing h of the set."""

    x: np.ndarray
    h: float


def node_set(scene: Scene, resolution, nodes: np.ndarray | None = None) -> NodeSet:
    """A solve's nodes: the user's ``nodes`` (checked), else the paper's
    grid (``resolution.counts``), else a grid of spacing ``resolution.h``."""
    if nodes is not None:
        return check_nodes(scene, nodes)
    if resolution.counts is not None:
        return grid_nodes(scene, counts=resolution.counts)
    return grid_nodes(scene, resolution.h)


def grid_nodes(scene: Scene, h: float | None = None, counts: tuple[int, int] | None = None) -> NodeSet:
    """A regular grid: ``counts`` nodes per direction, or spacing ≈ h."""
    dom = scene.domain
    if isinstance(dom, Rectangle):
        (x0, y0), (a, b) = dom.corner, dom.size
        nx, ny = counts if counts else (max(2, round(a / h) + 1), max(2, round(b / h) + 1))
        X, Y = np.meshgrid(np.linspace(x0, x0 + a, nx), np.linspace(y0, y0 + b, ny))
        return NodeSet(np.column_stack([X.ravel(), Y.ravel()]), max(a / (nx - 1), b / (ny - 1)))
    if counts is not None:
        raise DiscretisationError("efgm: node counts apply to rectangles; give h for a disc")
    return _disc_nodes(dom, h)


def perturbed_nodes(scene: Scene, h: float, fraction: float, seed: int = 0) -> np.ndarray:
    """The grid of spacing ``h`` with every node off the boundary moved by a
    seeded uniform amount of up to ``fraction·h`` in x and in y (an irregular
    node set that still has nodes on every supported boundary)."""
    x = grid_nodes(scene, h).x.copy()
    inner = np.abs(scene.domain.distance_to_boundary(x)) > tol.GEOMETRY * scene.length_scale
    x[inner] += np.random.default_rng(seed).uniform(-fraction, fraction, (int(inner.sum()), 2)) * h
    return x


def _disc_nodes(dom: Disc, h: float) -> NodeSet:
    """Grid points inside the disc (half a step clear of the rim) and a ring
    of nodes on the rim, spaced h."""
    c, R = np.asarray(dom.centre, float), dom.radius
    n = int(np.ceil(R / h))
    g = np.arange(-n, n + 1) * h
    X, Y = np.meshgrid(c[0] + g, c[1] + g)
    pts = np.column_stack([X.ravel(), Y.ravel()])
    pts = pts[np.hypot(*(pts - c).T) < R - 0.5 * h]
    m = int(np.ceil(2 * np.pi * R / h))
    t = 2 * np.pi * np.arange(m) / m
    ring = c + R * np.column_stack([np.cos(t), np.sin(t)])
    return NodeSet(np.vstack([pts, ring]), h)


def nodes_refused(scene: Scene, nodes: np.ndarray) -> tuple[int, str, int | None] | None:
    """The first node of ``nodes`` (N, 2), in ``scene``'s own coordinates,
    that no EFGM model can hold, why, and the other node it concerns: not
    finite, outside the domain by more than the scene's geometric
    tolerance, or within NODE_MATCH · L of an earlier node (that node's
    index third); None if every node fits."""
    x = np.asarray(nodes, float)
    bad = np.flatnonzero(~np.all(np.isfinite(x), axis=1))
    if len(bad):
        return int(bad[0]), "is not a finite point", None
    outside = np.flatnonzero(~scene.domain.contains(x, tol.GEOMETRY * scene.length_scale))
    if len(outside):
        return int(outside[0]), f"lies outside the domain ({len(outside)} of {len(x)} nodes outside)", None
    pairs = cKDTree(x).query_pairs(tol.NODE_MATCH * scene.length_scale, output_type="ndarray")
    if len(pairs):
        first, second = sorted(pairs.tolist(), key=lambda p: (max(p), min(p)))[0]
        return max(first, second), "coincides with an earlier node", min(first, second)
    return None


def check_nodes(scene: Scene, nodes: np.ndarray) -> NodeSet:
    """A user's point set: finite, inside the domain, distinct; spacing from
    the set.  A refused node is named by its index and its coordinates in
    the user's scene (``scene.user``: the nodes of a dimensionless scene are
    mapped back; its length unit)."""
    x = np.asarray(nodes, float)
    if x.ndim != 2 or x.shape[1] != 2 or len(x) < 4:
        raise DiscretisationError(f"efgm: nodes must be an (N, 2) array with N >= 4 (got shape {x.shape})")
    refused = nodes_refused(scene, x)
    if refused is not None:
        i, why, other = refused
        user = scene.user
        with np.errstate(invalid="ignore"):
            shown = Scales.of(user).to_user(x[i:i + 1])[0] if user is not scene else x[i]
        raise DiscretisationError(f"efgm: node {i} at ({shown[0]:.6g}, {shown[1]:.6g}) {user.units.length} {why}"
                                  + (f" (node {other})" if other is not None else ""))
    d, _ = cKDTree(x).query(x, k=2)
    return NodeSet(x, float(np.median(d[:, 1])))


def support_radii(nodes: NodeSet, dmax: float, rectangular: bool) -> np.ndarray:
    """``r_I = dmax · c_I`` (see :data:`SPACING_NEIGHBOUR`); (N,) or (N, 2)."""
    if not (dmax > 0 and np.isfinite(dmax)):  # inf: every node in every support, each moment matrix singular
        raise DiscretisationError(f"efgm: dmax must be finite and > 0 (got {dmax})")
    k = min(SPACING_NEIGHBOUR + 1, len(nodes.x))
    d, _ = cKDTree(nodes.x).query(nodes.x, k=k)
    r = dmax * d[:, -1]
    return np.column_stack([r, r]) if rectangular else r
