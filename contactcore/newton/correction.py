"""One Newton correction: ``J δu = −R`` on the free unknowns, solved with a
factorisation Newton kept where it can.

The tangent of a piecewise-linear law changes only when a point changes
status, so :class:`~contactcore.factorisations.KeptFactorisations` solves
a tangent that is one of the last FACTORISATIONS_KEPT factorised by that
factorisation, one that differs from one of theirs in a few points by a
low-rank correction of it, and factorises otherwise, picking from the maps
Newton is heading for (:meth:`_Correction._ahead`) which matrix to
factorise.  Where the law's tangent leaves a body free the solve takes a
tied or regularised tangent instead (:mod:`contactcore.newton.statuses`):
tied where Γ let a body go, regularised at once where a map's slipping
points leave it free or it is dominated by a map that proved singular, and
after the fact where a Coulomb map's factorisation fails.

Contract: a mixin of :class:`contactcore.newton.increments._Newton`; it
reads ``scene``, ``itf``, ``law``, ``state``, ``ranks``, ``_gamma`` and
``factorisations``, adds to ``report``, and writes ``_free_maps`` (a count of the step's
solves on maps that slip free) and ``_singular`` (the maps whose law
tangent proved singular).  :meth:`_Correction._solve` returns ``(δu, the
solve's report, the tangent solved with)``; every solve's report is added
to Newton's by :func:`_merge` (the caller's, or :meth:`_Correction.record`
for the slide's own solve).  Raises SolverError where even the regularised
solve fails.
"""
from __future__ import annotations

import numpy as np

from .. import health
from .. import tolerances as tol
from ..errors import SolverError
from ..result import SolverReport


def _merge(total: SolverReport, one: SolverReport) -> None:
    """Add the report of ``one`` solve to Newton's ``total``: the solves and
    factorisations counted, the worst backward error and condition, the
    warnings once each, the last solver and options."""
    total.solver = one.solver
    total.solves += 1
    total.factorisations += one.factorisations
    total.backward_error = np.nanmax([total.backward_error, one.backward_error])
    if one.condition is not None:
        total.condition = max(total.condition or 0.0, one.condition)
    total.warnings += [w for w in one.warnings if w not in total.warnings]
    total.options = one.options


class _Correction:
    """The linear solve of one Newton correction (module doc)."""

    def record(self, rep: SolverReport) -> None:
        """Count a solve made for this Newton outside its own steps (the
        slide's, :mod:`contactcore.slide`) in its report."""
        _merge(self.report, rep)

    def _ahead(self, u, du, status):
        """The maps Newton is heading for, farthest first: the law's
        tangents at ``u + e δu`` for e in AHEAD_STEPS (``δu`` the last
        step, decided from ``status`` within the band), each evaluated only
        when asked for, none that lets a body go or slip free (its tangent
        is singular).  A factorisation of one of them is corrected to the
        tangent Newton solves (:meth:`KeptFactorisations.solve`): it changes
        which matrix is factorised, not Newton's steps."""
        for e in tol.AHEAD_STEPS:
            response = self.itf.respond(self.law, u + e * du, self.state, status, self.ranks)
            gathered = self.ranks.gather(response.status)
            if health.lets_go(self.scene, *self._gamma, gathered) or (
                    response.secant is not None and health.slips_free(self.scene, *self._gamma, gathered)):
                continue
            yield response.tangent

    def _solve(self, tangent: np.ndarray, rhs: np.ndarray, scale: float, secant=None, status=None, ahead=()):
        """``J δu = rhs`` with the law's ``tangent`` at the points of the
        ``status`` map (:meth:`KeptFactorisations.solve`).  Also returns the tangent solved
        with: the law's, or where that is singular a Coulomb law's
        regularised one (:meth:`_regularised`; Newton is then not settled by
        it).  A map whose slipping points leave a body free to turn or slide
        (:func:`~contactcore.health.slips_free`, from the map and Γ's
        geometry, never from a factorisation's pivots, which round-off
        decides) is regularised at once, and so is one that no point sticks
        or closes on more than on one whose tangent proved singular
        (:meth:`_dominated`); one whose closed points leave a body free is
        tied (:meth:`_tied`)."""
        gathered, status_tangent = self.ranks.gather(status), tangent
        if health.lets_go(self.scene, *self._gamma, gathered):
            tangent = self._tied(tangent, status)
        free = secant is not None and health.slips_free(self.scene, *self._gamma, gathered)
        self._free_maps += free
        detour = free or (secant is not None and self._dominated(status))
        if detour:
            tangent = self._regularised(tangent, secant)
        ahead = () if detour or tangent is not status_tangent else ahead
        try:
            return (*self.factorisations.solve(tangent, rhs, scale, detour=detour, ahead=ahead), tangent)
        except SolverError:
            # a Coulomb law's slip tangent leaves a body held by friction
            # alone free to turn: one secant step there
            if secant is None or detour:
                raise
            regularised = self._regularised(tangent, secant)
            self._singular.append(status)
            return (*self.factorisations.solve(regularised, rhs, scale, detour=True), regularised)
