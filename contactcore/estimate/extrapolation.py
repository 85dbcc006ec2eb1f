"""Richardson extrapolation of each profile quantity's error, from one method's runs at h, h/2 (and h/4).

**Richardson extrapolation** (Richardson 1911; Roache, *Verification and
Validation in Computational Science*, 1998, ch. 5).  One method at ``h``
and ``h/2`` samples every profile at the same points.  If a quantity's
sample converges as ``q_h = q + C h^p``, the finer run's error is

    e_{h/2} = q_{h/2} − q ≈ (q_{h/2} − q_h) / (2^p − 1),

estimated sample by sample; the profile's worst sample and RMS summarise
it.  With a third run at ``h/4`` the order is observed,

    p = log₂ (‖q_{h/2} − q_h‖ / ‖q_{h/4} − q_{h/2}‖)        (RMS over the samples),

over the samples away from singular points (a singularity's differences
shrink at its own rate: :func:`~contactcore.estimate.singular.far_from_singular`),
clipped to :data:`~contactcore.tolerances.ORDER_RANGE`, and the estimate
is the finest run's at :func:`three_run_order`: the two-run order below
where the observed one is at or above it (an observed order above theory
is the coarse run's error cancelling, not a faster rate: Roache's GCI,
ASME V&V 20), but for fe and xfem the observed one where it lies within
theory's range above it (the third run shows the range's upper end at
work), else the balanced order of the two (below theory the coarse
run may be pre-asymptotic as well as the rate slower).  The cosine of the
two differences (:func:`differences_cosine`) checks Richardson's premise
that the last is the first scaled down.

With two runs the order is one that theory allows the quantity
(:func:`~contactcore.estimate.orders.order_range`).  Where that is a
range ``[low, high]`` (a degree-1 stress that may superconverge at a
sample, a displacement that a singular point may pollute) the estimate
takes the order between whose Richardson factor ``1/(2^q − 1)`` is the
geometric mean of the two (:func:`balanced_order`), so its effectivity
lies within ``[(1/3)^½, 3^½]`` for ``p = 1`` (``[(3/7)^½, (7/3)^½]`` for
``p = 2``) whichever holds.  With two runs of fe or xfem, the part of
their difference at the scale of the coarse run's cells
(:func:`cell_scale_part`), their local error, takes the upper order ``p``
and only the smooth rest, where the pollution lies, the range
(:func:`profile_estimates`).

Where not to trust the estimate: :mod:`~contactcore.estimate.caveats`
and :mod:`~contactcore.estimate.status`.

numpy only; no method is imported.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import tolerances as tol
from ..profiles import ProfileData
from ..scene import Scene
from ..scaling import Sizes
from ..result import MethodFacts
from .orders import STRESSES, TRACTIONS, lower_end, order_range, polluted, smooth_range
from .singular import far_from_singular, pollution_order, unknown_ends


def rms(x: np.ndarray) -> float:
    """The root mean square of ``x`` (0 for none)."""
    return float(np.sqrt(np.mean(np.square(x)))) if len(x) else 0.0


def balanced_order(low: float, high: float, ratio: float = 2.0) -> float:
    """The order ``q`` whose Richardson factor is the geometric mean of
    those of ``low`` and ``high``: ``r^q − 1 = ((r^low − 1)(r^high − 1))^½``
    (``r`` the refinement ratio).  If the error converges at either, the
    estimate at ``q`` is off by at most ``((r^high − 1)/(r^low − 1))^½``,
    up or down; ``low`` itself where the two are equal."""
    return float(np.log1p(np.sqrt((ratio ** low - 1) * (ratio ** high - 1))) / np.log(ratio))


@dataclass(frozen=True)
class QuantityEstimate:
    """The finest run's estimated error of one quantity on one profile:
    ``error`` (per sample, ≥ 0, in the quantity's units), the ``order`` used,
    the orders ``theory`` allows
    (:func:`~contactcore.estimate.orders.order_range`; recorded as
    ``"orders"``, so that a user sees why a two-run order is, say, 2.205: the
    balanced order of ``[1.52, 3]``); ``measured``, the order three runs
    showed (recorded as ``"observed_order"``), of which ``order`` is the least
    with the two-run one, None where the order was not observed (two runs, or
    three at round-off); ``observed`` says which.  ``cell_scale``, where the
    difference of the runs was split (:func:`cell_scale_part`): the share
    (RMS) of its part at the scale of the coarse run's cells, estimated at the
    upper order of ``theory`` (recorded as ``"cell_scale"``).  ``far_order``,
    where an exact law's traction was estimated sample by sample: the order
    taken at its samples far from Γ's status changes, ``order`` at the rest
    (:func:`richardson`'s ``far``; recorded as ``"far_order"``).  ``alike``,
    where the order was observed: the cosine of the two differences over the
    samples it was observed on (:func:`differences_cosine`; recorded as
    ``"alike"``), 1 where the last is the first scaled down, as Richardson's
    ``C h^p`` makes it."""

    error: np.ndarray
    order: float
    theory: tuple[float, float]
    cell_scale: float | None = None
    measured: float | None = None
    far_order: float | None = None
    alike: float | None = None

    @property
    def observed(self) -> bool:
        """Whether the order was observed (three runs showed one: ``measured``)."""
        return self.measured is not None

    @property
    def max(self) -> float:
        return float(np.max(self.error)) if len(self.error) else 0.0

    @property
    def rms(self) -> float:
        return rms(self.error)

    def record(self, kept: np.ndarray | None = None) -> dict:
        """JSON-ready; with ``kept`` (a mask of the samples away from
        singular points) also ``kept_rms``, the RMS over those."""
        out = {"max": self.max, "rms": self.rms, "order": self.order, "observed": self.observed,
               "orders": [float(t) for t in self.theory]}
        if kept is not None:
            out["kept_rms"] = rms(self.error[kept])
        if self.cell_scale is not None:
            out["cell_scale"] = self.cell_scale
        if self.measured is not None:
            out["observed_order"] = self.measured
        if self.far_order is not None:
            out["far_order"] = self.far_order
        if self.alike is not None:
            out["alike"] = self.alike
        return out


def observed_order(coarse: np.ndarray, mid: np.ndarray, fine: np.ndarray, ratio: float = 2.0,
                   floor: float = 0.0) -> float | None:
    """``log_ratio(‖mid − coarse‖ / ‖fine − mid‖)`` (RMS), clipped to
    :data:`~contactcore.tolerances.ORDER_RANGE`; None when a difference is
    at round-off: of the quantity's scale
    (:data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF`), or at most
    ``floor``, round-off of the scene's own size of the quantity's kind
    (:func:`roundoff_floor`): a quantity exactly zero (σxy of a column
    under its weight, 2e-8 Pa against 1e6) has values of round-off
    itself, and its differences' ratio is noise, no order to see."""
    scale = max(np.max(np.abs(fine)), np.max(np.abs(mid)), 0.0) if len(fine) else 0.0
    d1, d2 = rms(mid - coarse), rms(fine - mid)
    small = max(tol.ESTIMATE_ROUNDOFF * scale, floor)
    if d2 <= small or d1 <= small:
        return None
    p = np.log(d1 / d2) / np.log(ratio)
    return float(np.clip(p, *tol.ORDER_RANGE))


def cosine(u: np.ndarray, v: np.ndarray) -> float | None:
    """``cos ∠(u, v) = u·v / (‖u‖ ‖v‖)`` over the samples; None where
    either is 0 there (nothing to compare)."""
    norms = float(np.linalg.norm(u) * np.linalg.norm(v))
    return float(u @ v / norms) if norms > 0 else None


def differences_cosine(coarse: np.ndarray, mid: np.ndarray, fine: np.ndarray) -> float:
    """``cos ∠(δ₁, δ₂) = δ₁·δ₂ / (‖δ₁‖ ‖δ₂‖)``, ``δ₁ = mid − coarse``,
    ``δ₂ = fine − mid`` over the samples (0 where either is 0).  Where the
    error is ``C(x) h^p`` sample by sample (Richardson's premise) ``δ₂ =
    2^{−p} δ₁`` and the cosine is 1; where each run's error has a pattern of
    its own (a degree-1 stress, constant per cell, read at points that fall
    elsewhere in their cells at each h; a term that dies between the runs)
    the two share none, and ``‖δ₂‖ = (e₁² + e₂²)^½`` at worst, which Richardson
    reads as ``(2^{2p} + 1)^½ / (2^p − 1)`` times the error (2.24 at p = 1,
    1.37 at p = 2): the cosine is 0 or below."""
    c = cosine(mid - coarse, fine - mid)
    return 0.0 if c is None else c


def cell_scale_part(values: np.ndarray, s: np.ndarray, groups: np.ndarray, width: float) -> np.ndarray:
    """The part of ``values`` (samples at arc length ``s``) at the scale of
    a run's cells: ``values`` minus their local linear regression with a
    Gaussian kernel of standard deviation ``width`` (the coarse run's h),
    fitted within each group of samples (``groups``: a label per sample,
    −1 for none: contiguous samples away from singular points, in one
    body); 0 outside the groups and in a group too short to fit a line
    through its neighbours (:data:`CELL_SCALE_MIN_SAMPLES`)."""
    out = np.zeros(len(values))
    for g in np.unique(groups[groups >= 0]):
        idx = np.flatnonzero(groups == g)
        if len(idx) < CELL_SCALE_MIN_SAMPLES:
            continue
        si, vi = s[idx], values[idx]
        w = np.exp(-0.5 * ((si[None, :] - si[:, None]) / width) ** 2)            # (target, sample)
        d = si[None, :] - si[:, None]
        s0, s1, s2 = w.sum(1), (w * d).sum(1), (w * d * d).sum(1)
        t0, t1 = (w * vi[None, :]).sum(1), (w * d * vi[None, :]).sum(1)
        det = s0 * s2 - s1 * s1
        smooth = np.where(det > 0, (s2 * t0 - s1 * t1) / np.where(det > 0, det, 1.0), t0 / s0)
        out[idx] = vi - smooth
    return out


#: The fewest samples in a group through which :func:`cell_scale_part`
#: fits its local lines (fewer: the whole difference is taken as smooth).
CELL_SCALE_MIN_SAMPLES = 5


def roundoff_floor(sizes: Sizes | None, quantity: str) -> float:
    """Round-off of a scene's own size (``sizes``: :class:`~contactcore.scaling.Sizes`) of ``quantity``'s kind:
    :data:`~contactcore.tolerances.NEGLIGIBLE_SHARE` of
    :class:`~contactcore.scaling.Sizes`' stress for a stress or a traction,
    of its displacement otherwise (0 without sizes): a difference of runs
    at most this shows no order (:func:`observed_order`)."""
    if sizes is None:
        return 0.0
    return tol.NEGLIGIBLE_SHARE * (sizes.stress if quantity in STRESSES + TRACTIONS else sizes.displacement)


def three_run_order(measured: float, order: float, theory: tuple[float, float], upper: bool = False) -> float:
    """The order a three-run estimate takes, from the ``measured`` one and
    the two-run ``order`` (:func:`balanced_order` of ``theory``'s range): the
    two-run order where the measured one is at or above it (above theory is
    the coarse run's error cancelling, not a faster rate: Roache's GCI, ASME
    V&V 20), but with ``upper`` the measured one where it lies between that
    order and theory's upper end (since 2026-11-29, est3_37: within a range
    theory allows, the third run shows the upper end at work, which two runs
    could only hedge; scene C's degree-2 C4 tractions, observed 2.54-2.93
    of [1.52, 3] with true rates 3.05-3.13, read 2.21-2.33 at the balanced
    2.20, 1.27-1.66 at the observed order; not for EFGM, whose differences
    do not see its quadrature's floor and shrink faster than its error:
    :func:`profile_estimates`); the measured one where it is clipped or further than
    :data:`~contactcore.tolerances.ORDER_MISMATCH` below theory's range (the
    larger estimate, which a warning calls not to be trusted:
    :func:`~contactcore.estimate.caveats.order_mismatch`); else, unwarned,
    the :func:`balanced_order` of the two.  Below theory the
    runs cannot tell a slower true rate from a coarse run still
    pre-asymptotic (grader8's fe P1 σxy on a twisted rod: observed 0.84
    against 1-2, taken as it was the estimate 2.49 times the error, at the
    two-run order 1.13); between the two, the estimate lies within
    ``((r^order − 1)/(r^measured − 1))^½`` of the error whichever holds: within
    [0.58, 1.73] for a measured order a whole one below (the most
    :data:`~contactcore.tolerances.ORDER_MISMATCH` leaves unwarned)."""
    if measured >= order:
        return measured if upper and measured <= theory[1] else order
    if measured <= tol.ORDER_RANGE[0] or measured < theory[0] - tol.ORDER_MISMATCH:
        return measured
    return balanced_order(measured, order)


def richardson(values: list[np.ndarray], theory: tuple[float, float], ratio: float = 2.0, coarse: bool = False,
               kept: np.ndarray | None = None, cells=None, floor: float = 0.0,
               low: bool = False, far: tuple[np.ndarray, float] | None = None,
               upper: bool = False) -> QuantityEstimate:
    """The estimate of one quantity from its samples at h, h/2 (and h/4),
    coarse to fine (module doc): the finest run's error, or with ``coarse``
    the coarsest run's (``(q_{h/2} − q_h) r^p / (r^p − 1)``, two levels only).
    The order is observed on the ``kept`` samples (all by default): near a
    singular point the differences shrink at the singularity's rate, not the
    smooth solution's, and would set it. Without a third run it is the
    :func:`balanced_order` of the orders ``theory`` allows
    (:func:`~contactcore.estimate.orders.order_range`); with one,
    :func:`three_run_order` of the observed order (``measured``, None where a
    difference is at most ``floor``: :func:`observed_order`) and that one
    (``upper`` as it takes it); with ``cells`` (a function
    that returns a difference's part at the scale of the coarse run's cells,
    :func:`cell_scale_part`), that part is estimated at the upper order
    ``theory[1]`` and the rest at the balanced one: for a range that pollution
    widened (:func:`profile_estimates`).  With ``low`` a two-run estimate
    takes ``theory[0]``, not the balanced order
    (:func:`~contactcore.estimate.orders.lower_end`); three runs observe it.
    With ``far``, ``(mask, order)``, a two-run estimate takes that order at
    the samples of the mask and its own at the rest, a three-run one
    :func:`three_run_order` of the observed order and that one there
    (review20: a third run had dropped it, and fe P2's t_N across a
    stick/slip change read 2.72 of its error against two runs' 1.70): an exact law's
    traction far from Γ's status changes
    (:func:`~contactcore.estimate.orders.smooth_range`,
    :func:`~contactcore.estimate.status.far_from_changes`),
    ``|q_{h/2} − q_h| / (r^{p_i} − 1)`` with ``p_i`` the sample's order."""
    kept = slice(None) if kept is None or not np.any(kept) else kept
    p = observed_order(*(v[kept] for v in values[-3:]), ratio=ratio, floor=floor) if len(values) >= 3 else None
    alike = differences_cosine(*(v[kept] for v in values[-3:])) if p is not None else None
    order = balanced_order(*theory, ratio=ratio)
    if p is not None:
        order = three_run_order(p, order, theory, upper)
    elif low:
        order = float(theory[0])
    factor = lambda o: ratio ** o / (ratio ** o - 1) if coarse else 1 / (ratio ** o - 1)  # noqa: E731
    signed = values[-1] - values[-2]
    if far is not None and np.any(far[0]):
        far_order = far[1] if p is None else three_run_order(p, far[1], (theory[0], far[1]))
        return QuantityEstimate(np.abs(signed) * np.where(far[0], factor(far_order), factor(order)), order, theory,
                                measured=p, far_order=float(far_order), alike=alike)
    if p is not None or cells is None or theory[0] >= theory[1]:
        return QuantityEstimate(np.abs(signed) * factor(order), order, theory, measured=p, alike=alike)
    fine = cells(signed)
    share = rms(fine[kept]) / rms(signed[kept]) if rms(signed[kept]) > 0 else 0.0
    error = np.abs((signed - fine) * factor(order) + fine * factor(theory[1]))
    return QuantityEstimate(error, order, theory, cell_scale=float(share))


def sample_groups(scene: Scene, xy: np.ndarray, kept: np.ndarray) -> np.ndarray:
    """A label per sample of a profile (−1 for none): runs of consecutive
    ``kept`` samples in one body (a line that crosses Γ is split there,
    where its quantities kink or jump; samples on Γ are one group)."""
    d = scene.interface.signed_distance(xy)
    side = np.where(np.abs(d) <= tol.GEOMETRY * scene.length_scale, 0, np.sign(d))
    if not np.any(side != 0):
        side = np.ones(len(xy))
    ok = kept & (side != 0)
    labels, current, prev = np.full(len(xy), -1), -1, None
    for i in range(len(xy)):
        if not ok[i]:
            prev = None
            continue
        if prev is None or side[i] != side[prev]:
            current += 1
        labels[i], prev = current, i
    return labels


def profile_estimates(levels: list[list[ProfileData]], degree: int, facts: MethodFacts = MethodFacts(),
                      coarse: bool = False, scene: Scene | None = None, exclude: float = 0.0,
                      switching: bool | None = None, h: float | None = None,
                      smooth: dict[str, np.ndarray] | None = None) -> dict[str, dict[str, QuantityEstimate]]:
    """``{profile id: {quantity: estimate}}`` from the profiles of each run,
    coarse to fine (each a list in the scene's order) of a method of
    ``degree`` and ``facts`` (its options'); an observed order from
    the samples at least ``exclude`` from the ``scene``'s singular points;
    ``switching`` as :func:`~contactcore.estimate.orders.theoretical_order`
    takes it; the ``scene``'s
    :func:`~contactcore.estimate.singular.pollution_order` widens the orders
    of its displacements, gaps and penalty tractions
    (:func:`~contactcore.estimate.orders.order_range`).  With the coarse run's
    ``h``, a two-run estimate of a range that pollution widened
    (:func:`~contactcore.estimate.orders.polluted`) takes the difference's
    part at the scale of that run's cells (:func:`cell_scale_part`, over
    :func:`sample_groups`) at the upper order: away from a singular point its
    pollution solves the homogeneous equations, smooth at that scale, so what
    varies cell by cell is the runs' local error, which converges at the
    method's order.  Where the scene's straight Γ ends under an exact law
    (:func:`~contactcore.estimate.singular.exact_interface_ends`), or
    under springs stiff at the scale of the coarse run's cells
    (:func:`~contactcore.estimate.singular.stiff_spring_ends`), a bulk
    displacement of such a range takes its lower end from two runs
    (:func:`~contactcore.estimate.orders.lower_end`).  ``smooth``,
    ``{profile id: mask}``, holds the samples far from Γ's status changes
    (:func:`~contactcore.estimate.status.far_from_changes`), at which an
    exact law's traction takes from two runs the balanced order of the
    range it has where Γ's status does not change
    (:func:`~contactcore.estimate.orders.smooth_range`: 2 at degree 2,
    1.45 of ``[1, 2]`` at degree 1), and 1 at the rest.  A three-run
    estimate of a mesh method (not ``facts.meshfree``) takes an order observed
    within theory's range above the balanced one (:func:`three_run_order`'s
    ``upper``)."""
    out, law = {}, scene.law if scene else None
    pollution, sizes = pollution_order(scene), Sizes.of(scene) if scene is not None else None
    ends_unknown = unknown_ends(scene, h)
    for profs in zip(*levels):
        pid, cols = profs[-1].id, profs[-1].columns
        xy = np.column_stack([cols["x"], cols["y"]])
        kept = far_from_singular(scene, xy, exclude) if scene else None
        cells = None
        if scene is not None and h is not None:
            s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(xy, axis=0), axis=1))])
            groups = sample_groups(scene, xy, kept)
            cells = lambda v, s=s, groups=groups: cell_scale_part(v, s, groups, h)  # noqa: E731
        out[pid] = {}
        for q in profs[-1].names[3:]:
            theory = order_range(q, degree, facts, law, switching, pollution)
            far_range = smooth_range(q, degree, facts, law, switching)
            far = (smooth[pid], balanced_order(*far_range)) if smooth and pid in smooth and far_range else None
            out[pid][q] = richardson([p.columns[q] for p in profs], theory, coarse=coarse, kept=kept,
                                     floor=roundoff_floor(sizes, q),
                                     cells=cells if polluted(q, degree, facts, law, switching, pollution) else None,
                                     low=lower_end(q, theory, ends_unknown), far=far, upper=not facts.meshfree)
    return out


