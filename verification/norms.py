"""Error norms of any method's fields against an exact solution.

The integral runs over the exact geometry (the domain split along the exact
Γ, see :func:`contactcore.quadrature.volume_rule`) and samples each method only
through its :class:`~contactcore.result.Fields`, so every method is measured
the same way: ``‖u_h − u‖²_{L2} = Σ_q w_q |u_h(x_q) − u(x_q)|²`` with the
body of each quadrature point known exactly.
"""
from __future__ import annotations

import numpy as np

from contactcore.quadrature import volume_rule


def l2_error(scene, fields, exact, *, h: float, gauss: int = 4) -> tuple[float, float]:
    """``(‖u_h − u‖, ‖u‖)`` in L2 with cells of size ``h`` (≤ the method's
    own resolution, so the quadrature resolves its error) and ``gauss``²
    points per cell."""
    rule = volume_rule(scene, h, gauss)
    ue = exact.displacement(rule.points, rule.bodies)
    err = fields.displacement(rule.points, rule.bodies) - ue
    return float(np.sqrt(rule.weights @ np.sum(err ** 2, axis=1))), float(np.sqrt(rule.weights @ np.sum(ue ** 2,
                                                                                                      axis=1)))


def observed_rate(scene, exact, solve, hs) -> tuple[list[float], float]:
    """Relative L2 errors of ``solve(h)`` (a Result) on the resolutions
    ``hs`` and the least-squares slope of log error against log h."""
    errors = []
    for h in hs:
        err, ref = l2_error(scene, solve(h).fields, exact, h=h / 2)
        errors.append(err / ref)
    return errors, fitted_rate(hs, errors)


def fitted_rate(hs, errors) -> float:
    """The least-squares slope of log error against log h."""
    return float(np.polyfit(np.log(hs), np.log(errors), 1)[0])


def max_errors(scene, fields, exact, *, samples: int = 400, seed: int = 0) -> tuple[float, float]:
    """Largest pointwise displacement and stress errors, each relative to the
    largest exact value, at seeded random points of a rectangular domain
    (kept 2 % of its size away from the boundary)."""
    (x0, y0), (a, b) = scene.domain.corner, scene.domain.size
    unit = np.random.default_rng(seed).uniform(0.02, 0.98, (samples, 2))
    pts = np.array([x0, y0]) + unit * np.array([a, b])
    bodies = scene.body_of(pts)
    u, s = exact.displacement(pts, bodies), exact.stress(pts, bodies)
    return (float(np.max(np.abs(fields.displacement(pts, bodies) - u)) / np.max(np.abs(u))),
            float(np.max(np.abs(fields.stress(pts, bodies) - s)) / np.max(np.abs(s))))
