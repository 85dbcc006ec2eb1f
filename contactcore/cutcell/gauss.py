"""Gauss–Legendre rules on [0, 1] and on axis-aligned rectangles, and the rule's container.

Contract: :func:`gauss01` gives ``n`` points and weights on [0, 1] (numpy's
Gauss–Legendre, the same as basix's interval rules; cached, so read-only),
exact for a degree ``2n − 1`` polynomial; :func:`tensor_cells` and
``_tensor_rule`` their ``n × n`` products on rectangles.  :class:`Rule`
holds points (Q, 2), weights (Q,) and the body of each point.  numpy only.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np



@dataclass
class Rule:
    """Quadrature points (Q, 2), weights (Q,) and the body (0 −, 1 +) of each."""

    points: np.ndarray
    weights: np.ndarray
    bodies: np.ndarray

    @staticmethod
    def concatenate(rules: list["Rule"]) -> "Rule":
        rules = [r for r in rules if len(r.weights)]
        if not rules:
            return Rule(np.zeros((0, 2)), np.zeros(0), np.zeros(0, int))
        return Rule(np.concatenate([r.points for r in rules]), np.concatenate([r.weights for r in rules]),
                    np.concatenate([r.bodies for r in rules]))


@functools.cache
def gauss01(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre points and weights on [0, 1] (cached: read-only)."""
    x, w = np.polynomial.legendre.leggauss(n)
    return (x + 1) / 2, w / 2


def _tensor_rule(lo, hi, n):
    g, gw = gauss01(n)
    X, Y = np.meshgrid(lo[0] + g * (hi[0] - lo[0]), lo[1] + g * (hi[1] - lo[1]), indexing="ij")
    W = np.outer(gw, gw) * np.prod(hi - lo)
    return np.column_stack([X.ravel(), Y.ravel()]), W.ravel()


def tensor_cells(lo: np.ndarray, hi: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """n×n Gauss points of many cells at once: (C·n², 2) points and weights."""
    g, gw = gauss01(n)
    size = hi - lo
    gx, gy = np.meshgrid(g, g, indexing="ij")
    pts = lo[:, None, :] + np.stack([gx.ravel(), gy.ravel()], axis=-1)[None] * size[:, None, :]
    w = np.outer(gw, gw).ravel()[None] * np.prod(size, axis=1)[:, None]
    return pts.reshape(-1, 2), w.ravel()
