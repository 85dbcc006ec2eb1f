"""The entry point: a scene solved along its load path on any method's
system.

Before any solve the springs must leave the bulk digits in their rows
(:func:`contactcore.health.check_springs`) and the supports, pins and
springs must hold every rigid-body mode
(:func:`contactcore.health.check_restraint`).  A law with history
(Coulomb), or a scene that asks for the response along the path
(``follow_path``), follows every increment in order
(:meth:`~contactcore.newton.increments._Newton.increment`, with
cut-backs).  A law without history (linear, unilateral) is
path-independent: Newton goes to the last increment's factors in one step
(a linear law in one solve) and follows the increments only if that step
fails; a linear law's failed solve is refused at once
(:func:`~contactcore.newton.refusals._refusal`).  The report records the
steps solved, not the scene's count.

Contract: :func:`solve_increments` takes a scene and its
:class:`~contactcore.system.ContactSystem` and returns the unknowns at the
last increment, the interface's history
(:class:`~contactcore.interface_path.InterfacePath`, its ``state`` the
law's last) and the :class:`~contactcore.result.SolverReport`; or raises
a SolverError (a refusal, or the checks before a solve).  It
prints nothing: ``progress``, if given, is told of each increment of a
followed path.
"""
from __future__ import annotations

import numpy as np

from .. import health
from ..errors import SolverError, SolverOptionError
from ..interface_path import InterfacePath, canonical_order
from ..result import SolverReport
from ..system import ContactSystem
from . import partial
from .increments import _Newton
from .refusals import _refusal


def _final_state(scene, system: ContactSystem, newton: _Newton, progress=None) -> _Newton:
    """A law without history (linear, unilateral): its state at the last
    increment does not depend on the path, so Newton goes there in one step
    from the unloaded state (a linear law in one solve, its tangent settled
    at once).  A nonlinear law whose one step does not converge follows the
    increments instead, with cut-backs; a linear one ends with the error.
    Where the unilateral law's path fails too, its partial answer
    (:mod:`contactcore.newton.partial`: a point of Γ at ``y_N = 0`` with a
    share of the tie's shear, where no open/closed map is consistent) is
    the step to the last increment if the search finds one; else the
    path's refusal stands."""
    try:
        newton.step(float(scene.increments))
        return newton
    except (SolverOptionError, health.FreeBody):
        raise
    except SolverError as exc:
        if scene.law.is_linear:
            raise _refusal(scene, system, exc) from None
    tried, newton = newton, _Newton(scene, system)
    _carry(tried, newton)
    try:
        _follow(scene, newton, progress)
    except (SolverOptionError, health.FreeBody):
        raise
    except SolverError:
        # no consistent open/closed map along the path either: the
        # unilateral law's partial answer, if it has one (a point of Γ at
        # y_N = 0 carrying a share of the tie's shear), else the refusal
        if not partial.applies(scene, system):
            raise
        fallback = _Newton(scene, system)
        _carry(newton, fallback)
        if not partial.partial_answer(fallback, float(scene.increments)):
            raise
        return fallback
    return newton


def _carry(failed: _Newton, fresh: _Newton) -> None:
    """What a failed attempt solved and factorised counted in the fresh
    attempt's report: the run's cost is every attempt's."""
    fresh.report.solves += failed.report.solves
    fresh.report.factorisations += failed.report.factorisations


def _follow(scene, newton: _Newton, progress) -> None:
    """Every increment of the path, in order, reported to ``progress``."""
    for n in range(1, scene.increments + 1):
        newton.increment(n)
        if progress is not None:
            ranks = newton.ranks
            order = canonical_order(scene.interface, ranks.gather(newton.itf.points))
            progress(n, scene.increments, newton.path.final.gathered(ranks, order))


def solve_increments(scene, system: ContactSystem, progress=None,
                     guess=None) -> tuple[np.ndarray, InterfacePath, SolverReport]:
    """Solve ``scene`` on ``system``: its unknowns at the last increment, the
    interface's history and the solver's report (module doc).  ``progress``,
    if given, is called as ``progress(n, increments, step)`` after each
    increment ``n`` of a followed path converges (``step`` its
    :class:`Increment`): the driver reports it, the numerics print nothing.
    ``guess``, if given, is a coarser solve's status map
    (:class:`contactcore.newton.guess.StatusGuess`) for the first step's
    first correction: it shortens the status search and decides nothing."""
    ranks = system.collective
    weights, points = ranks.gather(system.interface.weights), ranks.gather(system.interface.points)
    health.check_springs(scene, weights)
    health.check_restraint(scene, points, weights)
    first = newton = _Newton(scene, system, guess)
    if not (scene.law.has_history or scene.follow_path):
        newton = _final_state(scene, system, newton, progress)
    else:
        _follow(scene, newton, progress)
    newton.report.first_map = first.first_map
    if not scene.law.is_linear:
        newton.report.solver = f"newton + {newton.report.solver}"
    newton.report.increments = len(newton.path.steps)  # what was solved, not the scene's count
    if guess is not None:  # what the coarser solve paid is the run's
        newton.report.solves += guess.solves
        newton.report.factorisations += guess.factorisations
    newton.report.warnings += health.material_warnings(scene)
    newton.path.state = newton.state
    return newton.u, newton.path, newton.report
