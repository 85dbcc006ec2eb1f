"""Interface laws: jumps (and state) in, tractions and tangents out.

A law works in the local frame of Γ.  For ``m`` interface points it takes the
jumps ``g = [g_N, g_T]`` (shape ``(m, 2)``, ``g_N = [[u]]·n``,
``g_T = [[u]]·t``) and returns the tractions ``[t_N, t_T]`` (Pa) and the
tangent ``∂t/∂g`` (shape ``(m, 2, 2)``, Pa/m).  The traction acting on the +
body is ``τ⁺ = −(t_N n + t_T t)``; the − body receives ``−τ⁺`` (SCENES.md).

In a weak form the law contributes ``∫_Γ t(g(u)) · g(δu) dΓ`` to the
internal virtual work.  Laws are looked up by name in :data:`LAWS`, so a new
law is one class and one registry entry; every method calls the same code.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .errors import SceneError


@dataclass(frozen=True)
class LawResponse:
    """Tractions ``[t_N, t_T]`` (m, 2), tangent (m, 2, 2) and the new state."""

    traction: np.ndarray
    tangent: np.ndarray
    state: np.ndarray | None


def _positive(params: dict, key: str, path: str) -> float:
    if key not in params:
        raise SceneError(f"{path}.{key}", "missing (a penalty stiffness in Pa/m)")
    value = params[key]
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(f"{path}.{key}", f"must be a number (got {value!r})")
    if not math.isfinite(value) or value <= 0:
        raise SceneError(f"{path}.{key}", f"must be a finite penalty > 0 (got {value!r})")
    return float(value)


@dataclass(frozen=True)
class LinearLaw:
    """The paper's Eq. (6): bonded springs ``t_N = k_N g_N``, ``t_T = k_T g_T``.

    Tension is allowed; the tangent is constant, so a scene with this law is
    one linear solve whatever its number of increments.
    """

    kN: float
    kT: float

    name: ClassVar[str] = "linear"
    parameters: ClassVar[tuple[str, ...]] = ("kN", "kT")
    is_linear: ClassVar[bool] = True

    @classmethod
    def from_params(cls, params: dict, path: str) -> "LinearLaw":
        """Build from a TOML table, naming the field of any bad value."""
        unknown = sorted(set(params) - set(cls.parameters) - {"type"})
        if unknown:
            raise SceneError(f"{path}.{unknown[0]}", f"unknown parameter of the '{cls.name}' law "
                             f"(it takes {', '.join(cls.parameters)})")
        return cls(**{k: _positive(params, k, path) for k in cls.parameters})

    def initial_state(self, m: int) -> None:
        """The linear law has no history."""
        return None

    def constant_tangent(self) -> np.ndarray:
        """``∂t/∂g = diag(k_N, k_T)``: the same at every point."""
        return np.diag([self.kN, self.kT])

    def evaluate(self, g: np.ndarray, state=None) -> LawResponse:
        g = np.asarray(g, dtype=float).reshape(-1, 2)
        D = self.constant_tangent()
        return LawResponse(g @ D.T, np.broadcast_to(D, (len(g), 2, 2)).copy(), None)

    @property
    def stiffness_scale(self) -> float:
        """The largest spring stiffness, used in conditioning diagnostics."""
        return max(self.kN, self.kT)


#: Every interface law by the name a scene file gives it.
LAWS = {law.name: law for law in (LinearLaw,)}

InterfaceLaw = LinearLaw


def make_law(params: dict, path: str = "interface.law"):
    """The law named by ``params["type"]`` built from the other entries."""
    if not isinstance(params, dict):
        raise SceneError(path, "must be a table with a 'type' and the law's parameters")
    kind = params.get("type")
    if kind is None:
        raise SceneError(f"{path}.type", f"missing (one of: {', '.join(LAWS)})")
    if kind not in LAWS:
        raise SceneError(f"{path}.type", f"unknown interface law {kind!r} (known: {', '.join(LAWS)})")
    return LAWS[kind].from_params(params, path)

