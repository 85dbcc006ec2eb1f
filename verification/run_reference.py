"""The reference ``run`` compares its methods with (``--reference``,
:func:`verification.run.run`).

Contract: :data:`DEFAULT_REFERENCE` is the (method, degree) compared with
unless the user names another; :func:`reference_label` is its curve label
(``fe P2``).  :func:`solve_reference` solves a reference that is not one
of the chosen runs at the answer's h, writes its profiles under
``out/reference/profiles`` and adds its profiles, summary row and status
map to the caller's collections; :func:`as_reference` names a reference's
failure as the reference's and says what to do instead
(``--reference none`` or another).
"""
from __future__ import annotations

import logging
from pathlib import Path

from contactcore import sample_profiles
from contactcore.errors import SolverError, SolverOptionError
from contactcore.labels import reference_text, run_label

from . import agreement, files, methods, pool
from .run_solve import prefixed

log = logging.getLogger("verification")


#: The run the Δ panels and the agreement table take as reference unless
#: ``--reference`` says otherwise: the most accurate of the methods at a
#: given h on the shipped scenes (docs/benchmarks.md), fe at degree 2.
DEFAULT_REFERENCE = ("fe", 2)


def reference_label(reference: tuple[str, int] | None) -> str | None:
    """The curve label of a ``(method, degree)`` reference
    (:func:`~contactcore.labels.run_label`: ``fe P2``)."""
    return None if reference is None else run_label(*reference)


def solve_reference(scene, reference, h, paper, petsc_options, out: Path, profiles: dict, summaries: list,
                    statuses: dict, flux: str | None = None) -> None:
    """Solve the ``reference`` run (method, degree) at ``h`` (the finest
    run's, where an estimate solved several) when it is not one of them,
    with the runs' ``petsc_options`` and fe's ``flux`` (where its method
    takes them), write its profiles under ``out/reference`` and add them to
    ``profiles`` and its summary to ``summaries``."""
    name, degree = reference
    log.info("scene %s: solving the %s", scene.name, reference_text(run_label(name, degree)))
    solve, on_comm = pool.solver(name) if pool.under_mpi_pool() else (methods.solver(name), {})
    result = as_reference(reference, "the methods asked for solved: compare them", solve, scene, h, degree=degree,
                          paper=paper, **methods.options_for(name, petsc_options=petsc_options, flux=flux), **on_comm)
    summaries.append({**result.summary(), "label": reference_text(run_label(name, degree))})
    statuses[reference_label(reference)] = agreement.status_map(scene, result)
    for prof in sample_profiles(scene, result.fields, result.interface):
        files.write_profile_csv(out / "reference" / "profiles" / f"{prof.id}.csv", prof)
        profiles.setdefault(prof.id, {})[reference_label(reference)] = prof


def as_reference(reference, what: str, call, *args, **kwargs):
    """``call(*args, **kwargs)`` for the ``reference`` (method, degree); its
    failure (not a refused option) named as the reference's
    (:func:`~verification.run_solve.prefixed`) and followed by ``what`` to do: ``what`` without a
    reference, ``--reference none``, or with another."""
    name, degree = reference
    try:
        return prefixed(reference_text(run_label(name, degree)), call, *args, **kwargs)
    except SolverOptionError:
        raise
    except SolverError as exc:
        hinted = SolverError(f"{exc}; {what} without a reference with --reference none, or with another, "
                             "--reference METHOD:DEGREE")
        hinted.details = getattr(exc, "details", "")
        raise hinted from None
