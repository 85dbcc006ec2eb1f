"""Profiles: quantities sampled on segments or along Γ (docs/scenes.md).

Sample points: 101 evenly spaced points on a segment, end points moved inside
by 1e-9 of its length; on a circular Γ, 101 polar angles from 0 to 2π, the
last moved back by 1e-9 of 2π.  Each point takes the body that contains it
(exact geometry, the sign of φ); on Γ the profile's ``side`` (+ by default).

Interface quantities come from the computed jump and the law, never from the
bulk stress (for a law enforced exactly, :mod:`contactcore.exact`, the
tractions are the solve's at the quadrature points of Γ, averaged over each
piece of Γ and read between the pieces' centres, past a straight Γ's end
piece's centre on the line through the end pieces' means:
:meth:`~contactcore.interface_path.InterfacePath.piece_means`): ``[[u]] = u⁺ − u⁻``, ``g_N = [[u]]·n``, ``g_T = [[u]]·t``, and
``(t_N, t_T)`` is the law's response to ``(g_N, g_T)`` — and, for a law with
history (``coulomb``), to the history at the last increment, which the
caller passes as data: the Result's ``interface`` path
(:class:`contactcore.interface_path.InterfacePath`).  That history lives at the
method's quadrature points on Γ and is interpolated along Γ to the samples:
exact where neighbouring points share a status, approximate where an open
point meets a closed one.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from . import tolerances as tol
from .errors import require_finite
from .exact import is_exact
from .geometry import CircleInterface, tangent_of
from .interface_path import along
from .collective import SERIAL
from .laws import OPEN, PARTIAL, SLIP, STICK, Decision
from .profile_data import ProfileData
from .scaling import Scales
from .result import Fields
from .errors import ContactError, SceneError
from .scene import (BODIES, DISPLACEMENT_QUANTITIES, INTERFACE_QUANTITIES, MEAN_SIDE, STRESS_QUANTITIES, LineProfile,
                    Profile, Scene)
from .scene.check_profiles import check_profiles
from .scene.profiles import InterfaceProfile


def _interior_fractions(n: int) -> np.ndarray:
    f = np.linspace(0.0, 1.0, n)
    f[0], f[-1] = tol.PROFILE_END_SHIFT, 1.0 - tol.PROFILE_END_SHIFT
    return f


def sample_points(scene: Scene, profile: Profile, n: int = tol.PROFILE_POINTS) -> tuple[np.ndarray, np.ndarray, str]:
    """``(s, points, parameter)``: the ``n`` samples of ``profile`` on
    ``scene``, ``s`` (n,) and ``points`` (n, 2) in the scene's length unit
    (``s`` in radians when ``parameter`` is ``"angle"``), ``parameter``
    ``"arclength"`` or ``"angle"``.  A line profile runs from its start to
    its end; an interface profile along Γ: a circle from θ = 0 to just
    short of 2π, a line along its chord through the domain.  The two ends
    of a segment are moved inwards by PROFILE_END_SHIFT of its length, so
    no sample lies on a corner.  Nothing is refused: the scene is
    validated already."""
    if isinstance(profile, LineProfile):
        a, b = np.asarray(profile.start, float), np.asarray(profile.end, float)
        f = _interior_fractions(n)
        return f * np.linalg.norm(b - a), a + f[:, None] * (b - a), "arclength"
    itf = scene.interface
    if isinstance(itf, CircleInterface):
        theta = np.linspace(0.0, 2.0 * np.pi, n)
        theta[-1] = 2.0 * np.pi * (1.0 - tol.PROFILE_END_SHIFT)
        s = theta if profile.parameter == "angle" else itf.radius * theta
        return s, itf.points_at_angles(theta), profile.parameter
    a, b = itf.chord(scene.domain)
    f = _interior_fractions(n)
    return f * np.linalg.norm(b - a), a + f[:, None] * (b - a), "arclength"


def interface_response(scene: Scene, fields: Fields, points: np.ndarray, path=None) -> dict[str, np.ndarray]:
    """``gN, gT, tN, tT`` at points of Γ from the jump of the computed field
    (and the law's history on ``path``, for a law that has one); an exact
    law's tractions are the solve's, averaged over each piece of Γ
    (:meth:`~contactcore.interface_path.InterfacePath.piece_means`)."""
    g = _jumps_at(scene, fields, points)
    if is_exact(scene.law):
        if path is None or not path.steps:
            raise ContactError(f"path: the exact '{scene.law.name}' law's tractions come from the solve: pass the "
                             "Result's interface path")
        t = path.piece_means(scene.interface, points, path.final.traction)
        return {"gN": g[:, 0], "gT": g[:, 1], "tN": t[:, 0], "tT": t[:, 1]}
    t, _ = _penalty_at(scene, g, points, path)
    return {"gN": g[:, 0], "gT": g[:, 1], "tN": t[:, 0], "tT": t[:, 1]}


def _jumps_at(scene: Scene, fields: Fields, points: np.ndarray) -> np.ndarray:
    """(m, 2): the computed field's jump ``(g_N, g_T)`` at points of Γ."""
    m = len(points)
    jump = fields.displacement(points, np.ones(m, int)) - fields.displacement(points, np.zeros(m, int))
    n = scene.interface.normals(points)
    return np.column_stack([np.sum(jump * n, axis=1), np.sum(jump * tangent_of(n), axis=1)])


def _law_at(scene: Scene, g: np.ndarray, points: np.ndarray, path=None, previous: np.ndarray | None = None):
    """A penalty law's response to the jumps ``g`` at ``points`` of Γ, its
    history read from ``path`` where it has one, decided as the solve
    decided (:class:`~contactcore.laws.Decision`): each sample's previous
    status its nearest quadrature point's (``previous``, given with
    ``path``), the scales Γ's at the quadrature points, all made
    dimensionless as the solve saw them (:class:`~contactcore.scaling.Scales`).  A switch within the
    band, or at rest within round-off, keeps the solve's status: on a Γ
    that no load presses every sample's g_N is round-off (review11 #2:
    shear_unilateral fe P2 at h = 0.1, |g_N| <= 6.4e-18 against g_T 1.2e-3,
    read open at 101 of 101 samples under one BLAS kernel, 100 under
    another, while every quadrature point sticks).  Without a path (a
    caller's own jumps) the law's plain response."""
    state = None
    if scene.law.has_history:
        if path is None or path.state is None:
            raise ContactError(f"path: the '{scene.law.name}' law needs the interface history: pass the Result's "
                             "interface path")
        state = path.state_at(scene.interface, points)
    if path is None or not path.steps:
        return scene.law.evaluate(g, state)
    scales = Scales.of(scene)
    U, law = scales.displacement, scales.law(scene.law)
    dimensionless = (lambda v: None if v is None else np.asarray(v, float) / U)  # noqa: E731
    decision = Decision.reduced(law, dimensionless(path.final.jump), dimensionless(path.state), previous, SERIAL)
    response = law.evaluate(dimensionless(g), dimensionless(state), decision)
    return replace(response, traction=response.traction * scales.stress)


def _nearest(scene: Scene, points: np.ndarray, path) -> np.ndarray:
    """The index of the quadrature point of Γ nearest each of ``points``
    along Γ; points tied within :data:`~contactcore.tolerances.GEOMETRY` of
    Γ's span go to the one first along Γ, so that round-off of the two
    distances does not choose (review12 #5: 9-19 samples a run lie midway
    between two quadrature points)."""
    a, b = along(scene.interface, path.points), along(scene.interface, points)
    d = np.abs(b[:, None] - a[None, :])
    span = float(np.ptp(a)) if len(a) > 1 else 1.0
    tied = d <= d.min(axis=1, keepdims=True) + tol.GEOMETRY * span
    return np.argmin(np.where(tied, a[None, :], np.inf), axis=1)


def nearest_status(scene: Scene, points: np.ndarray, path) -> np.ndarray:
    """The final increment's reported status (``Increment.reported_status``)
    of the quadrature point of Γ nearest each of ``points`` along Γ: the
    solve's own open/closed map, read at the samples."""
    return path.final.reported_status()[_nearest(scene, points, path)]


def _penalty_at(scene: Scene, g: np.ndarray, points: np.ndarray, path=None) -> tuple[np.ndarray, np.ndarray]:
    """A penalty law's traction (m, 2) and status at ``points`` of Γ, with
    jumps ``g``, each the other's.  The law decided as the solve decided
    (:func:`_law_at`) says open or closed: an interpolated gap that opens
    reads t = 0 whatever the nearest quadrature point's status (grader25b
    H1).  A closed sample is stick or slip as its nearest quadrature point
    is, where that point is closed, and a slipping one carries the slip
    traction, the law's ``slip_bound(t_N)`` (Coulomb's ``μ|t_N|``), in
    that point's direction: the slip history read
    between the quadrature points puts a sample of a slipping Γ inside the
    cone (grader28 F1: a penalty Coulomb Γ slipping everywhere read 82 %
    stick; review12 #1: labelled slip, its t_T was the stick branch's, down
    to 0.88 μ|t_N| on slide_everywhere and 0.33 on C-coulomb in xfem P1).
    Where that point is open, or without a path, the law's own; a closed
    sample whose nearest point is of the partial answer is reported
    partial and carries that point's share θ of the tie, ``y_N = 0`` and
    θ times its own tie's shear, ``(0, θ k_T g_T)`` (review11 #7: it
    carried the whole tie, ``k g``), an opening one reads open with t = 0
    as any other; a frictionless closed one is reported ``SLIP``, as
    ``Increment.reported_status`` reports the points."""
    if path is None or not path.steps:
        response = _law_at(scene, g, points, path)
        return response.traction, response.status
    index = _nearest(scene, points, path)
    reported = path.final.reported_status()[index]
    response = _law_at(scene, g, points, path, reported)
    own = np.where(path.final.frictionless & (response.status == STICK), SLIP, response.status)
    closed = (own != OPEN) & ((reported == STICK) | (reported == SLIP))
    partial = (own != OPEN) & (reported == PARTIAL)
    status = np.where(partial, PARTIAL, np.where(closed, reported, own)).astype(np.int8)
    t = np.array(response.traction, float)
    slip = closed & (reported == SLIP)
    if scene.law.frictional and slip.any():  # the law's slip bound, any law's (takeover31 #2)
        t[slip, 1] = scene.law.slip_bound(t[slip, 0]) * np.sign(path.final.traction[index[slip], 1])
    if partial.any():  # the unilateral law's partial answer (contactcore.newton.partial)
        t[partial] = np.column_stack([np.zeros(int(partial.sum())),
                                      path.final.theta[index[partial]] * scene.law.kT * g[partial, 1]])
    return t, status


def interface_status(scene: Scene, fields: Fields, points: np.ndarray, path) -> np.ndarray:
    """The status a profile's tractions at ``points`` of Γ follow (an index
    into ``REPORTED_STATUS_NAMES``): a penalty law's as :func:`_penalty_at`
    decides it with the traction, an exact law's the nearest quadrature
    point's (its tractions are the solve's, per piece of Γ)."""
    if is_exact(scene.law):
        return nearest_status(scene, points, path)
    return _penalty_at(scene, _jumps_at(scene, fields, points), points, path)[1]


def evaluate_quantities(scene: Scene, fields: Fields, points: np.ndarray, quantities, side: str = "plus",
                        path=None) -> dict:
    """Every quantity in ``quantities`` at ``points`` (see module doc;
    ``path`` the interface history, needed by a law that has one).  On Γ a
    body's field is read from ``side``; ``MEAN_SIDE`` reads the mean of
    the two sides' limits, ``{σ} = (σ⁺ + σ⁻)/2`` (off Γ both are the one
    body's)."""
    sides = BODIES if side == MEAN_SIDE else (side,)
    bodies = [scene.body_of(points, one) for one in sides]
    out = {}
    if set(quantities) & set(STRESS_QUANTITIES):
        sig = np.mean([fields.stress(points, b) for b in bodies], axis=0)
        out.update(zip(STRESS_QUANTITIES, sig.T))
    if set(quantities) & set(DISPLACEMENT_QUANTITIES):
        u = np.mean([fields.displacement(points, b) for b in bodies], axis=0)
        out.update(zip(DISPLACEMENT_QUANTITIES, u.T))
    if set(quantities) & set(INTERFACE_QUANTITIES):
        out.update(interface_response(scene, fields, points, path))
    return {q: out[q] for q in quantities}


def check_profile(scene: Scene, profile) -> None:
    """The rules a scene's own profiles meet (:func:`check_profiles`: known
    quantities, a segment inside the domain, on Γ for Γ's quantities…)
    applied to one profile a user built, or a :class:`SceneError` naming
    it; a ContactError if ``profile`` is no profile at all."""
    if not isinstance(profile, (LineProfile, InterfaceProfile)):
        raise ContactError(f"profile: must be a LineProfile or an InterfaceProfile, got {type(profile).__name__} "
                           f"{profile!r} (a scene's own: scene.profiles)")
    name = f"profile {profile.id!r}"
    if isinstance(profile, LineProfile):
        profile = replace(profile, **{end: _plane_point(getattr(profile, end), f"{name}.{end}")
                                      for end in ("start", "end")})
    try:
        check_profiles(replace(scene, profiles=(profile,)))
    except SceneError as exc:  # named by its id: it is no profiles[0] of the scene's
        field = exc.field.replace("profiles[0]", name, 1) if exc.field.startswith("profiles[0]") else exc.field
        raise SceneError(field, exc.problem) from None


def _finite(value) -> bool:
    try:
        return math.isfinite(value)
    except OverflowError:  # an int past float's range
        return False


def _plane_point(point, field: str) -> tuple[float, float]:
    """A segment's end a user built, as two floats: exactly two finite real
    numbers ``(x, y)`` (a tuple, list or array; numpy's numbers too), or a
    :class:`SceneError` naming ``field`` (a scene file's are always two; a
    third, z, was dropped silently, and one number or None raised an
    IndexError or a TypeError: review6's fault 5)."""
    values = tuple(point) if isinstance(point, (tuple, list, np.ndarray)) else None
    if (values is None or len(values) != 2
            or not all(isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, (bool, np.bool_))
                       and _finite(v) for v in values)):
        raise SceneError(field, f"must be two finite numbers (x, y) (got {point!r})")
    return float(values[0]), float(values[1])


def sample_profile(scene: Scene, fields: Fields, profile: Profile, path=None) -> ProfileData:
    """One profile of ``scene`` evaluated on ``fields`` (and the interface
    history ``path``, for a law that has one: a Result's ``interface``);
    SolverError if a quantity is not finite (the last guard before anything
    is written).  A profile the user built is held to the rules of a
    scene's own (:func:`check_profile`) before any field is evaluated:
    never a sample outside the domain, nor Γ's quantities off Γ.

    A Result's fields (:class:`contactcore.scaling.ScaledFields`) are
    sampled where the method solved, on the dimensionless scene, and mapped
    back: the same samples in any units and placement, so that one on a cell
    edge (a P1 stress jumps there) takes the same side of it."""
    check_profile(scene, profile)
    return _sampled(scene, fields, profile, path)


def _sampled(scene: Scene, fields: Fields, profile: Profile, path=None) -> ProfileData:
    """:func:`sample_profile` of a profile already checked."""
    scales = getattr(fields, "scales", None)
    if scales is not None:
        data = scales.profile_data(_sampled(scales.scene(scene), fields.inner, scales.profile(profile),
                                            scales.path_in(path)))
    else:
        s, pts, param = sample_points(scene, profile)
        columns = {"s": s, "x": pts[:, 0], "y": pts[:, 1]}
        columns.update(evaluate_quantities(scene, fields, pts, profile.quantities, profile.side, path))
        data = ProfileData(profile.id, param, columns)
    for q in profile.quantities:
        require_finite(f"profile {profile.id}: {q}", data.columns[q])
    return data


def sample_profiles(scene: Scene, fields: Fields, path=None) -> list[ProfileData]:
    """Every profile of ``scene`` (in its order, and only those), sampled on
    ``fields`` (a Result's ``fields``, or any :class:`~contactcore.result.Fields`)
    at PROFILE_POINTS samples each: a list of :class:`ProfileData`,
    columns ``s, x, y`` then the profile's quantities, in the scene's
    units (SI unless its ``[units]`` say otherwise).

    ``path`` is the Result's ``interface``: required where Γ's tractions
    depend on it (a law with history, such as ``coulomb``, and any exactly
    enforced law), else a ContactError says to pass it.  Pass the scene the
    run solved (``result.scene``): another law gives other tractions.  A
    quantity that is not finite is a SolverError naming the profile; a
    point the fields refuse is their FieldsError."""
    return [sample_profile(scene, fields, p, path) for p in scene.profiles]
