"""How ``run`` solves one method at one h or along an estimate's ladder,
and how a failed solve is named (:func:`verification.run.run`).

Contract: :func:`solve_estimated` returns the finest run and its
:class:`~contactcore.estimate.Estimate` (None without levels), logging
each run of the ladder; :func:`progress` gives the per-increment log
callback a solver takes.  :func:`prefixed` and :func:`named` call a solve
unchanged and, where it raises a
:class:`~contactcore.errors.SolverError`, raise it again with what failed
first (its ``details`` kept); a refused option
(:class:`~contactcore.errors.SolverOptionError`, the input's fault) passes
through untouched.  Nothing here writes a file.
"""
from __future__ import annotations

import logging

from contactcore import estimate as estimates
from contactcore.errors import SolverError, SolverOptionError

from .agreement import default_exclusion

log = logging.getLogger("verification")


def solve_estimated(solve, scene, h, levels: int | None, **options):
    """The run at ``h`` (or with ``levels``, runs at h, h/2 (, h/4), the
    finest returned) and its :class:`~contactcore.estimate.Estimate` (None
    without ``levels``)."""
    if not levels:
        return solve(scene, h, **options), None
    results, ladder = [], estimates.levels_of(h, levels)
    for k, hk in enumerate(ladder, 1):
        log.info("the estimate's run %d of %d, at h = %g%s", k, len(ladder), hk, " (the answer)" * (k == len(ladder)))
        results.append(prefixed(f"the estimate's run at h = {hk:g}", solve, scene, hk, **options))
    return results[-1], estimates.estimate_runs(scene, results, default_exclusion(scene))


def progress(name: str):
    """A method's progress along the load path, one log line per increment."""
    def report(n: int, total: int, step) -> None:
        counts = ", ".join(f"{v} {k}" for k, v in step.counts().items())
        log.info("%s: increment %d/%d: %d Newton iteration%s (%s)", name, n, total, step.iterations,
                 "" if step.iterations == 1 else "s", counts)
    return report


def named(chosen: list[str], name: str, solve, *args):
    """``solve(*args)``; where several methods are ``chosen``, a solve that
    fails names the method ``name`` first (:func:`prefixed`): which of
    them failed is the first thing to know."""
    return prefixed(name, solve, *args) if len(chosen) > 1 else solve(*args)


def prefixed(what: str, solve, *args, **kwargs):
    """``solve(*args, **kwargs)``; a solve that fails (not a refused
    option, the input's fault) is raised again with ``what`` first: the
    method, the reference, or the estimate's run that failed."""
    try:
        return solve(*args, **kwargs)
    except SolverOptionError:
        raise
    except SolverError as exc:
        named = SolverError(f"{what}: {exc}")
        named.details = getattr(exc, "details", "")
        raise named from None
