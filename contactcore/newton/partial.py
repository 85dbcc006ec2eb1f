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
``τ_P`` along Γ's tangent, from the unloaded ``u₀`` (``R₀`` its residual
under the map's own tractions at ``u₀``, :meth:`_Search.rest`):

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
``(0, τ)``, its θ the step's ``theta`` (NaN at every other point;
outputs report the point as ``partial``,
:meth:`contactcore.interface_path.Increment.reported_status`), and the
run warns once, naming the partial points, their ``θ`` and where they
lie (``Result.solver.warnings``).  The residual of the answer is held
to RESIDUAL_FAIL as Newton's is, and a body the answer lets go is
refused (:func:`contactcore.health.check_held`).

Measured 2026-11-28 (docs/contact-enforcement.md, "The unilateral law
under shear"): ``uni`` fe P1 at h = 0.05, one partial point, θ = 0.0587,
9 maps; grader17's ``tilt-unil-exact`` efgm P1 at h = 0.05 (one point)
and xfem P2 at h = 0.025 (two).

**Under mpirun** (fe, xfem: Γ's points split between ranks) the search
is the serial one: the bands' maxima are reduced over the ranks; the
partial points are every rank's, in rank order, and every rank solves
for each of them (a rank owning none with zero unit forces: the solve is
a collective); ``M`` and ``y_N,P(u₀ + v₀)`` are gathered, so ``τ`` is
the same on every rank; "no point moved" holds on every rank; the
warning lists every rank's partial points along Γ (its canonical order,
which no partition changes).  Each point's move reads only its own
margin and the Γ-wide bands, so the maps visited do not depend on the
partition.

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
from ..interface_path import canonical_order
from ..laws import OPEN, STICK, LawResponse
from .correction import _merge
from .iteration import _flat

#: the search's own statuses of a point (module doc)
_OPEN, _CLOSED, _PARTIAL = 0, 1, 2


def applies(scene, system) -> bool:
    """Whether the partial search may run: the ``unilateral`` law (no
    friction, no history; penalty or exact), on any number of ranks."""
    law = scene.law
    return law.unilateral and not law.frictional and not law.has_history and not law.is_linear


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
    if not itf.exact:
        return np.asarray(itf.jumps(u), float).reshape(-1, 2)
    local = u if itf.exchange is None else itf.exchange.forward(u)  # G̃'s columns are local: a collective
    y = itf.augmented @ local
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
        first = newton.ranks.max(float(np.max(np.abs(R0[newton.free]), initial=0.0)))
        self.scale = max(forces, data, newton._lift(supports), first, newton._least(u0))
        self.k = _stiffness(newton)
        self.m = newton.itf.size
        self.ranks = newton.ranks
        self.y0 = _jumps(newton, u0)  # not 0 where a prescribed displacement opens Γ at rest

    def response(self, s: np.ndarray, y: np.ndarray, tau: np.ndarray, P: np.ndarray) -> LawResponse:
        """The map ``s``'s law at the jumps ``y``: a closed point tied
        (``k y``, tangent ``k``), an open one free, a partial one
        ``(0, τ)``; statuses open or ``STICK`` (module doc)."""
        closed = s == _CLOSED
        traction = np.where(closed[:, None], self.k * y, 0.0)
        traction[P] = np.column_stack([np.zeros(len(P)), tau])
        tangent = np.zeros((self.m, 2, 2))
        tangent[closed, 0, 0], tangent[closed, 1, 1] = self.k[closed, 0], self.k[closed, 1]
        return LawResponse(traction, tangent, None, np.where(s == _OPEN, OPEN, STICK).astype(np.int8))

    def rest(self, s: np.ndarray) -> tuple[np.ndarray, LawResponse]:
        """The residual ``R₀`` at ``u₀`` with the map ``s``'s own
        tractions there, and that response (its tangent the map's) (a partial point's τ apart: its unit forces carry
        it), so ``J_s (u − u₀) = −R₀ − Σ τ_p f_p`` is the map's linear
        problem even where ``y(u₀) ≠ 0`` (review8: the law's response at
        ``u₀`` left a residual of 0.128 of the scale in a map opening
        points a prescribed displacement had opened)."""
        at_rest = self.response(s, self.y0, np.zeros(0), np.zeros(0, int))
        R0, _, _ = self.newton._residual(self.u0, self.b, at_rest)
        return R0, at_rest

    def unit(self, j: int, first: int, P: np.ndarray) -> np.ndarray:
        """The forces of a unit ``t_T`` at the ``j``-th partial point of
        every rank's (``Tᵀ W e_p``), this rank's partial points ``P``
        being the ``first``-th on: zero forces on a rank that does not own
        it, which takes part in the collective all the same."""
        t = np.zeros((self.m, 2))
        if first <= j < first + len(P):
            t[P[j - first], 1] = 1.0
        return self.newton.itf.internal(np.zeros_like(self.u0), t)

    def solve(self, s: np.ndarray):
        """The linear problem of the map ``s``: ``(u, y, τ_P, P)``, ``P``
        this rank's partial points and ``τ_P`` theirs; SolverError where
        its tangent is singular or ``M`` is.  Under mpirun the partial
        points are every rank's, in rank order: each rank solves for each
        of them, ``M`` and ``y_N,P(u₀ + v₀)`` gathered, ``τ`` the same on
        every rank."""
        newton, ranks = self.newton, self.ranks
        R0, at_rest = self.rest(s)
        tangent = at_rest.tangent
        P = np.flatnonzero(s == _PARTIAL)
        counts = ranks.gather(np.array([len(P)]))
        first, total = int(np.sum(counts[:ranks.rank])), int(np.sum(counts))
        solved = []
        for rhs in [-R0] + [self.unit(j, first, P) for j in range(total)]:
            x, rep = newton.factorisations.solve(tangent, rhs, self.scale)
            _merge(newton.report, rep)
            solved.append(x)
        tau = np.zeros(0)
        if total:
            M = np.column_stack([ranks.gather(_jumps(newton, v)[P, 0]) for v in solved[1:]])
            try:
                tau = np.linalg.solve(M, ranks.gather(_jumps(newton, self.u0 + solved[0])[P, 0]))
            except np.linalg.LinAlgError:
                raise SolverError("the partial points' equations are singular") from None
        u = self.u0 + solved[0] - sum((t * v for t, v in zip(tau, solved[1:])), np.zeros_like(self.u0))
        return u, _jumps(newton, u), tau[first:first + len(P)], P

    def moves(self, s: np.ndarray, y: np.ndarray, tau: np.ndarray, P: np.ndarray) -> np.ndarray:
        """The status each point asks for at ``y`` (module doc: beyond the
        band only)."""
        ranks = self.ranks
        gap = tol.DECISION_BAND * max(ranks.max(float(np.max(np.abs(y[:, 0]), initial=0.0))), tol.DECISION_FLOOR)
        want = s.copy()
        want[(s == _CLOSED) & (y[:, 0] > gap)] = _OPEN
        want[(s == _OPEN) & (y[:, 0] < -gap)] = _CLOSED
        if ranks.max(float(len(P))) > 0:  # the band's maximum is a collective
            tie = self.k[:, 1] * y[:, 1]
            band = tol.DECISION_BAND * max(ranks.max(float(np.max(np.abs(tie), initial=0.0))), tol.DECISION_FLOOR)
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
        if search.ranks.all(not len(moved)):
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
    ranks = search.ranks
    if ranks.max(float(len(P))) == 0:
        return False
    response = search.response(s, y, tau, P)
    status = response.status
    R, _, _ = newton._residual(u, search.b, response)
    relative = ranks.max(float(np.max(np.abs(R[newton.free]), initial=0.0))) / search.scale
    if not relative <= tol.RESIDUAL_FAIL:
        return False
    # the law's own decision at u, from these statuses, keeps every point
    # not partial as the search left it (review8: the search's band is
    # on y_N, Newton's in traction); else no answer is committed
    decided = newton.itf.respond(newton.law, u, newton.state, status, ranks).status
    kept = np.ones(search.m, bool)
    kept[P] = False
    if not ranks.all(np.array_equal(decided[kept], status[kept])):
        return False
    where = f"scene {newton.scene.name}: increment {k:g} of {newton.scene.increments}"
    health.check_held(newton.scene, *newton._gamma, ranks.gather(status), where)
    newton._commit(k, search.factors, u, response, maps, [relative])
    tie = search.k[P, 1] * y[P, 1]
    share = np.divide(tau, tie, out=np.zeros_like(tau), where=tie != 0)  # y_T = 0: τ within the band of 0
    newton.path.steps[-1].theta = np.full(search.m, np.nan)  # the step's θ per point, for its outputs
    newton.path.steps[-1].theta[P] = share
    theta = ranks.gather(share)
    points = ranks.gather(np.asarray(newton.itf.points, float).reshape(-1, 2)[P])
    order = canonical_order(newton.scene.interface, points)  # along Γ: no partition changes it
    points, theta = points[order], theta[order]
    listed = ", ".join(f"({x:.4g}, {z:.4g}) θ = {t:.3g}" for (x, z), t in zip(points, theta))
    newton.report.warnings.append(
        f"{where}: Newton found no open/closed map of the unilateral law consistent at every point; {len(points)} point(s) of Γ "
        f"hold y_N = 0 with a share θ of the tie's shear (the law's two branches mixed, Filippov's answer at its "
        f"jump; docs/contact-enforcement.md, \"The unilateral law under shear\"): {listed}")
    return True
