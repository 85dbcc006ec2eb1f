"""Penalty contact without tension: ``t_N = k_N min(g_N, 0)``, tied tangentially where closed.

Contract: :class:`UnilateralLaw` answers each point ``STICK`` (closed,
``t = diag(k_N, k_T) g``) or ``OPEN`` (``t = 0``), closed at ``g_N <= 0``
or by a Newton :class:`~contactcore.laws.decision.Decision`'s band; no
history, nothing refused.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .decision import Decision
from .response import OPEN, STICK, LawResponse
from .springs import _Law


@dataclass(frozen=True)
class UnilateralLaw(_Law):
    """Penalty contact without tension (docs/scenes.md): ``t_N = k_N min(g_N, 0)``;
    where closed (``g_N <= 0``) ``t_T = k_T g_T``, where open ``t_T = 0``.

    History-free but piecewise linear: the tangent is ``diag(k_N, k_T)`` on
    closed points and zero on open ones (status STICK or OPEN).
    """

    kN: float
    kT: float

    name: ClassVar[str] = "unilateral"
    is_linear: ClassVar[bool] = False
    homogeneous: ClassVar[bool] = True
    unilateral: ClassVar[bool] = True
    frictional: ClassVar[bool] = False

    def evaluate(self, g: np.ndarray, state=None, decision: Decision | None = None) -> LawResponse:
        """The response to the jumps ``g`` ((m, 2) or flat, ``[g_N, g_T]`` in
        the scene's length unit): where closed, ``t = diag(k_N, k_T) g``
        (``STICK``), where open ``t = 0`` (``OPEN``), with the tangent of
        each.  A point is closed where ``g_N <= 0``; with a Newton
        ``decision`` (:class:`Decision`), by its band, so that round-off
        cannot flip a point.  No state (``state`` is ignored); nothing is
        refused."""
        g, closed, tN = self._springs(g, decision)
        tT = np.where(closed, self.kT * g[:, 1], 0.0)
        tangent = np.zeros((len(g), 2, 2))
        tangent[:, 0, 0] = np.where(closed, self.kN, 0.0)
        tangent[:, 1, 1] = np.where(closed, self.kT, 0.0)
        return LawResponse(np.column_stack([tN, tT]), tangent, None,
                           np.where(closed, STICK, OPEN).astype(np.int8))
