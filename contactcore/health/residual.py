"""A solve's residual test, the one criterion every method's solve passes.

A solve of ``A x = b`` succeeds only if the *relative residual* of the
equations actually solved (the free block) is small:

    ρ = ‖b − A x‖∞ / max(‖b‖∞, F) <= RESIDUAL_FAIL,

``F`` the internal-force scale of a Newton iteration (0 for a plain linear
solve).  The normwise backward error ``‖b − A x‖/(‖A‖‖x‖ + ‖b‖)`` (Rigal and
Gaches' theorem, Higham, *Accuracy and Stability of Numerical Algorithms*,
2002, Thm 7.1) is reported beside it, never instead: for a (nearly)
singular ``A`` a huge ``x`` makes it tiny while ``ρ`` stays O(1).

Here too the words a failed solve is named by (:data:`NOT_CONVERGED`,
:data:`DIVERGED`), which the refusals of contactcore.newton read back.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol
from ..errors import SolverError


def _inf(v) -> float:
    v = np.asarray(v)
    return float(np.max(np.abs(v))) if v.size else 0.0


def relative_residual(r, b, force_scale: float = 0.0) -> float:
    """``‖r‖∞ / max(‖b‖∞, F)`` (``‖r‖∞`` itself when both are zero)."""
    scale = max(_inf(b), force_scale)
    return _inf(r) / scale if scale > 0 else _inf(r)


def backward_error(r, a_norm: float, x, b) -> float:
    """Normwise backward error ``‖r‖∞ / (‖A‖∞‖x‖∞ + ‖b‖∞)`` (reported only)."""
    scale = a_norm * _inf(x) + _inf(b)
    return _inf(r) / scale if scale > 0 else _inf(r)


def check_residual(residual: float, what: str, backward: float = float("nan"), hint: str = "") -> None:
    """Raise :class:`SolverError` unless ``residual <= RESIDUAL_FAIL`` (NaN fails)."""
    if not residual <= tol.RESIDUAL_FAIL:
        raise SolverError(f"{what}: relative residual {residual:.2e} exceeds {tol.RESIDUAL_FAIL:g} "
                          f"(backward error {backward:.1e}) — the answer does not satisfy the equations"
                          + (f"; {hint}" if hint else "; a rigid-body mode may be free, or the springs are too "
                             "stiff or too soft for double precision"))


#: How Newton's error begins when its iterations run out (contactcore.newton);
#: :func:`tie_cause` reads a failure by it.
NOT_CONVERGED = "Newton did not converge"


#: How a linear solve that PETSc reports as diverged is named
#: (contactcore.linear_solver; an iterative ``ksp_type`` out of iterations):
#: the options, not round-off, chose it, so a refusal keeps it
#: (contactcore.newton._refusal, _no_equilibrium).
DIVERGED = "the solver diverged"

#: How a solve is named whose user-chosen iterative solver (a ``ksp_type``
#: or ``pc_type`` option) stopped, by its own tolerances, short of
#: :data:`~contactcore.tolerances.RESIDUAL_FAIL`: the options chose it, as
#: they choose a divergence (review3, 2026-11-28: gmres + jacobi on
#: presspull read "no step converged" with the load's advice).
SHORT_OF_CHECK = "the solver the options chose stopped short of the residual check"


def options_chose(failure: str) -> bool:
    """Whether a solve's ``failure`` message is one the user's solver
    options chose (:data:`DIVERGED`, :data:`SHORT_OF_CHECK`), not
    round-off: a refusal names it as it is."""
    return DIVERGED in failure or SHORT_OF_CHECK in failure
