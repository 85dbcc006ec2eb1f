"""What a law answers at its points, and how Newton reads the slipping ones.

Contract: a law's ``evaluate`` returns a :class:`LawResponse` for ``m``
points: the tractions ``[t_N, t_T]`` (m, 2) in the scene's stress unit,
the tangent ``∂t/∂g`` (m, 2, 2), the new history (None for a law without
one), each point's status (:data:`OPEN`, :data:`STICK` or :data:`SLIP`,
int8) and, for a law with slip, the slipping points' secant stiffness.
:data:`PARTIAL` is never a law's status: outputs alone report it.
:func:`secant_tangent` puts that secant in place of a slipping point's
tangential tangent (Kačanov's step); it changes no response.  numpy only.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class LawResponse:
    """Tractions ``[t_N, t_T]`` (m, 2), tangent (m, 2, 2), the new state and
    the status of each point."""

    traction: np.ndarray
    tangent: np.ndarray
    state: np.ndarray | None
    status: np.ndarray  # (m,) OPEN, STICK or SLIP
    #: (m,) the secant tangential stiffness ``|t_T| / |g_T − s|`` of the
    #: slipping points (0 elsewhere), a stiffness their tangent lacks
    #: (:func:`contactcore.laws.secant_tangent`); None for a
    #: law without slip
    secant: np.ndarray | None = None


#: Status of an interface point (``LawResponse.status``).
OPEN, STICK, SLIP = 0, 1, 2
STATUS_NAMES = ("open", "stick", "slip")
#: A point of the unilateral law's partial answer (:mod:`contactcore.newton.partial`:
#: ``y_N = 0`` with a share θ of the tie's shear), as outputs report it
#: (:meth:`contactcore.interface_path.Increment.reported_status`).  No law
#: and no Newton status arithmetic ever sees it: there the point is ``STICK``.
PARTIAL = 3
REPORTED_STATUS_NAMES = STATUS_NAMES + ("partial",)


def secant_tangent(tangent: np.ndarray, secant: np.ndarray) -> np.ndarray:
    """``tangent`` (m, 2, 2) with each slipping point's ``secant``
    stiffness ``|t_T| / |g_T − s|`` (:attr:`LawResponse.secant`, 0 where
    the point does not slip) in place of its ``∂t_T/∂g_T = 0``: where every
    closed point of a body held by Γ alone slips, the slip tangent leaves
    the body free to turn (or slide): its moment is flat in the rotation
    until a point's trial re-enters the stick window.  This step (Kačanov's
    iteration for a monotone law), exact or penalty (for Nitsche, ``g``
    is the augmented jump ``y``), moves the rotation towards that window by
    as much as the slipping tractions ask, where the stick stiffness, far
    steeper, crept; Newton goes on with the law's tangent once a point
    sticks."""
    out = np.array(tangent, float, copy=True)
    slipping = secant > 0
    out[slipping, 1, 1] = secant[slipping]
    return out
