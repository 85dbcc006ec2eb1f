"""The rigid slide of a body that Γ's slipping points alone hold.

Where every closed point of a body held by Γ alone slips (or all but the
sticking points leave a rigid motion free, :func:`contactcore.health.slips_free`),
the penalty Coulomb law's tangent is singular along that rigid motion ``r``
(a block sliding along a straight Γ, a disc turning in its hole).  The
body's force along ``r``,

    φ(c) = rᵀ R(u + c r) = rᵀ R(u) + Σ w ρ·[t(g + c ρ) − t(g)],    ρ = G r,

(``A r = 0``: a rigid motion strains nothing) is then a staircase in ``c``:
flat where every point slips, a riser ``k_T w ρ_T²`` wide ``2μp/k_T`` where
one point's trial crosses its stick window.  With stiff springs the window
is far narrower than the slide Newton must find (the wedge of
tests/scenes/wedge_slide.toml: windows 2μp/k_T of 5e-5 mm, a slide of 3e-2 mm), so
Newton's steps and Kačanov's secant steps land on a tread and creep, and
halvings or doublings of a step almost never hit a riser.  φ is monotone
(each term is ``k_T ρ_T² ≥ 0`` or 0 in ``c``) and piecewise linear with
its kinks at the points' window edges, so its root is found exactly: the
kinks sorted, bisected for φ's sign change, and the bracketing segment
interpolated.  Its point then sticks, the map's tangent is regular, and
Newton goes on from there (:meth:`contactcore.newton._Newton._iterate`).

Only for a penalty law that is frictional (its ``slip_bound``, Coulomb's
``μp`` or any other, read at each point's normal traction, which the
slide does not change), a map with no open point, one free mode,
and a mode with no normal jump at any point of Γ (a slide along a straight
Γ, a turn in a round one): the normal tractions are then the same all along
``c``.  Where Γ opens, Newton's secant and pinned steps are left as they
were: on the squeezed disc of tests/free_disc.py (penalty, fe P1, h = 0.2,
open poles) a slide at every free map cycled through five maps, failing
after six cut-backs, where those steps converge in 5 (measured 2026-11-27).

The mode in the unknowns is ``r = J_stick⁻¹ Gᵀ W D g_r`` (``J_stick`` the tangent where
every point sticks, ``D = diag(k_N, k_T)``, ``g_r`` the rigid motion's jumps
at Γ's points): the discrete rigid motion of the held body (zero on the
other, whose supports hold it) satisfies ``A r = 0`` and ``G r = g_r``, so
it solves that system exactly whatever the springs.  It is checked
(``G r`` against ``g_r``) and the slide is not taken where it fails.
"""
from __future__ import annotations

import numpy as np

from . import health
from . import tolerances as tol
from .geometry import tangent_of
from .health.restraint import _free_modes, _modes, _restraint
from .laws import OPEN, STICK


def _free_motion(scene, points, weights, status):
    """The one rigid motion (a 6-vector of :func:`contactcore.health.restraint._modes`)
    the ``status`` map leaves free once its slipping points hold normally
    only, or None unless exactly one is free."""
    Q = _restraint(scene, points, weights, status != OPEN, status == STICK)[0]
    free = _free_modes(Q)
    return free[:, 0] if free.shape[1] == 1 else None


def _jumps(scene, motion, points) -> np.ndarray:
    """(m, 2) ``[g_N, g_T]`` at ``points`` of the rigid ``motion``."""
    centre, L = health.modes_centre(scene.domain), scene.length_scale
    move = (_modes(points, np.ones(len(points), int), centre, L)
            - _modes(points, np.zeros(len(points), int), centre, L)) @ motion
    n = scene.interface.normals(points)
    return np.column_stack([np.einsum("mi,mi->m", n, move), np.einsum("mi,mi->m", tangent_of(n), move)])


def _mode(newton, g_r_local: np.ndarray, scale: float):
    """The free motion in the unknowns (module doc), or None where the
    solve does not reproduce its jumps ``g_r_local`` (this rank's points)."""
    law, itf = newton.law, newton.itf
    stick = np.zeros((itf.size, 2, 2))
    stick[:, 0, 0], stick[:, 1, 1] = law.kN, law.kT
    rhs = itf.forces(g_r_local * np.array([law.kN, law.kT]))
    rhs[newton.system.fixed] = 0.0
    r, rep = newton.factorisations.solve(stick, rhs, scale)
    newton.record(rep)
    r[newton.system.fixed] = 0.0
    miss = newton.ranks.max(float(np.max(np.abs(itf.jumps(r) - g_r_local), initial=0.0)))
    return r if miss <= tol.SLIDE_MODE_MISS else None


def slide(newton, u: np.ndarray, b: np.ndarray, R: np.ndarray, response, scale: float):
    """``(u + c r, (response, residual))`` at the root ``c`` of the free
    body's force ``φ`` along its rigid motion ``r`` (module doc), where the
    map of ``response`` is closed everywhere and slips free, and the slide
    leaves a point sticking; None elsewhere (Newton then takes its secant
    step), and where φ has no root: every point slips one way and the
    loads still move the body (no equilibrium, which the refusal then
    names, :func:`contactcore.health.friction_demand`)."""
    law, itf, ranks = newton.law, newton.itf, newton.ranks
    if itf.exact or not law.frictional or response.secant is None:
        return None
    points, status = newton._gamma[0], ranks.gather(response.status)
    if np.any(status == OPEN) or not health.slips_free(newton.scene, *newton._gamma, status):
        return None
    motion = _free_motion(newton.scene, *newton._gamma, status)
    if motion is None:
        return None
    # a slide along Γ: no normal jump anywhere (unit: the largest |g_T|)
    g_all = _jumps(newton.scene, motion, points)
    top = np.max(np.abs(g_all[:, 1]), initial=0.0)
    if top == 0.0 or np.max(np.abs(g_all[:, 0])) > tol.SLIDE_NORMAL_SHARE * top:
        return None
    g_r = _jumps(newton.scene, motion, itf.points) / top
    r = _mode(newton, g_r, scale)
    if r is None:
        return None
    # the kinks of φ: where a closed point's trial k_T (g_T + c ρ_T − s) reaches ± its slip bound
    g = itf.jumps(u)
    rho = itf.jumps(r)[:, 1]
    s = np.zeros(itf.size) if newton.state is None else np.asarray(newton.state, float)
    closed = response.status != OPEN
    limit = np.where(closed, law.slip_bound(response.traction[:, 0]), 0.0)  # the law's, any bound (laws' module doc)
    moving = closed & (rho != 0.0)
    kinks = np.concatenate([((sign * limit - law.kT * (g[:, 1] - s)) / (law.kT * rho))[moving] for sign in (-1, 1)])
    kinks = np.unique(ranks.gather(kinks))
    if not len(kinks):
        return None
    base = ranks.sum(float(r[newton.free] @ R[newton.free]))
    w = itf.weights

    def phi(c: float) -> float:
        trial = law.kT * (g[:, 1] + c * rho - s)
        tT = np.where(closed, np.clip(trial, -limit, limit), 0.0)
        return base + ranks.sum(float(np.sum(w * rho * (tT - response.traction[:, 1]))))

    lo, hi = 0, len(kinks) - 1
    f_lo, f_hi = phi(kinks[lo]), phi(kinks[hi])
    if f_lo > 0 or f_hi < 0:
        return None  # every point slips one way and the body's force stays: no root along r
    while hi - lo > 1:
        mid = (lo + hi) // 2
        f = phi(kinks[mid])
        if f < 0:
            lo, f_lo = mid, f
        else:
            hi, f_hi = mid, f
    c = 0.5 * (kinks[lo] + kinks[hi]) if f_hi == f_lo else kinks[lo] - f_lo * (kinks[hi] - kinks[lo]) / (f_hi - f_lo)
    trial = u + c * r
    moved = itf.respond(law, trial, newton.state, response.status, ranks)
    if health.slips_free(newton.scene, *newton._gamma, ranks.gather(moved.status)):
        return None
    return trial, (moved, newton._residual(trial, b, moved))
