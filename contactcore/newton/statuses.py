"""The tangents Newton solves with where the law's own leaves a body free.

A status map's tangent ``J = A + Gᵀ W (∂t/∂g) G`` is singular where Γ's
points leave a body that nothing else holds free: every closed point open
(Γ let go of it), or every closed point slipping (a rigid turn or slide
with no normal jump has no ``∂t_T/∂g_T`` to hold it).  Newton reads this
from the status map and Γ's geometry (:func:`contactcore.health.lets_go`,
:func:`contactcore.health.slips_free`), never from a factorisation's
pivots, and solves instead with one of these tangents:

* **tied** (:meth:`_Statuses._tied`): each open point tied by
  FREE_BODY_TIE times its closed stiffness, in the tangent only (the
  residual, so the answer, stays the law's);
* **regularised** (:meth:`_Statuses._regularised`): the slipping points'
  secant stiffness ``|t_T|/|y_T − s|`` (Kačanov's iteration with the
  step's first secant), :func:`contactcore.laws.secant_tangent`;
* **pinned** (:meth:`_Statuses._pinned`): one slipping point made to stick,
  the one nearest its stick window, ties broken by coordinates (a
  primal-dual active-set guess), for a secant step that does not descend.

A map is known singular without a solve where it is **dominated**
(:meth:`_Statuses._dominated`) by one whose tangent proved singular: no
point sticks or is closed where that one's did not.  ``_CONSTRAINT`` ranks
the statuses by how much they hold a point, open < slip < stick.

Contract: a mixin of :class:`contactcore.newton.increments._Newton`; it
reads ``itf``, ``law``, ``ranks``, ``_gamma`` and ``_singular``; only
``_regularised`` writes, the step's ``_secant``.  Each returns a new
tangent array (the argument is never changed) or a decision taken alike on
every rank.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol
from ..laws import OPEN, SLIP, STICK, secant_tangent


#: How much a status holds a point (open < slip < stick), by status code.
_CONSTRAINT = np.zeros(max(SLIP, STICK, OPEN) + 1, np.int8)
_CONSTRAINT[[OPEN, SLIP, STICK]] = [0, 1, 2]


class _Statuses:
    """Tied, regularised and pinned tangents, and dominated maps (module doc)."""

    def _slipping(self, response) -> bool:
        """Whether a Coulomb point slips at ``response``, on any rank."""
        return response.secant is not None and self.ranks.max(float(np.any(response.status == SLIP))) > 0

    def _pinned(self, response) -> np.ndarray:
        """The law's tangent at ``response`` with one slipping point made to
        stick (``∂t/∂g = diag(k, k)``, ``k`` its ``γ`` or the law's
        ``k_T``), for a map whose secant step does not decrease the merit:
        the step then solves the neighbouring map where that point sticks,
        which holds the body's rotation by its tie (a primal-dual
        active-set guess, Hintermüller, Ito & Kunisch, SIAM J. Optim. 2002).
        The point is the one nearest its stick window (the largest
        ``secant/k = μp/|t*|``); of points within DECISION_BAND of that the
        first by their coordinates (x, then y), so that neither round-off
        nor numbering chooses between mirror points of a symmetric scene.
        Its step is solved from the slipping map's residual, so it solves
        no map's linear problem and settles nothing (:meth:`_settles`)."""
        k = self.itf.gamma if self.itf.exact else np.full(self.itf.size, self.law.kT)
        ratio = self.ranks.gather(np.where(response.status == SLIP, response.secant / k, -1.0))
        points = self._gamma[0]
        near = points[ratio >= np.max(ratio, initial=-1.0) - tol.DECISION_BAND]
        pin = np.all(self.itf.points == near[np.lexsort(near.T[::-1])[0]], axis=1)
        out = np.array(response.tangent, float, copy=True)
        out[pin] = k[pin, None, None] * np.eye(2)
        return out

    def _tied(self, tangent: np.ndarray, status: np.ndarray) -> np.ndarray:
        """The law's tangent with each open point tied by FREE_BODY_TIE
        times its closed stiffness (the springs ``k_N``, ``k_T``; Nitsche's
        ``γ``), in the tangent only: where Γ let go of a body that nothing
        else holds (:func:`~contactcore.health.lets_go`) its rigid motion
        follows the body it faces instead of round-off, and the residual,
        so the answer, is the law's.  An answer that still leaves it free is
        refused (:func:`~contactcore.health.check_held`)."""
        springs = self.law.at(self.itf.gamma) if self.itf.exact else self.law
        out, gone = np.array(tangent, float, copy=True), status == OPEN
        for c, k in enumerate((springs.kN, springs.kT)):
            out[gone, c, c] = tol.FREE_BODY_TIE * np.broadcast_to(k, gone.shape)[gone]
        return out

    def _regularised(self, tangent: np.ndarray, secant: np.ndarray):
        """The Coulomb law's tangent regularised by the slipping points'
        ``secant`` stiffness (:func:`contactcore.laws.secant_tangent`, exact
        or penalty), each point's as the step first gave it (a
        point that starts slipping later, its own): the secant steps of a
        step then share one matrix but for the points whose status changed,
        solved by a kept factorisation or a correction of it.  Kačanov's
        iteration with its first secant: each step still turns the body
        towards the stick window, which the line search's doubling reaches."""
        if self._secant is not None:
            secant = np.where(secant > 0, np.where(self._secant > 0, self._secant, secant), 0.0)
        self._secant = secant
        return secant_tangent(tangent, secant)

    def _dominated(self, status) -> bool:
        """Whether no point of the ``status`` map sticks where a map whose
        tangent proved singular did not, and none is closed where it was
        open.  That tangent's null mode is a body held by Γ alone turning
        (or sliding) with no normal jump at its closed points and no jump at
        its sticking ones (:func:`contactcore.laws.secant_tangent`):
        every such map leaves it free too, so its tangent is singular
        without a factorisation to tell."""
        rank = _CONSTRAINT[status]
        return any(self.ranks.all(bool(np.all(rank <= _CONSTRAINT[s]))) for s in self._singular)

