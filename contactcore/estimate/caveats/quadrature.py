"""Where EFGM P1's quadrature error, which neither the runs' differences
nor a recovery see, may be most of the error: its Zienkiewicz–Zhu
estimate at a tiny share of the run's energy (:func:`quadrature_energy`:
the layered slip's 0.41) and its stresses estimated below
:data:`~contactcore.tolerances.QUADRATURE_STRESS_SHARE` of the stress
(:func:`quadrature_stress`)."""
from __future__ import annotations

import numpy as np

from ... import tolerances as tol
from ...labels import run_label
from ...profiles import ProfileData
from ...result import MethodFacts
from ..energy import EnergyEstimate
from ..extrapolation import QuantityEstimate, rms
from ..orders import STRESSES
from .lines import see


def quadrature_energy(method: str, degree: int, facts: MethodFacts, energy: EnergyEstimate | None) -> list[str]:
    """One line where the energy estimate of a run whose ``facts`` say
    ``quadrature_energy`` (EFGM P1:
    :attr:`efgm.options.EFGM.quadrature_energy`, its measurement;
    ``method`` and ``degree`` name it) is below
    :data:`~contactcore.tolerances.QUADRATURE_ENERGY_SHARE` of the run's
    energy: its quadrature's error may then be most of the error, which the
    Zienkiewicz–Zhu recovery does not see (the layered slip's 0.41, the
    patch's 0.76)."""
    if not facts.quadrature_energy or energy is None or not energy.relative < tol.QUADRATURE_ENERGY_SHARE:
        return []
    if not energy.norm > energy.floor:  # a stress-free run: no error for a quadrature to dominate
        return []
    return [f"energy (ZZ): {run_label(method, degree)}'s estimate is {energy.relative:.2g} of the run's energy, "
            f"where its quadrature's error, unseen by a recovery, may dominate: likely too small"
            f"{see('quadrature energy')}"]


def quadrature_stress(profiles: dict[str, dict[str, QuantityEstimate]], finest: list[ProfileData],
                      kept: dict[str, dict[str, np.ndarray]], facts: MethodFacts) -> dict[str, float]:
    """``{PID:Q: share}`` of the stresses of a run whose ``facts`` say
    ``quadrature_energy`` (EFGM P1) whose estimate is below
    :data:`~contactcore.tolerances.QUADRATURE_STRESS_SHARE` of the stress:
    ``share = RMS(ê) / max |σ_h|`` over the ``kept`` samples of the
    ``finest`` run.  EFGM P1 misses a uniform stress by its Gauss
    quadrature's error (no patch test passes), an error of about the same
    size at every h: the runs' differences cancel it, so an estimate that
    small is of the floor's size and may miss it (scene A, three runs: A1 σxy
    and A2 σyy 0.41 and 0.42 of the error), or not (the closed forms' EFGM
    P1 stresses, named at 0.55-1.33: there the floor is smaller)."""
    if not facts.quadrature_energy:
        return {}
    out = {}
    for p in finest:
        for q, e in profiles.get(p.id, {}).items():
            keep = kept[p.id][q]
            if q not in STRESSES or not np.any(keep):
                continue
            top = float(np.max(np.abs(p.columns[q][keep])))
            share = rms(e.error[keep]) / top if top > 0 else np.inf
            if share < tol.QUADRATURE_STRESS_SHARE:
                out[f"{p.id}:{q}"] = float(share)
    return out


def quadrature_stress_warning(found: dict[str, float], method: str, degree: int) -> list[str]:
    """One line naming :func:`quadrature_stress`'s quantities, each with its
    estimate's share of the largest stress; "possibly": named entries read
    0.41-1.33 (scene A and the closed forms, 2026-11-29)."""
    if not found:
        return []
    names = ", ".join(f"{k} ({v:.1e})" for k, v in found.items())
    return [f"{names}: estimate (× the largest |σ|) as small as {run_label(method, degree)}'s quadrature error, "
            f"which the runs do not see: possibly too small{see('quadrature stress')}"]
