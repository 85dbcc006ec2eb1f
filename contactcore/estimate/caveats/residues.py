"""Quantities whose runs differ a thousand times less than others of their
kind in the same runs (:func:`residues`): the error's leading term nearly
cancels there, and a smaller one of another order may set the rate."""
from __future__ import annotations

import numpy as np

from ... import tolerances as tol
from ...profiles import ProfileData
from ...scaling import Sizes
from ...scene import Scene
from ..extrapolation import QuantityEstimate, rms
from ..orders import STRESSES, TRACTIONS
from ..singular import far_from_singular
from .lines import OBSERVE, see


#: The kinds of profile quantity whose errors a run compares
#: (:func:`residues`): bulk displacements, bulk stresses, gaps and
#: tractions on Γ.
KINDS = {"ux": "displacement", "uy": "displacement", "sxx": "stress", "syy": "stress", "sxy": "stress",
         "gN": "gap", "gT": "gap", "tN": "traction", "tT": "traction"}


def residues(scene: Scene, levels: list[list[ProfileData]],
             estimates: dict[str, dict[str, QuantityEstimate]], exclude: float) -> dict[str, tuple[float, str]]:
    """``{PID:Q: (share, PID:Q')}`` of the two-run estimates whose runs
    differ (RMS over the kept samples, at least ``exclude`` from the
    singular points) by less than
    :data:`~contactcore.tolerances.RESIDUE_SHARE` of the largest such
    difference among the quantities of its kind (:data:`KINDS`) on every
    profile of the same runs (``PID:Q'``).  The theoretical order is
    that of the error's leading term ``C h^p``, whose ``C`` the
    solution's derivatives near the sample set; where the runs differ a
    thousand times less than elsewhere that term nearly cancels, and a
    term whose coefficient is as small (the representation of Γ in the
    cut cells, quadrature) may set the rate: σxx along scene B's
    clamped top edge in xfem P2 converges at 1.28 and 0.96 between h =
    0.05, 0.025 and 0.0125, against 2 in theory and 1.98 for σxy in the
    same runs (docs/error-estimates.md, "Which estimates to warn of").
    Quantities with an observed order (three runs) are left to
    :func:`~contactcore.estimate.caveats.observed.order_warnings` but count in their kind's largest; a
    difference at round-off (of the
    quantity, :data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF`, or of
    the scene's size of its kind, :data:`~contactcore.tolerances.NEGLIGIBLE_SHARE`
    of :class:`~contactcore.scaling.Sizes`) shows nothing and is neither
    named nor the kind's largest."""
    sizes, found = Sizes.of(scene), {}
    for coarse, fine in zip(levels[-2], levels[-1]):
        cols = fine.columns
        xy = np.column_stack([cols["x"], cols["y"]])
        kept = far_from_singular(scene, xy, exclude)
        for q in fine.names[3:]:
            e = estimates.get(fine.id, {}).get(q)
            if e is None or q not in KINDS or not np.any(kept):
                continue
            d = rms((cols[q] - coarse.columns[q])[kept])
            scale = max(float(np.max(np.abs(cols[q]))), float(np.max(np.abs(coarse.columns[q]))))
            own = sizes.stress if q in STRESSES + TRACTIONS else sizes.displacement
            if d > max(tol.ESTIMATE_ROUNDOFF * scale, tol.NEGLIGIBLE_SHARE * own):
                found[f"{fine.id}:{q}"] = (d, KINDS[q], e.observed)
    largest = {}
    for key, (d, kind, _) in found.items():
        if d > largest.get(kind, (0.0, ""))[0]:
            largest[kind] = (d, key)
    return {key: (d / largest[kind][0], largest[kind][1]) for key, (d, kind, observed) in found.items()
            if not observed and d < tol.RESIDUE_SHARE * largest[kind][0]}


def residue_warnings(found: dict[str, tuple[float, str]], observed: bool = False) -> list[str]:
    """One line naming the quantities of :func:`residues`, each with its
    difference's share of the largest of its kind; from ``observed``
    runs (three) it does not advise a third."""
    if not found:
        return []
    names = ", ".join(f"{k} ({share:.2g})" for k, (share, _) in found.items())
    largest = ", ".join(dict.fromkeys(f"{other}'s" for _, other in found.values()))
    return [f"{names}: runs' difference under {tol.RESIDUE_SHARE:g} of their kind's most ({largest}): leading "
            f"error term nearly cancels, an indication only"
            + ("" if observed else f"; {OBSERVE}") + see("residue")]
