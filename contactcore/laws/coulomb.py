"""Unilateral penalty contact with Coulomb friction: the elastic predictor and return map.

Contract: :class:`CoulombLaw` (``kN``, ``kT``, ``mu`` checked by
:func:`_friction`: finite, 0 or in ``[MU_SMALLEST, MU_LARGEST]``) carries
each point's accumulated slip as its history and answers ``OPEN``,
``STICK`` or ``SLIP`` with the tractions, the (unsymmetric) tangent, the
new slip and the slipping points' secant; its slip bound is the cone
``μ max(−t_N, 0)``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .. import tolerances as tol
from ..errors import SceneError
from .contract import DIMENSIONLESS, STIFFNESS
from .decision import Decision
from .response import OPEN, SLIP, STICK, LawResponse
from .springs import _Law


def _friction(params: dict, path: str) -> float:
    if "mu" not in params:
        raise SceneError(f"{path}.mu", "missing (the friction coefficient, >= 0)")
    value = params["mu"]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
        raise SceneError(f"{path}.mu", f"must be a finite friction coefficient >= 0 (got {value!r})")
    if 0 < value < tol.MU_SMALLEST:
        raise SceneError(f"{path}.mu", f"{value:g} is below {tol.MU_SMALLEST:g}: a traction carries round-off up to "
                         f"{tol.TRACTION_ROUNDOFF:g} of the pressure p, a tenth or more of such a μp, so whether a "
                         f"point sticks or slips cannot be decided; give mu = 0 (frictionless) or mu >= "
                         f"{tol.MU_SMALLEST:g}")
    if value > tol.MU_LARGEST:
        raise SceneError(f"{path}.mu", f"{value:g} is above {tol.MU_LARGEST:g}: a μ of that size already makes "
                         "every closed point stick; give one at most that large")
    return float(value)


@dataclass(frozen=True)
class CoulombLaw(_Law):
    """Unilateral penalty contact with Coulomb friction (docs/scenes.md), the
    elastic-predictor / return-map of Wriggers, *Computational Contact
    Mechanics* (2006), §5.2, in one dimension of slip.

    State: the accumulated slip ``s`` of each point.  With ``p = −t_N`` and
    the trial ``t* = k_T (g_T − s)``:

    * open (``g_N > 0``): ``t = 0``, ``s ← g_T`` (closes with no shear), tangent 0;
    * stick (``|t*| <= μ p (1 + STICK_ROUNDOFF)``): ``t_T = t*``, tangent ``diag(k_N, k_T)``;
    * slip: ``t_T = μ p sign(t*)``, ``s ← g_T − t_T / k_T``; tangent
      ``∂t_T/∂g_N = −μ k_N sign(t*)``, ``∂t_T/∂g_T = 0`` — not symmetric.
    """

    kN: float
    kT: float
    mu: float

    name: ClassVar[str] = "coulomb"
    parameters: ClassVar[tuple[str, ...]] = ("kN", "kT", "mu")
    dimensions: ClassVar[dict[str, str]] = {"kN": STIFFNESS, "kT": STIFFNESS, "mu": DIMENSIONLESS}
    is_linear: ClassVar[bool] = False
    has_history: ClassVar[bool] = True
    homogeneous: ClassVar[bool] = True  # the cone μp scales with p, the slip s with g
    unilateral: ClassVar[bool] = True
    frictional: ClassVar[bool] = True

    @classmethod
    def extra_parameters(cls, params: dict, path: str) -> dict:
        """``mu``, checked (:func:`_friction`)."""
        return {"mu": _friction(params, path)}

    def initial_state(self, m: int) -> np.ndarray:
        """No slip before the first increment."""
        return np.zeros(m)

    def slip_bound(self, tN: np.ndarray) -> np.ndarray:
        """Coulomb's cone: ``μ max(−t_N, 0)``."""
        return self.mu * np.maximum(-np.asarray(tN, dtype=float), 0.0)

    def slides_off(self, body: str, shear: float, press: float, length: float) -> str:
        """:meth:`_Law.slides_off` in Coulomb's words: the loads' shear/normal
        beyond μ (by DEMAND_ROUNDOFF; Wriggers 2006, §2.3), the demand to 3
        digits and μ to 6, or both to as many digits as tell them apart
        (0.25 against μ = 0.2499999975)."""
        mu = self.mu
        if not shear > mu * press * (1.0 + tol.DEMAND_ROUNDOFF):
            return ""
        ratio, digits = shear / press, 3
        while digits < 17 and float(f"{ratio:.{digits}g}") <= float(f"{mu:.{max(digits, 6)}g}"):
            digits += 1
        return (f"on Γ the loads ask for shear/normal = {ratio:.{digits}g} of body {body}, above μ = "
                f"{mu:.{max(digits, 6)}g}: it slides off (no equilibrium); lower the shear load or raise μ")

    def evaluate(self, g: np.ndarray, state=None, decision: Decision | None = None) -> LawResponse:
        """The return map (class doc) at the jumps ``g`` ((m, 2) or flat,
        ``[g_N, g_T]`` in the scene's length unit) from the slip ``state``
        ((m,), same unit; None: no slip yet): tractions (stress unit),
        the tangent (not symmetric where a point slips), the new slip
        state, each point's ``OPEN``/``STICK``/``SLIP``, and the slipping
        points' secant stiffness.  Open/closed and stick/slip are decided
        at ``g_N <= 0`` and ``|t*| <= μp (1 + STICK_ROUNDOFF)``, or, with a
        Newton ``decision``, by its bands (round-off cannot flip a
        point).  Nothing is refused: ``state`` must have one entry per
        point (numpy broadcasting rules otherwise)."""
        g, closed, tN = self._springs(g, decision)
        limit = self.slip_bound(tN)
        s = np.zeros(len(g)) if state is None else np.asarray(state, dtype=float)
        trial = self.kT * (g[:, 1] - s)
        if decision is None:
            stick = closed & (np.abs(trial) <= limit * (1.0 + tol.STICK_ROUNDOFF))
        else:
            stick = closed & decision.switch(limit - np.abs(trial), decision.traction, decision.previous == STICK,
                                             self.kT, rest=decision.traction <= tol.DECISION_FLOOR
                                             and decision.pressure <= tol.DECISION_FLOOR)
        slip = closed & ~stick
        direction = np.sign(trial)
        tT = np.where(stick, trial, np.where(slip, limit * direction, 0.0))
        tangent = np.zeros((len(g), 2, 2))
        tangent[:, 0, 0] = np.where(closed, self.kN, 0.0)
        tangent[:, 1, 1] = np.where(stick, self.kT, 0.0)
        tangent[:, 1, 0] = np.where(slip, -self.mu * self.kN * direction, 0.0)
        new_state = np.where(stick, s, g[:, 1] - tT / self.kT)
        status = np.where(stick, STICK, np.where(slip, SLIP, OPEN)).astype(np.int8)
        # a slipping point's |t*| exceeds μp >= 0, so it is never 0 there
        secant = np.divide(np.broadcast_to(self.kT * limit, limit.shape), np.abs(trial),
                           out=np.zeros(len(g)), where=slip)
        return LawResponse(np.column_stack([tN, tT]), tangent, new_state, status, secant)
