"""Runs against their estimated errors (no reference): each quantity's
estimated RMS error and its scale (:func:`estimated_shares`), the largest
of their shares (:func:`worst_estimate`), and whether two methods differ
by more than their estimates allow (:func:`within_estimates`)."""
from __future__ import annotations

import numpy as np

from contactcore import Scene
from contactcore.estimate.extrapolation import rms
from contactcore.estimate.runs import ERROR_SUFFIX

from .groups import scale_of
from .measures import first_largest
from .samples import kept_samples
from .sizes import size_floor, user_floors


def estimated_shares(scene: Scene, profiles: dict, est, floors: dict | None = None
                     ) -> dict[tuple[str, str], tuple[float, float]]:
    """``(profile id, quantity) -> (RMS of the estimated error, RMS of its
    scale)`` over the samples of ``profiles`` (id -> ProfileData, the runs
    ``est`` estimated, a :class:`contactcore.estimate.Estimate`) that the
    estimate keeps (``est.kept``: away from the singular points and beyond
    the coarse run's reach of them,
    :func:`contactcore.estimate.beyond_reach`): the scale is its group's size
    (:func:`scale_of`: |t| for t_N, t_T), as :func:`profile_agreements`
    measures a true error, floored by ``floors`` (quantity -> value in its
    unit, :func:`user_floors`) and by :func:`negligible` (of the run and of
    the scene's scale)."""
    shares, given = {}, user_floors(floors)
    for pid, qs in est.profiles.items():
        for q, e in qs.items():
            keep = est.kept[pid][q]
            scale = scale_of(scene, pid, q, profiles, size_floor(q, given, profiles, scene=scene))
            shares[pid, q] = rms(e.error[keep]), rms(scale[keep])
    return shares


def worst_estimate(scene: Scene, profiles: dict, est, floors: dict | None = None) -> tuple[float, str]:
    """The largest estimated relative RMS error over every profile and
    quantity of :func:`estimated_shares` (with ``floors``) and where
    (``"B5:tT"``; the first in the scene's order of those within
    :data:`WORST_TIE`); ``(0, "")`` when no quantity has a scale."""
    rows = [(error / scale, f"{pid}:{q}") for (pid, q), (error, scale)
            in estimated_shares(scene, profiles, est, floors).items() if scale > 0]
    return first_largest(rows, key=lambda row: row[0]) if rows else (0.0, "")


def within_estimates(scene: Scene, a: dict, err_a: dict, b: dict, err_b: dict, exclude: float,
                     floors: dict | None = None) -> list[tuple[str, str, float, bool]]:
    """Two methods' profiles (``{id: ProfileData}``) against their estimated
    errors (``{id: {quantity + "_err": per-sample error}}``,
    :meth:`contactcore.estimate.Estimate.error_columns`): per profile and
    quantity, ``RMS(q_a − q_b) / max(RMS(e_a + e_b), f)`` over the kept
    samples (RMS, not the worst sample: a pointwise estimate vanishes where
    the runs at h and h/2 cross), ``f`` the larger of the quantity's floor
    in ``floors`` (:func:`user_floors`) and :func:`negligible` of the runs
    and of the scene's scale (a difference at round-off is within any
    estimate), and whether it
    exceeds 1 (they differ by more than their estimated errors allow)."""
    rows, given = [], user_floors(floors)
    for pid, prof in a.items():
        keep = kept_samples(scene, prof, exclude)
        for q in prof.names[3:]:
            diff = (prof.columns[q] - b[pid].columns[q])[keep]
            bound = (err_a[pid][f"{q}{ERROR_SUFFIX}"] + err_b[pid][f"{q}{ERROR_SUFFIX}"])[keep]
            floor = max(size_floor(q, given, a, b, scene=scene), np.finfo(float).tiny)
            ratio = rms(diff) / max(rms(bound), floor)
            rows.append((pid, q, ratio, ratio > 1.0))
    return rows


def beyond_own_estimate(scene: Scene, a: dict, err_a: dict, ref: dict, exclude: float,
                        floors: dict | None = None, err_ref: dict | None = None) -> dict[tuple[str, str], float]:
    """``(profile id, quantity) -> RMS(q_a − q_ref) / max(RMS(e_a [+ e_ref]), f)``
    over the kept samples: one method's distance from a reference run
    (``ref``, ``{id: ProfileData}``) against its own estimated error
    (``err_a`` as :func:`within_estimates` takes it), plus the reference's
    where it is estimated too (``err_ref``: the reference is one of the
    runs), ``f`` its floor.  Where two methods differ beyond their
    estimates, the one whose figure here exceeds 1 is the likelier one
    whose estimate is too small; a reference without an estimate has an
    error of its own, so a figure near 1 decides nothing (newuser35: this
    rule named the right method in four of four cases, but only from
    summary.json's figures; grader31: with fe P2 estimated but left out of
    the sum, its own underestimate flagged xfem P2 and efgm P2 at 1.35 and
    1.13 where their estimates held, 1.18 and 1.51).  It is
    :func:`within_estimates` with the reference as the second run, its
    error ``err_ref`` or zero."""
    if err_ref is None:  # the reference's own error left out: zero beside each of a's
        err_ref = {pid: {k: np.zeros_like(v) for k, v in errs.items()} for pid, errs in err_a.items()}
    return {(pid, q): ratio for pid, q, ratio, _ in within_estimates(scene, a, err_a, ref, err_ref, exclude, floors)}
