"""Error norms of any method's fields against an exact solution.

The integral runs over the exact geometry (the domain split along the exact
Γ, see :func:`efgm.method.volume_rule`) and samples each method only
through its :class:`~contactcore.result.Fields`, so every method is measured
the same way: ``‖u_h − u‖²_{L2} = Σ_q w_q |u_h(x_q) − u(x_q)|²`` with the
body of each quadrature point known exactly.
"""
from __future__ import annotations

import numpy as np

from efgm.method import volume_rule


def l2_error(scene, fields, exact, *, h: float, gauss: int = 4) -> tuple[float, float]:
    """``(‖u_h − u‖, ‖u‖)`` in L2 with cells of size ``h`` (≤ the method's
    own resolution, so the quadrature resolves its error) and ``gauss``²
    points per cell."""
    rule = volume_rule(scene, h, gauss)
    ue = exact.displacement(rule.points, rule.bodies)
    err = fields.displacement(rule.points, rule.bodies) - ue
    return float(np.sqrt(rule.weights @ np.sum(err ** 2, axis=1))), float(np.sqrt(rule.weights @ np.sum(ue ** 2,
                                                                                                      axis=1)))
