"""When not to trust the Richardson estimate: the warnings, each naming the quantities concerned.

The Richardson estimate (:mod:`~contactcore.estimate.extrapolation`)
holds once the runs are in the asymptotic range, where the error is
``C h^p`` at an order theory allows
(:func:`~contactcore.estimate.orders.order_range`).  Each function here
finds quantities whose runs are not, and a ``*_warning(s)`` function
says so in one short line: the quantities, what was found with its
numbers in their units, and the row of docs/error-estimates.md, "The
warnings", that explains it (:func:`see`), which holds the measured
ranges and the reasons the line leaves out (newuser32: twelve lines of
250-520 characters on one run).

An observed order (three runs) further than
:data:`~contactcore.tolerances.ORDER_MISMATCH` from the orders theory
allows, or clipped to an end of :data:`~contactcore.tolerances.ORDER_RANGE`,
means the runs are not yet in the asymptotic range
(:func:`order_mismatch`, :func:`order_warnings`).  An order of
:data:`POLLUTED_ORDER` or more taken from two runs on a domain with
singular points that :func:`~contactcore.estimate.singular.pollution_order`
does not take may make the estimate several times too small
(:func:`pollution_warning`).

Two runs are not asymptotic where the coarser one's stencil (a cell,
EFGM's support, xfem P1's recovery patch: :func:`stencil_radius`) is not
small against what it resolves: within two stencils of a singular point
that run's error is still the singular point's own, and a stencil over
1/:data:`~contactcore.tolerances.FEATURE_STENCILS` of the scene's smallest
feature (:func:`feature_size`) resolves it pre-asymptotically.  Richardson
cannot see either from two runs; the estimate names the quantities
concerned in a warning (:func:`unsettled`).  It names too the quantities
whose coarse run varies from cell to cell faster than theory allows
(:func:`cell_scale_orders`), and those whose runs differ a thousand times
less than others of their kind in the same runs, where the error's
leading term cancels and a smaller one of another order may set the rate
(:func:`residues`), and, for a polluted range split at the cells'
scale, those whose difference lies mostly at that scale, the part
taken at the range's upper order, which two runs cannot check
(:func:`split_cell_share`, an empirical marker of scene A's A5 fe P2
``g_N``, 0.485).

xfem P1's recovered stress (its options' ``recovered_stress``,
:class:`~contactcore.result.MethodFacts`) converges at order 1 in a
layer one cell thick along a curved Γ, where the recovery patch is one-sided and cut cells' samples carry an O(h)
bias, against 2 to 3 elsewhere: from h = 0.025 that layer sets a ray's
error and the two-run estimate, taken at the order elsewhere, reads 0.42
to 0.47 of it (docs/methods/xfem.md, "Degree-1 stress"); on other
scenes such entries read 0.18-2.2.  The estimate names such profiles
without a direction (:func:`curved_layer`).  (xfem P1's Zienkiewicz–Zhu
estimate takes that recovered stress as its ``σ*`` and the displacement's
own as ``σ_h``: :func:`~contactcore.estimate.energy.energy_estimate`.)  EFGM P1's
Zienkiewicz–Zhu estimate at a tiny share of the run's energy, where its
quadrature's error may be most of the error, is named too
(:func:`quadrature_energy`: the layered slip's 0.41).

An exact law's traction on Γ (Nitsche's multiplier) estimated from two
runs where theory allows it order 1 (within
:data:`~contactcore.tolerances.STATUS_CHANGE_CELLS` coarse cells of a
status change, at order 1; beyond, at 2 at degree 2 and at 1.45 of
``[1, 2]`` at degree 1: :func:`~contactcore.estimate.orders.smooth_range`)
is most often too
large: its pieces converge faster (up to 13.7 times the error on
grader17's tilted block, xfem P1), but not always (0.19 on a held-out
wedge; :func:`exact_tractions`).  A warning claims a direction (too
large, too small) only where every entry it named on the measured sets
lay that way; otherwise it gives the measured range.

Under an exact law a point where Γ's final status changes is a weak
singular point (the solution no smoother than H^{5/2-ε} there): a bulk
quantity's samples within
:data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS` coarse stencils
of one are left out of its ``kept_rms`` as a singular point's are, and a
line says so (:func:`beyond_reach`, :func:`near_status_changes`).

Where Γ's status differs between the runs: :mod:`~contactcore.estimate.status`.

numpy only; no method is imported or named: what a warning must know of
one, it reads from the run's :class:`~contactcore.result.MethodFacts`
(``facts``), as its options declared them.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol
from ..geometry import Rectangle
from ..labels import run_label
from ..profiles import ProfileData
from ..scaling import Sizes
from ..scene import Scene
from .energy import EnergyEstimate
from .extrapolation import QuantityEstimate, cell_scale_part, rms, sample_groups
from ..scene.resolution import body_thickness
from ..result import MethodFacts
from .orders import GAPS, STRESSES, TRACTIONS, _exact, lower_end
from .singular import far_from_singular, singular_points, stress_singular_points, unknown_ends

#: Γ's quantities: the gaps and the tractions.
GAMMA = GAPS + TRACTIONS

#: The page whose table, "The warnings", explains each estimate warning:
#: a row per warning, its first words the name a line points to (:func:`see`).
WARNINGS_PAGE = "docs/error-estimates.md"


#: What a warning of a two-run estimate advises: a third run observes the order.
OBSERVE = "try --estimate 3"


def see(row: str) -> str:
    """The end of a warning's line: where its explanation lives, the row
    of :data:`WARNINGS_PAGE`'s table that begins with ``row``."""
    return f" ({WARNINGS_PAGE}: {row})"


def _orders(theory: tuple[float, float]) -> str:
    """``"2"``, or ``"1-2"`` for a range."""
    low, high = theory
    return f"{low:.3g}" if low == high else f"{low:.3g}-{high:.3g}"


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


def _clipped(order: float) -> str:
    """``" (clipped)"`` where an observed order sits at an end of ORDER_RANGE."""
    return " (clipped)" if order <= tol.ORDER_RANGE[0] or order >= tol.ORDER_RANGE[1] else ""


#: The least order at which a corner's pollution shows: the degree-2
#: displacement and gaps (order 3) converged at 1.5-1.9 away from the
#: singular points of nine scenes the estimate was not tuned on, their
#: two-run estimates at order 3 0.15-0.46 of the error
#: (docs/error-estimates.md).
#: :func:`~contactcore.estimate.singular.pollution_order` takes the
#: clamped-free corners and Γ's ends under a penalty law; what is left at
#: this order lies on a domain whose singular points it does not take.
POLLUTED_ORDER = 3


def pollution_warning(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]]) -> list[str]:
    """A line when quantities are estimated from two runs at an order of
    :data:`POLLUTED_ORDER` or more on a domain with singular points that
    :func:`~contactcore.estimate.singular.pollution_order` does not take
    (corners between two clamped or two free edges, the end of an exactly
    enforced Γ, a straight Γ's ends on a disc): if one of them slows them
    everywhere after all, the estimate may be several times too small."""
    names = [f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items()
             if not e.observed and e.order >= POLLUTED_ORDER]
    if not names or not len(singular_points(scene)):
        return []
    return [f"{', '.join(names)}: estimated at order {POLLUTED_ORDER} from two runs on a domain with singular "
            f"points: may be 2-7 times too small; {OBSERVE}{see('pollution')}"]


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


def stencil_radius(record: dict, facts: MethodFacts, quantity: str) -> float:
    """The radius around a point within which lie the unknowns that set a
    run's ``quantity`` there (the run's discretisation ``record`` and
    :class:`~contactcore.result.MethodFacts`): a support of ``dmax · h``
    for a ``meshfree`` method (``√2`` times that to a rectangular
    support's corner), the recovery patch of
    :data:`~contactcore.tolerances.RECOVERY_RINGS` vertex rings around the
    point's cell for a ``recovered_stress``, and one cell, ``h``,
    otherwise."""
    h = float(record["h"])
    if facts.meshfree:
        return float(record["dmax"]) * h * (np.sqrt(2.0) if record.get("support") == "rectangular" else 1.0)
    if quantity in STRESSES and facts.recovered_stress:
        return (tol.RECOVERY_RINGS + 1) * h
    return h


def _distances(xy: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Each sample's (``xy``, (n, 2)) distance from the nearest of
    ``points`` ((m, 2)); infinite where there are none."""
    if not len(points):
        return np.full(len(xy), np.inf)
    return np.min(np.linalg.norm(xy[:, None] - points[None], axis=-1), axis=1)


def beyond_reach(scene: Scene, xy: np.ndarray, record: dict, facts: MethodFacts, quantity: str,
                 exclude: float, changes: np.ndarray | None = None) -> np.ndarray:
    """Mask of a profile's samples (``xy``) over which the estimate of
    ``quantity`` is summarised (its ``kept_rms``): at least ``exclude`` from
    every singular point (:func:`~contactcore.estimate.singular.far_from_singular`),
    and at least ``R = REACH_STENCILS · ρ`` from every point whose stress
    is singular (:func:`~contactcore.estimate.singular.stress_singular_points`),
    ``ρ`` the coarse run's :func:`stencil_radius` (``record``, its
    discretisation): a sample's value combines the unknowns within ``ρ``
    of it, each set by the equations within ``ρ`` of that unknown, so within
    ``R`` the coarse run's error is still the singular point's own and
    shrinks at no power of ``h`` that two runs can see
    (:data:`~contactcore.tolerances.REACH_STENCILS`).  ``R`` scales with
    the coarse ``h`` and the method's reach; it is at most
    :data:`~contactcore.tolerances.EXCLUDE_KEEP_SHARE` of the farthest
    sample's distance from those points, so that a profile keeps its
    middle; samples then still within reach are named by the reach cause
    of :func:`unsettled`.  A sample at ``R`` within
    :data:`~contactcore.tolerances.GEOMETRY` (relative) is kept, as
    :func:`unsettled` does not count it within reach.  ``exclude`` 0 keeps
    every sample: the caller left nothing out.

    ``changes``, the points where Γ's final status changes under an exact
    law (:func:`~contactcore.estimate.status.status_changes`), are treated
    alike for a bulk quantity (not Γ's :data:`GAMMA`, whose tractions take
    order 1 near them instead): its samples within
    :data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS` stencils of one
    are left out too, capped on their own (:func:`near_status_changes`)."""
    kept = far_from_singular(scene, xy, exclude)
    if exclude <= 0 or not len(xy):
        return kept
    rho = stencil_radius(record, facts, quantity)
    kept &= _beyond(_distances(xy, stress_singular_points(scene)), tol.REACH_STENCILS * rho)
    if changes is not None and quantity not in GAMMA:
        kept &= _beyond(_distances(xy, changes), tol.STATUS_CHANGE_STENCILS * rho)
    return kept


def _beyond(dist: np.ndarray, reach: float) -> np.ndarray:
    """Mask of the samples at ``dist`` from some points at least ``reach``
    from them, ``reach`` at most
    :data:`~contactcore.tolerances.EXCLUDE_KEEP_SHARE` of the farthest
    sample's distance (a profile keeps its middle), within
    :data:`~contactcore.tolerances.GEOMETRY` (relative); all of them where
    there are no points (``dist`` infinite)."""
    if not np.any(np.isfinite(dist)):
        return np.ones(len(dist), bool)
    return dist >= min(reach, tol.EXCLUDE_KEEP_SHARE * float(np.max(dist))) * (1 - tol.GEOMETRY)


def near_status_changes(profiles: list[ProfileData], changes: np.ndarray, record: dict, facts: MethodFacts,
                        kept: dict[str, dict[str, np.ndarray]]) -> dict[str, tuple[float, bool]]:
    """``{PID:Q: (R, capped)}`` of the bulk quantities (not Γ's
    :data:`GAMMA`) of ``profiles`` (the finest run's) with a sample within
    ``R`` = :data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS` coarse
    stencils (:func:`stencil_radius` of ``record``, the coarse run) of one
    of ``changes``, the points where Γ's final status changes under an
    exact law (:func:`~contactcore.estimate.status.status_changes`).
    There the solution is no smoother than H^{5/2-ε} (Moussaoui and Khodja
    1992): its stress is a weak singular point's, and a coarse run's error
    within reach of it is not ``C h^p`` (a vertical line that crossed an
    inclined bimaterial Γ where stick turned to slip,
    tests/scenes/stick_slip_crossing.toml: 99 % of fe P2's squared σyy
    error lay within one coarse cell of the crossing, estimated at 0.48 of
    it; :data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS`).
    :func:`beyond_reach` leaves those samples out of ``kept_rms``;
    ``capped`` says some are still ``kept`` (:data:`~contactcore.tolerances.EXCLUDE_KEEP_SHARE`),
    so that ``kept_rms`` itself is not asymptotic."""
    out = {}
    if not len(changes):
        return out
    for prof in profiles:
        dist = _distances(np.column_stack([prof.columns["x"], prof.columns["y"]]), changes)
        for q in prof.names[3:]:
            reach = tol.STATUS_CHANGE_STENCILS * stencil_radius(record, facts, q)
            within = dist < reach * (1 - tol.GEOMETRY)
            if q not in GAMMA and np.any(within):
                out[f"{prof.id}:{q}"] = (reach, bool(np.any(within & kept[prof.id][q])))
    return out


def status_change_warnings(found: dict[str, tuple[float, bool]], length: str = "m") -> list[str]:
    """One line per reach of :func:`near_status_changes`, naming its
    quantities: their samples within that distance (in the scene's unit
    named ``length``) of a change of Γ's status are left out of
    ``kept_rms`` (or, capped, some kept: then not asymptotic), and their
    ``q_err`` there is an indication only."""
    lines = []
    for reach, capped in sorted(set(found.values())):
        names = [k for k, v in found.items() if v == (reach, capped)]
        left = "some kept: not asymptotic" if capped else "left out of kept_rms; q_err there not asymptotic"
        lines.append(f"{', '.join(names)}: samples within {reach:.3g} {length} of a change of Γ's status: {left}"
                     f"{see('near a status change')}")
    return lines


def feature_size(scene: Scene) -> float:
    """The scene's smallest feature: the domain's smallest extent (a
    rectangle's shorter side, a disc's diameter), or a circular Γ's
    diameter where that is less."""
    domain = scene.domain
    size = float(min(domain.size)) if isinstance(domain, Rectangle) else domain.length_scale
    radius = getattr(scene.interface, "radius", None)
    return min(size, 2.0 * float(radius)) if radius is not None else size


def thinnest_body(scene: Scene) -> float:
    """The thinner body's thickness across a straight Γ
    (:func:`~contactcore.scene.resolution.body_thickness`: a layer between
    Γ and a parallel edge, a corner cut off), infinite for a curved Γ
    (its disc is in :func:`feature_size`)."""
    thickness = body_thickness(scene)
    return min(thickness.values()) if thickness else np.inf


def unsettled(scene: Scene, levels: list[list[ProfileData]], record: dict, facts: MethodFacts,
              exclude: float, estimates: dict[str, dict[str, QuantityEstimate]] | None = None
              ) -> dict[str, dict[str, tuple[float, float]]]:
    """The quantities whose two-run estimate is not asymptotic, by cause,
    from the coarser run (``record``, its discretisation; ``facts``, its
    method's :class:`~contactcore.result.MethodFacts`) of the pair that
    makes it: ``{"reach": {PID:Q: (ρ, h_ok)}, "coarse": {...}, "thin": {...}}``
    with ``ρ`` the quantity's :func:`stencil_radius` in that run and
    ``h_ok`` the coarse run's h from which the cause is gone (ρ scales
    with h).  ``reach``: a sample kept (at least ``exclude`` from the
    singular points) lies within
    :data:`~contactcore.tolerances.REACH_STENCILS` stencils of a singular
    point, where that run's error is still the singular point's own.
    ``coarse``: the stencil exceeds
    1/:data:`~contactcore.tolerances.FEATURE_STENCILS` of the scene's
    :func:`feature_size`.  ``thin``: a body is less than
    :data:`~contactcore.tolerances.THIN_BODY_STENCILS` stencils thick
    (:func:`thinnest_body`), so the coarse run hardly resolves a field
    across it (grader25b's layer 0.15 thick on xfem P1 cells of 0.1: the
    estimate of ``u_y`` read 0.127 of its error).  A tie within
    :data:`~contactcore.tolerances.GEOMETRY` (relative) is no cause: h =
    0.05 with supports of 2h on a feature of 0.8 sits on the threshold,
    and round-off must not decide it."""
    sing, feature, h = stress_singular_points(scene), feature_size(scene), float(record["h"])
    thin = thinnest_body(scene)
    out = {"reach": {}, "coarse": {}, "thin": {}}
    coarse_run = {p.id: p for p in levels[-2]} if len(levels) > 1 else {}
    for prof in levels[-1]:
        xy = np.column_stack([prof.columns["x"], prof.columns["y"]])
        kept = far_from_singular(scene, xy, exclude)
        dist = _distances(xy, sing)
        near = np.min(dist[kept]) if np.any(kept) else np.inf
        for q in prof.names[3:]:
            rho = stencil_radius(record, facts, q)
            within = kept & (dist < tol.REACH_STENCILS * rho * (1 - tol.GEOMETRY))
            local = rho <= h * (1 + tol.GEOMETRY) and not _lower_end(scene, estimates, prof.id, q, h)
            if np.any(within) and not _spread(prof, coarse_run.get(prof.id), q, within, kept & ~within, local):
                out["reach"][f"{prof.id}:{q}"] = (rho, h * near / (tol.REACH_STENCILS * rho))
            if rho * tol.FEATURE_STENCILS > feature * (1 + tol.GEOMETRY):
                out["coarse"][f"{prof.id}:{q}"] = (rho, h * feature / (tol.FEATURE_STENCILS * rho))
            if rho * tol.THIN_BODY_STENCILS > thin * (1 + tol.GEOMETRY):
                out["thin"][f"{prof.id}:{q}"] = (rho, h * thin / (tol.THIN_BODY_STENCILS * rho))
    return out


def _lower_end(scene: Scene, estimates: dict[str, dict[str, QuantityEstimate]] | None, pid: str, q: str,
               h: float) -> bool:
    """Whether the estimate of ``PID:Q`` takes the lower end of its range
    (:func:`~contactcore.estimate.orders.lower_end`: a bulk displacement
    on a scene whose straight Γ ends under an exact law,
    :func:`~contactcore.estimate.singular.exact_interface_ends`, or under
    springs stiff at the scale of the coarse run's cells ``h``,
    :func:`~contactcore.estimate.singular.stiff_spring_ends`): an end
    of an exponent not taken, whose error may pollute the whole domain,
    so that where the runs differ most says nothing of it.  On the nine
    held-out scenes the exact unilateral wedge's xfem P2 `u_x` (3.25,
    its runs' difference 1.8 times as large within reach as beyond) was
    named by the reach cause alone (docs/error-estimates.md, "Which
    estimates to warn of")."""
    e = (estimates or {}).get(pid, {}).get(q)
    return e is not None and lower_end(q, e.theory, unknown_ends(scene, h))


def _spread(fine: ProfileData, coarse: ProfileData | None, q: str, within: np.ndarray, beyond: np.ndarray,
            one_cell: bool) -> bool:
    """Whether the runs contradict the reach cause of :func:`unsettled`
    for a stencil of ``one_cell`` (fe, and xfem but for its recovered
    stress): their difference over the kept samples ``within`` reach of
    a singular point is no more than
    :data:`~contactcore.tolerances.REACH_CONCENTRATION` times (RMS) that
    ``beyond`` it, so the coarse run's error there is not the singular
    point's own.  False for a wider stencil (EFGM's supports, a recovery
    patch), without a coarse run, with no sample beyond, or where the
    difference is at round-off of the quantity."""
    if not one_cell or coarse is None or not np.any(beyond):
        return False
    d = fine.columns[q] - coarse.columns[q]
    scale = max(float(np.max(np.abs(fine.columns[q]))), float(np.max(np.abs(coarse.columns[q]))))
    far = rms(d[beyond])
    if far <= tol.ESTIMATE_ROUNDOFF * scale:
        return False
    return rms(d[within]) <= tol.REACH_CONCENTRATION * far


def unsettled_warnings(found: dict[str, dict[str, tuple[float, float]]], h: float, feature: float,
                       length: str = "m", thin: float = np.inf) -> list[str]:
    """One line per cause of :func:`unsettled` and per stencil, naming the
    quantities and the coarse h from which the cause is gone; each length
    followed by the scene's unit named ``length``
    (:class:`~contactcore.scene.Units`): the coarse run's ``h``, the
    stencil, the scene's smallest ``feature`` and ``thin``, its thinnest
    body's thickness.  A stencil is a cell, a support or a recovery patch
    (:func:`stencil_radius`; docs/error-estimates.md, "The warnings")."""
    lines, u = [], f" {length}"
    for cause, entries in found.items():
        for rho in sorted({v[0] for v in entries.values()}):
            names = [k for k, v in entries.items() if v[0] == rho]
            h_ok = min(entries[k][1] for k in names)
            stencils = f"stencils of {rho:.3g}{u} at h = {h:g}{u}"
            why = {"reach": f"within {tol.REACH_STENCILS * rho:.3g}{u} of a singular point "
                            f"({tol.REACH_STENCILS:g} {stencils})",
                   "coarse": f"{stencils} over 1/{tol.FEATURE_STENCILS:g} of the smallest feature "
                             f"({feature:.3g}{u})",
                   "thin": f"{tol.THIN_BODY_STENCILS:g} {stencils} over the thinner body across Γ "
                           f"({thin:.3g}{u})"}[cause]
            lines.append(f"{', '.join(names)}: {why}: not asymptotic; start below h = {h_ok:.3g}{u}"
                         f"{see('stencil')}")
    return lines


def cell_scale_orders(scene: Scene, levels: list[list[ProfileData]],
                      estimates: dict[str, dict[str, QuantityEstimate]], exclude: float,
                      h: float) -> dict[str, tuple[float, float]]:
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
    :func:`order_warnings`; a part at round-off shows no order: of the
    quantity (:data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF` of its largest
    |value|), or of the scene's own size of its kind
    (:data:`~contactcore.tolerances.NEGLIGIBLE_SHARE` of
    :class:`~contactcore.scaling.Sizes`' stress for a stress or traction,
    displacement otherwise), so that a quantity whose values are all round-off
    (σxy of a bonded patch, 1e-14) is named by no kernel."""
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
            a, b = (rms(cell_scale_part(v, s, groups, h)[kept]) for v in (coarse.columns[q], cols[q]))
            scale = max(float(np.max(np.abs(cols[q]))), float(np.max(np.abs(coarse.columns[q]))))
            own = sizes.stress if q in STRESSES + TRACTIONS else sizes.displacement
            if min(a, b) <= max(tol.ESTIMATE_ROUNDOFF * scale, tol.NEGLIGIBLE_SHARE * own):
                continue
            order = float(np.log2(a / b))
            if order > e.theory[1] + tol.CELL_SCALE_EXCESS:
                out[f"{fine.id}:{q}"] = (order, float(e.theory[1]))
    return out


def cell_scale_warnings(found: dict[str, tuple[float, float]], hs: tuple[float, float],
                        undirected: tuple[str, ...] | list[str] = (), length: str = "m") -> list[str]:
    """One line naming the quantities of :func:`cell_scale_orders`, each
    with the order at which its runs' variation at the cells' scale
    shrank and the highest order theory allows it (``hs`` in the scene's
    unit named ``length``).  The line says the
    estimate is likely too large (measured 0.99-8.05 times the error on
    the 28 entries it named on four sets, 2026-11-28) but for the
    quantities also in ``undirected`` (:func:`fast_gamma`'s, EFGM P1's Γ
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
    :func:`order_warnings` but count in their kind's largest; a
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




def curved_layer(scene: Scene, levels: list[list[ProfileData]], facts: MethodFacts, h: float,
                 exclude: float) -> list[str]:
    """The ``PID:Q`` of a recovered stress (``facts.recovered_stress``:
    xfem P1's) on profiles with
    a sample kept (at least ``exclude`` from the singular points) within one
    cell of the coarser run, ``h``, of a curved Γ: there that stress
    converges at order 1 and the estimate, taken at the order elsewhere,
    is not to be trusted: too small on the rays of the pressurised rods
    (module doc), but 0.18-2.2 times the error on the 54 entries it named
    on four sets (2026-11-28), so the warning gives no direction.  Empty for a straight Γ or a stress not recovered.
    A sample at h within :data:`~contactcore.tolerances.GEOMETRY`
    (relative) counts, so round-off does not decide it."""
    if not facts.recovered_stress or scene.interface.straight_in(scene.domain):
        return []
    names = []
    for prof in levels[-1]:
        xy = np.column_stack([prof.columns["x"], prof.columns["y"]])
        kept = far_from_singular(scene, xy, exclude)
        near = np.abs(scene.interface.signed_distance(xy[kept])) <= h * (1 + tol.GEOMETRY)
        if np.any(near):
            names += [f"{prof.id}:{q}" for q in prof.names[3:] if q in STRESSES]
    return names


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


def curved_layer_warning(names: list[str], h: float, length: str = "m") -> list[str]:
    """One line naming :func:`curved_layer`'s quantities; lengths in the
    scene's unit named ``length``."""
    if not names:
        return []
    return [f"{', '.join(names)}: the recovered stress converges at order 1 within a cell ({h:g} {length}) of the "
            f"curved Γ: off either way; degree 2 avoids it{see('curved layer')}"]


#: The key under which :func:`quadrature_energy` or :func:`recovery_floor` marks the energy estimate in
#: :attr:`~contactcore.estimate.runs.Estimate.unsettled` (a profile id
#: ``energy``, quantity ``‖σ‖_E``, as the effectivity table names it).
ENERGY_KEY = "energy:‖σ‖_E"


def recovery_floor(energy: EnergyEstimate | None) -> list[str]:
    """One line where the recovery's own error may be much of the
    Zienkiewicz–Zhu estimate: on a curved Γ, a second recovery of σ*
    moves it by more than :data:`~contactcore.tolerances.ENERGY_RECOVERY_SHARE`
    of η (:func:`~contactcore.estimate.energy.recovery_moves`).  No
    direction: of the 16 entries it named, 15 read 1.35-4.70 times the
    error, but EFGM P2's on a disc whose Γ is open 0.67 (2026-11-29)."""
    if energy is None or energy.recovery is None or not energy.recovery > tol.ENERGY_RECOVERY_SHARE * energy.eta:
        return []
    return [f"energy (ZZ): on this curved Γ the recovery's own error is much of the estimate (a second recovery "
            f"moves it by {energy.recovery / energy.eta:.2g} of η): off either way; refine"
            f"{see('recovery floor')}"]


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
