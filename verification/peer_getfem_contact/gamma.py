"""Γ's Gauss points, and the jump, traction and status of GetFEM's answer there.

The interface record (:class:`~contactcore.interface_path.InterfacePath`)
holds :data:`FACET_POINTS` Gauss–Legendre points on each facet of Γ in
gmsh's mesh (where the two bodies' meshes conform): the facet ``x(ξ)``, ``ξ ∈ [−1, 1]``, the quadratic Lagrange
curve through its end points and its midpoint (the chord's midpoint at
degree 1), weight ``w |x'(ξ)|``; profiles then report λ's mean over each
facet, as for our exact laws.

Sign conventions (docs/scenes.md): λ is the traction on the − body, so
``t_N = λ·n`` (< 0 in compression) and ``t_T = λ·t``, ``t = (n_y, −n_x)``;
``g = (u2 − u1)·(n, t)``.  Each point's status at an increment is
GetFEM's own Alart–Curnier test (Alart & Curnier, CMAME 92, 1991): open
where ``λ_N + r g_N ≥ 0``, else stick where
``|λ_T + r Δg_T| ≤ μ (−λ_N − r g_N)``, else slip.

Contract: :func:`_facet_points` returns points (m, 2), weights (m,) and
the points per facet; :class:`_Gamma`'s ``jump`` and ``traction`` are
(m, 2) in (N, T), ``status`` the law's codes (:mod:`contactcore.laws`).
"""
from __future__ import annotations

import numpy as np

from contactcore import Scene
from contactcore.geometry import tangent_of
from contactcore.interface_path import piece_centres
from contactcore.laws import OPEN, SLIP, STICK

from .bodies import _Bodies
from .fields import GetFEMContactFields

#: Gauss–Legendre points per Γ facet for the interface record: exact for a
#: degree-7 polynomial in the facet's parameter, where λ is linear and a
#: degree-2 facet's speed on a circle varies by O(θ²) over its angle θ.
FACET_POINTS = 4


def _facet_points(facets: np.ndarray, degree: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Gauss points (m, 2), weights (m,) and piece sizes of Γ's facets: the
    facet x(ξ), ξ ∈ [−1, 1], through its end points (and its midpoint at
    degree 2), weight w |x'(ξ)|."""
    xi, w = np.polynomial.legendre.leggauss(FACET_POINTS)
    a, b = facets[:, 0], facets[:, 1]
    mid = facets[:, 2] if degree == 2 else (a + b) / 2
    # quadratic Lagrange through ξ = −1, 1, 0
    pts = (a[:, None] * (xi * (xi - 1) / 2)[None, :, None] + b[:, None] * (xi * (xi + 1) / 2)[None, :, None]
           + mid[:, None] * (1 - xi ** 2)[None, :, None])
    speed = (a[:, None] * (xi - 0.5)[None, :, None] + b[:, None] * (xi + 0.5)[None, :, None]
             + mid[:, None] * (-2 * xi)[None, :, None])
    weights = w[None, :] * np.linalg.norm(speed, axis=2)
    return pts.reshape(-1, 2), weights.ravel(), np.full(len(facets), FACET_POINTS)


class _Gamma:
    """Γ's Gauss points and their frame; the jump, traction and status of
    GetFEM's solution there."""

    def __init__(self, scene: Scene, bodies: _Bodies, degree: int):
        self.points, self.weights, sizes = _facet_points(bodies.facets, degree)
        self.pieces = piece_centres(self.points, self.weights, sizes)
        n = scene.interface.normals(self.points)
        self.frame = np.stack([n, tangent_of(n)], axis=1)  # (m, 2 [N, T], 2 [x, y])
        self.zeros, self.ones = np.zeros(len(self.points), int), np.ones(len(self.points), int)

    def jump(self, fields: GetFEMContactFields) -> np.ndarray:
        """g = (g_N, g_T) of u2 − u1."""
        d = fields.displacement(self.points, self.ones) - fields.displacement(self.points, self.zeros)
        return np.einsum("pij,pj->pi", self.frame, d)

    def traction(self, fields: GetFEMContactFields) -> np.ndarray:
        """(t_N, t_T) = (λ·n, λ·t), λ read on the − side."""
        return np.einsum("pij,pj->pi", self.frame, fields.multiplier(self.points))

    @staticmethod
    def status(t: np.ndarray, g: np.ndarray, dg: np.ndarray, r: float, mu: float) -> np.ndarray:
        """GetFEM's Alart–Curnier test (module doc) at each point."""
        pressure = -(t[:, 0] + r * g[:, 0])
        trial = np.abs(t[:, 1] + r * dg[:, 1])
        return np.where(pressure <= 0, OPEN, np.where(trial <= mu * pressure, STICK, SLIP)).astype(np.int8)
