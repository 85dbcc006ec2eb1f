"""One health policy for every solve of every method.

A solve of ``A x = b`` succeeds only if the *relative residual* of the
equations actually solved (the free block) is small:

    ρ = ‖b − A x‖∞ / max(‖b‖∞, F) <= RESIDUAL_FAIL,

``F`` the internal-force scale of a Newton iteration (0 for a plain linear
solve).  The normwise backward error ``‖b − A x‖/(‖A‖‖x‖ + ‖b‖)`` is
reported beside it, never instead: for a (nearly) singular ``A`` a huge
``x`` makes it tiny while ``ρ`` stays O(1).

Before any solve, :func:`check_springs` refuses springs so stiff that the
bulk is lost in their rows, and :func:`check_restraint` asks whether the supports, pins
and interface springs remove the six rigid-body modes of the two bodies; a
mode held by less than ``RIGID_MODE_FREE·E`` (springs lost in round-off, a
missing support) is refused with the body and the missing support named.
During Newton, :func:`lets_go` asks the same of each status map's closed
points (a body that Γ has let go makes the tangent singular), and
:func:`check_held` refuses a converged answer that leaves a body free:
its position is not determined.
:func:`material_warnings` warns about volumetric locking near ν = 0.5, and
about Coulomb friction across two materials beyond the uniqueness bound
μ|β_Dundurs| (:func:`dundurs_warnings`); :func:`friction_excess_warnings`
about points a converged path holds at stick beyond μ|t_N|.
A method may refuse more before its solve: :func:`check_friction_springs`
(EFGM) penalty Coulomb springs that dwarf the softer body.
"""
from __future__ import annotations

import numpy as np

from . import tolerances as tol
from .errors import SolverError
from .geometry import Disc, LineInterface, Rectangle, tangent_of
from .laws import OPEN, STICK
from .scaling import Scales

#: Sample points per support boundary in the rigid-mode check (three
#: non-collinear points suffice; more make the check independent of them).
_SUPPORT_SAMPLES = 16


def _inf(v) -> float:
    v = np.asarray(v)
    return float(np.max(np.abs(v))) if v.size else 0.0


def relative_residual(r, b, force_scale: float = 0.0) -> float:
    """``‖r‖∞ / max(‖b‖∞, F)`` (``‖r‖∞`` itself when both are zero)."""
    scale = max(_inf(b), force_scale)
    return _inf(r) / scale if scale > 0 else _inf(r)


def backward_error(r, a_norm: float, x, b) -> float:
    """Normwise backward error ``‖r‖∞ / (‖A‖∞‖x‖∞ + ‖b‖∞)`` (reported only)."""
    scale = a_norm * _inf(x) + _inf(b)
    return _inf(r) / scale if scale > 0 else _inf(r)


def check_residual(residual: float, what: str, backward: float = float("nan"), hint: str = "") -> None:
    """Raise :class:`SolverError` unless ``residual <= RESIDUAL_FAIL`` (NaN fails)."""
    if not residual <= tol.RESIDUAL_FAIL:
        raise SolverError(f"{what}: relative residual {residual:.2e} exceeds {tol.RESIDUAL_FAIL:g} "
                          f"(backward error {backward:.1e}) — the answer does not satisfy the equations"
                          + (f"; {hint}" if hint else "; a rigid-body mode may be free, or the springs are too "
                             "stiff or too soft for double precision"))


def failure_hint(scene, weights) -> str:
    """Why a solve may fail, naming the springs (their entries ``k w``
    against the stiffer modulus ``E``: round-off in the spring rows grows as
    eps·k w/E; a body held by springs far below E/h is nearly free)."""
    E = max(m.E for m in scene.materials.values())
    w = float(np.max(weights)) if len(weights) else 0.0
    out, unit = [], spring_unit(scene)
    for c, k, k_user in _springs(scene):
        ratio = k * w / E
        if ratio > 1 / tol.SPRING_HINT_RANGE:
            out.append(f"interface.law.k{c} = {k_user:.3g} {unit} is too stiff: k w = {ratio:.1e} E, its round-off "
                       f"(~2e-16 k w/E) swamps the bulk — soften it")
        elif ratio < tol.SPRING_HINT_RANGE:
            out.append(f"interface.law.k{c} = {k_user:.3g} {unit} is very soft: k w = {ratio:.1e} E, a body held by it "
                       "is nearly free — stiffen it or add a support")
    return "; ".join(out) or "a rigid-body mode may be nearly free"


def material_cause(scene) -> str:
    """A nearly incompressible material in plane strain (ν above
    NU_LOCKING_WARN), named with ``λ/μ = 2ν/(1 − 2ν)``: the bulk rows
    carry λ, the shear rows μ, and a solve loses about log10(λ/μ) digits
    to round-off (Hughes 2000, §4.1); "" if none."""
    if scene.plane != "strain":
        return ""
    bad = [(body, m.nu) for body, m in scene.user.materials.items() if m.nu > tol.NU_LOCKING_WARN]
    if not bad:
        return ""
    nu = max(v for _, v in bad)
    names = " and ".join(f"materials.{body}.nu" for body, _ in bad)
    return (f"{names} = {nu:.10g} in plane strain: λ/μ = {2 * nu / (1 - 2 * nu):.1e}, nearly incompressible, "
            "and the solve keeps too few digits")


def check_springs(scene, weights) -> None:
    """Refuse springs whose entries ``k w`` (w the largest quadrature weight
    on Γ) exceed ``SPRING_ENTRY_MAX·E``: the bulk stiffness (~E) added to
    those rows keeps fewer digits than the residual policy asks for, so the
    matrix itself is wrong (t_N = k g_N loses the bulk's share) and no
    residual of it can tell."""
    E = max(m.E for m in scene.materials.values())
    w = float(np.max(weights)) if len(weights) else 0.0
    for c, k, k_user in _springs(scene):
        if k * w > tol.SPRING_ENTRY_MAX * E:
            unit = spring_unit(scene)
            raise SolverError(f"interface.law.k{c}: {k_user:.3g} {unit} is too stiff for double precision here: its "
                              f"entries k w = {k * w / E:.1e} E exceed {tol.SPRING_ENTRY_MAX:.1e} E, beyond which "
                              f"the bulk stiffness in the interface rows is lost to round-off (no accurate solve "
                              f"exists); use k_{c} <= {tol.SPRING_ENTRY_MAX * E / w * k_user / k:.2e} {unit}")


def check_friction_springs(scene, h: float, limits: dict, method: str) -> None:
    """Refuse a penalty Coulomb law whose spring ``k_c`` (c = N, T)
    exceeds ``limits[c]`` times the softer body's ``E/h`` (``α = k_c h /
    E``): ``method``'s tractions at Γ's points oscillate there, and its
    stick/slip decisions with them (the measurements are in
    contactcore.tolerances, EFGM_FRICTION_SPRINGS).  Springs at the limit
    to round-off (``α`` is formed from the scene made dimensionless) are
    carried, and the largest spring the message offers is rounded down, so
    that it is carried too."""
    if getattr(scene.law, "name", None) != "coulomb" or not hasattr(scene.law, "kN"):
        return
    for c, k, k_user in _springs(scene):
        alpha, limit = k * h / scene.softer_modulus, limits[c]
        if alpha > limit * (1 + tol.LIMIT_ROUNDOFF):
            h_user, unit = h * Scales.of(scene.user).length, spring_unit(scene)
            raise SolverError(f"interface.law.k{c}: {k_user:.3g} {unit} is {alpha:.1e} times the softer body's E/h "
                              f"(h = {h_user:.3g}, {method}'s spacing), above the {limit:.0e} {method} carries for "
                              f"k_{c} under Coulomb friction: its tractions at Γ's points oscillate from point to "
                              f"point and the stick/slip decisions follow the oscillation; use k_{c} <= "
                              f"{_rounded_down(k_user * limit / alpha):.2e} {unit}, a spacing h <= "
                              f"{_rounded_down(h_user * limit / alpha):.2e} {scene.user.units.length}, or fe or xfem")


def _rounded_down(x: float, digits: int = 3) -> float:
    """``x > 0`` rounded down to ``digits`` significant digits (a limit
    quoted so that the quoted value stays within it), its round-off
    within :data:`~contactcore.tolerances.LIMIT_ROUNDOFF` rounded up."""
    unit = 10.0 ** (np.floor(np.log10(x)) - digits + 1)
    return float(np.floor(x / unit * (1 + tol.LIMIT_ROUNDOFF)) * unit)


def _springs(scene):
    """``(component, k, k in the user's units)`` of the law's springs (none
    for a law enforced exactly)."""
    if not hasattr(scene.law, "kN"):
        return ()
    user = scene.user.law
    return (("N", scene.law.kN, user.kN), ("T", scene.law.kT, user.kT))


#: How Newton's error begins when its iterations run out (contactcore.newton);
#: :func:`tie_cause` reads a failure by it.
NOT_CONVERGED = "Newton did not converge"

#: How a linear solve that PETSc reports as diverged is named
#: (contactcore.linear_solver; an iterative ``ksp_type`` out of iterations):
#: the options, not round-off, chose it, so a refusal keeps it
#: (contactcore.newton._refusal, _no_equilibrium).
DIVERGED = "the solver diverged"


def spring_unit(scene) -> str:
    """The unit a spring is named in: the scene's stress over its length
    (:class:`contactcore.scene.Units`, labels only)."""
    units = scene.user.units
    return f"{units.stress}/{units.length}"


def _frictionless(scene) -> bool:
    """A Coulomb law with μ = 0: every closed point slips, Γ holds no shear."""
    return getattr(scene.law, "mu", None) == 0.0


# ----- rigid-body modes -------------------------------------------------------

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


def _boundary_points(domain, name: str) -> np.ndarray:
    """Evenly spaced points on the named boundary (an edge, or the rim)."""
    s = (np.arange(_SUPPORT_SAMPLES) + 0.5) / _SUPPORT_SAMPLES
    if isinstance(domain, Disc):
        a = 2 * np.pi * s
        return np.column_stack([domain.centre[0] + domain.radius * np.cos(a),
                                domain.centre[1] + domain.radius * np.sin(a)])
    c = domain.corners
    i, j = {"bottom": (0, 1), "right": (1, 2), "top": (2, 3), "left": (3, 0)}[name]
    return c[i] + s[:, None] * (c[j] - c[i])


def _restraint(scene, interface_points, interface_weights, holding=None,
               gripping=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``Q`` (6×6): the stiffness of the supports (E per held component),
    pins and springs (``Σ w k g gᵀ``) against the rigid modes, relative to
    the stiffer modulus; and the spring parts ``Q_N``, ``Q_T`` alone.
    ``holding`` (m,) bool: the points of Γ whose springs hold (every point
    if None; an open point of a unilateral law holds nothing); ``gripping``
    the points among them that hold tangentially too (``holding`` if None;
    a slipping point's tangent has no ``∂t_T/∂g_T``)."""
    E = max(m.E for m in scene.materials.values())
    dom = scene.domain
    centre = modes_centre(dom)
    L = scene.length_scale
    Q = np.zeros((6, 6))
    held = [(_boundary_points(dom, s.boundary), s.fix, 1.0 / _SUPPORT_SAMPLES) for s in scene.supports]
    held += [(np.asarray([p.point], float), p.fix, 1.0) for p in scene.pins]
    for pts, fix, weight in held:
        M = _modes(pts, scene.body_of(pts), centre, L)
        for c in (0, 1):
            if "xy"[c] in fix:
                Q += weight * M[:, c, :].T @ M[:, c, :]
    pts = np.asarray(interface_points, float)
    w = np.asarray(interface_weights, float)
    if len(pts):
        n = scene.interface.normals(pts)
        t = tangent_of(n)
        jump = _modes(pts, np.ones(len(pts), int), centre, L) - _modes(pts, np.zeros(len(pts), int), centre, L)
        gN, gT = np.einsum("mi,mij->mj", n, jump), np.einsum("mi,mij->mj", t, jump)
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


# ----- materials --------------------------------------------------------------

def material_warnings(scene) -> list[str]:
    """Volumetric locking: plane strain with ν above NU_LOCKING_WARN, in
    one warning that names every such body; and Coulomb friction across
    two materials beyond the uniqueness bound (:func:`dundurs_warnings`)."""
    return _locking_warnings(scene) + dundurs_warnings(scene)


def dundurs_beta(scene) -> float:
    """Dundurs' second parameter β of the two bodies (J. Appl. Mech. 1969),
    ``[G₋(κ₊ − 1) − G₊(κ₋ − 1)] / [G₋(κ₊ + 1) + G₊(κ₋ + 1)]`` with
    ``G = E / 2(1 + ν)`` and ``κ = 3 − 4ν`` (plane strain) or
    ``(3 − ν)/(1 + ν)`` (plane stress): how far shear across Γ moves its
    normal gap (0 for equal materials, up to ±1/2 in plane strain)."""
    G, kappa = [], []
    for body in ("minus", "plus"):
        m = scene.materials[body]
        G.append(m.E / (2 * (1 + m.nu)))
        kappa.append(3 - 4 * m.nu if scene.plane == "strain" else (3 - m.nu) / (1 + m.nu))
    return (G[0] * (kappa[1] - 1) - G[1] * (kappa[0] - 1)) / (G[0] * (kappa[1] + 1) + G[1] * (kappa[0] + 1))


def dundurs_warnings(scene) -> list[str]:
    """A Coulomb law whose μ·|β| (:func:`dundurs_beta`) exceeds
    MU_DUNDURS_WARN: the answer may be one of several, which one the
    method's (tolerances.py's note)."""
    mu = getattr(scene.law, "mu", 0.0)
    if scene.law.name != "coulomb" or not mu:
        return []
    beta = dundurs_beta(scene)
    if mu * abs(beta) <= tol.MU_DUNDURS_WARN:
        return []
    return [f"mu = {mu:g} across two materials of Dundurs' β = {beta:.3g}: μ|β| = {mu * abs(beta):.3g} is above "
            f"{tol.MU_DUNDURS_WARN:g}, where slip and the normal gap are coupled strongly enough for Coulomb "
            "friction to have several answers (a layered block of contrast 1e3 at μ|β| = 1 to 5: fe, xfem and "
            "efgm held Γ closed or opened up to 20 of 24 points under pressure, tractions up to 164 p apart); "
            "the answer given is one of them, the method's: compare methods, or lower μ "
            f"(below {tol.MU_DUNDURS_WARN / abs(beta):.3g} here) or the materials' contrast "
            "(docs/contact-enforcement.md, \"Known limits\")"]


def friction_excess_warnings(scene, path) -> list[str]:
    """Points a converged ``path`` (an
    :class:`~contactcore.interface_path.InterfacePath`) holds at stick with
    ``|t_T|`` beyond ``μ|t_N|`` by more than the traction's round-off
    (``STICK_ROUNDOFF`` of μp, or ``TRACTION_ROUNDOFF`` of the largest
    pressure along the path): Newton's stick/slip band (DECISION_BAND of Γ's
    largest μp) keeps a point's previous status within it, so a load whose
    shear/normal lies within 1e-5 of μ (above it: no sticking equilibrium)
    may come back sticking; and at a load back to zero the rest window
    (REST_ROUNDOFF) may hold a small real shear (docs/newton.md, "A small
    μ").  One warning naming how many (point, increment) pairs, the
    largest excess over μ|t_N| (or over the path's largest μp, where the
    point's is smaller) and its increment."""
    mu = getattr(scene.law, "mu", None)
    if mu is None or scene.law.name != "coulomb" or path is None:
        return []
    count, worst, where = 0, 0.0, None
    # the round-off of a traction is relative to the largest pressure Γ
    # carried along the path: at a load back to zero the step's own is round-off
    carried = max((float(np.max(-np.asarray(s.traction, float).reshape(-1, 2)[:, 0], initial=0.0))
                   for s in path.steps), default=0.0)
    for step in path.steps:
        t = np.asarray(step.traction, float).reshape(-1, 2)
        p = np.maximum(-t[:, 0], 0.0)
        limit = mu * p
        allowed = np.maximum(tol.STICK_ROUNDOFF * limit, tol.TRACTION_ROUNDOFF * carried)
        excess = np.abs(t[:, 1]) - limit
        held = (np.asarray(step.status) == STICK) & (excess > allowed)
        if np.any(held):
            count += int(np.count_nonzero(held))
            scale = np.maximum(limit[held], max(mu * carried, np.finfo(float).tiny))
            share = float(np.max(excess[held] / scale))
            if share > worst:
                worst, where = share, step.step
    if not count:
        return []
    return [f"Γ's points stick with |t_T| above μ|t_N| = {mu:g}|t_N| at {count} (point, increment) pair(s), by up to "
            f"{worst:.2g} of μ|t_N| (of its largest along the path where the point's is smaller; increment "
            f"{where:g}): Newton keeps a point's status within {tol.DECISION_BAND:g} of Γ's largest μp "
            "(DECISION_BAND, above the round-off of its margins) and holds a point at rest where Γ is unloaded "
            "(REST_ROUNDOFF), so the loads there ask a shear/normal within that band of μ or above it, where no "
            "sticking equilibrium exists, or leave a shear an unloaded Γ does not tell from round-off; a μ that "
            "much larger sticks (docs/newton.md, \"Decisions that round-off cannot move\")"]


def closed_tension_warnings(scene, path) -> list[str]:
    """Points a converged ``path`` (an
    :class:`~contactcore.interface_path.InterfacePath`) holds closed
    (``stick`` or ``slip``) with a tension ``t_N > 0`` beyond Newton's
    closed/open band in traction (DECISION_BAND of the largest pressure
    along the path) plus the traction's round-off (TRACTION_ROUNDOFF of it).
    ``t_N`` is the law's traction at the point, the one its status was
    decided on (exact laws: ``γ min(y_N, 0)`` at the augmented jump, which
    is never positive where the status follows its sign), so such a point
    contradicts the law: an exact law's band is in traction
    (:meth:`contactcore.laws.Decision.in_traction`), a penalty law's is
    DECISION_BAND of Γ's largest |g_N|, which an open gap can make
    ``k_N`` times a tension of that size.  One warning naming how many
    (point, increment) pairs, the largest tension as a share of the path's
    largest pressure and its increment; none for a law without statuses
    (linear, bonded)."""
    if path is None or scene.law.name not in ("unilateral", "coulomb"):
        return []
    carried = max((float(np.max(-np.asarray(s.traction, float).reshape(-1, 2)[:, 0], initial=0.0))
                   for s in path.steps), default=0.0)
    allowed = (tol.DECISION_BAND + tol.TRACTION_ROUNDOFF) * carried
    count, worst, where = 0, 0.0, None
    for step in path.steps:
        tN = np.asarray(step.traction, float).reshape(-1, 2)[:, 0]
        held = (np.asarray(step.status) != OPEN) & (tN > allowed)
        if np.any(held):
            count += int(np.count_nonzero(held))
            share = float(np.max(tN[held])) / max(carried, np.finfo(float).tiny)
            if share > worst:
                worst, where = share, step.step
    if not count:
        return []
    return [f"Γ's points are closed in tension (t_N > 0) at {count} (point, increment) pair(s), up to {worst:.2g} "
            f"of the largest pressure along the path (increment {where:g}), where the law closes a point only "
            f"under pressure: Newton kept their status within its round-off band (DECISION_BAND = "
            f"{tol.DECISION_BAND:g} of Γ's largest gap for a penalty law, which an open gap sets; of the largest "
            "pressure, in traction, for an exact one), so these points' tractions are not the law's; refine h, "
            "or for springs compare with enforcement = \"exact\" (docs/contact-enforcement.md, \"The closed/open "
            "band is in traction\")"]


def _locking_warnings(scene) -> list[str]:
    """Volumetric locking: plane strain with ν above NU_LOCKING_WARN."""
    if scene.plane != "strain":
        return []
    high = [(body, m.nu) for body, m in scene.materials.items() if m.nu > tol.NU_LOCKING_WARN]
    if not high:
        return []
    named = " and ".join(f"materials.{body}.nu = {nu:.10g} (λ/μ = {2 * nu / (1 - 2 * nu):.1e})" for body, nu in high)
    return [f"{named} in plane strain, above {tol.NU_LOCKING_WARN:g}: every method here is displacement-based and "
            "may lock volumetrically, its stresses off by tens of percent or more, degree 1 the most but degree 2 "
            "too (scene A at ν = 0.4999, h = 0.05: the upper block's moment from σyy on Γ 18 % off in fe P2, 180 % "
            "in xfem P2, 120 % in EFGM's quadratic basis); Γ's tractions come from the same fields and may be off "
            "as much (fe P1's t_N on a uniformly pressed Γ at ν = 0.499 ranged over 0.01–2.8 times the pressure)"]


# ----- friction -----------------------------------------------------------------

def friction_demand(scene, k: float) -> str:
    """The check a Coulomb or unilateral failure turns on, or "": a body
    held by Γ alone (no support or pin on it) under boundary tractions and
    pressures is in equilibrium only if their resultant ``F`` presses it
    onto a straight Γ with ``|F·t| <= μ |F·n|`` (Coulomb's cone, integrated
    over Γ; Wriggers 2006, §2.3).  The unilateral law ties a closed point
    tangentially, μ = ∞: only the press is checked.  ``F`` is the sum of
    ``factor(k)·traction·length`` over the part of each loaded edge on that
    body (φ linear along it), ``t = −p n_out`` for a pressure.  A body whose
    supports and pins hold some directions but leave it free to move off Γ
    (an x-roller leaves a block above a horizontal Γ free in y) is refused
    when the loads do positive work in such a motion (:func:`_pulled_off`):
    Γ's contact pushes only, so it cannot hold them.  Only a rectangle cut
    by a line with no body force on the body is judged here."""
    mu = float("inf") if scene.law.name == "unilateral" else getattr(scene.law, "mu", None)
    if mu is None:
        return ""
    for name, shear, press, held in _demands(scene, k):
        if held:
            return (f"body {name}: {held}, and the loads pull it off Γ: no equilibrium, as contact only pushes; "
                    "hold it that way with a support or pin, or with springs that carry tension (type = \"linear\")")
        if press <= 0:
            how = "pull it off Γ" if press < 0 else "lie along Γ and do not press it onto Γ"
            return f"body {name} is held by Γ alone and the loads {how}: no equilibrium without a support"
        if shear > mu * press:
            return (f"on Γ the loads ask for shear/normal = {shear / press:.3g} of body {name}, above μ = {mu:g}: "
                    "it slides off (no equilibrium); lower the shear load or raise μ")
    return ""


def _demands(scene, k: float):
    """``(name, |F·t|, F·n pressing it onto Γ, "")`` of each body held by Γ
    alone and loaded (:func:`friction_demand`), at increment ``k``, F·n
    within :data:`~contactcore.tolerances.ALONG_GAMMA` of |F| taken as 0
    (F along Γ); ``(name, 0, 0, how)`` of a body its supports and pins hold
    in part, whose loads pull it off Γ in the motion ``how`` they leave
    free (:func:`_pulled_off`); none where Γ is not a line across a
    rectangle."""
    if not isinstance(scene.interface, LineInterface) or not isinstance(scene.domain, Rectangle):
        return
    n = np.asarray(scene.interface.normal, float)
    supports = _restraint(scene, np.zeros((0, 2)), np.zeros(0))[0]
    for b, name in enumerate(_BODY_NAMES):
        if any(getattr(ld, "body", None) == ("minus", "plus")[b] for ld in scene.loads):
            continue
        free = _free_modes(supports[3 * b:3 * b + 3, 3 * b:3 * b + 3])
        if not free.shape[1]:
            continue
        if free.shape[1] < 3:  # held in part by its supports and pins
            how = _pulled_off(scene, b, supports[3 * b:3 * b + 3, 3 * b:3 * b + 3], k)
            if how:
                yield name, 0.0, 0.0, how
            continue
        force = _boundary_resultant(scene, b, scene.factors(k)[0])
        if force.any():
            press = -force @ n if b == 1 else force @ n
            along = abs(press) <= tol.ALONG_GAMMA * np.linalg.norm(force)  # round-off's sign decides nothing
            yield name, abs(force @ tangent_of(n[None])[0]), 0.0 if along else float(press), ""


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
            pivot = centre + L * np.array([-r[1], r[0]]) / r[2]
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
    found less often as h or the degree resolves the edge
    (docs/contact-enforcement.md, "The unilateral law under shear").
    Coulomb's ``|t_T| <= μ|t_N|`` lets the shear vanish with the pressure;
    μ must exceed the loads' shear/normal on a body held by Γ alone.  An
    increment ``from_rest`` along a straight path is the same problem at
    any size (the law is positively homogeneous), so more increments do
    not help it."""
    if scene.law.name != "unilateral" or NOT_CONVERGED not in failure:
        return ""
    ratios = [f"{shear / press:.3g} on body {name}" for name, shear, press, _ in _demands(scene, k) if press > 0]
    mu = f"mu a few times the loads' shear/normal ({ratios[0]})" if ratios else "a large mu"
    exact = scene.law.enforcement == "exact"
    more = ("more increments do not help: from rest a smaller step is the same problem scaled" if from_rest else
            "more increments help only where a consistent map exists")
    other = "another stabilisation seldom helps" if exact else "soften k_N, k_T to settle it, with their answer"
    return ("Newton found no open/closed map of the unilateral law consistent at every point, and there may be "
            "none: the law ties a closed point tangentially and frees it (t_T = 0) the moment it opens, so where "
            "Γ opens under shear the last closed points carry the tie's shear on almost no pressure and opening "
            f"one opens or closes its neighbours (a finer h or degree 2 fails more often; {more}; {other}); use "
            f"type = \"coulomb\" with {mu}: |t_T| <= mu|t_N| lets the shear vanish with the pressure where Γ "
            "opens")


def _mode_matrix(x, centre, L) -> np.ndarray:
    """(2, 3): the displacement at ``x`` of one body's rigid modes (x, y,
    rotation), as :func:`_modes` has them."""
    d = (np.asarray(x, float) - centre) / L
    return np.array([[1.0, 0.0, -d[1]], [0.0, 1.0, d[0]]])


def _loaded_parts(scene, body: int, factors):
    """Each traction or pressure on an edge of the rectangle, on ``body``'s
    part of that edge (:func:`_part`): ``(t, length, midpoint)``, ``t`` the
    traction vector at its factor of ``factors``."""
    from .scene import Pressure, Traction
    c = scene.domain.corners
    for load, f in zip(scene.loads, factors):
        if not isinstance(load, (Traction, Pressure)):
            continue
        i, j = {"bottom": (0, 1), "right": (1, 2), "top": (2, 3), "left": (3, 0)}[load.boundary]
        lo, hi = _part(*scene.interface.phi(c[[i, j]]), body)
        if hi <= lo:
            continue
        edge = c[j] - c[i]
        out = np.array([edge[1], -edge[0]]) / np.linalg.norm(edge)  # corners counter-clockwise
        t = np.asarray(load.value, float) if isinstance(load, Traction) else -load.value * out
        yield f * t, (hi - lo) * np.linalg.norm(edge), c[i] + 0.5 * (lo + hi) * edge


def _load_work(scene, body: int, centre, L, factors) -> np.ndarray:
    """(3,): the work of the tractions and pressures on ``body``'s part of
    each loaded edge of the rectangle in its rigid modes (:func:`_modes`,
    about ``centre``, lengths over ``L``): a uniform load's work in a
    linear motion is its resultant's at the part's midpoint."""
    work = np.zeros(3)
    for t, length, mid in _loaded_parts(scene, body, factors):
        work += length * (t @ _mode_matrix(mid, centre, L))
    return work


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
    return sum((t * length for t, length, _ in _loaded_parts(scene, body, factors)), np.zeros(2))
