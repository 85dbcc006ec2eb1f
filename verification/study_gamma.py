"""What a study records of Γ at each point beyond its largest values: the
share of Γ's length that sticks, slips and is open, the largest tractions
away from Γ's singular ends, and (``study --estimate``) the estimated error
of Γ's profile from a second run at 2h.

Every figure here is one ``run`` reports too, computed by the same code:

- the shares are :meth:`contactcore.interface_path.InterfacePath.status_shares`
  of the last increment, as increments.csv's ``open_fraction`` and
  ``slip_fraction`` and summary.json's split against the exact law;
- the maxima away from the ends leave out Γ's points within
  :func:`verification.agreement.default_exclusion` of a singular point
  (:func:`contactcore.estimate.far_from_singular`), the samples the
  agreement and the estimates leave out;
- the estimate is :func:`contactcore.estimate.estimate_runs` of the runs at
  2h and h (the study's h the finer, the answer, as ``run --h 2h
  --estimate`` solves h and h/2) and :func:`verification.run_files.estimate_record`
  of it, on the point's scene with Γ's own profile (:func:`with_gamma`):
  the scene's profiles may not lie on a moved Γ, so the study drops them.
"""
from __future__ import annotations

import numpy as np

from contactcore import ContactError, InterfaceProfile
from contactcore import estimate as estimates
from contactcore.estimate import far_from_singular

from .agreement import default_exclusion
from .run_files import estimate_record

#: The profile the study samples on every point's Γ, wherever it lies.
GAMMA = InterfaceProfile("gamma", ("gN", "gT", "tN", "tT"), title="Γ")
#: The shares of Γ's length per reported status, in study.csv; ``partial``
#: only where a row has partial points (the unilateral law's partial answer).
SHARES = ["open_share", "stick_share", "slip_share"]
PARTIAL_SHARE = "partial_share"
#: The largest |t_N|, |t_T| over Γ's points away from its singular ends.
AWAY = ["max_tN_away", "max_tT_away"]
#: study.csv's columns of Γ's status and tractions away from its ends, in order.
COLUMNS = [*SHARES, "stick_length", *AWAY]
#: ``study --estimate``'s columns: the worst estimated relative RMS error of
#: Γ's profile quantities and which (summary.json's ``"worst"``), the
#: estimated RMS error of t_N and t_T away from Γ's ends (in the stress
#: unit), how many warnings the estimate gave, and at how many of Γ's
#: profile samples the status differs between 2h and h (of ``est_samples``).
ESTIMATE_COLUMNS = ["est_worst", "est_worst_at", "est_tN", "est_tT", "est_warnings", "status_changed", "est_samples"]


def with_gamma(scene):
    """``scene`` with Γ's own profile as its only one (:data:`GAMMA`)."""
    return scene.with_changes(profiles=(GAMMA,))


def exclusion(scene) -> float:
    """The distance from singular points inside which Γ's points are left
    out: the agreement's default on the point's scene with Γ's profile."""
    return default_exclusion(with_gamma(scene))


def gamma_columns(scene, result) -> dict:
    """The last increment's share of Γ's length in each status (``partial``
    only where it has partial points), the sticking length (in the scene's
    length unit) and the largest |t_N|, |t_T| over Γ's quadrature points at
    least :func:`exclusion` from every singular point (blank where none is)."""
    path = result.interface
    shares = path.status_shares()
    row = {f"{name}_share": share for name, share in shares.items()}
    row["stick_length"] = path.status_lengths()["stick"]
    kept = far_from_singular(scene, path.points, exclusion(scene))
    traction = np.abs(path.final.traction[kept])
    row.update(dict(zip(AWAY, (float(v) for v in traction.max(axis=0)))) if kept.any() else dict.fromkeys(AWAY, ""))
    return row


def estimate_columns(scene, coarse, fine) -> tuple[dict, list[str]]:
    """The :data:`ESTIMATE_COLUMNS` of a point's runs at 2h (``coarse``) and
    h (``fine``, the row's answer), Results of ``scene`` (the point's), and
    the estimate's warnings: :func:`contactcore.estimate.estimate_runs` and
    :func:`verification.run_files.estimate_record` on :func:`with_gamma`'s scene,
    as ``run --estimate`` makes them."""
    gamma = with_gamma(scene)
    est = estimates.estimate_runs(gamma, [coarse, fine], default_exclusion(gamma))
    record = estimate_record(gamma, est, est.sampled)
    status = est.status or {}
    return ({"est_worst": record["worst"]["relative"], "est_worst_at": record["worst"]["at"],
             "est_tN": record[GAMMA.id]["tN"]["kept_rms"], "est_tT": record[GAMMA.id]["tT"]["kept_rms"],
             "est_warnings": len(est.warnings), "status_changed": status.get("differ", ""),
             "est_samples": status.get("samples", "")}, list(est.warnings))


def estimated_row(solve, scene, h: float, fine, reuse, **options) -> tuple[dict, list[str], str]:
    """Solve ``scene`` at 2h with ``solve`` (``options`` as the row's run,
    ``reuse`` told to keep nothing: the coarse system is the point's
    alone) and estimate ``fine``, the run at ``h``: its
    :func:`estimate_columns`, warnings and a message ("" where it went
    through; the columns blank and the message why where the coarse run
    or the estimate could not be made)."""
    keep, reuse.keep = reuse.keep, False
    try:
        coarse = solve(scene, 2 * h, reuse=reuse, **options)
    except ContactError as exc:
        return dict.fromkeys(ESTIMATE_COLUMNS, ""), [], f"not estimated: the run at 2h = {2 * h:g} failed: {exc}"
    finally:
        reuse.keep = keep
    try:
        columns, warnings = estimate_columns(scene, coarse, fine)
    except ContactError as exc:
        return dict.fromkeys(ESTIMATE_COLUMNS, ""), [], f"not estimated: {exc}"
    return columns, warnings, ""
