"""Whether the loads leave an equilibrium: the diagnosis of an increment
that found none.

A body held by Γ alone under boundary tractions and pressures is in
equilibrium only if their resultant ``F`` presses it onto a straight Γ
with ``|F·t|`` within what the law's slip bound carries over Γ
(``μ |F·n|``, Coulomb's cone integrated over Γ, Wriggers 2006, §2.3; any
frictional law's :meth:`~contactcore.laws._Law.slides_off`); a law that
cannot slip ties a closed point tangentially, μ = ∞
(:func:`friction_demand`, :func:`_demands`).  A body its supports and pins
hold in part is refused when the loads do positive work in a rigid motion
they leave free that opens Γ without sliding (:func:`_pulled_off`): contact
only pushes.  The unilateral law's tie under shear may admit no consistent
open/closed map (Dundurs, J. Appl. Mech. 1969; Comninou, J. Appl. Mech.
1977): :func:`tie_cause` names it from every cut-back's failure.

The loads are read on a rectangle cut by a line: the edge loads (as
each declares, :func:`contactcore.scene.place_of`; tractions, pressures)
on each body's part of each loaded edge (:func:`_part`, φ linear along
the edge), by their formula (:func:`contactcore.scene.edge_traction`),
their resultant (:func:`_boundary_resultant`) and their work in the
body's rigid modes (:func:`_load_work`; a uniform load's work in a linear
motion is its resultant's at the part's midpoint, a varying one's is
summed over three Gauss points), with each constant body force
(``body_force``) on the body's part of the rectangle (:func:`_body_parts`:
its resultant acts at the part's centroid, exact for its work in a linear
motion too); a body under any other body load is not judged.
"""
from __future__ import annotations

import math

import numpy as np

from .. import tolerances as tol
from ..geometry import clip_halfplane, LineInterface, polygon_area, polygon_centroid, Rectangle, tangent_of
from ..scaling import user_points
from ..scene.loads import BODY, BodyForce, EDGE, edge_traction, place_of
from .residual import NOT_CONVERGED
from .overturning import eccentricity, overturn_refusal, overturned
from .restraint import _BODY_NAMES, _free_modes, _mode_matrix, _restraint


def friction_demand(scene, k: float) -> str:
    """The check a failure of a law that can open turns on, or "": a body
    held by Γ alone (no support or pin on it) under boundary tractions and
    pressures is in equilibrium only if their resultant ``F`` presses it
    onto a straight Γ with ``|F·t|`` within the law's slip bound over Γ
    (``law.slides_off``; Coulomb: ``μ |F·n|``, the cone integrated over Γ,
    Wriggers 2006, §2.3).  A law that is not frictional ties a closed point
    tangentially, μ = ∞: only the press is checked.  ``F`` is the sum of
    ``factor(k)·traction·length`` over the part of each loaded edge on that
    body (φ linear along it), ``t = −p n_out`` for a pressure.  A body whose
    supports and pins hold some directions but leave it free to move off Γ
    (an x-roller leaves a block above a horizontal Γ free in y) is refused
    when the loads do positive work in such a motion (:func:`_pulled_off`):
    Γ's contact pushes only, so it cannot hold them.  Only a rectangle cut
    by a line is judged here, its body forces counted where they are
    constant (:func:`_body_parts`; since 2026-11-30, fix39: a body pulled
    off Γ against its weight was judged not at all, and told by
    :func:`tie_cause` to use Coulomb with a large μ), a body under another
    body load not at all."""
    if not scene.law.unilateral:  # springs that carry tension hold any load
        return ""
    for name, shear, press, held, e in _demands(scene, k):
        if held:
            return (f"body {name}: {held}, and the loads pull it off Γ: no equilibrium, as contact only pushes; "
                    "hold it that way with a support or pin, or with springs that carry tension (type = \"linear\")")
        if press <= 0:
            how = "pull it off Γ" if press < 0 else "lie along Γ and do not press it onto Γ"
            return f"body {name} is held by Γ alone and the loads {how}: no equilibrium without a support"
        slides = _slides_off(scene, name, shear, press)
        if slides:
            return slides
        if overturned(scene, e):
            return overturn_refusal(scene, name, e)
    return ""


def _slides_off(scene, name: str, shear: float, press: float) -> str:
    """The refusal of body ``name`` whose loads shear Γ by ``shear`` and
    press it by ``press`` > 0 beyond what the scene's frictional law
    carries over Γ (``law.slides_off`` with Γ's length: the law's words,
    Coulomb's by μ), or "" (and always for a law that is not frictional:
    it ties a closed point)."""
    ends = scene.interface.chord(scene.domain) if scene.law.frictional else None
    if ends is None:  # not frictional, or no Γ across the domain (refused as a scene)
        return ""
    a, b = np.asarray(ends, float)
    return scene.law.slides_off(name, shear, press, math.hypot(*(b - a)))


def beyond_cone(scene, k: float) -> str:
    """The refusal of a scene with a frictional law whose loads at
    increment ``k`` ask a body held by Γ alone for a shear beyond what the
    law's slip bound carries over Γ (Coulomb: a shear/normal beyond μ;
    ``law.slides_off``), or "".  Taken from the scene's data before Newton runs: Newton's
    stick/slip band (DECISION_BAND) holds a point at stick while its trial
    traction lies within 1e-5 of μp past the cone, so on a uniform load
    whose shear/normal lies at the band's edge (μ(1 + 1e-5)) the outcome
    — every point sticking, or no equilibrium — was a bare comparison of
    round-off, and followed the BLAS kernel (grader10 F1: xfem P2 refused
    under Haswell, answered under Nehalem).  A resultant beyond the cone
    proves there is no equilibrium (Wriggers 2006, §2.3), so such a load
    is refused on every machine alike, however close to μ.  Any
    frictional law is refused alike, by its slip bound (takeover31 #1: a
    threshold law below the loads' shear failed Newton after six cut-backs,
    told to use coulomb)."""
    if not scene.law.unilateral:  # springs that carry tension hold any load
        return ""
    for name, shear, press, held, e in _demands(scene, k):
        if held or press <= 0:
            continue
        slides = _slides_off(scene, name, shear, press)
        if slides:
            return slides
        if overturned(scene, e):  # any law without tension: the loads' line of action must meet Γ
            return overturn_refusal(scene, name, e)
    return ""


def _dot(a, b) -> float:
    """``a · b`` of two 2-vectors in Python floats: numpy's ``@`` may call
    BLAS, whose kernels (FMA or not) round differently by CPU."""
    return float(a[0]) * float(b[0]) + float(a[1]) * float(b[1])


def _demands(scene, k: float):
    """``(name, |F·t|, F·n pressing it onto Γ, "", e)`` of each body held
    by Γ alone and loaded (:func:`friction_demand`), at increment ``k``, F·n
    within :data:`~contactcore.tolerances.ALONG_GAMMA` of |F| taken as 0
    (F along Γ), ``e`` where the loads' line of action meets Γ's line,
    from Γ's midpoint (:func:`contactcore.health.overturning.eccentricity`;
    0 where F does not press); ``(name, 0, 0, how, 0)`` of a body its
    supports and pins hold in part, whose loads pull it off Γ in the motion
    ``how`` they leave free (:func:`_pulled_off`); none where Γ is not a
    line across a rectangle."""
    if not isinstance(scene.interface, LineInterface) or not isinstance(scene.domain, Rectangle):
        return
    n = np.asarray(scene.interface.normal, float)
    supports = _restraint(scene, np.zeros((0, 2)), np.zeros(0))[0]
    for b, name in enumerate(_BODY_NAMES):
        weight = _body_parts(scene, b, scene.factors(k)[0])
        if weight is None:
            continue
        free = _free_modes(supports[3 * b:3 * b + 3, 3 * b:3 * b + 3])
        if not free.shape[1]:
            continue
        if free.shape[1] < 3:  # held in part by its supports and pins
            how = _pulled_off(scene, b, supports[3 * b:3 * b + 3, 3 * b:3 * b + 3], k)
            if how:
                yield name, 0.0, 0.0, how, 0.0
            continue
        parts = list(_loaded_parts(scene, b, scene.factors(k)[0])) + weight
        force = _resultant(parts)
        if force.any():
            press = -_dot(force, n) if b == 1 else _dot(force, n)
            along = abs(press) <= tol.ALONG_GAMMA * math.hypot(*force)  # round-off's sign decides nothing
            e = 0.0 if along else eccentricity(scene, parts, force)
            yield name, abs(_dot(force, tangent_of(n[None])[0])), 0.0 if along else float(press), "", e


def _pulled_off(scene, body: int, Q: np.ndarray, k: float) -> str:
    """How body ``body`` (0 −, 1 +) may move off Γ against its loads, or "":
    a rigid motion ``r`` that its supports and pins leave free (``rᵀ Q r``
    within RIGID_MODE_FREE of ``|r|²``, ``Q`` their 3×3 restraint of its
    modes, :func:`_restraint`), that opens Γ everywhere without sliding
    (g_N >= 0, g_T = 0 at every point of the straight Γ), and in which the
    loads at increment ``k`` do positive work (beyond ALONG_GAMMA of
    ``|G||r|``, ``G`` their work per mode).  Such motions are the
    non-negative combinations of the turns about Γ's two ends that open
    it; contact's tractions push (t_N <= 0) and do no work along g_T = 0,
    so in that motion nothing balances the loads' work: no equilibrium,
    under a unilateral or Coulomb law alike."""
    itf, dom = scene.interface, scene.domain
    ends = itf.chord(dom)
    if ends is None:
        return ""
    ends = np.asarray(ends, float)
    centre, L = np.mean(dom.corners, axis=0), scene.length_scale
    n, sign = np.asarray(itf.normal, float), 1.0 if body == 1 else -1.0  # the jump is + minus −

    def opening(p, q):
        """The turn about ``p`` (unit) that opens Γ at its other end ``q``."""
        dp = (p - centre) / L
        r = np.array([dp[1], -dp[0], 1.0])
        gap = sign * n @ (_mode_matrix(q, centre, L) @ r)
        return r * np.sign(gap) / np.linalg.norm(r)

    a, c = opening(ends[0], ends[1]), opening(ends[1], ends[0])
    G = _load_work(scene, body, centre, L, scene.factors(k)[0])
    if not G.any():
        return ""
    # q(α) = r(α)ᵀ Q r(α), r(α) = α a + (1 − α) c: convex; its free set is an interval about its minimum
    d = a - c
    A, B = d @ Q @ d, 2 * c @ Q @ d
    candidates = {0.0, 1.0, float(np.clip(-B / (2 * A), 0.0, 1.0)) if A > 0 else 0.0}
    for alpha in sorted(candidates):
        r = alpha * a + (1 - alpha) * c
        size = r @ r
        if size > 0 and r @ Q @ r <= tol.RIGID_MODE_FREE * size and \
                G @ r > tol.ALONG_GAMMA * np.linalg.norm(G) * np.sqrt(size):
            if abs(r[2]) <= tol.ALONG_GAMMA * np.sqrt(size):
                return "its supports and pins leave it free to move straight off Γ"
            pivot = user_points(scene, centre + L * np.array([-r[1], r[0]]) / r[2])  # named in the user's terms
            return f"its supports and pins leave it free to turn off Γ about ({pivot[0]:.4g}, {pivot[1]:.4g})"
    return ""


def tie_cause(scene, k: float, failure: str, from_rest: bool = False) -> str:
    """Why a unilateral law's increment ``k`` failed, or "": another law,
    or a ``failure`` (every cut-back's message, one a line) where Newton
    never ran out of iterations (a solve that failed is not the tie's).
    Every cut-back's, not the last one's alone: how that one failed (out
    of iterations, null pivots, a residual) round-off may choose.
    The law ties a closed point (``t_T = k_T g_T``; exactly, ``g_T = 0``
    with any ``t_T``) and frees it the moment it opens (``t_T = 0``):
    ``t_T`` is not monotone in the jump.  Where Γ opens under shear, the
    last closed points carry the tie's shear on almost no pressure (a
    median 20 times their |t_N| on the points Newton flips); opening one
    hands that shear to its neighbours, and shear across an interface of
    two materials moves its normal gap (Dundurs' β, J. Appl. Mech. 1969;
    a bonded edge makes the open faces overlap, Comninou, J. Appl. Mech.
    1977), so a map consistent at every point need not exist, and is
    found at some h and degrees and not at others, in no order that
    holds across scenes: finer h and degree 2 failed more often on the
    tilted block, less often on a partly open block under shear (grader16
    F1; docs/contact-enforcement.md, "The unilateral law under shear").
    Coulomb's ``|t_T| <= μ|t_N|`` lets the shear vanish with the pressure;
    μ must exceed the loads' shear/normal on a body held by Γ alone.  A
    frictional law of any slip bound is not the tie, and gets "" here.  An
    increment ``from_rest`` along a straight path is the same problem at
    any size (``from_rest`` holds only for a law that declares itself
    positively homogeneous, ``law.homogeneous``), so more increments do
    not help it.  Taken for any law that can open and has no friction
    (``law.unilateral``, not ``law.frictional``), named as the scene names it."""
    if not scene.law.unilateral or scene.law.frictional or NOT_CONVERGED not in failure:
        return ""
    ratios = [f"{shear / press:.3g} on body {name}" for name, shear, press, *_ in _demands(scene, k) if press > 0]
    mu = f"mu a few times the loads' shear/normal ({ratios[0]})" if ratios else "a large mu"
    exact = scene.law.enforcement == "exact"
    more = "more increments do not help" if from_rest else "more increments help only where a consistent map exists"
    other = "another stabilisation seldom helps" if exact else "soften k_N, k_T to settle it, with their answer"
    return (f"Newton found no open/closed map of the {scene.law.name} law consistent at every point (under shear "
            f"there may be none; another h or degree may settle it or not; {more}; {other}); "
            f"use type = \"coulomb\" with {mu}")


def _loaded_parts(scene, body: int, factors):
    """Each edge load on an edge of the rectangle, on ``body``'s part of
    that edge (:func:`_part`): ``(t, length, point)``, ``t`` the traction
    vector at ``point`` by the load's formula
    (:func:`contactcore.scene.edge_traction`) at its factor of
    ``factors``: the part's midpoint and its whole length where the
    traction is the same at the part's three Gauss points (a uniform load,
    whose work in a rigid motion is its resultant's there), else those
    three points with their shares of the length (exact for a traction
    quadratic along the edge: resultant and moment)."""
    c = scene.domain.corners
    for load, f in zip(scene.loads, factors):
        if place_of(load) != EDGE:
            continue
        i, j = {"bottom": (0, 1), "right": (1, 2), "top": (2, 3), "left": (3, 0)}[load.boundary]
        lo, hi = _part(*scene.interface.phi(c[[i, j]]), body)
        if hi <= lo:
            continue
        edge = c[j] - c[i]
        size = math.hypot(*edge)  # not np.linalg.norm: BLAS's dot, whose rounding follows the CPU
        out = np.array([edge[1], -edge[0]]) / size  # corners counter-clockwise
        at = c[i] + np.outer(lo + _GAUSS3 * (hi - lo), edge)
        t = edge_traction(scene, load, at[:, 0], at[:, 1], np.tile(out, (3, 1)))
        if np.all(t == t[1]):
            yield f * t[1], (hi - lo) * size, c[i] + 0.5 * (lo + hi) * edge
            continue
        for tk, wk, xk in zip(t, _GAUSS3_WEIGHTS, at):
            yield f * tk, wk * (hi - lo) * size, xk


#: Gauss-Legendre's three points on [0, 1] and their weights.
_GAUSS3 = np.array([0.5 - 0.5 * math.sqrt(0.6), 0.5, 0.5 + 0.5 * math.sqrt(0.6)])
_GAUSS3_WEIGHTS = (5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0)


def _load_work(scene, body: int, centre, L, factors) -> np.ndarray:
    """(3,): the work of the tractions and pressures on ``body``'s part of
    each loaded edge of the rectangle, and of its constant body forces
    (:func:`_body_parts`), in its rigid modes (:func:`_modes`, about
    ``centre``, lengths over ``L``): a uniform load's work in a linear
    motion is its resultant's at the part's midpoint (centroid)."""
    work = np.zeros(3)
    for t, length, mid in list(_loaded_parts(scene, body, factors)) + (_body_parts(scene, body, factors) or []):
        work += length * (t @ _mode_matrix(mid, centre, L))
    return work


def _body_parts(scene, body: int, factors) -> list | None:
    """``[(b, area, centroid)]``: each constant body force ``b`` (at its
    factor of ``factors``) on ``body``'s part of the rectangle (0 −, 1 +:
    the rectangle clipped to that side of Γ's line), whose resultant
    ``b·area`` acts at the part's centroid, as
    :func:`_loaded_parts`' ``(t, length, point)``; [] with none; None
    where another body load acts on it (not judged)."""
    loads = [(ld, f) for ld, f in zip(scene.loads, factors)
             if place_of(ld) == BODY and ld.body == ("minus", "plus")[body]]
    if any(not isinstance(ld, BodyForce) for ld, _ in loads):
        return None
    if not loads:
        return []
    line = scene.interface if body == 0 else LineInterface(scene.interface.point,
                                                           tuple(-c for c in scene.interface.normal))
    part = clip_halfplane(scene.domain.corners, line)  # the side φ <= 0 of ``line``
    area, centroid = polygon_area(part), polygon_centroid(part)
    return [(f * np.asarray(ld.value, float), area, centroid) for ld, f in loads]


def _part(phi_a: float, phi_b: float, body: int) -> tuple[float, float]:
    """The part ``[lo, hi]`` (of [0, 1] along an edge) on ``body``, φ
    linear along it (a straight Γ) with ``phi_a``, ``phi_b`` at its ends
    (0: φ < 0, 1: φ > 0)."""
    if (phi_a > 0) == (phi_b > 0):
        on = (phi_a + phi_b > 0) == (body == 1)
        return (0.0, 1.0) if on else (0.0, 0.0)
    cut = phi_a / (phi_a - phi_b)
    plus = (0.0, cut) if phi_a > 0 else (cut, 1.0)
    return plus if body == 1 else ((cut, 1.0) if phi_a > 0 else (0.0, cut))


def _boundary_resultant(scene, body: int, factors) -> np.ndarray:
    """The resultant of the tractions and pressures on the part of each
    loaded edge of the rectangle that lies on ``body`` (0 −, 1 +)."""
    return _resultant(_loaded_parts(scene, body, factors))


def _resultant(parts) -> np.ndarray:
    """``Σ t·length`` of :func:`_loaded_parts`' ``(t, length, point)``."""
    return sum((t * length for t, length, _ in parts), np.zeros(2))
