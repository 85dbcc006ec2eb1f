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
2002): a closed or open point asks for the status the law's own
decision gives it at the map's answer, from its status in the map
(Newton's band: an exact law's in traction, so that no point is held
closed in tension or open in penetration by more than ``DECISION_BAND``
of Γ's pressure; :class:`contactcore.laws.Decision`); a partial one
whose ``τ`` lies beyond ``k_T y_T`` (``θ > 1``) by more than
``DECISION_BAND`` of Γ's largest ``|k_T y_T|`` closes, beyond 0
(``θ < 0``) opens.  Two walks, the second only where the first finds
nothing (or a map whose answer fails Newton's residual test): the first
moves every point as asked and makes the returning points partial only
where the map would be one it has visited (a cycle; :func:`_cycling`);
the second makes a closed or open point asked to take
a status it has already had partial at once (it contradicts both: the
point of ``uni`` above; :func:`_returning`).  The first lets an opening
edge overshoot and come back (scene A at 20°, efgm P2: the second walk
made six such points partial and was lost); the second settles a point
that alternates while its neighbours move (tilt-unil-exact, xfem P2: the
first walk wanders).  Each point's move depends on its own margin and
history and on whether the whole map repeats, never on the numbering,
and a margin within the band keeps its status, so round-off does not
choose (:class:`contactcore.laws.Decision`).  A walk stops at a map with
no point beyond its band, at PARTIAL_SEARCH_MAPS maps, at a singular map
(a body let go) or with more than PARTIAL_SEARCH_POINTS points partial.
A consistent map with partial points is the answer; one without is an
open/closed map Newton missed, handed to Newton as its start (Newton's
test accepts it, :func:`_answer`).  Where neither walk has an answer,
the refusal stands.

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
increment ``k``; it commits the answer (a partial one, or Newton's step
from a consistent open/closed map) and returns True, or returns False
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
from ..scaling import user_points
from .correction import _merge
from .iteration import _flat

#: the search's own statuses of a point (module doc)
_OPEN, _CLOSED, _PARTIAL = 0, 1, 2


def _law_status(s: np.ndarray) -> np.ndarray:
    """The law's status of each point of the search's map ``s``: open, or
    ``STICK`` (a closed or partial point: ``y_N = 0`` is closed in the
    law's definition)."""
    return np.where(s == _OPEN, OPEN, STICK).astype(np.int8)


def applies(scene, system) -> bool:
    """Whether the partial search may run: the ``unilateral`` law (no
    friction, no history; penalty or exact), on any number of ranks, with
    a flux linear in ``u`` (not fe's nodal reaction, whose ``y`` is affine
    in the loads: its Newton's refusal stands)."""
    law = scene.law
    linear_flux = getattr(getattr(system, "interface", None), "load_flux", None) is None
    return law.unilateral and not law.frictional and not law.has_history and not law.is_linear and linear_flux


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
        return LawResponse(traction, tangent, None, _law_status(s))

    def rest(self, s: np.ndarray) -> tuple[np.ndarray, LawResponse]:
        """The residual ``R₀`` at ``u₀`` with the map ``s``'s own
        tractions there (but a partial point's τ, which its unit forces
        carry), and that response (its tangent the map's), so
        ``J_s (u − u₀) = −R₀ − Σ τ_p f_p`` is the map's linear
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
            if singular(M):
                raise SolverError("the partial points' equations are singular")
            tau = np.linalg.solve(M, ranks.gather(_jumps(newton, self.u0 + solved[0])[P, 0]))
        u = self.u0 + solved[0] - sum((t * v for t, v in zip(tau, solved[1:])), np.zeros_like(self.u0))
        return u, _jumps(newton, u), tau[first:first + len(P)], P

    def moves(self, s: np.ndarray, u: np.ndarray, y: np.ndarray, tau: np.ndarray, P: np.ndarray) -> np.ndarray:
        """The status each point asks for at ``u`` (jumps ``y``): a closed
        or open point the law's own decision from its status (Newton's
        band, :class:`contactcore.laws.Decision`), a partial one by its
        ``τ`` beyond its band (module doc)."""
        ranks, newton = self.ranks, self.newton
        status = _law_status(s)
        decided = newton.itf.respond(newton.law, u, newton.state, status, ranks).status
        want = np.where(s == _PARTIAL, _PARTIAL, np.where(decided == OPEN, _OPEN, _CLOSED)).astype(np.int8)
        if ranks.max(float(len(P))) > 0:  # the band's maximum is a collective
            tie = self.k[:, 1] * y[:, 1]
            band = tol.DECISION_BAND * max(ranks.max(float(np.max(np.abs(tie), initial=0.0))), tol.DECISION_FLOOR)
            want[P] = partial_asks(tau, tie[P], band)
        return want


def partial_asks(tau: np.ndarray, tie: np.ndarray, band: float) -> np.ndarray:
    """What each partial point asks for (``_CLOSED``, ``_OPEN`` or
    ``_PARTIAL``) from its shear ``τ``, its tie's ``k_T y_T`` and the
    band: ``τ`` lies within ``[0, k_T y_T]`` (a share θ of the tie's
    shear); a point whose ``τ`` lies beyond its tie by more than ``band``
    closes, one beyond 0 (on the side away from its tie) by more than
    ``band`` opens, any other stays partial.  A tie within the band has no
    side but round-off's: there any ``τ`` beyond the band opens, either
    way (review11 #5)."""
    side = np.where(np.abs(tie) > band, np.sign(tie), 0.0)
    beyond_tie = side * (tau - tie) > band
    beyond_zero = np.where(side != 0, -side * tau, np.abs(tau)) > band
    return np.where(beyond_tie, _CLOSED, np.where(beyond_zero, _OPEN, _PARTIAL)).astype(np.int8)


def singular(M: np.ndarray) -> bool:
    """Whether the partial points' equations ``M`` (square, gathered: the
    same on every rank) are singular to working precision: the smallest
    singular value at most :data:`~contactcore.tolerances.PARTIAL_M_RCOND`
    of the largest (or not finite).  Not LAPACK's zero pivot, which one
    kernel meets and another passes by on the same map (review11 #1)."""
    if not np.all(np.isfinite(M)):
        return True
    sv = np.linalg.svd(M, compute_uv=False)
    return not sv[-1] > tol.PARTIAL_M_RCOND * sv[0]


def partial_answer(newton, k: float) -> bool:
    """The partial search at increment ``k`` from rest (module doc),
    committed to ``newton`` if it finds an answer: True; else False.  The
    walk that moves every point as asked goes first (:func:`_cycling`),
    the one that makes a returning point partial second
    (:func:`_returning`), where the first finds nothing or its map fails
    :func:`_answer`."""
    search = _Search(newton, k)
    for rule in (_cycling, _returning):
        found = _walk(search, rule)
        if found is not None and _answer(newton, search, k, *found):
            return True
    return False


def _walk(search: _Search, rule):
    """The maps from every point closed, each moved by ``rule`` from the
    points beyond their bands: the consistent map's ``(s, u, y, τ, P,
    maps)``, or None at PARTIAL_SEARCH_MAPS maps, at a singular map or
    where more than PARTIAL_SEARCH_POINTS points of Γ are partial (the
    walk is lost: an answer's partial points sit where Γ opens)."""
    ranks = search.ranks
    s = np.full(search.m, _CLOSED, np.int8)
    had = np.zeros((search.m, 3), bool)
    had[:, _CLOSED] = True
    seen = [s.copy()]
    for maps in range(1, tol.PARTIAL_SEARCH_MAPS + 1):
        try:
            u, y, tau, P = search.solve(s)
        except SolverError:
            return None
        want = search.moves(s, u, y, tau, P)
        moved = np.flatnonzero(want != s)
        if ranks.all(not len(moved)):
            return s, u, y, tau, P, maps
        s = rule(s, want, moved, had, seen, ranks)
        had[moved, s[moved]] = True
        seen.append(s.copy())
        if len(ranks.gather(np.flatnonzero(s == _PARTIAL))) > tol.PARTIAL_SEARCH_POINTS:
            return None
    return None


def _returning(s, want, moved, had, seen, ranks) -> np.ndarray:
    """The next map: each moved point takes the status it asks for, or
    becomes partial where it asks for one it has had in this walk (it
    contradicts both: grader16's ``uni``; module doc)."""
    new = s.copy()
    back = (s[moved] != _PARTIAL) & had[moved, want[moved]]
    new[moved] = np.where(back, _PARTIAL, want[moved])
    return new


def _cycling(s, want, moved, had, seen, ranks) -> np.ndarray:
    """The next map: every moved point takes the status it asks for (the
    primal-dual active set's full step), unless that map is one the walk
    has visited: a cycle, whose returning points become partial
    (:func:`_returning`).  Where Γ opens, the all-closed map's jumps open
    points beyond the opening's edge, which the next map closes again:
    scene A with Γ at 20° through (0.5, 0.402), exact, efgm P2 at h =
    0.0125, the 3rd map closes 6 of the 11 points the 2nd opened; made
    partial at once, they took τ of up to 772 times their tie and the walk
    was lost, where moved as asked it settles at the 12th map with one
    point partial (docs/contact-enforcement-log.md, "Two walks on the
    law's band").  Map
    equality is each rank's own part equal on every rank: the partition
    does not change it."""
    new = s.copy()
    new[moved] = want[moved]
    if any(ranks.all(np.array_equal(new, old)) for old in seen):
        return _returning(s, want, moved, had, seen, ranks)
    return new


def _answer(newton, search: _Search, k: float, s, u, y, tau, P, maps: int) -> bool:
    """Commit the walk's consistent map: with partial points, its own
    answer (:func:`_commit`); with none, an open/closed map Newton's own
    iterations missed, solved by Newton from the map's answer and statuses
    (one correction of round-off: Newton's test, not the search's, accepts
    it).  False where either fails."""
    if search.ranks.max(float(len(P))) > 0:
        return _commit(newton, search, k, s, u, y, tau, P, maps)
    status = _law_status(s)
    try:
        factors, u, response, iterations, history = newton._iterate(k, start=(u, status))
    except health.FreeBody:
        raise
    except SolverError:
        return False
    newton._commit(k, factors, u, response, maps + iterations, history)
    return True


def _commit(newton, search: _Search, k: float, s, u, y, tau, P, maps: int) -> bool:
    """Commit the consistent map ``s``'s answer as the step to ``k``: its
    tractions, its statuses (a partial point ``STICK``), the warning; False
    where its residual fails RESIDUAL_FAIL."""
    ranks = search.ranks
    response = search.response(s, y, tau, P)
    status = response.status
    R, _, _ = newton._residual(u, search.b, response)
    relative = ranks.max(float(np.max(np.abs(R[newton.free]), initial=0.0))) / search.scale
    if not relative <= tol.RESIDUAL_FAIL:
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
    points, theta = user_points(newton.scene, points[order]), theta[order]
    listed = ", ".join(f"({x:.4g}, {z:.4g}) θ = {t:.3g}" for (x, z), t in zip(points, theta))
    newton.report.warnings.append(
        f"{where}: Newton found no open/closed map of the unilateral law consistent at every point; {len(points)} point(s) of Γ "
        f"hold y_N = 0 with a share θ of the tie's shear (the law's two branches mixed, Filippov's answer at its "
        f"jump; docs/contact-enforcement.md, \"The unilateral law under shear\"): {listed}")
    return True
