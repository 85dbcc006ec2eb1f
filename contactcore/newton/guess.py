"""A first status map for an exact law's first increment, from the same
scene solved at twice the spacing.

From rest, an exact law's Newton starts from every point sticking (the
all-stick solve) and its status search then moves the map a few points per
iteration at the edge of the contact zone: exact C-coulomb, xfem P2 at
h = 0.0125, 13 iterations and 5 factorisations in its first increment
where the penalty takes 4 and 2 (docs/newton.md, "A first map from a
coarser solve").  The same scene at 2h costs about a quarter of that,
and its converged map, carried to the fine Γ's points, is within a
correction of the fine answer's.

:func:`coarse_guess` solves the first increment of ``scene`` on a coarser
system and keeps, per coarse Γ point, its position, status and the law's
2 × 2 tangent over its ``γ`` (:class:`StatusGuess`).
:meth:`StatusGuess.at` gives each point of another interface the status
and tangent (times that interface's own ``γ``) of its nearest coarse
point.  The fine Newton's first correction is solved with that map's
tangent in place of the all-stick one (:meth:`_Iteration._correct`), and
every later decision is Newton's own from its own iterates, so the guess
shortens the path and decides nothing: the fine answer is the one Newton
reaches from the all-stick map, within Newton's tolerance (the tests and
figures of docs/newton.md).

Contract: :func:`coarse_guess` takes a dimensionless scene with an exact,
nonlinear law and a callable that builds the coarse
:class:`~contactcore.system.ContactSystem` (or raises
:class:`~contactcore.errors.ContactError`); it returns a
:class:`StatusGuess` (every rank's coarse points, on every rank), or None
where the coarse system cannot be built or its first step does not
converge.  It
prints nothing and closes the coarse system.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from ..collective import SERIAL, Collective
from ..errors import ContactError
from .increments import _Newton

#: The coarser solve's spacing over the fine one (None: no coarser solve;
#: the tests of the status search itself set it so).
COARSER = 2.0

#: A coarse first step of at most this many iterations (the all-stick
#: solve and the map it gives, settled) leaves the fine search as it was:
#: it would take as few from every point sticking, and a guessed start
#: changes which matrix is factorised first (the kept factorisation later
#: increments correct from) for nothing.
SEARCH_WORTH_GUESSING = 2


@dataclass(frozen=True)
class StatusGuess:
    """A converged status map of a coarser interface: its points (m, 2),
    their status codes (m,) and the law's tangent over each point's ``γ``
    (m, 2, 2), which an exact law's tangent is a multiple of; and what the
    coarser solve paid, its ``solves`` and ``factorisations`` (added to the
    fine run's report: :func:`~contactcore.newton.solve_increments`)."""

    points: np.ndarray
    status: np.ndarray
    shape: np.ndarray
    solves: int = 0
    factorisations: int = 0
    #: the coarse first step's iterations: a search of at most
    #: SEARCH_WORTH_GUESSING is not shortened by a guess (:meth:`worth`)
    iterations: int = 0

    def worth(self) -> bool:
        """Whether the coarse search was long enough that starting the fine
        one from its map can shorten it (more than SEARCH_WORTH_GUESSING
        iterations: the all-stick solve and one map after it are what any
        start costs)."""
        return self.iterations > SEARCH_WORTH_GUESSING

    def at(self, points: np.ndarray, gamma: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The tangent (times ``gamma``) and status of the nearest of the
        guess's points to each of ``points`` (ties to the first in the
        guess's order, as :class:`scipy.spatial.cKDTree` returns them)."""
        _, nearest = cKDTree(self.points).query(np.asarray(points, float).reshape(-1, 2))
        return self.shape[nearest] * np.asarray(gamma, float)[:, None, None], self.status[nearest].copy()


def coarse_guess(scene, build, ranks: Collective = SERIAL) -> StatusGuess | None:
    """The converged map of ``scene``'s first step on the system
    ``build()`` makes (module doc), or None (``build`` failing in any way
    means no guess, never a failed run): its first increment, or for a
    law without history on a path not followed the step to its last
    increment, which :func:`~contactcore.newton.solve_increments` takes
    first.  ``ranks``: the fine system's; a ``build`` that returns to
    this call failed on any rank means no guess on every rank, so none
    waits in the coarse Newton's reductions for a rank that left it (the
    local check of the coarse interface, say).  A rank failing inside one
    of the build's own collective steps (dolfinx's mesh distribution) is
    not covered: the others wait in that step, as in any dolfinx build."""
    try:
        system = build()
    except Exception:  # noqa: BLE001 - a coarser mesh or system the method cannot make: no guess, the search as before
        system = None
    if not ranks.all(system is not None):
        if system is not None:
            system.close()
        return None
    try:
        newton = _Newton(scene, system)
        if scene.law.has_history or scene.follow_path:
            newton.increment(1)
        else:  # the one step to the last increment that solve_increments takes first
            newton.step(float(scene.increments))
        itf, law = newton.itf, newton.law
        response = itf.respond(law, newton.u, law.initial_state(itf.size), newton.status, newton.ranks)
        gamma, ranks = np.asarray(itf.gamma, float), newton.ranks  # every rank's points, on every rank
        return StatusGuess(ranks.gather(np.asarray(itf.points, float).reshape(-1, 2)), ranks.gather(response.status),
                           ranks.gather(response.tangent / gamma[:, None, None]), newton.report.solves,
                           newton.report.factorisations, newton.report.iterations[0])
    except ContactError:
        return None
    finally:
        system.close()
