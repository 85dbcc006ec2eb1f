"""Newton's iterations for one step: predict, evaluate, test, correct.

For the step to increment ``k`` (factors ``λ``), from the predicted state
(:meth:`_Iteration._predicted`) or a given start ``(u, statuses)``, each
iteration

1. evaluates the law's response at ``u`` (statuses decided within the
   band from the previous iterate's) and the residual
   ``R(u) = A u − b(λ) + Gᵀ W t`` (:mod:`contactcore.newton.residual`),
   unless the line search already did at that ``u``;
2. records ``‖R‖∞`` over the step's round-off scale
   ``max(forces, data, lift, R₀, least)`` (the history) and the
   equilibrium rows' residual over their forces (the figure the test
   judges), and refuses a residual that is not finite;
3. from the second iteration on, accepts the step if it has converged
   (:mod:`contactcore.newton.convergence`), held to RESIDUAL_FAIL against
   that scale (:func:`contactcore.health.check_residual`) and to a body
   held (:func:`contactcore.health.check_held`);
4. else corrects ``u`` (:meth:`_Iteration._correct`): a body that Γ's
   slipping points alone hold is slid to its balance
   (:func:`contactcore.slide.slide`), else ``J δu = −R`` is solved
   (:mod:`contactcore.newton.correction`) and, for a nonlinear law, damped
   by the line search (:mod:`contactcore.newton.line_search`), a secant
   step that does not descend replaced by a pinned one
   (:mod:`contactcore.newton.statuses`).

The predictor: along a straight load path, ``u₁ + c (u₁ − u₀)`` from the
last two converged states (Crisfield 1991, §9.3), else the committed state
with the points that slipped tried as sticking (Wriggers 2006, §5.2).

Contract: a mixin of :class:`contactcore.newton.increments._Newton`.
:meth:`_Iteration._iterate` returns ``(factors, u, response, iterations,
history)`` — the step's ``(loads, supports)`` factors, its converged
unknowns, the law's response there, the iterations taken and the residual
history — and commits nothing; it raises SolverError naming
:data:`contactcore.health.NOT_CONVERGED` and the judged figures when the
budget runs out, health.FreeBody for an answer that leaves a body free.
It writes the step's ``_secant`` and ``_free_maps`` and adds every solve
to ``report``.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from .. import health
from .. import tolerances as tol
from ..errors import SolverError
from ..laws import SLIP, STICK
from ..slide import slide
from .correction import _merge

#: Where the first status search of an exact, nonlinear law started
#: (``SolverReport.first_map``): a coarser solve's map, or every point
#: sticking and why (contactcore.newton.guess).
FROM_COARSER = "a coarser solve's map"
STICKING = "every point sticking: "


class _Walk:
    """One step's iterate and record between its iterations: the increment
    ``k``, its ``factors`` and load vector ``b``, the iterate ``u`` (and
    ``u0``, where the step began), the statuses the next response is
    decided from (``previous``), the lift, the residual ``history`` and
    the ``judged`` figures, the last correction ``du`` and the tangent it
    was solved with (None: none, or a partial step), the step's first
    nonzero residual (``first``), the statuses each point ``held``, the
    iteration budget, the line search's response and residual at ``u``
    (``evaluated``) and the iterations so far."""

    def __init__(self, k, factors, b, u, previous, lift):
        self.k, self.factors, self.b, self.u, self.previous, self.lift = k, factors, b, u, previous, lift
        self.history, self.tangent, self.first, self.du, self.u0 = [], None, 0.0, None, u.copy()
        # the figure the convergence test judges: the equilibrium rows' residual over their forces
        self.judged = []
        self.held, self.budget = None, tol.NEWTON_MAX_ITERATIONS  # the statuses each point held (_progress)
        self.evaluated = None  # the line search's response and residual at u
        self.guess = None  # a coarser solve's (tangent, statuses) for the first correction (_guessed)
        self.it = 0


class _Iteration:
    """Newton's iterations of one step (module doc)."""

    def _iterate(self, k: float, start=None):
        """Newton's iterations to increment ``k`` from the predicted state,
        or from ``start`` (``(u, statuses)``): the factors, ``u``, the law's
        response, the iterations and the residual history; SolverError with
        the history if they do not converge."""
        walk = self._begin(k, start)
        while walk.it < walk.budget:
            walk.it += 1
            response, R, scale, judged_forces = self._measure(walk)
            if walk.it > 1 and self._converged(R, judged_forces, walk.tangent, response, walk.du, walk.u - walk.u0):
                return self._accepted(walk, response)
            walk.held, progress = self._progress(walk.held, response.status)
            walk.budget = min(walk.budget + tol.NEWTON_PROGRESS_ITERATIONS * progress, tol.NEWTON_PROGRESS_CAP)
            self._correct(walk, R, response, scale)
        raise self._exhausted(walk)

    def _begin(self, k: float, start) -> _Walk:
        """The step to ``k``'s first iterate, prescribed values set, and its
        record; the step's secant and free-map count reset and its kept
        factorisations told a step begins."""
        loads, supports = self.scene.factors(k)
        b = self.system.external(loads, supports)
        self.itf.loaded(b)  # an affine flux's load part (contactcore.exact.NitscheInterface.loaded)
        u, previous = self._predicted(_flat((loads, supports))) if start is None else (start[0].copy(), start[1])
        u[self.system.fixed] = self.system.fixed_values(supports)
        walk = _Walk(k, (loads, supports), b, u, previous, self._lift(supports))
        if self._guess is not None and start is None and self._at_rest():
            if self._guess.worth():
                walk.guess = self._guess.at(self.itf.points, self.itf.gamma)
            else:
                self.first_map = STICKING + (f"the coarser search settled in {self._guess.iterations} "
                                             "iteration(s), too few to shorten this one")
        self._guess = None  # the first step's first try only: cut-backs and continuations go as before
        self._secant, self._free_maps = None, 0  # each step its own secant and its maps that slip free
        self.factorisations.begin_step()
        return walk

    def _at_rest(self) -> bool:
        """Whether Newton stands at rest: ``u = 0`` and the law's history
        untouched (the first step, where a coarser solve's map may start
        the status search)."""
        return self.ranks.all((self.state is None or not np.any(self.state)) and not self.u.any())

    def _measure(self, walk: _Walk):
        """The law's response and residual at ``walk.u`` (the line search's,
        where it evaluated them), their figures recorded in the walk's
        history and judged list: the response, ``R``, the step's round-off
        scale and the forces the convergence test judges against.
        SolverError where the residual is not finite."""
        if walk.evaluated is None:
            response = self.itf.respond(self.law, walk.u, self.state, walk.previous, self.ranks)
            walk.evaluated = response, self._residual(walk.u, walk.b, response)
        response, (R, forces, data) = walk.evaluated
        walk.previous = response.status
        norm = self.ranks.max(float(np.max(np.abs(R[self.free]), initial=0.0)))
        walk.first = walk.first or norm
        # the round-off scale of this step's solves: the forces, the data
        # (``lift``, the forces the prescribed displacements alone exert on
        # the free unknowns; EFGM's prescribed values) and the residual the
        # step began with (the first solve's right-hand side).  A
        # stress-free answer — a rigid shift, bodies pulled apart, a load
        # back to zero — has internal forces of round-off, which alone made
        # round-off look like a residual of order 1; and a load held at
        # zero has nothing but round-off, so RESIDUAL_FLOOR of the
        # scene's full loads, or the round-off of A u at u's size, is the
        # least scale (_least).
        least = self._least(walk.u)
        scale = max(forces, data, walk.lift, walk.first, least)
        walk.history.append(norm / scale if scale > 0 else norm)
        if not np.isfinite(norm):
            raise SolverError(f"the residual is not finite; residual history {_fmt(walk.history)}")
        # what _converged judges the balance against: the forces, at least
        # RESIDUAL_FLOOR of the full loads; not the round-off floor of u's
        # size, whose NEWTON_RTOL is the round-off of A u (PRODUCT_ROUNDOFF)
        judged_forces = max(forces, self._least_force)
        walk.judged.append(self._balance(R) / judged_forces if judged_forces > 0 else self._balance(R))
        return response, R, scale, judged_forces

    def _accepted(self, walk: _Walk, response):
        """The converged step's answer (:meth:`_iterate`), once its residual
        passes the round-off check and its statuses hold every body."""
        health.check_residual(walk.history[-1], "the settled Newton step")
        health.check_held(self.scene, *self._gamma, self.ranks.gather(response.status),
                          f"scene {self.scene.name}: increment {walk.k:g} of {self.scene.increments}")
        return walk.factors, walk.u, response, walk.it - 1, walk.history

    def _correct(self, walk: _Walk, R, response, scale: float) -> None:
        """The next iterate: a body held by Γ's slipping points alone slid
        (:func:`contactcore.slide.slide`, its response and residual kept),
        else ``u + δu`` with ``J δu = −R`` solved (:meth:`_solve`) and, for
        a nonlinear law, damped (:meth:`_damped`)."""
        u = walk.u
        slid = slide(self, u, walk.b, R, response, scale)  # a body held by Γ's slipping points alone, slid
        if slid is not None:
            walk.du, (walk.u, walk.evaluated), walk.tangent = slid[0] - u, slid, None
            return
        solved = self._guessed(walk, R, response, scale) if walk.guess is not None else None
        if solved is None:
            ahead = () if walk.du is None else self._ahead(u, walk.du, response.status)
            du, rep, tangent = self._solve(response.tangent, -R, scale, response.secant, response.status, ahead)
        else:
            response, (du, rep, tangent) = solved
        _merge(self.report, rep)
        if not self.law.is_linear:  # a linear law is solved in one step
            du, tangent, walk.evaluated = self._damped(walk, R, response, scale, du, tangent)
        else:
            walk.evaluated = None
        walk.du, walk.tangent, walk.u = du, tangent, u + du

    def _guessed(self, walk: _Walk, R, response, scale: float):
        """The step's first correction solved with a coarser solve's map
        (``walk.guess``, :mod:`contactcore.newton.guess`) in place of the
        all-stick one: ``(response, (δu, report, tangent))``, ``response``
        the one at ``u`` with that map's tangent and statuses, from which
        the line search decides the next map within the band.  Taken once;
        None (the all-stick correction is solved, :meth:`_correct`) where
        the map lets a body go or its slipping points leave one free (its
        tangent is singular, the all-stick one is not) or its solve fails."""
        tangent, status = walk.guess
        walk.guess = None
        gathered = self.ranks.gather(status)
        if health.lets_go(self.scene, *self._gamma, gathered) or health.slips_free(self.scene, *self._gamma, gathered):
            self.first_map = STICKING + "the coarser map lets a body go"
            return None
        guessed = dataclasses.replace(response, tangent=tangent, status=status, secant=None)
        try:
            solved = guessed, self._solve(tangent, -R, scale, status=status)
        except SolverError:
            self.first_map = STICKING + "the coarser map's solve failed"
            return None
        self.first_map = FROM_COARSER
        return solved

    def _damped(self, walk: _Walk, R, response, scale: float, du, tangent):
        """The correction ``du`` (solved with ``tangent``) scaled by the
        line search's ``α``, the tangent it settles (None for a partial
        step) and the response and residual the search evaluated there; a
        secant step that no halving lets descend is replaced by the pinned
        map's (:meth:`_pinned`)."""
        u, b = walk.u, walk.b
        # a regularised step on any rank is one on every rank (a rank
        # whose points do not slip holds the law's own tangent)
        secant = not self.ranks.all(np.array_equal(tangent, response.tangent))
        alpha, evaluated = self._line_search(u, du, b, R, response.status, secant, tangent)
        if secant and evaluated is None and self._slipping(response):  # the secant step is no descent
            # the pinned map's tangent with the slipping map's residual: its
            # step solves no map's linear problem, so it settles nothing
            du, rep, _ = self._solve(self._pinned(response), -R, scale, status=response.status)
            _merge(self.report, rep)
            alpha, evaluated, tangent = *self._line_search(u, du, b, R, response.status), None
        return alpha * du, (tangent if alpha == 1.0 else None), evaluated  # a partial step settles nothing

    def _exhausted(self, walk: _Walk) -> SolverError:
        """The error of a step whose budget ran out: the iterations, how many
        stood on maps that slip free, and the judged figures against
        NEWTON_RTOL."""
        free = (f" ({self._free_maps} of them on maps whose slipping points alone held a body that nothing else "
                "holds, free to turn or slide until a point sticks)" if self._free_maps else "")
        return SolverError(f"{health.NOT_CONVERGED} in {walk.it} iterations{free}; relative residual of the "
                           f"equilibrium rows over their forces {_fmt(walk.judged)}, converged at <= "
                           f"{tol.NEWTON_RTOL:.0e}")

    def _predicted(self, factors: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The step's first iterate and the statuses it starts from.  Along
        a straight load path (the factors' step a positive multiple ``c`` of
        the last converged one) the secant predictor ``u₁ + c (u₁ − u₀)``
        from the last two converged states, with their statuses (Crisfield,
        *Non-linear finite element analysis of solids and structures*, 1991,
        §9.3): a linear response — proportional loading of every law here
        while no point changes status — is then predicted exactly.
        Elsewhere (the first step, a kink or reversal of the path) the
        committed state and the elastic predictor: a point that slipped is
        tried as sticking (its margin is ~0 at the converged state, so the
        band keeps this choice), the return map of Wriggers (2006, §5.2)."""
        elastic = (self.u.copy(), np.where(self.status == SLIP, STICK, self.status))
        if len(self._converged_at) < 2:
            return elastic
        (f0, u0), (f1, u1) = self._converged_at
        last, step = f1 - f0, factors - f1
        c = float(step @ last) / float(last @ last) if last.any() else 0.0
        if c <= 0 or np.linalg.norm(step - c * last) > tol.PATH_STRAIGHT * np.linalg.norm(step):
            return elastic
        return u1 + c * (u1 - u0), self.status


def _flat(factors) -> np.ndarray:
    """The loads' and supports' factors of a step as one vector."""
    return np.array([*factors[0], *factors[1]], float)


def _fmt(values) -> str:
    """Figures as a short list for a message: ``[1.00e+00, 2.50e-09]``."""
    return "[" + ", ".join(f"{v:.2e}" for v in values) + "]"
