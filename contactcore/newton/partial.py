"""The unilateral law's answer where no open/closed map is consistent: a
point in a partial state (Filippov's convexification of the tie's jump).

The ``unilateral`` law (penalty or exact) ties a closed point (``t =
D y``, ``D = diag(k_N, k_T)``, or ``γ I`` for Nitsche's augmented jump
``y``) and frees an open one (``t = 0``): its tangential traction jumps
from ``k_T y_T`` to 0 as ``y_N`` crosses 0.  A law with a jump need not
have a root among its point statuses: on grader16's ``uni`` (exact, fe
P1, h = 0.05) the Gauss point at s = 0.325 has ``y_N = +4.7e-4`` of
max |y_N| when closed and ``−4.2e-4`` when open, every other point
consistent, so Newton cycles and is refused.  The law's graph there is a
jump, and the one answer it admits is Filippov's (*Differential
equations with discontinuous righthand sides*, 1988, §2.4; the
set-valued completion of a discontinuous law, the convex hull of its two
branches at the switch): at ``y_N = 0`` exactly the traction is

    t = θ D y + (1 − θ) · 0,   θ ∈ [0, 1],

so ``t_N = θ k_N y_N = 0`` and ``t_T = τ = θ k_T y_T``, a share of the
tie's shear.  The point is *partial*: ``y_N = 0`` is its equation and
``τ`` its unknown (one each, a square system), and the answer is
consistent where ``θ = τ / (k_T y_T)`` lies in ``[0, 1]``.  ``θ = 1`` is
the closed branch at ``y_N = 0`` and ``θ = 0`` the open one, so where a
consistent open/closed map exists it is such an answer with no partial
point, and this search only runs where Newton, and the path followed
with cut-backs, found none (:func:`contactcore.newton.driver._final_state`):
every answer Newton gives is unchanged, bit for bit.

**The linear problem of a map.** With the closed points ``C`` tied
(tangent ``D``), the open ones free and the partial ones ``P`` carrying
``τ_P`` along Γ's tangent, from the unloaded ``u₀`` (residual ``R₀``):

    J_C u = J_C u₀ − R₀ − Σ_{p∈P} τ_p f_p,   y_N,p(u) = 0  (p ∈ P),

``f_p`` the forces of a unit ``t_T`` at ``p`` (``Tᵀ W e_p``). With
``v₀ = J_C⁻¹(−R₀)`` and ``v_p = J_C⁻¹ f_p`` the ``|P| × |P|`` system
``M τ = y_N,P(u₀ + v₀)``, ``M_qp = y_N,q(v_p)``, gives ``τ``: ``1 + |P|``
solves of one factorisation (kept, or a low-rank correction of one).

**The search.** From every point closed (Newton's all-stick start), each
map is solved and every point beyond its band moved at once (the
primal-dual active set of Hintermüller, Ito & Kunisch, SIAM J. Optim.
2002): a closed point whose ``y_N`` exceeds ``DECISION_BAND`` of Γ's
largest ``|y_N|`` opens, an open one below minus that band closes, a
partial one whose ``τ`` lies beyond ``k_T y_T`` (``θ > 1``) by more
than ``DECISION_BAND`` of Γ's largest ``|k_T y_T|`` closes, beyond 0
(``θ < 0``) opens; a closed or open point asked to take a status it has
already had in this search becomes partial instead (it contradicts both:
the point of ``uni`` above).  Each point's move depends on its own
margin and history only, never on the numbering, and a margin within
the band keeps its status, so round-off does not choose
(:class:`contactcore.laws.Decision`).  The search stops at a map with no
point beyond its band, at PARTIAL_SEARCH_MAPS maps, at a singular map (a
body let go), or when it has no partial answer: then the refusal stands.

The answer is committed as the step to the last increment (a law
without history is path-independent): a partial point's status is
``STICK`` (``y_N = 0`` is closed in the law's definition), its traction
``(0, τ)``, and the run warns once, naming the partial points, their
``θ`` and where they lie (``Result.solver.warnings``).  The residual of
the answer is held to RESIDUAL_FAIL as Newton's is, and a body the
answer lets go is refused (:func:`contactcore.health.check_held`).

Measured 2026-11-28 (docs/contact-enforcement.md, "The unilateral law
under shear"): ``uni`` fe P1 at h = 0.05, one partial point, θ = 0.0587,
8 maps; grader17's ``tilt-unil-exact`` efgm P1 at h = 0.05 (one point)
and xfem P2 at h = 0.025 (two). Serial only: under mpirun the refusal
stands (the partial points' equations would be gathered over ranks).

Contract: :func:`partial_answer` takes a fresh :class:`_Newton` and the
increment ``k``; it commits the answer and returns True, or returns False
with nothing committed; it raises nothing but a FreeBody from
:func:`contactcore.health.check_held`.
"""
from __future__ import annotations

import numpy as np

from .. import health
from .. import tolerances as tol
from ..errors import SolverError
from ..laws import OPEN, STICK, LawResponse
from .correction import _merge
from .iteration import _flat

#: the search's own statuses of a point (module doc)
_OPEN, _CLOSED, _PARTIAL = 0, 1, 2


def applies(scene, system) -> bool:
    """Whether the partial search may run: the ``unilateral`` law (no
    friction, no history; penalty or exact), in one process."""
    law = scene.law
    return (law.unilateral and not law.frictional and not law.has_history and not law.is_linear
            and not system.collective.parallel)


def _stiffness(newton) -> np.ndarray:
    """(m, 2): each point's closed stiffness ``(k_N, k_T)`` (Nitsche's ``γ``
    for both under an exact law)."""
    itf = newton.itf
    if itf.exact:
        return np.column_stack([itf.gamma, itf.gamma]).astype(float)
    return np.tile([float(newton.law.kN), float(newton.law.kT)], (itf.size, 1))


def _jumps(newton, u: np.ndarray) -> np.ndarray:
    """(m, 2): the jumps the law reads, ``y = G̃ u`` (exact) or ``g = G u``."""
    itf = newton.itf
    y = itf.augmented @ u if itf.exact else itf.jumps(u)
    return np.asarray(y, float).reshape(-1, 2)


class _Search:
    """One partial search's system: the unloaded ``u₀``, its residual and
    scale, the closed stiffnesses and the unit forces (module doc)."""

    def __init__(self, newton, k: float):
        self.newton = newton
        loads, supports = newton.scene.factors(k)
        self.factors = (loads, supports)
        self.b = newton.system.external(loads, supports)
        u0 = np.zeros(newton.system.size)
        u0[newton.system.fixed] = newton.system.fixed_values(supports)
        self.u0 = u0
        R0, forces, data = newton._residual(u0, self.b, newton.itf.respond(newton.law, u0, newton.state))
        first = float(np.max(np.abs(R0[newton.free]), initial=0.0))
        self.R0 = R0
        self.scale = max(forces, data, newton._lift(supports), first, newton._least(u0))
        self.k = _stiffness(newton)
        self.m = newton.itf.size

    def unit(self, p: int) -> np.ndarray:
        """The forces of a unit ``t_T`` at point ``p`` (``Tᵀ W e_p``)."""
        t = np.zeros((self.m, 2))
        t[p, 1] = 1.0
        return self.newton.itf.internal(np.zeros_like(self.u0), t)

    def solve(self, s: np.ndarray):
        """The linear problem of the map ``s``: ``(u, y, τ_P, P)``;
        SolverError where its tangent is singular or ``M`` is."""
        newton = self.newton
        tangent = np.zeros((self.m, 2, 2))
        closed = s == _CLOSED
        tangent[closed, 0, 0], tangent[closed, 1, 1] = self.k[closed, 0], self.k[closed, 1]
        P = np.flatnonzero(s == _PARTIAL)
        solved = []
        for rhs in [-self.R0] + [self.unit(p) for p in P]:
            x, rep = newton.factorisations.solve(tangent, rhs, self.scale)
            _merge(newton.report, rep)
            solved.append(x)
        tau = np.zeros(0)
        if len(P):
            M = np.array([[_jumps(newton, v)[q, 0] for v in solved[1:]] for q in P])
            try:
                tau = np.linalg.solve(M, _jumps(newton, self.u0 + solved[0])[P, 0])
            except np.linalg.LinAlgError:
                raise SolverError("the partial points' equations are singular") from None
        u = self.u0 + solved[0] - sum((t * v for t, v in zip(tau, solved[1:])), np.zeros_like(self.u0))
        return u, _jumps(newton, u), tau, P

    def moves(self, s: np.ndarray, y: np.ndarray, tau: np.ndarray, P: np.ndarray) -> np.ndarray:
        """The status each point asks for at ``y`` (module doc: beyond the
        band only)."""
        gap = tol.DECISION_BAND * max(float(np.max(np.abs(y[:, 0]), initial=0.0)), tol.DECISION_FLOOR)
        want = s.copy()
        want[(s == _CLOSED) & (y[:, 0] > gap)] = _OPEN
        want[(s == _OPEN) & (y[:, 0] < -gap)] = _CLOSED
        if len(P):
            tie = self.k[:, 1] * y[:, 1]
            band = tol.DECISION_BAND * max(float(np.max(np.abs(tie), initial=0.0)), tol.DECISION_FLOOR)
            side = np.sign(tie[P])  # τ within [0, k_T y_T]: beyond the tie closes, beyond 0 opens
            beyond_tie = side * (tau - tie[P]) > band
            beyond_zero = np.where(side != 0, -side * tau, np.abs(tau)) > band
            want[P[beyond_tie]] = _CLOSED
            want[P[beyond_zero & ~beyond_tie]] = _OPEN
        return want


def partial_answer(newton, k: float) -> bool:
    """The partial search at increment ``k`` from rest (module doc),
    committed to ``newton`` if it finds an answer: True; else False."""
    search = _Search(newton, k)
    s = np.full(search.m, _CLOSED, np.int8)
    had = np.zeros((search.m, 3), bool)
    had[:, _CLOSED] = True
    for maps in range(1, tol.PARTIAL_SEARCH_MAPS + 1):
        try:
            u, y, tau, P = search.solve(s)
        except SolverError:
            return False
        want = search.moves(s, y, tau, P)
        moved = np.flatnonzero(want != s)
        if not len(moved):
            return _commit(newton, search, k, s, u, y, tau, P, maps)
        for p in moved:
            s[p] = _PARTIAL if s[p] != _PARTIAL and had[p, want[p]] else want[p]
            had[p, s[p]] = True
    return False


def _commit(newton, search: _Search, k: float, s, u, y, tau, P, maps: int) -> bool:
    """Commit the consistent map ``s``'s answer as the step to ``k``: its
    tractions, its statuses (a partial point ``STICK``), the warning; False
    where its residual fails RESIDUAL_FAIL or it has no partial point (a
    consistent map Newton missed is Newton's to find, not this search's)."""
    if not len(P):
        return False
    closed = s == _CLOSED
    traction = np.where(closed[:, None], search.k * y, 0.0)
    traction[P] = np.column_stack([np.zeros(len(P)), tau])
    tangent = np.zeros((search.m, 2, 2))
    tangent[closed, 0, 0], tangent[closed, 1, 1] = search.k[closed, 0], search.k[closed, 1]
    status = np.where(s == _OPEN, OPEN, STICK).astype(np.int8)
    response = LawResponse(traction, tangent, None, status)
    R, _, _ = newton._residual(u, search.b, response)
    relative = float(np.max(np.abs(R[newton.free]), initial=0.0)) / search.scale
    if not relative <= tol.RESIDUAL_FAIL:
        return False
    where = f"scene {newton.scene.name}: increment {k:g} of {newton.scene.increments}"
    health.check_held(newton.scene, *newton._gamma, status, where)
    newton._commit(k, search.factors, u, response, maps, [relative])
    theta = tau / (search.k[P, 1] * y[P, 1])
    points = newton.itf.points[P]
    listed = ", ".join(f"({x:.4g}, {z:.4g}) θ = {t:.3g}" for (x, z), t in zip(points, theta))
    newton.report.warnings.append(
        f"{where}: Newton found no open/closed map of the unilateral law consistent at every point; {len(P)} point(s) of Γ "
        f"hold y_N = 0 with a share θ of the tie's shear (the law's two branches mixed, Filippov's answer at its "
        f"jump; docs/contact-enforcement.md, \"The unilateral law under shear\"): {listed}")
    return True
