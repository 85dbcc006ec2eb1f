"""The fallbacks of one step: continuation in an exact law's
stabilisation, a start from a stiffer one, and a load taken to zero as a
limit.

A step is Newton's iterations from the committed state (or a given start,
``(u, statuses)``) to increment ``k`` (:meth:`_Continuation._solved`).
Where they fail under an exact law (Nitsche), two continuations follow,
each from the same start (Nitsche is consistent: the answer at another
stabilisation γ' differs from the one at γ by the stabilisation's small
effect only, so it starts Newton next to the answer with the right status
map):

* softer (:meth:`_Continuation._continued`): solved at γ/10, down to
  CONTINUATION_FLOOR of γ, each answer starting the next stiffer solve;
  a stiff γ narrows every stick window to ``2μp/γ``;
* stiffer (:meth:`_Continuation._from_stiffer`): solved at
  CONTINUATION_STEP·γ, whose Newton takes other maps than one that
  settles where no step leaves its map.

A step that takes every load to zero from a loaded state, under a law with
history, where a body is held by Γ alone (:meth:`_Continuation._approached`),
is solved as a limit: first to LOAD_APPROACH of the step short of zero
(a regular problem), then to zero from that answer and its map; at zero
every slip limit ``μp`` vanishes and round-off would choose where the body
stands.  A penalty law has no stabilisation to continue in; its failures
are raised as they are.

Contract: a mixin of :class:`contactcore.newton.increments._Newton`.  Each
method returns :meth:`~contactcore.newton.iteration._Iteration._iterate`'s
answer ``(factors, u, response, iterations, history)`` or raises
SolverError (SolverOptionError and FreeBody at once, never continued).
``_at`` puts Newton on a softened interface and restores ``itf``, fresh
kept factorisations and an empty ``_singular`` whatever the outcome
(:meth:`_Continuation._use`); nothing is committed here.
"""
from __future__ import annotations

import numpy as np

from .. import health
from .. import tolerances as tol
from ..errors import SolverError, SolverOptionError
from ..factorisations import KeptFactorisations
from ..laws import SLIP


class _Continuation:
    """A step, with an exact law's continuations and the load's approach to
    zero (module doc)."""

    def _solved(self, k: float, start=None):
        """The step to ``k`` (:meth:`_iterate`, from the committed state or
        from ``start``, ``(u, statuses)``).  An exact law whose step fails is
        continued in its stabilisation (:meth:`_continued`), else started
        from a stiffer one (:meth:`_from_stiffer`), each from ``start``
        too."""
        try:
            return self._iterate(k, start=start)
        except (SolverOptionError, health.FreeBody):
            raise
        except SolverError:
            if not self.itf.exact:  # a penalty law has no stabilisation to continue in
                raise
            try:
                return self._continued(k, 1.0, start)
            except SolverError as softer:
                try:
                    return self._from_stiffer(k, start)
                except SolverError:
                    raise softer from None

    def _approached(self, k: float):
        """The step to ``k`` (:meth:`_solved`).  One that takes every load
        to zero from a loaded state (prescribed displacements may stay),
        under a law with history, where a body is held by Γ alone, is solved
        as the limit of the loads along the step: first to LOAD_APPROACH of
        the step short of zero, then to zero from that answer and its
        status map.  At zero load every slip limit ``μp`` is zero, so every
        position of that body along its free motion (a block sliding on a
        straight Γ) solves the step, and Newton's singular solves chose one
        by round-off (scene A on Coulomb springs unloaded: the block 3.3e-9
        to 1.8e-4 m along by kernel and method, fe refused under Haswell).
        Short of zero the step is regular: its map holds the body by the one
        point whose stick window balances it, and is the same for every
        load below some share of the step (measured: 1e-2 to 1e-6), where
        the answer is linear in the load; from it one solve of that map at
        zero lands on the limit, the point's trial zero (at rest), every
        other point slipping on its history with zero traction.  Each of the
        two solves has the exact law's fallbacks (:meth:`_solved`), never the
        zero load itself from the committed state."""
        start = self.path.steps[-1].step if self.path.steps else 0.0
        if not (self.law.has_history and self._unloaded(k) and not self._unloaded(start) and self._held_by_gamma()):
            return self._solved(k)
        # each of the two solves with an exact law's fallbacks (_solved): a
        # fallback of the step to zero solved from the committed state would
        # meet the singular zero load itself, and round-off chose the answer
        # (exact unloaded.toml: the block 1.2e-10 or 5.1e-8 m along by
        # kernel, xfem P1 at h = 0.05; docs/newton.md, "A load back to zero")
        near = k + tol.LOAD_APPROACH * (start - k)
        _, u, response, approach, _ = self._solved(near)
        factors, u, response, iterations, history = self._solved(k, start=(u, response.status))
        return factors, u, response, approach + iterations, history

    def _unloaded(self, k: float) -> bool:
        """Whether no load acts at increment ``k`` (the equilibrium rows of
        ``b`` zero on every rank; prescribed displacements may not be)."""
        loads, supports = self.scene.factors(k)
        return self.ranks.all(not self.system.external(loads, supports)[self.balance].any())

    def _held_by_gamma(self) -> bool:
        """Whether a body is held by Γ alone: the map where every point is
        closed and slips leaves a rigid motion free (:func:`health.slips_free`)."""
        return health.slips_free(self.scene, *self._gamma, np.full(len(self._gamma[1]), SLIP, np.int8))

    def _from_stiffer(self, k: float, start=None):
        """The step to ``k`` started from its solution at CONTINUATION_STEP
        times the stabilisation, where the softer continuation failed.
        Newton from the committed state can settle where no step leaves
        its map (a body held by Γ alone whose closed points all slip, its
        secant step's merit flat).  The stiffer problem's Newton takes other
        maps; its answer differs from this one's by the stabilisation's
        small effect (Nitsche is consistent) and starts Newton next to it
        with its sticking points."""
        return self._at(k, 1.0, _started(self._at(k, tol.CONTINUATION_STEP, start)))

    def _continued(self, k: float, factor: float, start=None):
        """The step to ``k`` at ``factor`` times the stabilisation, started
        from its solution at a tenth of it (solved the same way, down to
        CONTINUATION_FLOOR): a stiff γ narrows every point's stick window to
        2μp/γ, and Newton from the committed state cannot find it, while the
        softer problem's answer differs from the stiffer one's by the
        stabilisation's small effect only (Nitsche is consistent), so it
        starts Newton next to the answer with the right status map."""
        softer = factor / tol.CONTINUATION_STEP
        try:
            answer = self._at(k, softer, start)
        except SolverError:
            if softer / tol.CONTINUATION_STEP < tol.CONTINUATION_FLOOR:
                raise
            answer = self._continued(k, softer, start)
        return self._at(k, factor, _started(answer))

    def _at(self, k: float, factor: float, start=None):
        """The step to ``k`` at ``factor`` times the stabilisation of the
        interface Newton is on, from the committed state or from ``start``
        (``(u, statuses)``); that interface is Newton's again afterwards,
        whatever the outcome."""
        target = self.itf
        self._use(target.softened(factor) if factor != 1.0 else target)
        try:
            return self._iterate(k, start=start)
        finally:
            self._use(target)

    def _use(self, interface) -> None:
        """Newton on ``interface`` from here on; the factorisations kept
        were of another matrix."""
        self.itf, self._singular = interface, []
        self.factorisations = KeptFactorisations(self.system, interface, self.free, self.ranks)


def _started(answer) -> tuple[np.ndarray, np.ndarray]:
    """An :meth:`~contactcore.newton.iteration._Iteration._iterate` answer
    as the start of another solve: its ``u`` and status map."""
    return answer[1], answer[2].status

