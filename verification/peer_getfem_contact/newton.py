"""GetFEM's Newton for one increment, judged by the residual in force units.

GetFEM's ``Model.solve`` runs Newton with MUMPS (:data:`LINEAR_SOLVER`);
here it is called one iteration at a time, so that the test is ours
(:func:`_residual`): GetFEM's contact rows are Alart–Curnier's
``∫ (λ − P(λ − r g)) μ / r`` (Alart & Curnier, CMAME 92, 1991), a length,
and its own test (‖R‖ against the loads) is blind to them.  Multiplied by
``r`` they are forces, and every equation is judged against the external
forces ‖F‖ (:func:`_external_norm`).

Contract: :func:`_newton` returns the iterations and the residual after
each, ``‖R‖/‖F‖ ≤`` :data:`NEWTON_RESIDUAL` at the last, or raises a
:class:`~contactcore.DiscretisationError` naming the scene, the increment
and the residual reached in :data:`NEWTON_ITERATIONS`.
"""
from __future__ import annotations

import numpy as np

from contactcore import DiscretisationError, Scene

from .reach import METHOD

#: Newton's test: the residual in force units against the loads
#: (:func:`_residual`), and the iterations it may take.
NEWTON_RESIDUAL = 1e-10
NEWTON_ITERATIONS = 100

LINEAR_SOLVER = "mumps"


def _external_norm(md) -> float:
    """‖F‖, the external forces of the current loads: the right-hand side
    at u = 0, λ = 0 (where the contact rows vanish)."""
    x = md.from_variables()
    md.to_variables(np.zeros_like(x))
    md.assembly(option="build_rhs")
    scale = float(np.linalg.norm(md.rhs()))
    md.to_variables(x)
    return scale


def _residual(md, r: float, scale: float) -> float:
    """The residual of every equation in force units, against ‖F‖.

    GetFEM's contact rows are Alart–Curnier's ``∫ (λ − P(λ − r g)) μ / r``,
    a length: its own Newton test (‖R‖ against the loads) would pass a
    status map with λ_N > 0 in tension, whose contact rows are 1e-11 of the
    forces (measured: C-coulomb at h = 0.05 in one increment, Newton
    stopped after one iteration with max t_N = +1.4e5 Pa).  Multiplied by r
    they are forces, ``∫ (λ − P(…)) μ``."""
    md.assembly(option="build_rhs")
    res = np.array(md.rhs())
    first, size = md.interval_of_variable("lambda")
    res[first:first + size] *= r
    return float(np.linalg.norm(res) / scale)


def _newton(md, scene: Scene, k: int, r: float) -> tuple[int, list[float]]:
    """GetFEM's Newton for increment k, one iteration per call so that the
    test is :func:`_residual` (GetFEM's own test is blind to the contact
    rows); its iterations and residuals, or a clear error."""
    scale, history = _external_norm(md), []
    for it in range(1, NEWTON_ITERATIONS + 1):
        md.solve("max_res", 0.0, "max_iter", 1, "lsolver", LINEAR_SOLVER)
        history.append(_residual(md, r, scale))
        if not all(np.isfinite(md.variable(v)).all() for v in ("u1", "u2", "lambda")):
            break
        if history[-1] <= NEWTON_RESIDUAL:
            return it, history
    raise DiscretisationError(f"{METHOD}: GetFEM's Newton did not converge on scene {scene.name} at increment "
                              f"{k} in {NEWTON_ITERATIONS} iterations (relative residual {history[-1]:.1e})")
