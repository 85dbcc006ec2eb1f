"""Newton's state along the load path, and the increments with their
cut-backs.

:class:`_Newton` holds one system and law: the committed unknowns ``u``,
the law's history ``state`` and statuses, the interface path, the solver
report and the kept factorisations.  A step to increment ``k``
(:meth:`_Newton.step`) is solved from the committed state
(:mod:`contactcore.newton.continuation`, :mod:`contactcore.newton.iteration`)
and committed only if it converged: the state then moves to its answer,
the last two converged ``(factors, u)`` feed the predictor, and the
increment joins the path.

An increment ``n`` that fails (no convergence, a singular tangent) is
halved: the pending steps ``n − 1 → (n − 1 + k)/2 → k`` are solved in turn,
down to MAX_CUTBACKS halvings, after which the increment is refused
(:func:`contactcore.newton.refusals._no_equilibrium`), every cut-back's
failure in its details.  A step from rest along a straight load path
(:meth:`_Newton._from_rest`) under a law that declares itself positively
homogeneous is the same problem scaled at every halving, and the refusal
says so.  A refused solver option or a free body is raised
at once: no smaller step helps.

Contract: :class:`_Newton` takes a scene and its
:class:`~contactcore.system.ContactSystem`; :meth:`_Newton.increment` and
:meth:`_Newton.step` either commit a converged step or raise SolverError
with the state as it was.  Its other ideas are its mixins', one module
each: the residual, the convergence test, the line search, the statuses'
tangents, the correction's solve, the iterations and the step's
continuations.
"""
from __future__ import annotations

import numpy as np

from .. import health, laws
from .. import tolerances as tol
from ..errors import SolverError, SolverOptionError
from ..exact import enforced
from ..factorisations import KeptFactorisations
from ..interface_path import Increment, InterfacePath
from ..laws import STICK
from ..result import SolverReport
from ..system import ContactSystem
from .continuation import _Continuation
from .convergence import _Convergence
from .correction import _Correction
from .iteration import _flat, _Iteration
from .line_search import _LineSearch
from .refusals import _no_equilibrium
from .residual import _Residual
from .statuses import _Statuses


class _Newton(_Continuation, _Iteration, _Correction, _Statuses, _LineSearch, _Convergence, _Residual):
    """Newton on one system and law, state committed only on convergence."""

    def __init__(self, scene, system: ContactSystem, guess=None):
        self.scene, self.system, self.law = scene, system, scene.law
        # a coarser solve's status map for the first step's first correction
        # (contactcore.newton.guess), taken by the first step from rest only
        self._guess = guess
        self.first_map = ""  # where the first status search started (iteration.FROM_COARSER, STICKING)
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


    def step(self, k: float) -> None:
        """Converge the step to increment ``k`` from the committed state and
        commit it, or raise SolverError with the residual history
        (:meth:`_approached`)."""
        self._commit(k, *self._approached(k))

    def _commit(self, k, factors, u, response, iterations, history) -> None:
        """Make the converged step to ``k`` (:meth:`_iterate`'s answer) the
        state: ``u``, the law's history and statuses, the predictor's last
        two converged states, the path's increment and the report's count."""
        self.u, self.state, self.status = u, response.state, response.status
        self._converged_at = (self._converged_at + [(_flat(factors), u.copy())])[-2:]
        g = self.itf.jumps(u)
        frictionless = laws.frictionless(self.law)
        self.path.steps.append(Increment(k, factors, iterations, history, g, response.traction, response.status,
                                         frictionless=frictionless))
        self.report.iterations.append(iterations)
        self.report.residual = history[-1]

    def _from_rest(self, start: float, k: float) -> bool:
        """Whether the step ``start → k`` starts from rest (``u = 0``, no
        load, the law's history untouched) along a straight load path, for
        a law that declares itself positively homogeneous
        (``law.homogeneous``: ``t(c y) = c t(y)`` for ``c > 0`` at ``s = 0``,
        contactcore.laws' contract; Nitsche's ``y = G̃ u`` is linear): a
        halved step is then the same problem scaled, and Newton repeats its
        iterates (the squeezed disc of tests/free_disc.py, xfem P1 at
        h = 0.05: the same residual history at each of six cut-backs): more
        increments do not help.  False for any other law (a gap, a
        threshold: a smaller step is another problem)."""
        if not self.law.homogeneous:
            return False
        untouched = self.ranks.all((self.state is None or not np.any(self.state)) and not self.u.any())
        f0, f1, half = (_flat(self.scene.factors(x)) for x in (start, k, (start + k) / 2))
        if f0.any() or not untouched:
            return False
        return bool(np.linalg.norm(half - f1 / 2) <= tol.PATH_STRAIGHT * np.linalg.norm(f1))

    def increment(self, n: int) -> None:
        """Increment ``n`` (from ``n − 1``), halving it on failure; refused
        before any step where the scene's loads leave Γ's friction cone
        (:func:`contactcore.health.beyond_cone`): Newton's stick/slip band
        would hold such a load at stick or not as round-off decides."""
        beyond = health.beyond_cone(self.scene, float(n))
        if beyond:
            bound = "μ" if hasattr(self.law, "mu") else "the slip bound"
            raise SolverError(f"scene {self.scene.name}: increment {n} of {self.scene.increments}: {beyond}\n  "
                              f"(from the scene's loads, before Newton: a resultant beyond {bound}, or meeting Γ "
                              f"beyond its ends, by more than {tol.DEMAND_ROUNDOFF:g} of it has no equilibrium)")
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
                    raise _no_equilibrium(self.scene, n, depth, failures, rest,
                                          self.system.interface.load_flux is not None) from None
                mid = (start + k) / 2
                pending[:0] = [(mid, depth + 1), (k, depth + 1)]
