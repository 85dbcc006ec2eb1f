"""One estimate of a run: solve at h, h/2 (and h/4) and gather every part into an :class:`Estimate`.

:func:`estimate` solves a scene with one discretisation at the
resolutions of :func:`levels_of`; :func:`estimate_runs` reads the runs
(only through their :class:`~contactcore.result.Result`) and gathers the
Richardson estimate of every profile quantity
(:mod:`~contactcore.estimate.extrapolation`, the orders of
:mod:`~contactcore.estimate.orders`), the warnings that say where not to
trust it (:mod:`~contactcore.estimate.caveats`,
:mod:`~contactcore.estimate.status`) and the finest run's
Zienkiewicz–Zhu estimate in energy (:mod:`~contactcore.estimate.energy`).

numpy only; no method is imported (:func:`estimate` solves through
:func:`contactcore.discretisation.solve`).
"""
from __future__ import annotations

from collections.abc import Set
from dataclasses import dataclass, field

import numpy as np

from ..profiles import interface_status, ProfileData, sample_profiles
from ..scene import Scene
from .caveats import (above_range, above_range_warning, beyond_reach, cell_scale_orders, cell_scale_warnings, exact_traction_warning, exact_tractions, fast_gamma,
                      fast_gamma_warning, feature_size, roundoff_runs, thinnest_body,
                      order_mismatch, order_warnings,
                      pollution_warning, residue_warnings, residues, unsettled, unsettled_warnings,
                      curved_layer, curved_layer_warning, ENERGY_KEY, near_status_changes, status_change_warnings,
                      quadrature_energy, quadrature_stress, quadrature_stress_warning, recovery_floor,
                      split_cell_share, split_cell_share_warning, observed_exact_traction_warning,
                      observed_exact_tractions, slow_halving, slow_halving_warning, steady_exact_tractions,
                      steady_exact_traction_warning, enforced_gaps, enforced_gap_warning, unlike_differences,
                      unlike_differences_warning, unlike_runs, unlike_runs_warning)
from .energy import EnergyEstimate, energy_estimate
from .extrapolation import QuantityEstimate, profile_estimates
from .orders import _exact, GAPS, smooth_range, TRACTIONS
from .status import far_from_changes, status_change, status_changes, status_warning, switches


#: The suffix of an estimated error's column beside its quantity
#: (``q_err``, in q's unit).
ERROR_SUFFIX = "_err"


@dataclass
class Estimate:
    """Everything estimated about the finest of a method's runs at ``hs``
    (coarse to fine): per profile and quantity
    (:class:`~contactcore.estimate.extrapolation.QuantityEstimate`), in energy
    (:class:`~contactcore.estimate.energy.EnergyEstimate`), the status along Γ
    compared between the two finest runs (a law with history), warnings, the
    finest run's profiles as sampled (``sampled``, in the scene's order: what
    a driver writes, not sampled again), and the ``PID:Q`` whose estimate a
    warning calls not asymptotic
    (:func:`~contactcore.estimate.caveats.unsettled`,
    :func:`~contactcore.estimate.caveats.cell_scale_orders`,
    :func:`~contactcore.estimate.caveats.curved_layer`,
    :func:`~contactcore.estimate.caveats.exact_tractions`,
    :func:`~contactcore.estimate.caveats.steady_exact_tractions`,
    :func:`~contactcore.estimate.caveats.enforced_gaps`,
    :func:`~contactcore.estimate.caveats.split_cell_share`,
    :func:`~contactcore.estimate.caveats.quadrature_stress`, the energy's
    :data:`~contactcore.estimate.caveats.ENERGY_KEY` where
    :func:`~contactcore.estimate.caveats.quadrature_energy` or
    :func:`~contactcore.estimate.caveats.recovery_floor` applies, and with three
    runs :func:`~contactcore.estimate.caveats.order_mismatch`,
    :func:`~contactcore.estimate.caveats.observed_exact_tractions` and
    :func:`~contactcore.estimate.caveats.slow_halving`: :func:`three_run_caveats`, and where no
    other line names it :func:`~contactcore.estimate.caveats.unlike_differences`) or not to be
    trusted (:func:`~contactcore.estimate.caveats.residues`); ``kept``,
    ``{PROFILE: {QUANTITY: mask}}``, the samples each quantity's estimate
    is summarised over (``kept_rms``): away from the singular points and
    beyond the coarse run's reach of them, and for a bulk quantity under an
    exact law beyond its reach of Γ's status changes
    (:func:`~contactcore.estimate.caveats.beyond_reach`,
    :func:`~contactcore.estimate.status.status_changes`)."""

    hs: tuple
    profiles: dict[str, dict[str, QuantityEstimate]]
    energy: EnergyEstimate | None
    status: dict | None = None
    warnings: list[str] = field(default_factory=list)
    sampled: list[ProfileData] = field(default_factory=list)
    unsettled: set[str] = field(default_factory=set)
    kept: dict[str, dict[str, np.ndarray]] = field(default_factory=dict)

    def error_columns(self, pid: str) -> dict[str, np.ndarray]:
        """``{q + ERROR_SUFFIX: per-sample error}`` of profile ``pid``."""
        return {f"{q}{ERROR_SUFFIX}": e.error for q, e in self.profiles.get(pid, {}).items()}

    def summary(self) -> dict:
        """JSON-ready: ``{PROFILE: {QUANTITY: {max, rms, kept_rms, order,
        observed, orders (, cell_scale, observed_order)}}}`` plus ``energy``,
        ``h`` (the runs), ``status`` and ``warnings``; ``kept_rms`` over the
        samples away from singular points and beyond the coarse run's reach
        of them (``kept``).  summary.json's
        ``"estimate"`` is this dict with each quantity's ``scale`` and
        ``kept_scale`` and the ``"worst"`` added
        (:func:`verification.run_files.estimate_record`: the scales are the
        agreement's, floored as it floors them)."""
        out = {pid: {q: e.record(self.kept.get(pid, {}).get(q)) for q, e in qs.items()}
               for pid, qs in self.profiles.items()}
        out.update({"energy": self.energy.record() if self.energy else None, "h": list(self.hs),
                    "status": self.status, "warnings": list(self.warnings)})
        return out


def levels_of(h: float, levels: int) -> list[float]:
    """``h, h/2`` (and ``h/4``), coarse to fine."""
    if levels not in (2, 3):
        raise ValueError(f"levels must be 2 or 3 (got {levels})")
    return [h / 2 ** k for k in range(levels)]


def estimate_runs(scene: Scene, results: list, exclude: float = 0.0, energy: bool = True,
                  coarse: bool = False) -> Estimate:
    """The :class:`Estimate` of the finest of ``results`` (one method at
    h, h/2 (, h/4), coarse to fine), or with ``coarse`` of the coarser of
    two (its profiles' errors; the energy estimate still the finest run's);
    the energy and an observed order leave out what lies within
    ``exclude`` of a singular point, its ``kept`` samples also what lies
    within the coarse run's reach of one, or for a bulk quantity under an
    exact law of a point where Γ's final status changes in the two finest
    runs (:func:`~contactcore.estimate.caveats.beyond_reach`,
    :func:`~contactcore.estimate.caveats.near_status_changes`).  The
    ``PID:Q`` whose two finest runs differ only at round-off
    (:func:`~contactcore.estimate.caveats.roundoff_runs`) are found once
    here and passed (``roundoff``) to each line that names none of them:
    :func:`~contactcore.estimate.caveats.unsettled`, the exact tractions,
    steady tractions and enforced gaps, the pollution line, the
    above-the-range orders (:func:`three_run_caveats`), the unlike
    differences and unlike runs."""
    hs = tuple(float(r.discretisation["h"]) for r in results)
    levels = [sample_profiles(scene, r.fields, r.interface) for r in results]
    switching = None if scene.law.is_linear else switches([r.interface for r in results])
    facts = results[-1].facts  # what the method's options declared (contactcore.result.MethodFacts)
    exact_switch = switching and _exact(scene.law)
    changes = status_changes(scene, results[-2:]) if exact_switch else np.zeros((0, 2))
    smooth = far_from_changes(scene, results[-2:], levels[-1], hs[-2], changes) if exact_switch else None
    profiles = profile_estimates(levels, results[-1].degree, facts, coarse, scene, exclude, switching, h=hs[-2],
                                 smooth=smooth)
    roundoff = roundoff_runs(scene, levels)  # once: every line below that skips round-off runs takes it
    found = unsettled(scene, levels, results[-2].discretisation, facts, exclude, profiles, roundoff=roundoff)
    layer = curved_layer(scene, levels, facts, hs[-2], exclude)
    rough = cell_scale_orders(scene, levels, profiles, exclude, hs[-2],
                              far_tractions(smooth, results[-1].degree, facts, scene.law, switching))
    residue = residues(scene, levels, profiles, exclude)
    split = split_cell_share(scene, levels, profiles, exclude, results[-1].degree)
    nitsche = exact_tractions(scene, profiles, smooth, roundoff=roundoff)
    steady = steady_exact_tractions(scene, profiles, results[-1].degree, smooth, roundoff=roundoff)
    held = enforced_gaps(scene, profiles, gamma_statuses(scene, results[-2:], levels[-1]), roundoff=roundoff)
    observed = three_run_caveats(scene, profiles, smooth, roundoff=roundoff)
    # an exact law's traction has its own line (and order): not fast Γ's too (review20); nor an order above a
    # range (observed[1]), whose estimate takes the range's balanced order (review22); each with its order taken
    own = set(nitsche) | set(steady) | observed[1]
    fast = {k: order for k, order in fast_gamma(profiles, facts).items() if k not in own}
    held = [k for k in held if k not in fast]  # EFGM P1's own measured line first: one line an entry
    warnings = (order_warnings(profiles) + pollution_warning(scene, profiles, roundoff=roundoff, three=len(levels) > 2)
                + exact_traction_warning(nitsche, len(levels) > 2) + steady_exact_traction_warning(steady)
                + enforced_gap_warning(held)
                + fast_gamma_warning(fast, results[-1].method, results[-1].degree, len(levels) > 2)
                + unsettled_warnings(found, hs[-2], feature_size(scene), scene.user.units.length,
                                     thinnest_body(scene))
                + curved_layer_warning(layer, hs[-2], scene.user.units.length)
                + split_cell_share_warning(split)
                + cell_scale_warnings(rough, hs[-2:], list(fast), scene.user.units.length)
                + residue_warnings(residue, len(levels) > 2) + observed[0])
    status = None
    if scene.law.has_history or not scene.law.is_linear:
        status = status_change(scene, results[-2], results[-1], hs[-2:])
    split_moved = status_warning(status, scene.user.units.length)
    warnings += split_moved
    moved = {f"{pid}:{q}" for pid, qs in profiles.items() for q in qs} if split_moved else set()
    zz = (energy_estimate(scene, results[-1].fields, hs[-1], exclude,
                          recovered=facts.recovered_stress)
          if energy else None)
    kept = {p.id: {q: beyond_reach(scene, np.column_stack([p.columns["x"], p.columns["y"]]),
                                   results[-2].discretisation, facts, q, exclude, changes) for q in p.names[3:]}
            for p in levels[-1]}
    near = near_status_changes(levels[-1], changes, results[-2].discretisation, facts, kept) if exclude > 0 else {}
    warnings += status_change_warnings(near, scene.user.units.length)
    floor = quadrature_stress(profiles, levels[-1], kept, facts)
    warnings += quadrature_stress_warning(floor, results[-1].method, results[-1].degree)
    caveat = ((quadrature_energy(results[-1].method, results[-1].degree, facts, zz) + recovery_floor(zz)) if energy
              else [])
    named = ({k for v in found.values() for k in v} | set(layer) | set(rough) | set(residue) | set(nitsche)
             | set(steady) | set(held) | set(split)
             | set(fast) | set(floor) | moved | {k for k, (_, capped) in near.items() if capped} | observed[1]
             | ({ENERGY_KEY} if caveat else set())
             | {f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items() if order_mismatch(e)})
    unlike = unlike_differences(profiles, named, roundoff=roundoff)  # only where no other line names it: it claims a direction
    noise = unlike_runs(levels, kept, named | roundoff)  # two runs; one line an entry
    return Estimate(hs, profiles, zz, status,
                    warnings + unlike_differences_warning(unlike) + unlike_runs_warning(noise) + caveat, levels[-1],
                    named | set(unlike) | set(noise), kept)


def far_tractions(smooth: dict[str, np.ndarray] | None, degree: int, facts, law, switching: bool | None
                  ) -> dict[str, dict[str, tuple[np.ndarray, float]]] | None:
    """``{PID: {Q: (mask, high)}}``: each exact traction that takes the far
    order at ``smooth``'s samples (``mask``, far from Γ's status changes),
    with the highest order theory allows it there
    (:func:`~contactcore.estimate.orders.smooth_range`), for
    :func:`~contactcore.estimate.caveats.cell_scale_orders`; None where no
    sample is far."""
    if not smooth:
        return None
    ranges = {q: smooth_range(q, degree, facts, law, switching) for q in TRACTIONS}
    return {pid: {q: (mask, r[1]) for q, r in ranges.items() if r is not None} for pid, mask in smooth.items()}


def gamma_statuses(scene: Scene, results: list, profiles: list[ProfileData]) -> dict[str, list[np.ndarray]]:
    """``{profile id: [final status per sample, one array a run]}`` of
    each profile with a gap on Γ (:data:`~contactcore.estimate.orders.GAPS`),
    in each of ``results`` (:func:`contactcore.profiles.interface_status`),
    at the samples of ``profiles``; none for a law without exact
    enforcement (:func:`~contactcore.estimate.caveats.enforced_gaps`)."""
    if not _exact(scene.law):
        return {}
    out = {}
    for p in profiles:
        if set(GAPS) & set(p.names[3:]):
            xy = np.column_stack([p.columns["x"], p.columns["y"]])
            out[p.id] = [interface_status(scene, r.fields, xy, r.interface) for r in results]
    return out


def three_run_caveats(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]],
                      smooth: dict[str, np.ndarray] | None = None, *,
                      roundoff: Set[str] = frozenset()) -> tuple[list[str], set[str]]:
    """The warnings of a three-run estimate beyond its order's
    (:func:`~contactcore.estimate.caveats.observed_exact_tractions`, of
    the tractions with a sample near a status change, ``smooth`` the
    samples beyond: :func:`~contactcore.estimate.status.far_from_changes`;
    :func:`~contactcore.estimate.caveats.slow_halving`,
    :func:`~contactcore.estimate.caveats.above_range`, which skips the
    ``PID:Q`` in ``roundoff``) and the ``PID:Q`` they name; none for two
    runs."""
    traction = observed_exact_tractions(scene, profiles, smooth)
    slow = {k: v for k, v in slow_halving(profiles).items() if k not in traction}  # one line an entry (review20)
    above = {k: v for k, v in above_range(profiles, roundoff=roundoff).items() if k not in traction}
    return (observed_exact_traction_warning(traction) + slow_halving_warning(slow) + above_range_warning(above),
            set(traction) | set(slow) | set(above))


def estimate(scene: Scene, discretisation, h: float, levels: int = 2, *, exclude: float = 0.0, reuse=None,
             progress=None):
    """Solve ``scene`` with ``discretisation`` (:mod:`contactcore.discretisation`)
    at ``h``, ``h/2`` (and ``h/4`` with ``levels=3``) and return the finest
    :class:`~contactcore.result.Result` with its :class:`Estimate`; the
    energy estimate leaves out Gauss points within ``exclude`` of the
    singular points."""
    from ..discretisation import solve
    results = [solve(scene, discretisation, hk, reuse=reuse, progress=progress) for hk in levels_of(h, levels)]
    return results[-1], estimate_runs(scene, results, exclude)
