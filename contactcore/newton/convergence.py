"""When a Newton step stops: converged, settled, still, or out of budget.

A step is accepted (:meth:`_Convergence._converged`) when one of three
holds, each on every rank alike:

* the equilibrium rows' residual is small against their own forces,
  ``‖R_balance‖∞ <= NEWTON_RTOL · F`` (``F`` the loads and internal forces
  there, at least RESIDUAL_FLOOR of the full loads), not against the
  round-off scale, whose data can dwarf a soft body's forces;
* the law's tangent at the iterate is the one the last full step was
  solved with (:meth:`_Convergence._settles`): a piecewise-linear law's
  status map then had its linear problem solved exactly, up to round-off;
* the last correction moved no digit of what the step moved ``u`` by
  (STEP_ROUNDOFF): points whose gap is round-off flip at every solve and
  change nothing.

The caller then holds the step to the round-off check (RESIDUAL_FAIL)
against its scale.  A step has NEWTON_MAX_ITERATIONS iterations, and
NEWTON_PROGRESS_ITERATIONS more for each that moves a point to a status
it has not held in the step (:meth:`_Convergence._progress`); a point can
do so at most twice, so the budget is finite (at most 25 + 4m for m
points, capped at NEWTON_PROGRESS_CAP).

Contract: a mixin of :class:`contactcore.newton.increments._Newton`; it
reads ``ranks`` and the residual's ``_balance``
(:class:`~contactcore.newton.residual._Residual`) and writes nothing.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol


class _Convergence:
    """The step's convergence test and iteration budget (module doc)."""

    def _converged(self, R, forces: float, tangent, response, du, moved) -> bool:
        """Whether the step has converged: the equilibrium rows' residual
        small against their own forces (not against the round-off scale:
        the data of a stiff body, E δ/h, can dwarf the forces of a soft one,
        and a wrong stick/slip split passed); or the law's tangent is the one
        the last full solve used (a piecewise-linear law is then solved
        exactly, up to that solve's round-off); or the last correction
        ``du`` moved no digit of what the step ``moved`` u by (points whose
        gap is round-off change status at every solve and change nothing:
        a rigid shift under unilateral contact).  The caller then holds it
        to the round-off check against the step's scale."""
        balance = self._balance(R)
        settled = self._settles(tangent, response)
        still = du is not None and self.ranks.max(float(np.max(np.abs(du), initial=0.0))) <= (
            tol.STEP_ROUNDOFF * self.ranks.max(float(np.max(np.abs(moved), initial=0.0))))
        return balance <= tol.NEWTON_RTOL * forces or settled or still

    def _settles(self, tangent, response) -> bool:
        """Whether the law's tangent at ``response`` is the ``tangent`` the
        last full step was solved with (None: none, or a partial step), on
        every rank: the step then solved its status map's linear problem."""
        return tangent is not None and self.ranks.all(np.array_equal(tangent, response.tangent))

    def _progress(self, held, status):
        """The statuses each point has ``held`` in the step (a bit per
        status) with ``status`` added, and whether ``status`` moved a point,
        on any rank, to a status it had not held in the step.  Each such
        iteration adds NEWTON_PROGRESS_ITERATIONS to the step's budget: a
        point can do so at most twice (open, stick, slip), so the budget
        stays finite, while a semismooth Newton that moves points at a tie
        of the law from stick to slip a few per iteration (docs/newton.md,
        "A tie") goes on, and one that cycles (points moving back to
        statuses they held) stops at NEWTON_MAX_ITERATIONS."""
        bits = np.left_shift(1, np.asarray(status, np.int64))
        if held is None:
            return bits, False
        return held | bits, self.ranks.max(float(np.any((held & bits) == 0))) > 0
