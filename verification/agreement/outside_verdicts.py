"""The verdicts an outside answer's samples get (issue 34; docs/api.md,
"An outside code's answer"): when a difference is the outside code's, when
the two answers agree, when the project's warned estimate allows no
verdict, and each verdict in words (:data:`VERDICTS`).

Contract: :func:`sample_verdicts` gives each sample one key of
:data:`VERDICTS` from its difference, the project's estimated error there
(the budget, :mod:`~verification.agreement.outside_budget`), whether the
sample is kept, whether the estimate is warned, the quantity's floor and
size: ``outside`` beyond :data:`BLAME_MULTIPLE` × the budget, ``outside
(estimate warned)`` beyond :data:`WARNED_MULTIPLE` × it and
:data:`WARNED_MIN_SHARE` of the size; :func:`verdict_regions` groups
consecutive samples (in ``s`` order) of one verdict into a :class:`Region`
each, with RMS(difference) / RMS(budget) over it (NaN where left out).
numpy and contactcore.tolerances only; no solve.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contactcore.tolerances import ESTIMATE_TRUST

#: A difference beyond this many times the project's estimated error is
#: the outside code's, at least mostly.  Where the estimate is trusted, the
#: project's true error |e_p| lies within ESTIMATE_TRUST (2) of it either
#: way (docs/error-estimates.md, the closed forms' range), so a difference
#: |d| > 2·ESTIMATE_TRUST·e leaves the outside code an error |e_o| >= |d| −
#: |e_p| > ESTIMATE_TRUST·e >= |e_p|: at least as large as the project's,
#: at least half of the difference.  Within it, the two agree within the
#: project's error (the difference is no more than the project's error
#: could be together with an outside error no larger).
BLAME_MULTIPLE = 2 * ESTIMATE_TRUST

#: The lowest effectivity (estimate / true error) docs/error-estimates.md
#: records of a warned estimate ("Known limits": an exact law's traction on
#: Γ, 0.09 the rebuilt wedge-coulomb-slip-exact's xfem P2 ``t_T`` at
#: h = 0.1 -> 0.05, 2026-11-29, 0.11 before its degree-2 traction took
#: order 2 away from status changes; until then 0.19, a held-out wedge's):
#: a warned estimate may be this many times too small.
WARNED_EFFECTIVITY = 0.09

#: Where the project's estimate is warned, a difference beyond this many
#: times it is still the outside code's: even if the estimate is
#: :data:`WARNED_EFFECTIVITY` of the true error, the difference exceeds
#: :data:`BLAME_MULTIPLE` times that true error (newuser34: a wrong μ's
#: G ``g_T`` at 311×, C4 ``t_N`` of the wrong sign at 7.05e4×, read
#: ``warned`` before).  Below it a warned quantity reads ``warned``.
WARNED_MULTIPLE = BLAME_MULTIPLE / WARNED_EFFECTIVITY

#: And, where the estimate is warned, a difference above this share of the
#: quantity's size (the agreement's, :class:`~verification.agreement.Agreement`'s
#: ``size``): a warned estimate can be near zero beside a status change,
#: which no multiple bounds (review18, 2026-11-29: fe P2 at h = 0.0125 judged
#: against fe P2 at 0.025 on exact C-coulomb, one C4 t_N sample next to
#: where Γ closes at 22.9 × a 0.0192 Pa estimate, 2e-5 of t_N's size).  50
#: times that, and 20 times below the smallest outside error the tests and
#: newuser34 put in (2 % of the size).
WARNED_MIN_SHARE = 1e-3

#: The verdicts of a region, in words (docs/api.md).
VERDICTS = {
    "outside": f"|difference| > {BLAME_MULTIPLE:g} × the project's estimated error: the difference is at least "
               "mostly the outside code's error",
    "agree": f"|difference| within {BLAME_MULTIPLE:g} × the project's estimated error: the two agree within the "
             "project's error",
    "outside (estimate warned)": f"the project's estimate is warned but |difference| > {WARNED_MULTIPLE:.3g} × it "
                                 f"({BLAME_MULTIPLE:g} / {WARNED_EFFECTIVITY:g}, the lowest effectivity "
                                 "docs/error-estimates.md records) and > "
                                 f"{WARNED_MIN_SHARE:g} of the quantity's size: the outside code's error even if the "
                                 "estimate is that far too small",
    "warned": f"the project's estimate of this quantity is warned (below) and |difference| is within "
              f"{WARNED_MULTIPLE:.3g} × it: no verdict",
    "left out": "within the exclusion distance of a singular point, as the agreement table leaves it out",
}


@dataclass(frozen=True)
class Region:
    """Consecutive samples along ``s`` (``s_from`` to ``s_to``, ``samples``
    of them) with one ``verdict`` (:data:`VERDICTS`); ``ratio`` is
    RMS(difference) / RMS(the project's estimated error) over them (NaN
    where left out)."""

    verdict: str
    s_from: float
    s_to: float
    samples: int
    ratio: float


def sample_verdicts(diff: np.ndarray, budget: np.ndarray, keep: np.ndarray, warned: bool, floor: float,
                    size: float) -> np.ndarray:
    """Each sample's verdict (a key of :data:`VERDICTS`, as objects): ``left
    out`` where not ``keep``; else ``outside`` (``outside (estimate
    warned)`` if ``warned``) where ``|diff|`` exceeds :data:`BLAME_MULTIPLE`
    (:data:`WARNED_MULTIPLE` if warned) times ``budget``, the quantity's
    ``floor`` and, if warned, :data:`WARNED_MIN_SHARE` of its ``size``;
    ``agree`` (``warned``) below."""
    least = WARNED_MIN_SHARE * size if warned else 0.0
    beyond = np.abs(diff) > np.maximum((WARNED_MULTIPLE if warned else BLAME_MULTIPLE) * budget, max(floor, least))
    return np.where(~keep, "left out", np.where(
        beyond, "outside (estimate warned)" if warned else "outside",
        "warned" if warned else "agree")).astype(object)


def verdict_regions(s: np.ndarray, verdict: np.ndarray, diff: np.ndarray, budget: np.ndarray) -> tuple[Region, ...]:
    """Consecutive samples of one verdict, with RMS(diff)/RMS(budget) over each."""
    out, start = [], 0
    for i in range(1, len(s) + 1):
        if i == len(s) or verdict[i] != verdict[start]:
            part = slice(start, i)
            if verdict[start] == "left out":
                ratio = float("nan")
            else:
                d, b = np.sqrt(np.mean(diff[part] ** 2)), np.sqrt(np.mean(budget[part] ** 2))
                ratio = float(d / b) if b > 0 else (0.0 if d == 0 else float("inf"))
            out.append(Region(str(verdict[start]), float(s[start]), float(s[i - 1]), i - start, ratio))
            start = i
    return tuple(out)
