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
whatever μ and the springs.  The loads are the edge tractions and pressures
by their own formulas (``_loaded_parts`` of :mod:`contactcore.health.equilibrium`,
at the increment's factors); a body with a body force is not judged here
(as in :func:`contactcore.health.equilibrium._demands`).
"""
from __future__ import annotations

import math

import numpy as np

from .. import tolerances as tol
from ..geometry import LineInterface, Rectangle, tangent_of
from ..scene.loads import BODY, acts_on
from .restraint import _BODY_NAMES, _free_modes, _restraint


def overturns(scene, k: float, loaded_parts) -> str:
    """The refusal of a scene whose loads at increment ``k`` overturn a
    body held by Γ alone (no support or pin on it), or "": any law that
    carries no tension (``law.unilateral``), Γ a line across a rectangle,
    the loads pressing the body onto Γ.  ``|e|`` beyond the half-length by
    more than DEMAND_ROUNDOFF of it (the scene's data, Python floats: the
    same on every machine).  ``loaded_parts(scene, body, factors)``: the
    edge loads' ``(t, length, point)`` on the body's parts of the edges
    (:func:`contactcore.health.equilibrium._loaded_parts`, passed in: it
    imports this module)."""
    if not scene.law.unilateral:
        return ""
    if not isinstance(scene.interface, LineInterface) or not isinstance(scene.domain, Rectangle):
        return ""
    ends = scene.interface.chord(scene.domain)
    if ends is None:
        return ""
    ends = np.asarray(ends, float)
    mid, half = 0.5 * (ends[0] + ends[1]), 0.5 * math.hypot(*(ends[1] - ends[0]))
    if half <= 0:
        return ""
    n = np.asarray(scene.interface.normal, float)
    tau = tangent_of(n[None])[0]
    supports = _restraint(scene, np.zeros((0, 2)), np.zeros(0))[0]
    factors = scene.factors(k)[0]
    for b, name in enumerate(_BODY_NAMES):
        if any(acts_on(ld) == BODY and ld.body == ("minus", "plus")[b] for ld in scene.loads):
            continue
        if _free_modes(supports[3 * b:3 * b + 3, 3 * b:3 * b + 3]).shape[1] < 3:
            continue  # held (in part) by its supports: _pulled_off's case
        force, moment = np.zeros(2), 0.0
        for t, length, point in loaded_parts(scene, b, factors):
            r = point - mid
            force += length * t
            moment += length * (float(r[0]) * float(t[1]) - float(r[1]) * float(t[0]))
        along_n = float(force[0]) * float(n[0]) + float(force[1]) * float(n[1])  # no BLAS
        press = -along_n if b == 1 else along_n
        if press <= tol.ALONG_GAMMA * math.hypot(*force):
            continue  # not pressed onto Γ: friction_demand's refusal
        across = float(tau[0]) * float(force[1]) - float(tau[1]) * float(force[0])  # τ × F, |.| = press
        e = moment / across
        if abs(e) > half * (1.0 + tol.DEMAND_ROUNDOFF):
            return (f"body {name} is held by Γ alone and the loads overturn it: their resultant meets Γ's line "
                    f"{abs(e):.3g} from Γ's midpoint, beyond Γ's half-length {half:.3g} (eccentricity/half-length "
                    f"= {abs(e) / half:.3g} > 1), and contact only pushes: no equilibrium, whatever μ and the "
                    "springs; lower the shear load or its lever arm, or hold the body with a support")
    return ""
