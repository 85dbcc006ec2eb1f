"""Γ between two of its points, and a straight side, as a curve ``(C(τ), C′(τ))``, ``τ ∈ [0, 1]``.

Contract: ``_gamma_curve(itf, p, q)`` is Γ from ``p`` to ``q`` (both on
Γ): the segment for a line, the short arc for a circle (exact), and for a
general level set the chord projected onto ``φ = 0`` along its normal by
:data:`PROJECTIONS` Newton steps (not finite where ``∇φ`` is normal to the
chord's normal: the caller refuses it).  ``_segment(p, q)`` is a straight
side.  Each is a pair of functions of an array of ``τ``, returning (n, 2).
"""
from __future__ import annotations

import numpy as np

from contactcore.geometry import LevelSetInterface, LineInterface


#: Newton steps projecting a chord point onto a general Γ (quadratic
#: convergence from a chord within O(h²) of Γ: 8 reach round-off).
PROJECTIONS = 8


def _projected_curve(itf, p: np.ndarray, q: np.ndarray):
    """Γ between two of its points as the chord projected onto φ = 0 along
    the chord's normal m: C(τ) = p + τ(q − p) + s(τ) m, with φ(C) = 0 by
    Newton and C′ = (q − p) + s′ m, s′ = −∇φ·(q − p) / ∇φ·m."""
    d = q - p
    m = np.array([-d[1], d[0]]) / np.linalg.norm(d)

    def solve(t):
        base = p + t[:, None] * d
        s = np.zeros(len(t))
        with np.errstate(divide="ignore", invalid="ignore"):  # ∇φ ⟂ m: not finite, and refused by the caller
            for _ in range(PROJECTIONS):
                x = base + s[:, None] * m
                s -= itf.phi(x) / (np.asarray(itf.grad_fn(x)) @ m)
        return base + s[:, None] * m

    def tangent(t):
        g = np.asarray(itf.grad_fn(solve(t)))
        return d + (-(g @ d) / (g @ m))[:, None] * m

    return solve, tangent


def _gamma_curve(itf, p: np.ndarray, q: np.ndarray):
    """Γ from p to q as ``(C(τ), C′(τ))`` (the short arc for a circle)."""
    if isinstance(itf, LevelSetInterface):
        return _projected_curve(itf, p, q)
    if isinstance(itf, LineInterface):
        return lambda t: p + t[:, None] * (q - p), lambda t: np.broadcast_to(q - p, (len(t), 2))
    c, R = np.asarray(itf.centre, float), itf.radius
    a0, a1 = np.arctan2(*(p - c)[::-1]), np.arctan2(*(q - c)[::-1])
    da = (a1 - a0 + np.pi) % (2 * np.pi) - np.pi
    ang = lambda t: a0 + t * da  # noqa: E731
    return (lambda t: c + R * np.column_stack([np.cos(ang(t)), np.sin(ang(t))]),
            lambda t: R * da * np.column_stack([-np.sin(ang(t)), np.cos(ang(t))]))


def _segment(p, q):
    return lambda t: p + t[:, None] * (q - p), lambda t: np.broadcast_to(q - p, (len(t), 2))
