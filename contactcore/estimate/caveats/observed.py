"""Warnings of a three-run estimate: an observed order far from theory
(:func:`order_mismatch`, :func:`order_warnings`), a last halving much
slower than the first (:func:`slow_halving`) and an order observed above
the range theory allows, the estimate taken at the range's balanced
order (:func:`above_range`).

An observed order further than :data:`~contactcore.tolerances.ORDER_MISMATCH`
from the orders theory allows, or clipped to an end of
:data:`~contactcore.tolerances.ORDER_RANGE`, means the runs are not yet in
the asymptotic range."""
from __future__ import annotations

from collections.abc import Set

from ... import tolerances as tol
from ..extrapolation import QuantityEstimate
from .lines import see


def order_warnings(estimates: dict[str, dict[str, QuantityEstimate]]) -> list[str]:
    """One line per quantity whose observed order is further than
    :data:`~contactcore.tolerances.ORDER_MISMATCH` from the orders theory
    allows, or was clipped to an end of
    :data:`~contactcore.tolerances.ORDER_RANGE` (the differences do not
    shrink like a power of h at all)."""
    return [f"{pid}:{q}: observed order {e.measured:.2f}{_clipped(e.measured)}, {_orders(e.theory)} in theory: "
            f"not asymptotic, not to be trusted{see('order')}"
            for pid, qs in estimates.items() for q, e in qs.items()
            if e.measured is not None and order_mismatch(e)]


def order_mismatch(e: QuantityEstimate) -> bool:
    """Whether ``e``'s observed order (three runs) lies further than
    :data:`~contactcore.tolerances.ORDER_MISMATCH` from the orders theory
    allows, or was clipped to an end of
    :data:`~contactcore.tolerances.ORDER_RANGE`."""
    p = e.measured
    return p is not None and bool(_clipped(p) or not e.theory[0] - tol.ORDER_MISMATCH <= p
                                  <= e.theory[1] + tol.ORDER_MISMATCH)


def _orders(theory: tuple[float, float]) -> str:
    """``"2"``, or ``"1-2"`` for a range."""
    low, high = theory
    return f"{low:.3g}" if low == high else f"{low:.3g}-{high:.3g}"


def _clipped(order: float) -> str:
    """``" (clipped)"`` where an observed order sits at an end of ORDER_RANGE."""
    return " (clipped)" if order <= tol.ORDER_RANGE[0] or order >= tol.ORDER_RANGE[1] else ""


def slow_halving(profiles: dict[str, dict[str, QuantityEstimate]]) -> dict[str, float]:
    """``{PID:Q: slowdown}`` of the three-run estimates whose last halving's
    difference fell by much less than the first's: with ``d₁ = ‖q_{h/2} −
    q_h‖``, ``d₂ = ‖q_{h/4} − q_{h/2}‖`` (RMS, the observed order's) and
    ``p`` the least order theory allows, the slowdown
    ``(d₂/d₁) / 2^{-p} = 2^{p − p_obs}`` exceeds
    :data:`~contactcore.tolerances.SLOW_HALVING`; those
    :func:`order_mismatch` names already are left to it.  A floor in the
    finest run's error (EFGM P2's between h = 0.025 and 0.0125 on the
    Lamé disc: its stresses' errors 0.0029 → 0.0039 % of σ) shows only as
    a modestly slow last halving (2.49 and 2.52 against 3): the balanced
    order then reads 0.45-0.47 of the error; a coarse run pre-asymptotic
    shows the same way and over-estimates (fe P2's σxx, σyy 2.70, 3.40 at
    1.24 against 2).  An indication, off either way."""
    out = {}
    for pid, qs in profiles.items():
        for q, e in qs.items():
            if e.observed and not order_mismatch(e) and 2.0 ** (e.theory[0] - e.measured) > tol.SLOW_HALVING:
                out[f"{pid}:{q}"] = float(2.0 ** (e.theory[0] - e.measured))
    return out


def slow_halving_warning(found: dict[str, float]) -> list[str]:
    """One line naming :func:`slow_halving`'s quantities, each with its
    slowdown, without a direction (0.45-3.40 times the error on the Lamé
    disc's 26 entries it named from h = 0.05, 2026-11-29)."""
    if not found:
        return []
    names = ", ".join(f"{k} ({v:.2f})" for k, v in found.items())
    return [f"{names}: last halving's difference slowed (× theory's 2^-p): a floor or a pre-asymptotic "
            f"coarse run, off either way{see('slow halving')}"]


def above_range(profiles: dict[str, dict[str, QuantityEstimate]], *,
                roundoff: Set[str] = frozenset()) -> dict[str, float]:
    """``{PID:Q: observed order}`` of the three-run estimates whose theory
    allows a range ``[low, high]`` (``low < high``) and whose observed order
    ``p`` lies above it, ``high < p ≤ high +``
    :data:`~contactcore.tolerances.ORDER_MISMATCH` (further, the order
    line names it), but for those in ``roundoff``, the ``PID:Q`` whose two
    finest runs differ only at round-off at every sample
    (:func:`~contactcore.estimate.caveats.unsettled.roundoff_runs` of the
    estimate's runs, made once per estimate by
    :func:`~contactcore.estimate.runs.estimate_runs`; none by default): the
    order is observed over the kept samples against their own scale, so a
    quantity whose largest values lie at a singular point left out can
    show one from round-off of the whole, an order that means nothing
    (as :func:`~contactcore.estimate.caveats.unlike_differences` skips
    them, review22).  Such an estimate is taken at the range's balanced
    order ``q`` (:func:`~contactcore.estimate.extrapolation.three_run_order`):
    ``|q_{h/4} − q_{h/2}| / (2^q − 1)``.  If the error is ``C h^high`` the
    estimate reads ``(2^high − 1)/(2^q − 1)`` times it (1.53 for ``[2, 3]``,
    a degree-1 recovered stress; 1.95 for ``[1.52, 3]``; 1.33 for
    ``[1.42, 2]``), more where the last halving is faster still (scene A's
    xfem P1 A1 σxy: observed 3.03, true rates 3.10 then 3.63, 2.52; an
    exact law's fe P2 ``g_N`` on tests/scenes/tilt_unil_exact.toml: 2.51
    against ``[1.42, 2]``, 3.84).  But an order above theory is as well
    the coarse run's error cancelling against a second term
    ``D h^s`` of the other sign (``d₁/d₂ = 2^p`` with ``p`` above either
    rate), and then the estimate at ``q`` is the right size or too
    small, and one at ``high`` (Roache's ``min(p, p_formal)``) too small:
    scene C's xfem P2 C4 ``t_N`` from h = 0.05, observed 3.09 of
    ``[1.52, 3]``, read 0.72 at ``q``, 0.37 at ``high`` (orders37,
    2026-11-29).  Three runs cannot tell the two apart, so the order is
    left and the line names the entry, off either way (0.16-3.84 on the
    19 entries it named on A, B, C, tilt_unil_exact, thin_top_layer_exact,
    the closed forms and the Lamé disc from three runs, 6 outside [0.5, 2],
    2026-11-30: docs/error-estimates.md, "The warnings", "above the
    range")."""
    return {f"{pid}:{q}": float(e.measured) for pid, qs in profiles.items() for q, e in qs.items()
            if e.observed and not order_mismatch(e) and e.theory[0] < e.theory[1] < e.measured
            and f"{pid}:{q}" not in roundoff}


def above_range_warning(found: dict[str, float]) -> list[str]:
    """One line naming :func:`above_range`'s quantities, each with its
    observed order."""
    if not found:
        return []
    names = ", ".join(f"{k} ({v:.2f})" for k, v in found.items())
    return [f"{names}: observed order above theory's range, the estimate at its balanced order: "
            f"off either way{see('above the range')}"]
