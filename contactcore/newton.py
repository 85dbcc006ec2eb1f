"""Load increments and Newton's method for any interface law, any method.

Every method reduces its discretisation to the same algebraic object, a
:class:`~contactcore.system.ContactSystem`: a bulk operator ``A`` (elasticity, and for EFGM its
constraint rows), load vectors ``b(λ)``, prescribed unknowns, and the
interface operator ``G`` that maps the unknowns to the jumps
``g = [g_N, g_T]`` at the interface quadrature points.  The residual and the
consistent tangent of the law are then method-independent:

    R(u) = A u − b(λ) + Gᵀ W t(G u, s),      J = A + Gᵀ W (∂t/∂g) G,

``W`` the quadrature weights and ``s`` the law's history at the points.  For
each increment (:meth:`Scene.factors`) the prescribed values are set, then
Newton iterates ``J δu = −R`` on the free unknowns until
``‖R‖∞ <= NEWTON_RTOL·F`` (:mod:`contactcore.tolerances`; ``F`` the larger
of the loads and the internal forces), or until the law's tangent is the
one the last solve used: a piecewise-linear law (every law here) is then
solved exactly up to that solve's round-off, which stiff springs
(k ≥ 1e8 E/h) raise above NEWTON_RTOL, or until the last correction
moved no digit of what the step moved ``u`` by (STEP_ROUNDOFF).  Either way
the step is accepted only if ``‖R‖∞ <= RESIDUAL_FAIL·max(F, L, R₀)``, ``L``
the forces of the prescribed displacements alone, ``R₀`` the residual the
step began with (the round-off scale of a stress-free answer), and every
solve passed the same test (:mod:`contactcore.health`): a settled status whose solve was
singular (a body sliding away at the slip limit) is a failure, not a
converged runaway.  Before any solve the springs must leave the bulk
digits in their rows (:func:`contactcore.health.check_springs`) and the
supports, pins and springs must hold every rigid-body mode
(:func:`contactcore.health.check_restraint`).  ``J`` is symmetric but
while Coulomb points slip: every method factorises it by MUMPS's LDLᵀ while
it is symmetric, by LU otherwise (:class:`contactcore.linear_solver.Tangent`).
The tangent of a piecewise-linear law changes only when a point changes
status: a solve whose tangent is one of the last factorised
(:data:`~contactcore.tolerances.FACTORISATIONS_KEPT`) reuses that
factorisation, often for whole load paths, one whose tangent differs from
one of theirs in a few points is solved by a low-rank correction of it
(:mod:`contactcore.factorisations`, one process), and the system refills the matrices it
allocated once.  Every status decision is taken so that round-off cannot move it
(:class:`~contactcore.laws.Decision`): a point whose margin (its gap, or
``μp − |t*|``) lies within DECISION_BAND of the margin's Γ-wide scale keeps
the status of the previous iterate, and a step starts from the elastic
predictor (points that slipped are tried as sticking).  Every correction of
a nonlinear law is damped by an Armijo line search on ``‖R‖₂``
(:meth:`_Newton._line_search`), which a cycle between status maps cannot
survive.
A failed increment (no convergence, a singular tangent) is halved up to
``MAX_CUTBACKS`` times; the state is committed only at converged steps.  A
law without history (linear, unilateral) is path-independent: unless the
scene asks for the response along the path (``follow_path``), Newton goes
to the last increment's factors in one step (a linear law in one solve),
and follows the increments only if that step fails; the report records the
steps solved.
"""
from __future__ import annotations

import numpy as np

from . import health
from . import tolerances as tol
from .errors import SolverError, SolverOptionError
from .exact import enforced
from .factorisations import KeptFactorisations
from .interface_path import Increment, InterfacePath, canonical_order
from .laws import OPEN, SLIP, STICK, secant_tangent
from .result import SolverReport
from .slide import slide
from .system import ContactSystem


def _merge(total: SolverReport, one: SolverReport) -> None:
    total.solver = one.solver
    total.solves += 1
    total.factorisations += one.factorisations
    total.backward_error = np.nanmax([total.backward_error, one.backward_error])
    if one.condition is not None:
        total.condition = max(total.condition or 0.0, one.condition)
    total.warnings += [w for w in one.warnings if w not in total.warnings]
    total.options = one.options


#: How much a status holds a point (open < slip < stick), by status code.
_CONSTRAINT = np.zeros(max(SLIP, STICK, OPEN) + 1, np.int8)
_CONSTRAINT[[OPEN, SLIP, STICK]] = [0, 1, 2]


class _Newton:
    """Newton on one system and law, state committed only on convergence."""

    def __init__(self, scene, system: ContactSystem):
        self.scene, self.system, self.law = scene, system, scene.law
        self.itf = enforced(scene.law, system.interface)
        self.free = np.setdiff1d(np.arange(system.size), system.fixed)
        # rows that prescribe displacements (EFGM's multipliers, scaled by E:
        # s (C u − ū)) rather than balance forces: data, like the lift
        self.constraint = np.zeros(system.size, bool)
        self.constraint[np.asarray(system.constraint_rows, int)] = True
        self.balance = self.free[~self.constraint[self.free]]
        # the least force scale of any step: RESIDUAL_FLOOR of the scene's
        # loads at full value on the equilibrium rows
        full = system.external(tuple(1.0 for _ in scene.loads), tuple(1.0 for _ in scene.supports))
        self._least_force = tol.RESIDUAL_FLOOR * system.collective.max(
            float(np.max(np.abs(full[self.balance]), initial=0.0)))
        self.u = np.zeros(system.size)
        self.state = self.law.initial_state(self.itf.size)
        self.status = np.full(self.itf.size, STICK, np.int8)  # an unloaded interface is closed and sticks
        # the converged (factors, u) the predictor extrapolates from, the last
        # two; the unloaded state is one where every factor is zero (u = 0 solves it)
        unloaded = _flat(scene.factors(0))
        self._converged_at = [(unloaded, self.u.copy())] if not unloaded.any() else []
        self.report = SolverReport(solver="", solves=0, iterations=[])
        self.path = InterfacePath(self.itf.points, self.itf.weights, pieces=self.itf.pieces)
        self.ranks = system.collective  # every decision is taken on all ranks alike
        self.factorisations = KeptFactorisations(system, self.itf, self.free, self.ranks)
        self._gamma = self.ranks.gather(self.itf.points), self.ranks.gather(self.itf.weights)  # lets_go, check_held
        self._singular = []  # status maps whose law tangent proved singular
        self._secant = None  # the step's secant stiffnesses of its slipping points (_regularised)
        self._free_maps = 0  # the step's solves on maps that health.slips_free

    def _residual(self, u, b, response) -> tuple[np.ndarray, float, float]:
        """The residual, the forces its equilibrium rows are judged against
        (the largest of the loads and the internal forces there), and the
        largest prescribed value of the constraint rows (data)."""
        internal = self.system.internal(u) + self.itf.internal(u, response.traction)
        R = internal - b
        forces = max(np.max(np.abs(b[self.balance]), initial=0.0),
                      np.max(np.abs(internal[~self.constraint]), initial=0.0))
        data = np.max(np.abs(b[self.constraint]), initial=0.0)
        return R, self.ranks.max(forces), self.ranks.max(data)

    def _least(self, u) -> float:
        """The least round-off scale of a residual at ``u``, for the health
        check (RESIDUAL_FAIL) only: RESIDUAL_FLOOR of the scene's full
        loads, or the scale at which the round-off ``A u`` carries,
        PRODUCT_ROUNDOFF of ``|u|``, is RESIDUAL_FAIL of it (``A u`` sums
        terms of ``u``'s size, however well they cancel: a body displaced
        rigidly, stress-free at zero load, has ``A u`` of round-off).  Never
        a convergence floor: NEWTON_RTOL of it would be round-off itself
        (PRODUCT_ROUNDOFF's note)."""
        size = self.ranks.max(float(np.max(np.abs(u[self.balance]), initial=0.0)))
        return max(self._least_force, tol.PRODUCT_ROUNDOFF / tol.RESIDUAL_FAIL * size)

    def _lift(self, supports) -> float:
        """The largest force on a free unknown of the prescribed
        displacements at the ``supports``' factors, every other unknown at
        zero, over the ranks: each takes part in ``internal`` (a collective)
        unless none holds a prescribed value."""
        prescribed = np.zeros(self.system.size)
        prescribed[self.system.fixed] = self.system.fixed_values(supports)
        if self.ranks.all(not prescribed.any()):
            return 0.0
        return self.ranks.max(float(np.max(np.abs(self.system.internal(prescribed)[self.free]), initial=0.0)))

    def step(self, k: float) -> None:
        """Converge the step to increment ``k`` from the committed state and
        commit it, or raise SolverError with the residual history
        (:meth:`_approached`)."""
        self._commit(k, *self._approached(k))

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

    def _iterate(self, k: float, start=None):
        """Newton's iterations to increment ``k`` from the predicted state,
        or from ``start`` (``(u, statuses)``): the factors, ``u``, the law's
        response, the iterations and the residual history; SolverError with
        the history if they do not converge."""
        loads, supports = self.scene.factors(k)
        b = self.system.external(loads, supports)
        u, previous = self._predicted(_flat((loads, supports))) if start is None else (start[0].copy(), start[1])
        u[self.system.fixed] = self.system.fixed_values(supports)
        lift = self._lift(supports)
        history, tangent, start, du, u0 = [], None, 0.0, None, u.copy()
        judged = []  # the figure the convergence test judges: the equilibrium rows' residual over their forces
        held, budget = None, tol.NEWTON_MAX_ITERATIONS  # the statuses each point held in the step (_progress)
        self._secant, self._free_maps = None, 0  # each step its own secant and its maps that slip free
        self.factorisations.begin_step()
        evaluated = None  # the line search's response and residual at u
        it = 0
        while it < budget:
            it += 1
            if evaluated is None:
                response = self.itf.respond(self.law, u, self.state, previous, self.ranks)
                evaluated = response, self._residual(u, b, response)
            response, (R, forces, data) = evaluated
            previous = response.status
            norm = self.ranks.max(float(np.max(np.abs(R[self.free]), initial=0.0)))
            start = start or norm
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
            least = self._least(u)
            scale = max(forces, data, lift, start, least)
            history.append(norm / scale if scale > 0 else norm)
            if not np.isfinite(norm):
                raise SolverError(f"the residual is not finite; residual history {_fmt(history)}")
            # what _converged judges the balance against: the forces, at least
            # RESIDUAL_FLOOR of the full loads; not the round-off floor of u's
            # size, whose NEWTON_RTOL is the round-off of A u (PRODUCT_ROUNDOFF)
            judged_forces = max(forces, self._least_force)
            judged.append(self._balance(R) / judged_forces if judged_forces > 0 else self._balance(R))
            if it > 1 and self._converged(R, judged_forces, tangent, response, du, u - u0):
                health.check_residual(history[-1], "the settled Newton step")
                health.check_held(self.scene, *self._gamma, self.ranks.gather(response.status),
                                  f"scene {self.scene.name}: increment {k:g} of {self.scene.increments}")
                return (loads, supports), u, response, it - 1, history
            held, progress = self._progress(held, response.status)
            budget = min(budget + tol.NEWTON_PROGRESS_ITERATIONS * progress, tol.NEWTON_PROGRESS_CAP)
            slid = slide(self, u, b, R, response, scale)  # a body held by Γ's slipping points alone, slid
            if slid is not None:
                du, (u, evaluated), tangent = slid[0] - u, slid, None
                continue
            ahead = () if du is None else self._ahead(u, du, response.status)
            du, rep, tangent = self._solve(response.tangent, -R, scale, response.secant, response.status, ahead)
            _merge(self.report, rep)
            if not self.law.is_linear:  # a linear law is solved in one step
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
                du = alpha * du
                tangent = tangent if alpha == 1.0 else None  # a partial step settles nothing
            else:
                evaluated = None
            u = u + du
        free = (f" ({self._free_maps} of them on maps whose slipping points alone held a body that nothing else "
                "holds, free to turn or slide until a point sticks)" if self._free_maps else "")
        raise SolverError(f"{health.NOT_CONVERGED} in {it} iterations{free}; relative residual of the equilibrium "
                          f"rows over their forces {_fmt(judged)}, converged at <= {tol.NEWTON_RTOL:.0e}")

    def record(self, rep: SolverReport) -> None:
        """Count a solve made for this Newton outside its own steps (the
        slide's, :mod:`contactcore.slide`) in its report."""
        _merge(self.report, rep)

    def _balance(self, R) -> float:
        """The largest residual of the equilibrium rows, over every rank."""
        return self.ranks.max(float(np.max(np.abs(R[self.balance]), initial=0.0)))

    def _progress(self, held, status):
        """The statuses each point has ``held`` in the step (a bit per
        status) with ``status`` added, and whether ``status`` moved a point,
        on any rank, to a status it had not held in the step.  Each such
        iteration adds NEWTON_PROGRESS_ITERATIONS to the step's budget: a
        point can do so at most twice (open, stick, slip), so the budget
        stays finite, while a semismooth Newton that moves points at a tie
        of the law from stick to slip a few per iteration (docs/newton.md,
        "A tie") goes on, and one that cycles (points moving back to
        statuses they held) stops at NEWTON_MAX_ITERATIONS."""
        bits = np.left_shift(1, np.asarray(status, np.int64))
        if held is None:
            return bits, False
        return held | bits, self.ranks.max(float(np.any((held & bits) == 0))) > 0

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

    def _converged(self, R, forces: float, tangent, response, du, moved) -> bool:
        """Whether the step has converged: the equilibrium rows' residual
        small against their own forces (not against the round-off scale:
        the data of a stiff body, E δ/h, can dwarf the forces of a soft one,
        and a wrong stick/slip split passed); or the law's tangent is the one
        the last full solve used (a piecewise-linear law is then solved
        exactly, up to that solve's round-off); or the last correction
        ``du`` moved no digit of what the step ``moved`` u by (points whose
        gap is round-off change status at every solve and change nothing:
        a rigid shift under unilateral contact).  The caller then holds it
        to the round-off check against the step's scale."""
        balance = self._balance(R)
        settled = self._settles(tangent, response)
        still = du is not None and self.ranks.max(float(np.max(np.abs(du), initial=0.0))) <= (
            tol.STEP_ROUNDOFF * self.ranks.max(float(np.max(np.abs(moved), initial=0.0))))
        return balance <= tol.NEWTON_RTOL * forces or settled or still

    def _merit(self, R: np.ndarray) -> float:
        """``‖R‖₂`` over the free rows of every rank."""
        return float(np.sqrt(self.ranks.sum(float(np.sum(R[self.free] ** 2)))))

    def _settles(self, tangent, response) -> bool:
        """Whether the law's tangent at ``response`` is the ``tangent`` the
        last full step was solved with (None: none, or a partial step), on
        every rank: the step then solved its status map's linear problem."""
        return tangent is not None and self.ranks.all(np.array_equal(tangent, response.tangent))

    def _line_search(self, u, du, b, R, status, secant: bool = False, tangent=None):
        """The largest ``α = 2⁻ʲ`` (j <= LINE_SEARCH_HALVINGS) whose step
        ``u + α δu`` decreases the merit ``‖R‖₂`` by Armijo's rule
        ``‖R(u + α δu)‖ <= (1 − ARMIJO α) ‖R(u)‖`` — the globalised
        semismooth Newton of GetFEM's contact bricks and PETSc's
        ``vinewtonrsls``: ``δu = −J⁻¹R`` is a descent direction of ``½‖R‖²``
        for any generalised Jacobian ``J`` of the semismooth residual, so a
        small enough step always decreases it and breaks a cycle between
        status maps.  If none does, a law step is taken whole (the merit has
        a kink there that is no zero, and smaller steps only cycle about it),
        a secant step at its smallest with no response (the caller then
        pins a point, :meth:`_pinned`).  A ``secant`` step
        (a body free to turn, :meth:`_solve`) is taken whole where it only
        keeps the merit: along that rotation the merit is flat until a
        point re-enters its stick window, which is where the step goes.  A full step that
        passes is doubled while the merit keeps falling (at most
        LINE_SEARCH_EXPANSIONS times): a regularised tangent, stiffer than
        the law's, asks for longer steps than it gives; not one that
        :meth:`_settles` the ``tangent`` it was solved with: that step
        solved its map's linear problem, Newton stops there, and a longer
        one could only win by round-off.  Also returns the
        law's response and :meth:`_residual` at ``u + α δu`` where it was
        evaluated (None elsewhere): the next iterate's, computed alike."""
        merit, seen = self._merit(R), {}

        def along(alpha):
            trial = u + alpha * du
            response = self.itf.respond(self.law, trial, self.state, status, self.ranks)
            seen[alpha] = (response, self._residual(trial, b, response))
            return self._merit(seen[alpha][1][0])

        alpha = 1.0
        for _ in range(tol.LINE_SEARCH_HALVINGS):
            value = along(alpha)
            if value <= (1.0 - tol.ARMIJO * alpha) * merit or (secant and alpha == 1.0 and value <= merit):
                break
            alpha /= 2
        else:
            # a law step that no halving lets descend stands at a kink of
            # the merit that is not a zero (a point whose stick and slip
            # each send Newton to the other): taken whole, it leaves the
            # cycle; a secant step is then pinned instead (_pinned)
            return (alpha, None) if secant else (1.0, seen[1.0])
        if alpha < 1.0 or self._settles(tangent, seen[alpha][0]):
            return alpha, seen[alpha]
        for _ in range(tol.LINE_SEARCH_EXPANSIONS):
            longer = along(2 * alpha)
            if longer >= value:
                break
            alpha, value = 2 * alpha, longer
        return alpha, seen[alpha]

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

    def _commit(self, k, factors, u, response, iterations, history) -> None:
        self.u, self.state, self.status = u, response.state, response.status
        self._converged_at = (self._converged_at + [(_flat(factors), u.copy())])[-2:]
        g = self.itf.jumps(u)
        self.path.steps.append(Increment(k, factors, iterations, history, g, response.traction, response.status))
        self.report.iterations.append(iterations)
        self.report.residual = history[-1]

    def _from_rest(self, start: float, k: float) -> bool:
        """Whether the step ``start → k`` starts from rest (``u = 0``, no
        load, the law's history untouched) along a straight load path: every
        law here is positively homogeneous there (``t(c y) = c t(y)`` for
        ``c > 0`` at ``s = 0``, and Nitsche's ``y = G̃ u`` is linear), so a
        halved step is the same problem scaled, and Newton repeats its
        iterates (the squeezed disc of tests/free_disc.py, xfem P1 at
        h = 0.05: the same residual history at each of six cut-backs): more
        increments do not help."""
        untouched = self.ranks.all((self.state is None or not np.any(self.state)) and not self.u.any())
        f0, f1, half = (_flat(self.scene.factors(x)) for x in (start, k, (start + k) / 2))
        if f0.any() or not untouched:
            return False
        return bool(np.linalg.norm(half - f1 / 2) <= tol.PATH_STRAIGHT * np.linalg.norm(f1))

    def increment(self, n: int) -> None:
        """Increment ``n`` (from ``n − 1``), halving it on failure."""
        pending, failures, rest = [(float(n), 0)], [], False
        start = float(n - 1)
        while pending:
            k, depth = pending.pop(0)
            try:
                self.step(k)
                start = k
            except (SolverOptionError, health.FreeBody):
                raise  # a refused solver option or a free body: no smaller step helps
            except SolverError as exc:
                failures.append(f"step {start:g} → {k:g}: {exc}")
                rest = rest if depth else self._from_rest(start, k)
                if depth >= tol.MAX_CUTBACKS:
                    raise _no_equilibrium(self.scene, n, depth, failures, rest) from None
                mid = (start + k) / 2
                pending[:0] = [(mid, depth + 1), (k, depth + 1)]


#: How a failed linear solve is named where round-off chose how it failed
#: (a relative residual above RESIDUAL_FAIL, whose figure follows the
#: BLAS kernel and MUMPS's ordering, or pivots MUMPS or PETSc found null):
#: the check it failed, never the figure.
SOLVE_FAILED = f"singular to working precision or short of the residual check ({tol.RESIDUAL_FAIL:g})"


def _refusal(scene, system: ContactSystem, exc: SolverError) -> SolverError:
    """A linear law's failed solve, its cause first: a nearly
    incompressible material (:func:`~contactcore.health.material_cause`),
    checked before the springs and rigid modes are blamed.  How the solve
    failed is round-off's choice (fe P1, scene A in plane strain at
    ν = 0.4999999999, h = 0.1: relative residual 5.8e-3, 1.0e-2, 8.2e-3
    under OPENBLAS_CORETYPE = Haswell, Nehalem, SandyBridge, 7.6e-3 with
    MUMPS's ordering 0), so the message names the check it failed
    (:data:`SOLVE_FAILED`); ``exc`` is kept whole in ``details``."""
    step = f"increment {scene.increments} of {scene.increments}, a linear law's one step from rest"
    cause = health.material_cause(scene)
    if health.options_chose(str(exc)):  # the solver's options chose it, not round-off
        error = SolverError(f"{exc} (at {step})")
    elif cause:
        error = SolverError(f"scene {scene.name}: {cause}\n  (its solve at {step}, was {SOLVE_FAILED}); lower ν or "
                            "use plane stress")
    else:
        weights = system.collective.gather(system.interface.weights)
        error = SolverError(f"scene {scene.name}: {step}: the solve was {SOLVE_FAILED}; "
                            f"{health.failure_hint(scene, weights)}")
    error.details = str(exc)
    return error


#: What :meth:`_Newton._iterate`'s failure says of iterations on maps that
#: left a body free (:func:`contactcore.health.slips_free`); the refusal
#: names it without their count.
_FREE_MAPS = "on maps whose slipping points alone held a body that nothing else holds"


def _no_equilibrium(scene, n: int, depth: int, failures: list[str], from_rest: bool = False) -> SolverError:
    """Two lines, the failed check first: the friction cone on Γ if the
    loads leave it (:func:`~contactcore.health.friction_demand`), a nearly
    incompressible material, the unilateral law's tie
    (:func:`~contactcore.health.tie_cause`, asked of every cut-back's
    failure, not the last one's alone); else that no step converged, then
    what may cause it.  How a cut-back failed (a residual above the
    threshold and its figure, null pivots, no convergence and its
    iterations and residuals) is round-off's choice (grader5 #4: by BLAS
    kernel), so no line names it: the first names the check, the second
    the cut-backs, which always reach MAX_CUTBACKS, or the remedies.
    More increments are not offered for an increment that starts
    ``from_rest`` (:meth:`_Newton._from_rest`).  Every cut-back's full
    message is kept in the error's ``details``."""
    where = f"scene {scene.name}: increment {n} of {scene.increments}"
    cut = f"failed after {depth} cut-backs (step 1/{2 ** depth})"
    demand, material = health.friction_demand(scene, float(n)), health.material_cause(scene)
    tie = not (demand or material) and health.tie_cause(scene, float(n), "\n".join(failures), from_rest)
    chosen = [f.split(": ", 1)[1] for f in failures if health.options_chose(f)]  # the options chose it
    if demand:
        error = SolverError(f"{where}: {demand}\n  ({cut}, as it must without equilibrium)")
    elif chosen:
        error = SolverError(f"{where} {cut}: no step converged: {chosen[0]}")
    elif material:
        error = SolverError(f"{where}: {material}\n  ({cut}); lower ν or use plane stress")
    elif tie:
        error = SolverError(f"{where}: {tie}\n  ({cut}: {health.NOT_CONVERGED})")
    else:
        free = any(_FREE_MAPS in f for f in failures)  # of every cut-back, not how many: round-off's count
        error = SolverError(f"{where} {cut}: no step converged ({health.NOT_CONVERGED}, or a linear solve was "
                            f"{SOLVE_FAILED})" + (f"; Newton's iterations stood {_FREE_MAPS}, free to turn or slide "
                                                  "until a point sticks" if free else "")
                            + f"\n  {_unsettled(scene.law, from_rest)}")
    error.details = "\n".join(failures)
    return error


def _unsettled(law, from_rest: bool = False) -> str:
    """Why an increment may not converge under ``law``, naming only the
    remedies that apply to it: softer springs where the law is enforced by
    k_N, k_T, another β where it is enforced exactly (Nitsche), more
    increments only for a nonlinear law (a linear law's step is one solve
    whatever its size) and not ``from_rest`` (:meth:`_Newton._from_rest`),
    the friction limit μp only for a coulomb law."""
    exact = law.enforcement == "exact"
    if law.is_linear:
        return ("a linear law's step is one linear solve, failed whatever its size (more increments do not help): "
                + ("another stabilisation, or a rigid-body mode nearly free" if exact else
                   "springs far stiffer or softer than the bulk (k_N, k_T against E/h), or a rigid-body mode "
                   "nearly free"))
    friction = law.name == "coulomb"
    held = ("shear above μp, " if friction else "") + "a body held only by open points"
    status = "open/closed and stick/slip" if friction else "open/closed"
    more = "" if from_rest else " or use more increments"
    remedy = (f"Newton cannot settle the exact law's {status} map: use another stabilisation{more}"
              if exact else f"the springs are too stiff to settle the {status} map: soften k_N, k_T{more}")
    rest = ("; more increments do not help: from rest along a straight load path a smaller step is the same "
            "problem scaled" if from_rest else "")
    return f"either the load has no equilibrium ({held}) or {remedy}{rest}"


def _started(answer) -> tuple[np.ndarray, np.ndarray]:
    """An :meth:`_Newton._iterate` answer as the start of another solve:
    its ``u`` and status map."""
    return answer[1], answer[2].status


def _flat(factors) -> np.ndarray:
    """The loads' and supports' factors of a step as one vector."""
    return np.array([*factors[0], *factors[1]], float)


def _fmt(values) -> str:
    return "[" + ", ".join(f"{v:.2e}" for v in values) + "]"


def _final_state(scene, system: ContactSystem, newton: _Newton, progress=None) -> _Newton:
    """A law without history (linear, unilateral): its state at the last
    increment does not depend on the path, so Newton goes there in one step
    from the unloaded state (a linear law in one solve, its tangent settled
    at once).  A nonlinear law whose one step does not converge follows the
    increments instead, with cut-backs; a linear one ends with the error."""
    try:
        newton.step(float(scene.increments))
        return newton
    except (SolverOptionError, health.FreeBody):
        raise
    except SolverError as exc:
        if scene.law.is_linear:
            raise _refusal(scene, system, exc) from None
    newton = _Newton(scene, system)
    _follow(scene, newton, progress)
    return newton


def _follow(scene, newton: _Newton, progress) -> None:
    """Every increment of the path, in order, reported to ``progress``."""
    for n in range(1, scene.increments + 1):
        newton.increment(n)
        if progress is not None:
            ranks = newton.ranks
            order = canonical_order(scene.interface, ranks.gather(newton.itf.points))
            progress(n, scene.increments, newton.path.final.gathered(ranks, order))


def solve_increments(scene, system: ContactSystem, progress=None) -> tuple[np.ndarray, InterfacePath, SolverReport]:
    """Solve ``scene`` on ``system``: its unknowns at the last increment, the
    interface's history and the solver's report (module doc).  ``progress``,
    if given, is called as ``progress(n, increments, step)`` after each
    increment ``n`` of a followed path converges (``step`` its
    :class:`Increment`): the driver reports it, the numerics print nothing."""
    ranks = system.collective
    weights, points = ranks.gather(system.interface.weights), ranks.gather(system.interface.points)
    health.check_springs(scene, weights)
    health.check_restraint(scene, points, weights)
    newton = _Newton(scene, system)
    if not (scene.law.has_history or scene.follow_path):
        newton = _final_state(scene, system, newton, progress)
    else:
        _follow(scene, newton, progress)
    if not scene.law.is_linear:
        newton.report.solver = f"newton + {newton.report.solver}"
    newton.report.increments = len(newton.path.steps)  # what was solved, not the scene's count
    newton.report.warnings += health.material_warnings(scene)
    newton.path.state = newton.state
    return newton.u, newton.path, newton.report
