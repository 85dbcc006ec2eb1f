"""The files ``run`` writes of one method's run (:func:`verification.run.run`).

Contract: :func:`write_method` writes under ``out/<method>/`` the
profiles (with ``q_err`` columns where estimated), the field files (with
``--fields``), ``summary.json`` and, for a nonlinear law or a followed
path, ``increments.csv``/``interface.csv`` and the status plot; it adds
the run's profiles, path, estimate and status map to the caller's
collections under its label and returns its summary.
:func:`written_profiles` writes the profiles alone and returns the
summary (with ``"ranks"`` and ``"estimate"``);
:func:`estimate_record` is summary.json's ``"estimate"``.  Nothing here
solves.
"""
from __future__ import annotations

import logging
from pathlib import Path

from contactcore import Scene, sample_profiles
from contactcore import estimate as estimates
from contactcore.labels import run_label

from . import agreement, files, interface, methods
from .agreement import measured_against

log = logging.getLogger("verification")


def write_method(out: Path, scene: Scene, name: str, result, est, fields: bool, draw: bool, profiles: dict,
                 paths: dict, estimated: dict, gaps: dict, floors: dict | None = None,
                 statuses: dict | None = None) -> dict:
    """Method ``name``'s files (profiles with their estimated errors, their
    relative sizes floored by ``floors`` (:func:`estimate_record`),
    fields, summary with its distance from the exact answer if ``gaps``
    has it, the response along the path); its profiles, path and
    estimate join ``profiles``, ``paths`` and ``estimated`` under its
    label, its status map along Γ ``statuses``.  Returns its summary."""
    label = run_label(name, result.degree)
    summary, sampled = written_profiles(out / name, scene, result, est, floors)
    if label in gaps:
        summary["against_exact"] = gaps[label]
    if est is not None:
        estimated[label] = ({p.id: p for p in sampled}, {p.id: est.error_columns(p.id) for p in sampled},
                            est.unsettled)
    for prof in sampled:
        profiles.setdefault(prof.id, {})[label] = prof
    if statuses is not None:
        statuses[label] = agreement.status_map(scene, result)
    if fields:
        from . import fields_out  # meshio, only for field files
        on_mesh = methods.discretisation(name).field_output == "mesh"
        written = fields_out.write_fields(out / name / "fields", result, mesh=on_mesh)
        log.info("%s: wrote %d field files%s", name, len(written), "" if on_mesh else " (Γ only: no mesh)")
    files.write_json(out / name / "summary.json", summary)
    if not scene.law.is_linear or scene.follow_path:  # the response along the path, every step solved
        paths[label] = result.interface
        interface.write_history(out / name, scene, result.interface)
        if draw:
            interface.plot_status(out / "plots" / f"status_{name}.png", scene, label, result.interface)
    return summary


def written_profiles(folder: Path, scene: Scene, result, est, floors: dict | None = None) -> tuple[dict, list]:
    """``result``'s profiles of ``scene`` written under ``folder/profiles``,
    with their estimated errors if ``est`` (else None) has them; returns
    its summary (with ``"ranks"``, :func:`verification.files.ranks`, and
    ``"estimate"``, :func:`estimate_record` with ``floors``) and the
    profiles."""
    summary = {**result.summary(), "ranks": files.ranks()}
    sampled = est.sampled if est is not None else sample_profiles(scene, result.fields, result.interface)
    if est is not None:
        summary["estimate"] = estimate_record(scene, est, sampled, floors)
    for prof in sampled:
        files.write_profile_csv(folder / "profiles" / f"{prof.id}.csv", prof,
                                est.error_columns(prof.id) if est is not None else None)
    return summary, sampled


def estimate_record(scene, est, profiles: list, floors: dict | None = None) -> dict:
    """summary.json's ``"estimate"``: ``est.summary()``
    (:meth:`contactcore.estimate.Estimate.summary`: each quantity's max, RMS,
    kept RMS and order) with ``scale`` (the RMS of the quantity itself, an exact
    law's gaps floored as the agreement floors them), and ``kept_rms``,
    ``kept_scale`` the same over the samples the estimate keeps (away from
    singular points and beyond the coarse run's reach of them), the
    scale the size of the quantity's group (|t| for t_T)
    (:func:`~verification.agreement.estimated_shares`: the kept scale
    floored by ``floors`` and by round-off); ``"worst"``, the
    largest ``kept_rms / kept_scale`` and where
    (:func:`~verification.agreement.worst_estimate`, as ``efficiency``
    takes it): what summary.md shows."""
    record, by_id = est.summary(), {p.id: p for p in profiles}
    for (pid, q), (kept_rms, kept_scale) in agreement.estimated_shares(scene, by_id, est, floors).items():
        scale = estimates.rms(measured_against(scene, q, by_id[pid].columns[q]))
        record[pid][q].update(scale=scale, kept_rms=kept_rms, kept_scale=kept_scale)
    relative, where = agreement.worst_estimate(scene, by_id, est, floors)
    record["worst"] = {"relative": relative, "at": where}
    return record
