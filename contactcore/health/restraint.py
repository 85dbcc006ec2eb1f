"""Rigid-body restraint: whether the supports, pins and Γ hold the six rigid
modes of the two bodies.

The modes are each body's two translations and its rotation about the
domain's centre (:func:`modes_centre`), lengths over the scene's length
scale ``L``: at a point ``x`` of a body, ``u = (r₁ − r₃ d_y, r₂ + r₃ d_x)``
with ``d = (x − centre)/L`` (:func:`_modes`, :func:`_mode_matrix`).  Their
restraint, relative to the stiffer modulus ``E``, is (:func:`_restraint`)

    Q = Σ_held (mean over x of M_c(x)ᵀ M_c(x)) + Σ_Γ w (κ_N g_N g_Nᵀ + κ_T g_T g_Tᵀ),
    κ_c = min(k_c / E, 1 / Σ_Γ w),

``M_c(x)`` (1×6) the held component ``c`` of the modes at a support's
sampled points (a pin's point), ``g_N``, ``g_T`` (6,) the normal and
tangential jumps the modes make at a point of Γ: a support holds like E
per held component, a spring stiffer than E per |Γ| like a support, a law
enforced exactly like the stiffest spring, and frictionless contact holds
no shear.  A mode ``Q`` holds by at most ``RIGID_MODE_FREE`` is free
(:func:`_free_modes`).

Before any solve :func:`check_restraint` refuses a scene that leaves a
mode free, naming the body, the motion and why.  During Newton,
:func:`lets_go` asks the same of a status map's closed points (a body that
Γ has let go makes the tangent singular) and :func:`slips_free` of its
sticking ones (a slipping point holds normally only), and
:func:`check_held` refuses a converged answer that leaves a body free
(:class:`FreeBody`): its position is not determined.  They read the status
map and the geometry only, never a factorisation, whose null pivots
round-off decides.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol
from ..errors import SolverError
from ..geometry import Disc, LineInterface, tangent_of
from ..laws import OPEN, STICK
from .stiffness import _springs


#: Sample points per support boundary in the rigid-mode check (three
#: non-collinear points suffice; more make the check independent of them).
_SUPPORT_SAMPLES = 16

#: Points per support boundary searched for a body's part of it that the
#: coarse samples miss: Γ crossing an edge within 1/(2·_SUPPORT_SAMPLES)
#: of its end leaves that body's part of the support unsampled, and the
#: body was taken for held by Γ alone (review5: a block clamped on the top
#: 0.03 of its left edge refused as "slides off (no equilibrium)", and
#: Newton steered as for a free body).  Such a part is sampled this finely.
_SUPPORT_SEARCH = 1024


def _frictionless(scene) -> bool:
    """A Coulomb law with μ = 0: every closed point slips, Γ holds no shear."""
    return getattr(scene.law, "mu", None) == 0.0


_BODY_NAMES = ("−", "+")


def modes_centre(domain) -> np.ndarray:
    """The point the rigid modes (:func:`_modes`) turn about: a disc's
    centre, a rectangle's middle."""
    return np.asarray(domain.centre, float) if isinstance(domain, Disc) else np.mean(domain.corners, axis=0)


def _modes(points: np.ndarray, bodies: np.ndarray, centre: np.ndarray, length: float) -> np.ndarray:
    """(m, 2, 6): displacement of each point under the six rigid modes
    (body −: x, y, rotation; body +: x, y, rotation), zero off the point's body."""
    out = np.zeros((len(points), 2, 6))
    d = (points - centre) / length
    for b in (0, 1):
        on = bodies == b
        out[on, 0, 3 * b] = 1.0
        out[on, 1, 3 * b + 1] = 1.0
        out[on, 0, 3 * b + 2] = -d[on, 1]
        out[on, 1, 3 * b + 2] = d[on, 0]
    return out


def _mode_matrix(x, centre, L) -> np.ndarray:
    """(2, 3): the displacement at ``x`` of one body's rigid modes (x, y,
    rotation), as :func:`_modes` has them."""
    d = (np.asarray(x, float) - centre) / L
    return np.array([[1.0, 0.0, -d[1]], [0.0, 1.0, d[0]]])


def _boundary_points(domain, name: str, count: int = _SUPPORT_SAMPLES) -> np.ndarray:
    """``count`` evenly spaced points on the named boundary (an edge, or the rim)."""
    s = (np.arange(count) + 0.5) / count
    if isinstance(domain, Disc):
        a = 2 * np.pi * s
        return np.column_stack([domain.centre[0] + domain.radius * np.cos(a),
                                domain.centre[1] + domain.radius * np.sin(a)])
    c = domain.corners
    i, j = {"bottom": (0, 1), "right": (1, 2), "top": (2, 3), "left": (3, 0)}[name]
    return c[i] + s[:, None] * (c[j] - c[i])


def _support_samples(scene, support) -> list:
    """``(points, fix, weight)`` of a support: its boundary's
    :data:`_SUPPORT_SAMPLES` points (weight 1/count each, a mean over the
    boundary), and, for a body whose part of the boundary none of them
    lies on, that part's points among :data:`_SUPPORT_SEARCH` (weight
    1/_SUPPORT_SEARCH each): a support holds each body along its part of
    the edge, however short."""
    dom = scene.domain
    coarse = _boundary_points(dom, support.boundary)
    out = [(coarse, support.fix, 1.0 / _SUPPORT_SAMPLES)]
    fine = _boundary_points(dom, support.boundary, _SUPPORT_SEARCH)
    found, on = set(scene.body_of(coarse).tolist()), scene.body_of(fine)
    for b in (0, 1):
        if b not in found and np.any(on == b):
            out.append((fine[on == b], support.fix, 1.0 / _SUPPORT_SEARCH))
    return out


#: How many scenes' restraint geometry :func:`_geometry` keeps (a run's
#: Newton asks of one scene and one Γ; a coarser first map's of a second Γ).
_GEOMETRY_KEPT = 4

_geometry_kept: list = []  # (scene, Γ's points and weights as bytes, geometry), last used last


def _geometry(scene, interface_points, interface_weights):
    """What :func:`_restraint` reads of the scene and Γ's points alone,
    whatever the status map: the supports' and pins' restraint ``Q₀``, E,
    and at Γ's points the normal and tangential jumps ``g_N``, ``g_T`` the
    modes make.  Newton asks :func:`lets_go`, :func:`slips_free` and
    :func:`check_held` of every map it solves or accepts, on the same scene
    and Γ, so these are kept for the last :data:`_GEOMETRY_KEPT` (scene
    object, Γ's points and weights by value): the same arrays, computed
    once, give the same figures bit for bit.  A kept entry holds its scene,
    so no other scene can take its ``id``."""
    pts = np.asarray(interface_points, float)
    w = np.asarray(interface_weights, float)
    key = (pts.shape, pts.tobytes(), w.tobytes())
    for i, (kept_scene, kept_key, geometry) in enumerate(_geometry_kept):
        if kept_scene is scene and kept_key == key:
            _geometry_kept.append(_geometry_kept.pop(i))
            return geometry
    E = max(m.E for m in scene.materials.values())
    dom = scene.domain
    centre = modes_centre(dom)
    L = scene.length_scale
    Q = np.zeros((6, 6))
    held = []
    for s in scene.supports:
        held += _support_samples(scene, s)
    held += [(np.asarray([p.point], float), p.fix, 1.0) for p in scene.pins]
    for hpts, fix, weight in held:
        M = _modes(hpts, scene.body_of(hpts), centre, L)
        for c in (0, 1):
            if "xy"[c] in fix:
                Q += weight * M[:, c, :].T @ M[:, c, :]
    gN = gT = None
    if len(pts):
        n = scene.interface.normals(pts)
        t = tangent_of(n)
        jump = _modes(pts, np.ones(len(pts), int), centre, L) - _modes(pts, np.zeros(len(pts), int), centre, L)
        gN, gT = np.einsum("mi,mij->mj", n, jump), np.einsum("mi,mij->mj", t, jump)
    geometry = E, Q, gN, gT
    for a in (Q, gN, gT):
        if a is not None:
            a.flags.writeable = False
    _geometry_kept.append((scene, key, geometry))
    del _geometry_kept[:-_GEOMETRY_KEPT]
    return geometry


def _restraint(scene, interface_points, interface_weights, holding=None,
               gripping=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``Q`` (6×6): the stiffness of the supports (E per held component),
    pins and springs (``Σ w k g gᵀ``) against the rigid modes, relative to
    the stiffer modulus; and the spring parts ``Q_N``, ``Q_T`` alone.
    ``holding`` (m,) bool: the points of Γ whose springs hold (every point
    if None; an open point of a unilateral law holds nothing); ``gripping``
    the points among them that hold tangentially too (``holding`` if None;
    a slipping point's tangent has no ``∂t_T/∂g_T``).  The parts that do
    not depend on the map are :func:`_geometry`'s, kept."""
    E, Q, gN, gT = _geometry(scene, interface_points, interface_weights)
    w = np.asarray(interface_weights, float)
    if gN is not None:
        # a spring stiffer than E per |Γ| holds like a support; capping it
        # there keeps the eigenvalues of Q within double precision
        cap = 1.0 / np.sum(w)
        wN = w if holding is None else np.where(holding, w, 0.0)
        wT = wN if gripping is None else np.where(gripping, w, 0.0)
        # a law enforced exactly holds like the stiffest spring
        QN = (wN[:, None] * gN).T @ gN * min(getattr(scene.law, "kN", np.inf) / E, cap)
        # frictionless contact (μ = 0) carries no shear: no tangential hold
        kT = 0.0 if _frictionless(scene) else min(getattr(scene.law, "kT", np.inf) / E, cap)
        QT = (wT[:, None] * gT).T @ gT * kT
    else:
        QN = QT = np.zeros((6, 6))
    return Q + QN + QT, QN, QT


def _describe(scene, v: np.ndarray) -> str:
    """The motion of mode ``v`` (6): which body, translation or rotation."""
    parts = [np.linalg.norm(v[:3]), np.linalg.norm(v[3:])]
    if min(parts) > 0.3 * max(parts):
        who, u = "bodies − and + together", v[:3] if parts[0] >= parts[1] else v[3:]
    else:
        b = int(np.argmax(parts))
        who, u = f"body {_BODY_NAMES[b]}", v[3 * b:3 * b + 3]
    u = u / np.linalg.norm(u)
    if abs(u[2]) > np.hypot(u[0], u[1]):
        return f"{who} can rotate"
    d = u[:2] / np.linalg.norm(u[:2])
    if isinstance(scene.interface, LineInterface):
        nrm = np.asarray(scene.interface.normal, float)
        if abs(d @ nrm) < 0.1:
            return f"{who} can slide along Γ"
        if abs(d @ nrm) > 0.99:
            return f"{who} can move normal to Γ"
    d = np.round(d, 2) + 0.0  # the direction as shown: round-off of a motion along an axis is no component
    return f"{who} can translate along ({d[0]:.2g}, {d[1]:.2g})"


def _free_modes(Q: np.ndarray) -> np.ndarray:
    """(6, f): the rigid-body modes ``Q`` holds by at most RIGID_MODE_FREE."""
    lam, vec = np.linalg.eigh(Q)
    return vec[:, lam <= tol.RIGID_MODE_FREE]


def check_restraint(scene, interface_points, interface_weights) -> None:
    """Refuse a scene whose supports, pins and springs leave a rigid-body
    mode free: an eigenvalue of the restraint ``Q`` (relative to E) below
    ``RIGID_MODE_FREE``.  The message names the body, the motion and why
    (a negligible spring, or no support)."""
    Q, QN, QT = _restraint(scene, interface_points, interface_weights)
    free = _free_modes(Q)
    if not free.shape[1]:
        return
    v = free[:, 0]
    why = [f"k_{c} is {k_user:.3g}" for (c, _, k_user), Qc in zip(_springs(scene), (QN, QT))
           if 0 < np.trace(Qc) <= tol.RIGID_MODE_FREE]
    why = " and ".join(why) + " (springs lost in round-off beside E)" if why else (
        "no support or pin holds it that way, and Γ is frictionless (μ = 0): its contact carries no shear"
        if _frictionless(scene) else "no support or pin holds it that way")
    raise SolverError(f"scene {scene.name}: {_describe(scene, v)}: {why} — {free.shape[1]} rigid-body mode(s) "
                      "are not removed by the supports, pins and interface springs; add a support or pin")


class FreeBody(SolverError):
    """Newton converged where Γ no longer holds a body that nothing else
    holds (:func:`check_held`): the answer exists but does not fix that
    body's position, so no smaller step or other stabilisation helps."""


def _let_go(scene, interface_points, interface_weights, status) -> np.ndarray:
    """(6, f): the rigid-body modes that the supports, pins and the points
    of Γ not open in ``status`` (m,) leave free (:func:`_restraint`,
    :func:`_free_modes`).

    At an open point the law's tangent ``D`` is zero.  A rigid motion ``r``
    of one body strains nothing (``A r = 0``) and has no consistent
    traction (``S r = 0``, so ``C r = 0`` and ``G̃ r = G r``), so the
    tangent ``J = A + C + Tᵀ W D G̃`` (the penalty's ``A + Gᵀ W D G``) gives
    ``J r = 0`` wherever ``G r`` vanishes at every closed point: ``J`` is
    singular in exact arithmetic, and only round-off decides whether a
    factorisation says so (MUMPS's null pivots) or returns a rigid motion
    of round-off size.  This reads the status map and the geometry only,
    not the factorisation; the map itself is decided within Newton's
    round-off band (:class:`~contactcore.laws.Decision`; a point at rest,
    its margin round-off, is closed and sticks: REST_ROUNDOFF's note).  A
    slipping point counts as holding tangentially: a body held by slipping
    points alone is left to Newton's
    secant step (:func:`contactcore.laws.secant_tangent`), exact or
    penalty (:func:`slips_free`)."""
    holding = np.asarray(status) != OPEN
    if holding.all():
        return np.zeros((6, 0))
    return _free_modes(_restraint(scene, interface_points, interface_weights, holding)[0])


def lets_go(scene, interface_points, interface_weights, status) -> bool:
    """Whether the status map ``status`` leaves a rigid-body mode free
    (:func:`_let_go`): its tangent is singular."""
    return bool(_let_go(scene, interface_points, interface_weights, status).shape[1])


def slips_free(scene, interface_points, interface_weights, status) -> bool:
    """Whether the status map ``status`` leaves a rigid-body mode free once
    its slipping points hold normally only (:func:`_restraint`): a Coulomb
    point's slip tangent has no ``∂t_T/∂g_T``, so a rigid motion ``r`` of a
    body held by Γ alone with no normal jump at any closed point and no
    jump at any sticking one has ``J r = 0`` — a disc turning in its hole,
    a rod sliding along a straight Γ, with every closed point slipping.
    Like :func:`lets_go` this reads the map and the geometry (Γ's own
    normals), never a factorisation, whose null pivots round-off decides."""
    status = np.asarray(status)
    if (status == STICK).all():
        return False
    Q = _restraint(scene, interface_points, interface_weights, status != OPEN, status == STICK)[0]
    return bool(_free_modes(Q).shape[1])


def check_held(scene, interface_points, interface_weights, status, where: str) -> None:
    """Refuse a converged answer whose status map ``status`` leaves a
    rigid-body mode free (:func:`_let_go`): a small motion in that mode
    keeps every open point open and every closed point's jump, so it
    solves the same equations, and the body's position is not determined.
    ``where`` (the scene and increment) starts the one-line
    :class:`FreeBody` error."""
    free = _let_go(scene, interface_points, interface_weights, status)
    if not free.shape[1]:
        return
    closed = int(np.count_nonzero(np.asarray(status) != OPEN))
    held = f"only {closed} of {len(status)} points of Γ stay closed" if closed else "Γ is open at every point"
    more = f" ({free.shape[1]} rigid-body modes are free)" if free.shape[1] > 1 else ""
    raise FreeBody(f"{where}: {_describe(scene, free[:, 0])}{more}: no support or pin holds it that way and {held}, so its "
                   "position is not determined; hold it with a support or pin, or with springs that carry tension "
                   "(type = \"linear\")")
