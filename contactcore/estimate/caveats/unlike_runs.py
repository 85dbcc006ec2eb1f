"""Two runs whose values share little pattern (:func:`unlike_runs`).

Richardson's premise is an error ``C(x) h^p`` sample by sample: the runs
``q_h = q + C h^p`` and ``q_{h/2} = q + C (h/2)^p`` differ by a pattern
that the coarse run's error, scaled, repeats.  Where the exact ``q`` is
(nearly) zero, each run's value is its own error, and the two runs'
cosine over the kept samples,

    cos ∠(q_h, q_{h/2}) = q_h·q_{h/2} / (‖q_h‖ ‖q_{h/2}‖),

is that of their errors: 1 where the premise holds (the same pattern,
scaled), near 0 where each run's error has a pattern of its own (an
unstructured mesh at h and h/2, not nested, gmsh's for fe: a roller
block's ``u_x`` and ``g_T``, exactly 0, at 1e-5 of the displacement
scale, grader34).  There ``q_{h/2} − q_h`` is about ``q_h`` itself
(‖δ‖² = ‖q_h‖² + ‖q_{h/2}‖² − 2 cos ‖q_h‖ ‖q_{h/2}‖), and the estimate
``‖δ‖/(2^p − 1)`` holds only if the unrelated errors happen to fall at
the rate ``p``: the run's own ratio ``‖e_h‖/‖e_{h/2}‖`` decides, which
two runs do not see (0.47 to 3.71 on the named entries).  A quantity
whose exact value is not small against its error has a cosine near 1
whatever its error (``q`` dominates both runs), so the line names only
quantities the runs resolve no better than their own noise.

Two runs only: three observe the order and compare the differences'
patterns (:mod:`~contactcore.estimate.caveats.unlike`)."""
from __future__ import annotations

import numpy as np

from ... import tolerances as tol
from ...profiles import ProfileData
from ..extrapolation import cosine
from .lines import OBSERVE, see, with_cosines


def unlike_runs(levels: list[list[ProfileData]], kept: dict[str, dict[str, np.ndarray]],
                skip: set[str] = frozenset()) -> dict[str, float]:
    """``{PID:Q: cosine}`` of a two-run estimate's quantities whose two
    runs' values (``levels``, coarse to fine) have cosine
    (:func:`~contactcore.estimate.extrapolation.cosine`) over the fine run's ``kept`` samples at most
    :data:`~contactcore.tolerances.UNLIKE_RUNS_COSINE`, but for those in
    ``skip`` (named by another line, or whose runs differ only at
    round-off: :func:`~contactcore.estimate.caveats.unsettled.roundoff_runs`);
    none from three runs."""
    if len(levels) != 2:
        return {}
    found = {}
    for coarse, fine in zip(*levels):
        for q in fine.names[3:]:
            mask = kept.get(fine.id, {}).get(q)
            key = f"{fine.id}:{q}"
            if key in skip or mask is None or np.count_nonzero(mask) < 2:
                continue
            c = cosine(coarse.columns[q][mask], fine.columns[q][mask])
            if c is not None and c <= tol.UNLIKE_RUNS_COSINE:
                found[key] = c
    return found


def unlike_runs_warning(found: dict[str, float]) -> list[str]:
    """One line naming :func:`unlike_runs`' quantities, each with its
    cosine."""
    if not found:
        return []
    names = with_cosines(found)
    return [f"{names}: the two runs' values share little pattern (cosine ≤ {tol.UNLIKE_RUNS_COSINE:.2g}): each is "
            f"mostly its own error; off either way; {OBSERVE}{see('unlike runs')}"]
