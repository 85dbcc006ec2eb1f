"""Two runs whose difference lies at the coarse run's cells' scale.

:func:`cell_scale_orders` names the quantities whose coarse run varies
from cell to cell faster than theory allows; for a polluted range split
at the cells' scale, :func:`split_cell_share` names those whose difference
lies mostly at that scale, the part taken at the range's upper order,
which two runs cannot check (an empirical marker of scene A's A5 fe P2
``g_N``, 0.485)."""
from __future__ import annotations

import numpy as np

from ... import tolerances as tol
from ...profiles import ProfileData
from ...scaling import Sizes
from ...scene import Scene
from ..extrapolation import cell_scale_part, QuantityEstimate, rms, sample_groups
from ..orders import STRESSES, TRACTIONS
from ..singular import far_from_singular
from .lines import OBSERVE, see


def cell_scale_orders(scene: Scene, levels: list[list[ProfileData]],
                      estimates: dict[str, dict[str, QuantityEstimate]], exclude: float,
                      h: float, far: dict[str, dict[str, tuple[np.ndarray, float]]] | None = None
                      ) -> dict[str, tuple[float, float]]:
    """``{PID:Q: (order, high)}`` of the two-run estimates whose coarse run is
    rough at the scale of its cells: the RMS over the kept samples (at least
    ``exclude`` from the singular points) of each run's part at that scale
    (:func:`~contactcore.estimate.extrapolation.cell_scale_part`, the same
    kernel of the coarse run's ``h`` for both, fitted over
    :func:`~contactcore.estimate.extrapolation.sample_groups`) shrinks between
    the runs at an ``order`` above the highest that theory allows the quantity
    (``high``, :func:`~contactcore.estimate.orders.order_range`) by more than
    :data:`~contactcore.tolerances.CELL_SCALE_EXCESS`.  A smooth exact value
    leaves the same part in both runs (ratio 1); what varies from cell to cell
    beyond it is each run's local error, which shrinks at the method's order
    once the runs are asymptotic.  Faster means the coarse run's is not yet
    (the runs of docs/error-estimates.md, "Which estimates to warn of").
    Quantities with an observed order (three runs) are left to
    :func:`~contactcore.estimate.caveats.observed.order_warnings`; a part at round-off shows no order: of the
    quantity (:data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF` of its largest
    |value|), or of the scene's own size of its kind
    (:data:`~contactcore.tolerances.NEGLIGIBLE_SHARE` of
    :class:`~contactcore.scaling.Sizes`' stress for a stress or traction,
    displacement otherwise), so that a quantity whose values are all round-off
    (σxy of a bonded patch, 1e-14) is named by no kernel.

    ``far``, ``{PID: {Q: (mask, high)}}``: an exact law's traction on a Γ
    that switches, whose samples of ``mask`` (far from every status change,
    :func:`~contactcore.estimate.status.far_from_changes`) take the far
    order: there the part's order is compared with the highest order theory
    allows beyond the changes (``high``,
    :func:`~contactcore.estimate.orders.smooth_range`), at the rest with
    ``theory[1]`` (1), each over its own kept samples.  On
    tests/scenes/tilt_unil_exact.toml at h = 0.1 → 0.05 (2026-11-29,
    docs/error-estimates.md, "Which estimates to warn of") that names the
    five degree-1 tractions at 3.5-6.8 times their error the whole profile
    named two of, and none of the 31 others of the exact scenes measured."""
    sizes, out = Sizes.of(scene), {}
    for coarse, fine in zip(levels[-2], levels[-1]):
        cols = fine.columns
        xy = np.column_stack([cols["x"], cols["y"]])
        kept = far_from_singular(scene, xy, exclude)
        s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(xy, axis=0), axis=1))])
        groups = sample_groups(scene, xy, kept)
        for q in fine.names[3:]:
            e = estimates.get(fine.id, {}).get(q)
            if e is None or e.observed or not np.any(kept):
                continue
            parts = [cell_scale_part(v, s, groups, h) for v in (coarse.columns[q], cols[q])]
            scale = max(float(np.max(np.abs(cols[q]))), float(np.max(np.abs(coarse.columns[q]))))
            own = sizes.stress if q in STRESSES + TRACTIONS else sizes.displacement
            floor = max(tol.ESTIMATE_ROUNDOFF * scale, tol.NEGLIGIBLE_SHARE * own)
            for mask, high in _sample_sets(kept, e, (far or {}).get(fine.id, {}).get(q)):
                order = _part_order(parts, mask, floor)
                if order is not None and order > high + tol.CELL_SCALE_EXCESS:
                    out[f"{fine.id}:{q}"] = (order, float(high))
                    break
    return out


def _sample_sets(kept: np.ndarray, e: QuantityEstimate, far: tuple[np.ndarray, float] | None
                 ) -> list[tuple[np.ndarray, float]]:
    """The ``(samples, highest order)`` pairs :func:`cell_scale_orders`
    tests: the ``kept`` samples at ``e``'s ``theory[1]``, or, with ``far``
    (``(mask, high)``), the kept samples of ``mask`` at ``high`` and the
    other kept ones at ``theory[1]``."""
    if far is None:
        return [(kept, float(e.theory[1]))]
    mask, high = far
    return [(kept & mask, float(high)), (kept & ~mask, float(e.theory[1]))]


def _part_order(parts: list[np.ndarray], mask: np.ndarray, floor: float) -> float | None:
    """``log₂(RMS(coarse part) / RMS(fine part))`` over ``mask``; None where
    no sample is in it or a part is at most ``floor`` (round-off)."""
    if not np.any(mask):
        return None
    a, b = (rms(p[mask]) for p in parts)
    return None if min(a, b) <= floor else float(np.log2(a / b))


def cell_scale_warnings(found: dict[str, tuple[float, float]], hs: tuple[float, float],
                        undirected: tuple[str, ...] | list[str] = (), length: str = "m") -> list[str]:
    """One line naming the quantities of :func:`cell_scale_orders`, each
    with the order at which its runs' variation at the cells' scale
    shrank and the highest order theory allows it (``hs`` in the scene's
    unit named ``length``).  The line says the
    estimate is likely too large (measured 0.99-8.05 times the error on
    the 28 entries it named on four sets, 2026-11-28) but for the
    quantities also in ``undirected`` (:func:`~contactcore.estimate.caveats.tractions.fast_gamma`'s, EFGM P1's Γ
    quantities, which it named at 0.55 on the layered slip): those get a
    line of their own without a direction."""
    lines = []
    for part, direction in (([k for k in found if k not in undirected], ", likely too large"),
                            ([k for k in found if k in undirected], "")):
        if not part:
            continue
        names = ", ".join(f"{k} ({found[k][0]:.2f} > {found[k][1]:.3g})" for k in part)
        lines.append(f"{names}: from h = {hs[0]:g} {length} to {hs[1]:g} {length} the cell-to-cell variation "
                     f"shrinks at orders above theory's: not asymptotic{direction}{see('cell scale')}")
    return lines


#: The least degree :func:`split_cell_share` names: at degree 1 the split
#: takes ``[2λ, 2]``, whose Richardson factors differ by at most 1.27, so
#: that part's order moves the estimate little (the error_estimate
#: example's fe P1 ``g_N``: share 0.67, effectivity 1.04); at degree 2
#: ``[2λ, 3]``, up to 1.95.
SPLIT_CELL_DEGREE = 2


def split_cell_share(scene: Scene, levels: list[list[ProfileData]],
                     estimates: dict[str, dict[str, QuantityEstimate]], exclude: float,
                     degree: int) -> dict[str, float]:
    """``{PID:Q: share}`` of the two-run estimates of a range pollution
    widened, of a run of ``degree`` :data:`SPLIT_CELL_DEGREE` or more,
    whose difference lies at the scale of the coarse run's cells by a
    share of at least :data:`~contactcore.tolerances.SPLIT_CELL_SHARE` (the estimate's
    ``cell_scale``): that part is taken at the range's upper order, which
    two runs cannot check; where it converges slower the estimate is too
    small (A5's fe P2 ``g_N``, 0.485), where it does not it is right
    (C4's degree-2 tractions, 1.27-1.77).  A difference at round-off (of
    the quantity, :data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF`, or of
    the scene's own size of its kind,
    :data:`~contactcore.tolerances.NEGLIGIBLE_SHARE` of
    :class:`~contactcore.scaling.Sizes`) shows nothing and is not named."""
    sizes, out = Sizes.of(scene), {}
    if degree < SPLIT_CELL_DEGREE:
        return out
    for coarse, fine in zip(levels[-2], levels[-1]):
        xy = np.column_stack([fine.columns["x"], fine.columns["y"]])
        kept = far_from_singular(scene, xy, exclude)
        for q in fine.names[3:]:
            e = estimates.get(fine.id, {}).get(q)
            if e is None or e.observed or e.cell_scale is None or e.cell_scale < tol.SPLIT_CELL_SHARE:
                continue
            d = rms((fine.columns[q] - coarse.columns[q])[kept]) if np.any(kept) else 0.0
            scale = max(float(np.max(np.abs(fine.columns[q]))), float(np.max(np.abs(coarse.columns[q]))))
            own = sizes.stress if q in STRESSES + TRACTIONS else sizes.displacement
            if d > max(tol.ESTIMATE_ROUNDOFF * scale, tol.NEGLIGIBLE_SHARE * own):
                out[f"{fine.id}:{q}"] = float(e.cell_scale)
    return out


def split_cell_share_warning(found: dict[str, float]) -> list[str]:
    """One line naming :func:`split_cell_share`'s quantities, each with its
    share, without a direction (measured 0.485-1.77 on the six entries it
    names on A, B, C)."""
    if not found:
        return []
    names = ", ".join(f"{k} ({v:.2f})" for k, v in found.items())
    return [f"{names}: most of the runs' difference (shares) is at the coarse cells' scale, unchecked by two "
            f"runs: off either way; {OBSERVE}{see('split share')}"]
