"""The bonded springs (the paper's Eq. (6)): ``t = diag(k_N, k_T) g``, in tension too.

Contract: :class:`LinearLaw` answers every point ``STICK`` with the
constant tangent, no history, nothing refused; it is linear
(``is_linear``), so a scene with it is one linear solve.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .decision import Decision
from .response import STICK, LawResponse
from .springs import _Law


@dataclass(frozen=True)
class LinearLaw(_Law):
    """The paper's Eq. (6): bonded springs ``t_N = k_N g_N``, ``t_T = k_T g_T``.

    Tension is allowed; the tangent is constant, so a scene with this law is
    one linear solve whatever its number of increments.
    """

    kN: float
    kT: float

    name: ClassVar[str] = "linear"
    is_linear: ClassVar[bool] = True
    homogeneous: ClassVar[bool] = True
    unilateral: ClassVar[bool] = False
    frictional: ClassVar[bool] = False

    def constant_tangent(self) -> np.ndarray:
        """``∂t/∂g = diag(k_N, k_T)``: the same at every point."""
        return np.diag([self.kN, self.kT])

    def evaluate(self, g: np.ndarray, state=None, decision: Decision | None = None) -> LawResponse:
        """The springs' response to the jumps ``g`` ((m, 2) or flat, ``[g_N,
        g_T]`` in the scene's length unit; tractions in its stress unit, k in
        stress per length): ``t = diag(k_N, k_T) g`` at every point, in
        tension too; the constant tangent; no state (``state`` and
        ``decision`` are ignored); every point ``STICK``.  Nothing is
        refused: a non-finite jump gives a non-finite traction, which the
        health checks refuse."""
        g = np.asarray(g, dtype=float).reshape(-1, 2)
        D = self.constant_tangent()
        return LawResponse(g @ D.T, np.broadcast_to(D, (len(g), 2, 2)).copy(), None,
                           np.full(len(g), STICK, dtype=np.int8))
