"""Γ's gaps and tractions whose estimate theory's order does not fit.

An exact law's traction on Γ (Nitsche's multiplier) estimated where theory
allows it order 1 is most often too large, not always
(:func:`exact_tractions`, from two runs; :func:`observed_exact_tractions`,
from three); EFGM P1's gaps and tractions shrink faster than the order
taken, or are set by its quadrature (:func:`fast_gamma`).  A warning
claims a direction only where every entry it named on the measured sets
lay that way; otherwise it gives the measured range."""
from __future__ import annotations

from ... import tolerances as tol
from ...labels import run_label
from ...result import MethodFacts
from ...scene import Scene
from ..extrapolation import QuantityEstimate
from ..orders import _exact, TRACTIONS
from .lines import GAMMA, OBSERVE, see


def exact_tractions(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]]) -> list[str]:
    """The ``PID:Q`` of an exact law's tractions on Γ (Nitsche's
    multiplier, :data:`~contactcore.estimate.orders.TRACTIONS`) estimated
    from two runs whose orders theory allows reach down to 1: the
    degree-1 multiplier (``[1, 2]`` where Γ's status never changes, 1 where
    it does), or any degree's where Γ's status switches
    (:func:`~contactcore.estimate.orders.theoretical_order`), at the
    samples within :data:`~contactcore.tolerances.STATUS_CHANGE_CELLS`
    coarse cells of a status change at 1 (beyond them at 2 at degree 2,
    1.45 at degree 1: :func:`~contactcore.estimate.orders.smooth_range`).
    Order 1 is the least theory allows it; its pieces converge faster (1.4-3 on
    the held-out wedges; on a sheared and reversed block degree 2's t_N at
    2.3-2.5 beyond two coarse cells of a status change, 1.5-1.7 within,
    and xfem and efgm P1's at 2.5-2.6), so the estimate is
    most often too large: up to 13.7 times the error (grader17's tilted block
    under exact Coulomb, xfem P1 t_N at h = 0.05 → 0.025), 2.2-2.9 on the
    Lamé disc under an exact law (docs/error-estimates.md, "Known
    limits")."""
    if not _exact(scene.law):
        return []
    return [f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items()
            if q in TRACTIONS and not e.observed and e.theory[0] <= 1]


def exact_traction_warning(names: list[str]) -> list[str]:
    """One line naming :func:`exact_tractions`' quantities.  It gives the
    measured ratios, not a direction: of the 82 entries it named on four
    sets (2026-11-28), 80 read 1 or more (up to 13.7) but the held-out
    exact Coulomb wedge's xfem P2 ``t_T`` 0.19 and grader17's tilted
    block's xfem P1 ``t_N`` 0.83 (docs/error-estimates.md, "Which
    estimates to warn of").  With degree 2 taken at 2 beyond
    :data:`~contactcore.tolerances.STATUS_CHANGE_CELLS` coarse cells of a
    status change (2026-11-29), 96 entries on four scenes read 0.09-8.51,
    2 below 0.5; with degree 1 at 1.45 beyond them and where Γ's status
    never changes (deg1_36), its 72 entries on six scenes 0.69-6.80, none
    below 0.5 (docs/error-estimates.md, "Known limits")."""
    if not names:
        return []
    return [f"{', '.join(names)}: an exact Γ traction from two runs at order 1 near status changes (faster "
            f"beyond): often too large (up to 13.7×), not always; {OBSERVE}{see('exact tractions')}"]


def observed_exact_tractions(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]]) -> list[str]:
    """The ``PID:Q`` of an exact law's tractions on Γ estimated from three
    runs (an observed order) where theory allows them order 1 alone (a Γ
    whose status switches: :func:`~contactcore.estimate.orders.order_range`;
    beyond its changes the far order applies,
    :func:`~contactcore.estimate.extrapolation.richardson`): the cause
    of :func:`exact_tractions` does not go with a third run.  Where the
    multiplier's error varies from sample to sample unlike from run to
    run, its runs' difference ``q_{h/2} − q_h`` is about ``(1 + 2^{-2p})^½``
    times the coarser run's error, not ``1 − 2^{-p}`` times it: the RMS
    ratio of two such differences still shows ``p``, but Richardson at
    ``p`` = 1 then reads ``(2^{2p} + 1)^½ / (2^p − 1)`` = 2.24 times the
    error, whatever the number of runs (est3_36: 1.91-2.47 from three runs
    on a Lamé disc at order 1).  A degree-1 traction on a Γ that never
    switches takes its range [1, 2] (deg1_36) and is not named: there the
    six degree-1 entries of that disc read 1.38-1.88 from three runs
    (review20, 2026-11-29)."""
    if not _exact(scene.law):
        return []
    return [f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items()
            if q in TRACTIONS and e.observed and e.theory[1] <= 1]


def observed_exact_traction_warning(names: list[str]) -> list[str]:
    """One line naming :func:`observed_exact_tractions`' quantities,
    without a direction measured beyond one scene (module doc of that
    function: up to 2.24 times the error in theory)."""
    if not names:
        return []
    return [f"{', '.join(names)}: an exact Γ traction that theory allows order 1, from three runs: its "
            f"cell-to-cell error differs run to run (up to 2.24× in theory){see('exact tractions')}"]


def fast_gamma(profiles: dict[str, dict[str, QuantityEstimate]], facts: MethodFacts) -> list[str]:
    """The ``PID:Q`` of the gaps and tractions on Γ (:data:`GAMMA`) of a
    method and degree whose ``facts`` say ``fast_gamma`` (EFGM P1:
    :attr:`efgm.options.EFGM.fast_gamma`, its measurement) estimated from
    two runs, or from three whose observed order lies above the highest theory allows by more than
    :data:`~contactcore.tolerances.FAST_GAMMA_EXCESS` (the estimate then
    takes that highest, capped).
    Their runs' differences often shrink faster than the order the
    estimate takes (2.5-2.8 against 2 on the closed forms), and the
    estimate is then too large: above 2 for 80 of the 128 two-run entries
    measured; but where EFGM's quadrature sets their error the
    differences do not see it and the estimate is too small: 14 of the 128
    below 1 (the layered slip's 0.55), and from three runs the layered
    slip's 0.49 at an observed 2.52 (the tolerance's note).  An
    indication, off either way."""
    if not facts.fast_gamma:
        return []
    return [f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items()
            if q in GAMMA and (not e.observed or e.measured > e.theory[1] + tol.FAST_GAMMA_EXCESS)]


def fast_gamma_warning(names: list[str], method: str, degree: int, observed: bool = False) -> list[str]:
    """One line naming :func:`fast_gamma`'s quantities, from ``observed``
    runs (three) or two.  It gives the measured ratios, not a direction:
    the 128 two-run entries measured read 0.55 to 10.6 times the error,
    80 above 2 but 14 below 1 (the layered slip's 0.55, the patch's
    0.68-0.71: the error there is EFGM's quadrature's, which the runs'
    differences do not see); the three-run ones 0.49-1.14."""
    if not names:
        return []
    if observed:
        return [f"{', '.join(names)}: {run_label(method, degree)}'s gaps and tractions on Γ shrink faster than the "
                f"order taken ({degree + 1}): off either way (0.49-1.14 times the error){see('fast Γ')}"]
    return [f"{', '.join(names)}: {run_label(method, degree)}'s gaps and tractions on Γ at order {degree + 1} from "
            f"two runs: off either way (0.55-10.6 times the error); {OBSERVE}{see('fast Γ')}"]
