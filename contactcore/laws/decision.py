"""The status decision Newton hands a law, so that no status follows round-off.

Contract: :class:`Decision` holds each point's previous status and the
Γ-wide scales of the closed/open and stick/slip margins (reduced over
every rank by :meth:`Decision.reduced`); :meth:`Decision.switch` keeps a
point's previous status where its margin lies within
:data:`~contactcore.tolerances.DECISION_BAND` of the scale, and decides a
point at rest as a zero margin is.  The same jumps and history give the
same statuses on every machine and rank count.  A law reads it in its
``evaluate``; nothing here knows a particular law.  numpy only.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .. import tolerances as tol


@dataclass(frozen=True)
class Decision:
    """What Newton hands a law so that no status follows round-off.

    ``previous`` is each point's status at the previous iterate (at a
    step's first iterate, the last converged one).  A switch whose margin —
    ``−g_N`` for closed/open, ``μp − |t*|`` for stick/slip — lies within
    ``DECISION_BAND`` of its scale keeps the previous status (the scale
    never below ``DECISION_FLOOR`` of the scene's units: with no load every
    gap is round-off, and so would its largest be): the traction
    of either branch differs there by at most that band, far above the
    round-off that a BLAS kernel, a MUMPS ordering or a renumbering leaves
    in the margin, so every machine takes the same decision.  The scales
    are Γ-wide (reduced over every rank by Newton): ``gap`` the largest
    ``|g_N|``, ``traction`` the largest slip limit of a closed point, the
    law's ``slip_bound`` (Coulomb's ``μp``; :meth:`_Law.decision_scales`).
    A margin within REST_ROUNDOFF of ``size`` (the larger of the scene's
    displacement unit and Γ's largest jump or slip history; a traction
    margin over the point's stiffness) is a point at rest, decided
    as a zero margin is (closed, sticking) whatever it was before: a load
    back to exactly zero leaves every margin round-off, and the band
    relative to round-off scales is round-off too.

    Γ is at rest for the stick/slip decision where its largest pressure
    ``pressure`` is at DECISION_FLOOR too, not only its largest slip limit
    ``μp``: a small μ puts μp below the floor under any load (the layered
    cycle at μ = 1e-6, p = 5e-5 of E), and the rest window held every
    point at stick there.  Under load the traction scale is
    ``max(μp, TRACTION_ROUNDOFF · p)``, with no absolute floor: the band
    then lets a sticking ``|t_T|`` past ``μp`` by at most ``1e-5 μp`` or the
    traction's round-off (μ below MU_SMALLEST is refused, where that
    round-off would be a tenth of μp or more).
    """

    previous: np.ndarray
    gap: float
    traction: float
    #: the size of Γ's jumps and slip history (their largest, at least the
    #: displacement unit): the round-off of a margin ``g − s`` is relative to it
    size: float = 1.0
    #: Γ's largest pressure ``p = −t_N`` (reduced over ranks); at or below
    #: DECISION_FLOOR Γ is at rest for the stick/slip decision
    pressure: float = 0.0
    #: the closed/open band's scale per point where it is narrower than
    #: ``gap`` (None: ``gap``): an exact law's ``p/γ`` (:meth:`in_traction`),
    #: so that a point the band holds closed carries a tension (or one it
    #: holds open a penetration) of at most DECISION_BAND of Γ's pressure
    normal: np.ndarray | None = None

    @classmethod
    def reduced(cls, law, g: np.ndarray, state, previous: np.ndarray, ranks) -> "Decision":
        """The decision of ``law`` at the jumps ``g``, its scales reduced
        over ``ranks`` (a :class:`~contactcore.collective.Collective`)."""
        scales = [ranks.max(float(v)) for v in law.decision_scales(g, state)]
        gap, limit = scales[0], scales[1]
        pressure = scales[2] if len(scales) > 2 else 0.0
        if pressure > tol.DECISION_FLOOR:  # Γ loaded: the band follows μp and the traction's round-off
            traction = max(limit, tol.TRACTION_ROUNDOFF * pressure)
        else:
            traction = max(limit, tol.DECISION_FLOOR)
        history = 0.0 if state is None else float(np.max(np.abs(state), initial=0.0))
        size = max(1.0, ranks.max(max(float(np.max(np.abs(g), initial=0.0)), history)))
        return cls(previous, max(gap, tol.DECISION_FLOOR), traction, size, pressure)

    def in_traction(self, stiffness: np.ndarray, pressure: float) -> "Decision":
        """This decision with its closed/open band narrowed, point by point,
        to ``pressure / stiffness`` where that is below ``gap``: the band
        then holds a point's status while ``stiffness × margin``, the
        traction its other branch would carry, lies within DECISION_BAND of
        Γ's largest ``pressure`` (reduced over ranks).  ``gap``, the largest
        jump, is an open gap's where Γ opens, and held a closed point with
        a tension of 2.4e-3 of p (xfem P2, grader7's partial contact).
        Unchanged where Γ carries no pressure above DECISION_FLOOR."""
        if not pressure > tol.DECISION_FLOOR:
            return self
        k = np.asarray(stiffness, float)
        return replace(self, normal=np.minimum(self.gap, pressure / k))

    def switch(self, margin: np.ndarray, scale: float, was: np.ndarray, stiffness=1.0,
               rest: bool | None = None) -> np.ndarray:
        """``margin > 0`` where it is beyond the band, ``True`` (a zero
        margin's side: closed, sticking) where Γ is at rest (``rest``; by
        default where Γ's ``scale`` is at DECISION_FLOOR) and ``|margin|``
        within REST_ROUNDOFF (times the ``stiffness`` that makes a gap of
        it, for a traction margin), else ``was``."""
        band = tol.DECISION_BAND * scale
        # at rest only where Γ as a whole is (a load back to zero); under
        # load the band decides, and a stiff spring's window would
        # otherwise hold a point past μp
        if rest is None:
            rest = scale <= tol.DECISION_FLOOR
        rest = rest & (np.abs(margin) <= tol.REST_ROUNDOFF * self.size * np.asarray(stiffness, float))
        return np.where(rest | (margin > band), True, np.where(margin < -band, False, was))
