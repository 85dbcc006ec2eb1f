"""Whether the loads overturn a body held by Γ alone (grader22 F2).

Contact on a straight Γ only pushes (t_N <= 0 under a unilateral or
Coulomb law), and its tangential tractions act along Γ, so they have no
moment about a point of Γ: the contact tractions' resultant acts on a line
that meets Γ within its extent (at the centroid of the pressures).  A body
held by Γ alone is in equilibrium only if the loads' resultant does the
same: its line of action meets Γ at a distance ``|e|`` from Γ's midpoint no
greater than Γ's half-length, ``e = M / (τ × F)``, ``M`` the loads' moment
about the midpoint, ``F`` their resultant, ``τ`` Γ's tangent.  Otherwise no
pressure distribution balances them: the body overturns (no equilibrium),
whatever μ and the springs.  The loads, the bodies judged and the press
are :func:`contactcore.health.equilibrium._demands`' (edge tractions and
pressures by their own formulas, and constant body forces, their
resultant at the body's part's centroid); this module gives the
geometry and the words.
"""
from __future__ import annotations

import math

import numpy as np

from .. import tolerances as tol
from ..geometry import tangent_of


def _middle(scene) -> tuple[np.ndarray, float]:
    """Γ's midpoint and half-length in the rectangle (a line across it;
    half-length 0 where it only touches it)."""
    ends = scene.interface.chord(scene.domain)
    if ends is None:
        return np.zeros(2), 0.0
    ends = np.asarray(ends, float)
    return 0.5 * (ends[0] + ends[1]), 0.5 * math.hypot(*(ends[1] - ends[0]))


def eccentricity(scene, parts, force: np.ndarray) -> float:
    """``e = M / (τ × F)``: where the line of action of the loads
    ``parts`` (``(t, length, point)``, resultant ``force`` pressing the body
    onto Γ) meets Γ's line, measured along τ from Γ's midpoint; in Python
    floats (no BLAS: the same on every machine)."""
    mid, _ = _middle(scene)
    moment = 0.0
    for t, length, point in parts:
        r = point - mid
        moment += length * (float(r[0]) * float(t[1]) - float(r[1]) * float(t[0]))
    tau = tangent_of(np.asarray(scene.interface.normal, float)[None])[0]
    return moment / (float(tau[0]) * float(force[1]) - float(tau[1]) * float(force[0]))  # τ × F, |.| = press


def overturned(scene, e: float) -> bool:
    """Whether ``|e|`` lies beyond Γ's half-length by more than
    DEMAND_ROUNDOFF of it (the scene's data: the same on every machine)."""
    _, half = _middle(scene)
    return half > 0 and abs(e) > half * (1.0 + tol.DEMAND_ROUNDOFF)


def overturn_refusal(scene, name: str, e: float) -> str:
    """The refusal's words, naming the eccentricity against Γ's half-length."""
    _, half = _middle(scene)
    return (f"body {name} is held by Γ alone and the loads overturn it: their resultant meets Γ's line "
            f"{abs(e):.3g} from Γ's midpoint, beyond Γ's half-length {half:.3g} (eccentricity/half-length "
            f"= {abs(e) / half:.3g} > 1), and contact only pushes: no equilibrium, whatever μ and the "
            "springs; lower the shear load or its lever arm, or hold the body with a support")
