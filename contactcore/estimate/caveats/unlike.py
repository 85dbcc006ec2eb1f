"""Three runs whose two differences share no pattern (:func:`unlike_differences`).

Richardson's premise is an error ``C(x) h^p`` sample by sample, so that
the last difference of three runs is the first scaled down, ``δ₂ =
2^{−p} δ₁``; the observed order checks only their sizes.  Their cosine
over the samples (:func:`~contactcore.estimate.extrapolation.differences_cosine`,
``QuantityEstimate.alike``) checks the pattern: 1 where the premise
holds; at most :data:`~contactcore.tolerances.UNLIKE_COSINE` (0) where
each run's error has a pattern of its own, which the differences then
add rather than cancel (``‖δ₂‖`` up to ``(e₁² + e₂²)^½``), so that the
estimate over-reads the error: ``(2^{2p} + 1)^½ / (2^p − 1)`` times it for
unrelated patterns (2.24 at p = 1, 1.37 at p = 2).  A degree-1 stress,
constant per cell, read at points that fall elsewhere in their cells at
each h (scene B's fe P1 σxy: cosines −0.20, −0.13, read 2.09, 2.19),
and an error term that dies between the runs (scene A's EFGM P2 σxx on
A3, whose error falls 15-fold over the last halving: −0.58, 5.01) show
this way."""
from __future__ import annotations

from collections.abc import Set

from ... import tolerances as tol
from ..extrapolation import QuantityEstimate
from .lines import see, with_cosines


def unlike_differences(profiles: dict[str, dict[str, QuantityEstimate]], named: Set[str] = frozenset(), *,
                       roundoff: Set[str] = frozenset()) -> dict[str, float]:
    """``{PID:Q: cosine}`` of the three-run estimates whose two differences'
    cosine (``alike``) is at most :data:`~contactcore.tolerances.UNLIKE_COSINE`,
    but for those another warning already ``named`` (``PID:Q``) and those
    in ``roundoff``, the ``PID:Q`` whose two finest runs differ only at
    round-off at every sample
    (:func:`~contactcore.estimate.caveats.unsettled.roundoff_runs` of the
    estimate's runs, made once per estimate by
    :func:`~contactcore.estimate.runs.estimate_runs`; none by default), as
    the other lines skip them: the observed order, and with it the cosine,
    is taken over the kept samples against their own scale, so a quantity
    whose largest values lie at a singular point left out can still show
    one there, from differences that are round-off of the whole (fix38).
    Over the
    entries no other line named it names 0.74-5.01 times the error, none
    below 0.5 (A, B, C, the closed forms and the Lamé disc from three runs,
    2026-11-29: docs/error-estimates.md, "The warnings", "unlike
    differences"), where the entries other lines name hold under-estimates
    too (EFGM P1's quadrature floor, 0.42); but on a thin top layer under
    exact contact (docs/scenes/thin_top_layer_exact.toml, three runs from
    h = 0.1) it named xfem P1's ``t_N`` alone at 0.26 (fix38), so the line
    claims no direction."""
    skip = set(named) | set(roundoff)
    return {f"{pid}:{q}": float(e.alike) for pid, qs in profiles.items() for q, e in qs.items()
            if e.alike is not None and e.alike <= tol.UNLIKE_COSINE and f"{pid}:{q}" not in skip}


def unlike_differences_warning(found: dict[str, float]) -> list[str]:
    """One line naming :func:`unlike_differences`' quantities, each with its
    cosine."""
    if not found:
        return []
    names = with_cosines(found)
    return [f"{names}: the runs' two differences share no pattern (cosine ≤ 0), each run's error its own: "
            f"often too large, not always{see('unlike differences')}"]
