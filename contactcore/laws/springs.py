"""What every penalty law shares: its springs ``k_N``, ``k_T`` and the class contract's defaults.

Contract: :class:`_Law` reads a law's parameters from a scene's TOML table
(:meth:`_Law.from_params`; a bad value a SceneError naming its dotted
path, ``kN`` and ``kT`` finite and > 0 by :func:`_positive`, the others by
the class's :meth:`_Law.extra_parameters`), gives the scales of a
:class:`~contactcore.laws.decision.Decision`
(:meth:`_Law.decision_scales`), the closed points of a spring law
(:meth:`_Law._springs`), and the refusal of a load Γ cannot hold
(:meth:`_Law.slides_off`).  It declares no capability, so that a new law
cannot inherit a wrong one (:mod:`contactcore.laws.contract`).
"""
from __future__ import annotations

import math
from typing import ClassVar

import numpy as np

from .. import tolerances as tol
from ..errors import ContactError, SceneError
from ..spelling import hint
from .contract import STIFFNESS
from .decision import Decision
from .response import OPEN


def _positive(params: dict, key: str, path: str) -> float:
    if key not in params:
        raise SceneError(f"{path}.{key}", "missing (a penalty stiffness, in the scene's stress unit per length unit: "
                         "Pa/m in SI, MPa/mm in a scene of mm and MPa)")
    value = params[key]
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(f"{path}.{key}", f"must be a number (got {value!r})")
    if not math.isfinite(value) or value <= 0:
        raise SceneError(f"{path}.{key}", f"must be a finite penalty > 0 (got {value!r})")
    return float(value)


class _Law:
    """What every law shares: reading its parameters, its spring scale.

    A law class declares (contactcore.laws' module doc; :func:`law_contract` refuses one that
    does not): ``name``; ``parameters`` and the ``dimensions`` of each;
    ``homogeneous``, whether ``t(c·g) = c·t(g)`` for ``c > 0`` from an
    untouched history; ``unilateral``, whether it can open (no tension);
    ``frictional``, whether a closed point may slip, with its
    ``slip_bound(t_N)`` then.  The capabilities are deliberately not given
    here, so that a new law cannot inherit a wrong one."""

    parameters: ClassVar[tuple[str, ...]] = ("kN", "kT")
    dimensions: ClassVar[dict[str, str]] = {"kN": STIFFNESS, "kT": STIFFNESS}
    homogeneous: ClassVar[bool]
    unilateral: ClassVar[bool]
    frictional: ClassVar[bool]
    has_history: ClassVar[bool] = False
    #: how the law is enforced: by its springs (here) or exactly
    #: (:mod:`contactcore.exact`, which evaluates these laws with per-point
    #: stiffness arrays in place of k_N, k_T)
    enforcement: ClassVar[str] = "penalty"

    @classmethod
    def from_params(cls, params: dict, path: str):
        """Build from a TOML table, naming the field of any bad value."""
        unknown = sorted(set(params) - set(cls.parameters) - {"type"})
        if unknown:
            raise SceneError(f"{path}.{unknown[0]}", f"unknown parameter of the '{cls.name}' law "
                             f"(it takes {', '.join(cls.parameters)}, and enforcement = \"penalty\" or \"exact\")"
                             f"{hint(unknown[0], (*cls.parameters, 'enforcement'))}")
        values = {k: _positive(params, k, path) for k in ("kN", "kT")}
        values.update(cls.extra_parameters(params, path))
        return cls(**values)

    @classmethod
    def extra_parameters(cls, params: dict, path: str) -> dict:
        """``{name: value}`` of the law's parameters beyond ``kN``, ``kT``,
        read from the TOML table ``params`` and checked (a bad one a
        SceneError naming ``path.name``): none here.  A law with more
        parameters gives its own (CoulombLaw: ``mu``); its exact form reads
        them through it (:meth:`contactcore.exact._ExactLaw.from_params`)."""
        extra = [p for p in cls.parameters if p not in ("kN", "kT")]
        if extra:
            raise ContactError(f"the '{cls.name}' law ({cls.__qualname__}) declares the parameters "
                               f"{', '.join(extra)} but no extra_parameters(params, path) to read and check them")
        return {}

    def initial_state(self, m: int):
        """The history of ``m`` points before the first increment (none)."""
        return None

    @property
    def stiffness_scale(self) -> float:
        """The largest spring stiffness, used in conditioning diagnostics."""
        return max(self.kN, self.kT)

    def decision_scales(self, g: np.ndarray, state=None) -> np.ndarray:
        """This rank's scales of :class:`Decision`: ``[gap, traction]``, the
        largest ``|g_N|`` and ``|k_N g_N|``; for a frictional law ``[gap,
        traction, pressure]``: the largest ``|g_N|``, the largest slip limit
        ``slip_bound(t_N)`` of a closed point (not the trial, which a
        far-off iterate can make arbitrarily large; Coulomb's ``μp``) and
        the largest pressure ``p``."""
        if not self.frictional:
            g = np.asarray(g, dtype=float).reshape(-1, 2)
            return np.array([float(np.max(np.abs(g[:, 0]), initial=0.0)),
                             float(np.max(np.abs(self.kN * g[:, 0]), initial=0.0))])
        g, closed, tN = self._springs(g)
        return np.array([float(np.max(np.abs(g[:, 0]), initial=0.0)),
                         float(np.max(self.slip_bound(tN[closed]), initial=0.0)),
                         float(np.max(-tN, initial=0.0))])

    def slides_off(self, body: str, shear: float, press: float, length: float) -> str:
        """Why a body held by Γ alone (a straight Γ of ``length``) slides
        off under loads whose resultant presses Γ with ``press`` > 0 and
        shears it with ``shear`` >= 0, or "" where Γ's slip bound may hold
        them: by the concavity of :meth:`slip_bound` (contactcore.laws' module doc) Γ carries
        at most ``|Γ| slip_bound(−press/|Γ|)``, taken beyond
        DEMAND_ROUNDOFF of it (the scene's data, no BLAS: the same on every
        machine).  A frictional law's; CoulombLaw words it by μ."""
        bound = length * float(np.asarray(self.slip_bound(np.array([-press / length])), float).reshape(-1)[0])
        if not shear > bound * (1.0 + tol.DEMAND_ROUNDOFF):  # (a zero bound: any shear slides)
            return ""
        ratio, digits = shear / bound if bound > 0 else math.inf, 3  # unit-free: the scene may be dimensionless here
        while digits < 17 and float(f"{ratio:.{digits}g}") <= 1.0:
            digits += 1
        return (f"on Γ the loads ask for {ratio:.{digits}g} times the shear the '{self.name}' law's slip bound "
                f"carries over Γ at their pressure (body {body}): it slides off (no equilibrium); lower the shear "
                "load or raise the bound")

    def _springs(self, g: np.ndarray, decision: Decision | None = None):
        """``g`` as (m, 2), the closed points (``g_N <= 0``, or by
        ``decision`` within its band) and ``t_N``."""
        g = np.asarray(g, dtype=float).reshape(-1, 2)
        if decision is None:
            closed = g[:, 0] <= 0.0
        else:
            was = decision.previous != OPEN
            if decision.normal is None:
                closed = decision.switch(-g[:, 0], decision.gap, was)
            else:  # the band in traction; at rest as the gap scale says
                closed = decision.switch(-g[:, 0], decision.normal, was, rest=decision.gap <= tol.DECISION_FLOOR)
        return g, closed, np.where(closed, self.kN * g[:, 0], 0.0)
