"""One solve of a study, and its outcome: accurate, warned, refused or wrong.

Every study (stiff and extreme sweeps, parameter studies, refinement ladders)
runs many solves; a solve that fails must not end the study, and an answer
must never be taken on trust.  :func:`attempt` runs one solve and catches the
project's own errors (bad input, singular systems, failed solves), and
:func:`classify` names the outcome from the error against the exact answer:

* ``refused``  — the method stopped with a clear message;
* ``warned``   — it answered, with a warning (e.g. ill-conditioning);
* ``accurate`` — it answered silently, within the bound, and its relative
  residual passes the health policy (:data:`~contactcore.tolerances.RESIDUAL_FAIL`);
* ``wrong``    — it answered silently, beyond the bound or with a residual the
  policy rejects: a bug, not a data point.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from contactcore import ContactError
from contactcore import tolerances as tol


#: The exit status of a command that wrote its results but could not
#: compute all it was asked for (:class:`Incomplete`): a study with a failed
#: point, a sweep with a *wrong* case.  Bad input and refused runs exit 2.
INCOMPLETE_STATUS = 1


class Incomplete(Exception):
    """Raised by a driver asked to be ``strict``, after it has written all
    its results, when part of what it was asked for failed (a study point
    that did not solve, a sweep case that was *wrong*): the command puts its
    folder in place, says this line and exits :data:`INCOMPLETE_STATUS`."""


@dataclass
class Attempt:
    """A solve that was tried: its result, or the message that refused it."""

    result: object | None
    message: str = ""

    @property
    def refused(self) -> bool:
        return self.result is None


def attempt(solve, *args, **kwargs) -> Attempt:
    """``solve(*args, **kwargs)``, with the project's errors caught."""
    try:
        return Attempt(solve(*args, **kwargs))
    except ContactError as exc:
        return Attempt(None, str(exc))


def accuracy_bound(nominal_error: float) -> float:
    """The largest error still called accurate (contactcore.tolerances)."""
    return max(tol.ACCURATE_FACTOR * nominal_error, tol.ACCURATE_FLOOR)


def classify(tried: Attempt, error: float, bound: float) -> str:
    """The outcome of a solve whose error against the exact answer is ``error``."""
    if tried.refused:
        return "refused"
    if tried.result.solver.warnings:
        return "warned"
    healthy = tried.result.solver.residual <= tol.RESIDUAL_FAIL
    return "accurate" if healthy and math.isfinite(error) and error <= bound else "wrong"


def health(tried: Attempt) -> dict:
    """DOFs, times and solver health of a solve, blanks when it was refused."""
    if tried.refused:
        return {"dofs": "", "total": "", "condition": "", "backward_error": "", "residual": ""}
    r = tried.result
    return {"dofs": r.dofs, "total": r.timings.total,
            "condition": "" if r.solver.condition is None else r.solver.condition,
            "backward_error": r.solver.backward_error, "residual": r.solver.residual}
