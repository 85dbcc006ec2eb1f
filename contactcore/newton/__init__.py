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
(:mod:`contactcore.newton.line_search`), which a cycle between status maps cannot
survive.
A failed increment (no convergence, a singular tangent) is halved up to
``MAX_CUTBACKS`` times; the state is committed only at converged steps.  A
law without history (linear, unilateral) is path-independent: unless the
scene asks for the response along the path (``follow_path``), Newton goes
to the last increment's factors in one step (a linear law in one solve),
and follows the increments only if that step fails; the report records the
steps solved.

One idea a module, each with its maths and contract:

- :mod:`~contactcore.newton.driver`: :func:`solve_increments`, the entry
  point: the checks before any solve, the path followed or its last
  increment in one step;
- :mod:`~contactcore.newton.increments`: ``_Newton``, the state committed
  at converged steps, and each increment's cut-backs;
- :mod:`~contactcore.newton.continuation`: a step and its fallbacks (an
  exact law's continuation in its stabilisation, softer then stiffer; a
  load back to zero as a limit);
- :mod:`~contactcore.newton.iteration`: one step's iterations (the
  predictor, the residual's figures, the test, the correction);
- :mod:`~contactcore.newton.correction`: ``J δu = −R`` with a kept
  factorisation, and the solve reports merged;
- :mod:`~contactcore.newton.statuses`: the tied, regularised and pinned
  tangents where the law's leaves a body free, and dominated maps;
- :mod:`~contactcore.newton.line_search`: Armijo's rule on ``‖R‖₂``, with
  doubling;
- :mod:`~contactcore.newton.convergence`: the convergence test (balance,
  a settled map, a still step) and the iteration budget;
- :mod:`~contactcore.newton.residual`: the residual and the scales it is
  judged against;
- :mod:`~contactcore.newton.refusals`: what the user reads when no step
  converges (:data:`SOLVE_FAILED`);
- :mod:`~contactcore.newton.guess`: an exact law's first status map from
  the same scene solved at twice the spacing, for the first step's first
  correction (:func:`contactcore.discretisation.solve` makes it).

The arrows: ``driver`` → ``increments`` → ``continuation``, ``iteration``,
``correction``, ``statuses``, ``line_search``, ``convergence``,
``residual``; ``iteration`` → ``correction`` and :mod:`contactcore.slide`;
``driver``, ``increments`` → ``refusals``; ``guess`` → ``increments``
(the coarser solve's own Newton).  ``_Newton`` is one class made
of the mixins (each module's ``_Name``), which share its attributes as
each module's contract lists them.

The package's public names, imported here as ``contactcore.newton.NAME``,
are :func:`solve_increments` and :data:`SOLVE_FAILED`.  Three private
names are imported here too, because other code, the tests and the
scripts of docs/newton.md and docs/contact-enforcement.md reach them as
``contactcore.newton.NAME``: ``_Newton`` (whose methods the census
scripts wrap, ``newton._Newton._line_search``), ``_refusal`` and
``_no_equilibrium``.  Every other private helper stays in its home.
"""
from .driver import solve_increments
from .increments import _Newton  # noqa: F401  (the docs' scripts wrap its methods)
from .refusals import SOLVE_FAILED, _no_equilibrium, _refusal  # noqa: F401  (the tests' messages)

__all__ = [
    # driver
    "solve_increments",
    # refusals
    "SOLVE_FAILED",
]
