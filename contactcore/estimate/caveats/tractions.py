"""Γ's gaps and tractions whose estimate theory's order does not fit.

An exact law's traction on Γ (Nitsche's multiplier) estimated where theory
allows it order 1 is most often too large, not always
(:func:`exact_tractions`, from two runs; :func:`observed_exact_tractions`,
from three); EFGM P1's gaps and tractions shrink faster than the order
taken, or are set by its quadrature (:func:`fast_gamma`).  A warning
claims a direction only where every entry it named on the measured sets
lay that way; otherwise it gives the measured range."""
from __future__ import annotations

from collections.abc import Set

import numpy as np

from ... import tolerances as tol
from ...labels import run_label
from ...laws import OPEN, STICK
from ...result import MethodFacts
from ...scene import Scene
from ..extrapolation import QuantityEstimate
from ..orders import _exact, SUPERCONVERGENT_DEGREES, TRACTIONS
from .lines import GAMMA, OBSERVE, see


def exact_tractions(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]],
                    smooth: dict[str, np.ndarray] | None = None, *, roundoff: Set[str] = frozenset()) -> list[str]:
    """The ``PID:Q`` of an exact law's tractions on Γ (Nitsche's
    multiplier, :data:`~contactcore.estimate.orders.TRACTIONS`) whose
    estimate, without an observed order, takes order 1 at some sample:
    a Γ whose status switches (:func:`~contactcore.estimate.orders.theoretical_order`)
    with a sample within :data:`~contactcore.tolerances.STATUS_CHANGE_CELLS`
    coarse cells of a change of its final status (``smooth``, the samples
    beyond them: :func:`~contactcore.estimate.status.far_from_changes`;
    None: every sample taken as near), which take 1 (beyond, 2 at degree
    2, 1.45 at degree 1: :func:`~contactcore.estimate.orders.smooth_range`).
    Where no sample lies near a change (a slip or a stick that switched
    only in the history) the estimate takes the far order everywhere:
    :func:`steady_exact_tractions` at degree 1, none at degree 2 (as on a
    Γ that never switches; fix37).  A quantity in ``roundoff`` is not
    named: the ``PID:Q`` whose two finest runs differ only at round-off
    (:func:`~contactcore.estimate.caveats.unsettled.roundoff_runs` of the
    estimate's runs, made once per estimate by
    :func:`~contactcore.estimate.runs.estimate_runs`; none by default).
    Order 1 is the least theory allows it; its pieces converge faster (1.4-3 on
    the held-out wedges; on a sheared and reversed block degree 2's t_N at
    2.3-2.5 beyond two coarse cells of a status change, 1.5-1.7 within,
    and xfem and efgm P1's at 2.5-2.6), so the estimate is
    most often too large: up to 13.7 times the error (grader17's tilted block
    under exact Coulomb, xfem P1 t_N at h = 0.05 → 0.025), 2.2-2.9 on the
    Lamé disc under an exact law (docs/error-estimates.md, "Known
    limits")."""
    return [k for k in _unobserved_tractions(scene, profiles, roundoff)
            if _near_change(k, _entry(profiles, k), smooth)]


def steady_exact_tractions(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]], degree: int,
                           smooth: dict[str, np.ndarray] | None = None, *, roundoff: Set[str] = frozenset()
                           ) -> list[str]:
    """The ``PID:Q`` of an exact law's degree-1 tractions on Γ (a degree
    in :data:`~contactcore.estimate.orders.SUPERCONVERGENT_DEGREES`)
    estimated without an observed order at the balanced 1.45 of ``[1, 2]``
    at every sample: Γ's final status does not change along it (never
    switched, or only in the history: ``smooth`` all True), so
    :func:`exact_tractions`' order 1 applies nowhere (fix37: its line said
    so on a crack in slip and a block that sticks).  Whether a piece mean
    superconverges two runs cannot tell (:mod:`~contactcore.estimate.orders`);
    measured 2026-11-29 (RMS over the kept samples): 0.69-3.86 on the 24
    entries of two scenes that never switch (deg1_36), 0.68-2.13 on an
    inclined block that sticks under its weight and 0.65 on an inclined
    crack in slip (efgm P1; fe's and xfem's at round-off, not named: in
    ``roundoff``, as for :func:`exact_tractions`)."""
    if degree not in SUPERCONVERGENT_DEGREES:
        return []
    return [k for k in _unobserved_tractions(scene, profiles, roundoff)
            if not _near_change(k, _entry(profiles, k), smooth)]


def _unobserved_tractions(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]],
                          roundoff: Set[str]) -> list[str]:
    """The ``PID:Q`` of an exact law's tractions on Γ whose estimate has
    no observed order (two runs, or three of which one difference is at
    round-off) and whose runs do not differ only at round-off (not in
    ``roundoff``)."""
    if not _exact(scene.law):
        return []
    return [f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items()
            if q in TRACTIONS and not e.observed and e.theory[0] <= 1 and f"{pid}:{q}" not in roundoff]


def _entry(profiles: dict[str, dict[str, QuantityEstimate]], key: str) -> QuantityEstimate:
    """The estimate of ``PID:Q``."""
    pid, q = key.split(":")
    return profiles[pid][q]


def _near_change(key: str, e: QuantityEstimate, smooth: dict[str, np.ndarray] | None) -> bool:
    """Whether the estimate ``e`` of ``PID:Q`` takes order 1 at some
    sample: its order is 1 and no far order applies, or one does
    (``far_order``) but not at every sample (``smooth``, unknown: near)."""
    if e.order > 1:
        return False
    if e.far_order is None or smooth is None:
        return True
    return not bool(np.all(smooth.get(key.split(":")[0], np.zeros(1, bool))))


def exact_traction_warning(names: list[str], three: bool = False) -> list[str]:
    """One line naming :func:`exact_tractions`' quantities; with ``three``
    runs, of which the estimate observed no order (one difference at
    round-off: :func:`~contactcore.estimate.extrapolation.observed_order`),
    it says so instead of "from two runs".  It gives the
    measured ratios, not a direction: of the 82 entries it named on four
    sets (2026-11-28), 80 read 1 or more (up to 13.7) but the held-out
    exact Coulomb wedge's xfem P2 ``t_T`` 0.19 and grader17's tilted
    block's xfem P1 ``t_N`` 0.83 (docs/error-estimates.md, "Which
    estimates to warn of").  With degree 2 taken at 2 beyond
    :data:`~contactcore.tolerances.STATUS_CHANGE_CELLS` coarse cells of a
    status change (2026-11-29), 96 entries on four scenes read 0.09-8.51,
    2 below 0.5; degree 1 at 1.45 beyond them (deg1_36), its 48 entries
    on four scenes 0.76-6.80, none below 0.5 (docs/error-estimates.md,
    "Known limits")."""
    if not names:
        return []
    if three:
        return [f"{', '.join(names)}: an exact Γ traction at order 1 near status changes, three runs showing no "
                f"order: often too large (up to 13.7×), not always{see('exact tractions')}"]
    return [f"{', '.join(names)}: an exact Γ traction from two runs at order 1 near status changes (faster "
            f"beyond): often too large (up to 13.7×), not always; {OBSERVE}{see('exact tractions')}"]


def steady_exact_traction_warning(names: list[str]) -> list[str]:
    """One line naming :func:`steady_exact_tractions`' quantities, with
    their measured range (its docstring: 0.65-3.86 times the error on 32
    entries, none below 0.5), not a direction."""
    if not names:
        return []
    return [f"{', '.join(names)}: a degree-1 exact Γ traction without status changes, at 1.45 of [1, 2]: "
            f"0.65-3.86× the error; {OBSERVE}{see('steady tractions')}"]


def enforced_gaps(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]],
                  statuses: dict[str, list[np.ndarray]], *, roundoff: Set[str] = frozenset()) -> list[str]:
    """The ``PID:Q`` of an exact law's gaps on Γ that are its enforcement's
    own violation, estimated without an observed order: ``g_N`` of a
    profile closed (stick or slip) at every sample, ``g_T`` of one that
    sticks at every sample, in the final status of each run
    (``statuses``, ``{profile id: [status per sample, one array a run]}``:
    :func:`contactcore.profiles.interface_status`).  There the true value
    is 0 and the run's is Nitsche's consistent residual, which converges
    at an order that theory's ``degree + 1`` for a gap does not give (an
    inclined block that sticks under its weight, fe P1 ``g_T``: 3.2e-8 →
    1.1e-8 m from h = 0.05 → 0.025, order 1.5 against 2; its two-run
    estimate 0.39 of the error over the kept samples, fix37, 2026-11-29).
    A quantity in ``roundoff`` is not named: the ``PID:Q`` whose two
    finest runs differ only at round-off
    (:func:`~contactcore.estimate.caveats.unsettled.roundoff_runs` of the
    estimate's runs, made once per estimate by
    :func:`~contactcore.estimate.runs.estimate_runs`; none by default: fe
    and xfem's gaps of a crack in slip)."""
    if not _exact(scene.law):
        return []
    held = {"gN": lambda s: s != OPEN, "gT": lambda s: s == STICK}
    return [f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items()
            if q in held and not e.observed and f"{pid}:{q}" not in roundoff and statuses.get(pid)
            and all(np.all(held[q](np.asarray(s))) for s in statuses[pid])]


def enforced_gap_warning(names: list[str]) -> list[str]:
    """One line naming :func:`enforced_gaps`' quantities, with the measured
    range, not a direction: 0.32-4.52 times the error (RMS over the kept
    samples) on the 27 entries it named on four scenes at h = 0.1 → 0.05
    (2026-11-29: a Lamé disc under exact unilateral contact and
    tests/scenes/wedge_held.toml, against fe P2 at h = 0.0125; the
    inclined block that sticks and the inclined crack in slip against
    their closed forms), 3 below 0.5 (fe P1's g_N of the wedge 0.32, of
    the block g_T 0.38, efgm P2's g_N there 0.39) and 3 above 2 (the
    wedge's xfem P2 g_T 4.52; docs/error-estimates.md, "The warnings":
    enforced gaps)."""
    if not names:
        return []
    return [f"{', '.join(names)}: an exact law's gap where Γ is held (closed, stuck): the enforcement's residue, "
            f"at no order theory gives: 0.32-4.52× the error; {OBSERVE}{see('enforced gaps')}"]


def observed_exact_tractions(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]],
                             smooth: dict[str, np.ndarray] | None = None) -> list[str]:
    """The ``PID:Q`` of an exact law's tractions on Γ estimated from three
    runs (an observed order) where theory allows them order 1 alone (a Γ
    whose status switches: :func:`~contactcore.estimate.orders.order_range`;
    beyond its changes the far order applies,
    :func:`~contactcore.estimate.extrapolation.richardson`) with a sample
    within :data:`~contactcore.tolerances.STATUS_CHANGE_CELLS` coarse cells
    of a change of its final status (``smooth``, the samples beyond them;
    None: every sample taken as near): the cause of :func:`exact_tractions`
    does not go with a third run.  Where no sample lies near a change (a
    Γ that switched only in its history) every sample takes the far order
    and the line's cause is absent, as for two runs (fix38, 2026-11-29:
    an inclined crack in slip, efgm P1 and P2 ``t_N``, ``t_T`` at an
    observed 0.50, clipped, 3.31 and 3.74 times the error, are named by
    the order line; each of the 48 entries this line named on four scenes
    that switch had 6-52 of its 101 samples near a change, and stays
    named: docs/error-estimates.md, "The warnings", exact tractions).
    Where the multiplier's error varies from sample to sample unlike from
    run to run, its runs' difference ``q_{h/2} − q_h`` is about ``(1 + 2^{-2p})^½``
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
            if q in TRACTIONS and e.observed and e.theory[1] <= 1 and _near_change(f"{pid}:{q}", e, smooth)]


def observed_exact_traction_warning(names: list[str]) -> list[str]:
    """One line naming :func:`observed_exact_tractions`' quantities,
    without a direction measured beyond one scene (module doc of that
    function: up to 2.24 times the error in theory)."""
    if not names:
        return []
    return [f"{', '.join(names)}: an exact Γ traction that theory allows order 1, from three runs: its "
            f"cell-to-cell error differs run to run (up to 2.24× in theory){see('exact tractions')}"]


def fast_gamma(profiles: dict[str, dict[str, QuantityEstimate]], facts: MethodFacts) -> dict[str, float]:
    """``{PID:Q: order}`` (the order its estimate took, its ``order``) of
    the gaps and tractions on Γ (:data:`~contactcore.estimate.caveats.lines.GAMMA`) of a
    method and degree whose ``facts`` say ``fast_gamma`` (EFGM P1:
    :attr:`efgm.options.EFGM.fast_gamma`, its measurement) estimated from
    two runs, or from three whose observed order lies above the highest theory allows by more than
    :data:`~contactcore.tolerances.FAST_GAMMA_EXCESS` (the estimate then
    takes the two-run order, theory's alone or a range's balanced one:
    :func:`~contactcore.estimate.extrapolation.three_run_order`).
    Their runs' differences often shrink faster than the order the
    estimate takes (2.5-2.8 against 2 on the closed forms), and the
    estimate is then too large: above 2 for 80 of the 128 two-run entries
    measured; but where EFGM's quadrature sets their error the
    differences do not see it and the estimate is too small: 14 of the 128
    below 1 (the layered slip's 0.55), and from three runs the layered
    slip's 0.49 at an observed 2.52 (the tolerance's note).  An
    indication, off either way."""
    if not facts.fast_gamma:
        return {}
    return {f"{pid}:{q}": float(e.order) for pid, qs in profiles.items() for q, e in qs.items()
            if q in GAMMA and (not e.observed or e.measured > e.theory[1] + tol.FAST_GAMMA_EXCESS)}


def fast_gamma_warning(taken: dict[str, float], method: str, degree: int, observed: bool = False) -> list[str]:
    """One line naming :func:`fast_gamma`'s quantities (``taken``: each
    with the order its estimate took), from ``observed`` runs (three) or
    two, with those orders as the estimate recorded them: ``degree + 1``
    where theory allows that alone, but the balanced order of a range that
    pollution widened (:func:`~contactcore.estimate.orders.order_range`:
    docs/scenes/thin_top_layer_exact.toml from h = 0.1, three runs, ``G:gN``
    took 1.698 of [1.42, 2], which the line gave as 2 until fix40).  It
    gives the measured ratios, not a direction: the 128 two-run entries
    measured read 0.55 to 10.6 times the error, 80 above 2 but 14 below 1
    (the layered slip's 0.55, the patch's 0.68-0.71: the error there is
    EFGM's quadrature's, which the runs' differences do not see); the
    three-run ones 0.49-1.14."""
    if not taken:
        return []
    names, (word, orders) = ", ".join(taken), _orders_taken(taken.values())
    if observed:
        return [f"{names}: {run_label(method, degree)}'s gaps and tractions on Γ shrink faster than the "
                f"{word} taken ({orders}): off either way (0.49-1.14 times the error){see('fast Γ')}"]
    return [f"{names}: {run_label(method, degree)}'s gaps and tractions on Γ at {word} {orders} from "
            f"two runs: off either way (0.55-10.6 times the error); {OBSERVE}{see('fast Γ')}"]


def _orders_taken(orders) -> tuple[str, str]:
    """``("order", "2")``, or ``("orders", "1.7, 2")``: the distinct
    ``orders`` (three significant figures), least first."""
    shown = list(dict.fromkeys(f"{o:.3g}" for o in sorted(orders)))
    return f"order{'s' if len(shown) > 1 else ''}", ", ".join(shown)
