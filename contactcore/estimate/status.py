"""Γ's status (open, stick, slip, partial) in the runs of an estimate.

Whether it ever took more than one value (:func:`switches`) sets the
orders theory allows Γ's quantities under an exactly enforced law: at a
point where the status changes the solution is no smoother than
H^{5/2-ε} (Moussaoui & Khodja, Comm. PDE 17, 1992; Chouly, Hild & Renard,
Math. Comp. 84, 2015; :func:`~contactcore.estimate.orders.theoretical_order`).

That limit is local to the points where the status changes: an exact
law's traction takes the orders of a law that never switches (degree 2:
2; degree 1: 1.45 of ``[1, 2]``) at the samples farther
than :data:`~contactcore.tolerances.STATUS_CHANGE_CELLS` coarse cells
from every change of either run's final status (:func:`far_from_changes`);
a bulk quantity's samples within reach of one are left out of its
``kept_rms`` (:func:`status_changes`,
:func:`~contactcore.estimate.caveats.beyond_reach`).

For a law with history (unilateral, Coulomb) the profiles are the final
increment's, and the status along Γ of the two runs is compared at
:data:`~contactcore.tolerances.PROFILE_POINTS` points
(:func:`status_change`): where it differs, the error there is not
asymptotic, and the estimate says so (:func:`status_warning`).

numpy only; no method is imported.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol
from ..geometry import CircleInterface
from ..laws import PARTIAL, REPORTED_STATUS_NAMES, SLIP
from ..profiles import ProfileData, interface_status, nearest_status, sample_points
from ..scene import InterfaceProfile, Scene
from .caveats import see
from .orders import TRACTIONS


def switches(paths) -> bool:
    """Whether Γ's status (open, stick, slip forwards, slip backwards: the
    sign of t_T; partial, a point of the unilateral law's partial answer,
    between open and closed) took more than one value over all increments
    of the runs' interface ``paths``.  Where it never did (scene A under the exact
    unilateral law: closed and tied everywhere), no point of Γ separates
    two statuses, now or in the history that set a Coulomb slip, so nothing
    limits the solution's smoothness there
    (:func:`~contactcore.estimate.orders.theoretical_order`).
    Slip in both directions is a switch: t_T jumps between ±μp."""
    seen = set()
    for path in paths:
        for step in path.steps:
            status = step.reported_status()  # a partial point PARTIAL (Increment.reported_status)
            # a frictionless point's t_T is round-off: no direction to tell
            frictionless = step.frictionless
            backwards = (status == SLIP) & (np.asarray(step.traction)[:, 1] < 0) & (not frictionless)
            seen.update(np.unique(np.where(backwards, -1, status)).tolist())
    return len(seen) > 1


def change_points(xy: np.ndarray, statuses: list[np.ndarray]) -> np.ndarray:
    """The points (k, 2) midway between neighbouring samples ``xy`` of a
    profile whose status differs in any of ``statuses`` (one array a run,
    an index a sample): where Γ's status changes along it in some run."""
    pts = [0.5 * (xy[i] + xy[i + 1]) for s in statuses for i in np.flatnonzero(s[1:] != s[:-1])]
    return np.array(pts).reshape(-1, 2)


def status_changes(scene: Scene, results) -> np.ndarray:
    """The points (k, 2) where the final status of any of ``results``
    changes between neighbouring samples of Γ's own
    :data:`~contactcore.tolerances.PROFILE_POINTS` (:func:`change_points`;
    the status a profile's tractions follow,
    :func:`contactcore.profiles.interface_status`).  Under an exact law the
    solution there is no smoother than H^{5/2-ε}: its stress, in the bulk
    beside the point too, is not ``C h^p`` for a coarse run within reach
    of it (:func:`far_from_changes` for Γ's tractions,
    :func:`~contactcore.estimate.caveats.near_status_changes` for the bulk)."""
    gamma = _samples(scene)
    return change_points(gamma, [interface_status(scene, r.fields, gamma, r.interface) for r in results])


def far_from_changes(scene: Scene, results, profiles: list[ProfileData], h: float,
                     changes: np.ndarray | None = None) -> dict[str, np.ndarray]:
    """``{profile id: mask}`` for each profile with a traction on Γ
    (:data:`~contactcore.estimate.orders.TRACTIONS`): its samples farther
    than :data:`~contactcore.tolerances.STATUS_CHANGE_CELLS` × ``h`` (the
    coarse run's) from every point where the final status of any of
    ``results`` changes between neighbouring samples of the profile or of
    all of Γ (:func:`change_points`; the status a profile's tractions follow,
    :func:`contactcore.profiles.interface_status`).  There the solution is
    as smooth as between Γ's status changes, and an exact law's traction
    takes the orders of a law that never switches
    (:func:`~contactcore.estimate.orders.smooth_range`).  ``changes``,
    Γ's own (:func:`status_changes` of ``results``), where the caller
    has them already."""
    out = {}
    # Γ's own changes, along all of Γ: a profile that starts past one still lies near it (review19b: a
    # traction profile from x = 0.08 on tilt_unil_exact, whose status changes at x = 0.075, took 11
    # samples within two cells of it as smooth)
    whole = status_changes(scene, results) if changes is None else changes
    for prof in profiles:
        if not set(TRACTIONS) & set(prof.names[3:]):
            continue
        xy = np.column_stack([prof.columns["x"], prof.columns["y"]])
        own = change_points(xy, [interface_status(scene, r.fields, xy, r.interface) for r in results])
        points = np.vstack([own.reshape(-1, 2), whole.reshape(-1, 2)])
        if not len(points):
            out[prof.id] = np.ones(len(xy), bool)
            continue
        nearest = np.min(np.linalg.norm(xy[:, None, :] - points[None, :, :], axis=2), axis=1)
        out[prof.id] = nearest > tol.STATUS_CHANGE_CELLS * h
    return out


def status_along(scene: Scene, result) -> np.ndarray:
    """The final increment's reported status (index into
    ``REPORTED_STATUS_NAMES``: a partial point ``PARTIAL``) at the profile
    samples of Γ, the status the profile's tractions follow there
    (:func:`contactcore.profiles.interface_status`; grader25b H1: a sample
    whose interpolated gap opens reads t = 0 beside a sticking quadrature
    point, and the nearest point's status hid that the runs differed)."""
    return interface_status(scene, result.fields, _samples(scene), result.interface)


def _gamma_profile(scene: Scene) -> InterfaceProfile:
    """A profile of Γ along Γ's own parameter, as a scene's Γ profiles
    take it: the angle on a circle, the arclength on a line."""
    along = "angle" if isinstance(scene.interface, CircleInterface) else "arclength"
    return InterfaceProfile("gamma", ("gN",), parameter=along)


def _samples(scene: Scene) -> np.ndarray:
    """Γ's :data:`~contactcore.tolerances.PROFILE_POINTS` profile samples."""
    return sample_points(scene, _gamma_profile(scene))[1]


def stretches(s: np.ndarray, differ: np.ndarray) -> list[list[float]]:
    """``[[s_first, s_last], ...]``: each run of consecutive samples (at
    ``s``) where ``differ`` holds, from its first sample's ``s`` to its
    last's (one sample: both the same)."""
    index = np.flatnonzero(differ)
    runs = np.split(index, np.flatnonzero(np.diff(index) > 1) + 1) if len(index) else []
    return [[float(s[r[0]]), float(s[r[-1]])] for r in runs]


def status_change(scene: Scene, coarse, fine, hs: tuple[float, float] | None = None) -> dict:
    """The final status of two runs' Results (at ``hs``, coarse and fine)
    compared along Γ: the share of Γ in each status per run
    (:func:`status_along`; ``partial`` only where either run has a partial
    point at a sample), and the samples whose status differs, in the
    profile's status or in the nearest quadrature point's
    (:func:`contactcore.profiles.nearest_status`, the solve's own map): a
    change in either is a change of the open/closed split.  Either alone
    misses some: the profile's status missed unil_partopen's fe and xfem P2
    (2026-11-29, their g_T and t_T estimates 0.30-0.37 of the error), the
    nearest point's its fe and xfem P1 (t_T 5.3-6.2)."""
    s, pts, parameter = sample_points(scene, _gamma_profile(scene))  # _samples' points, s along Γ's parameter
    s0, s1 = (interface_status(scene, r.fields, pts, r.interface) for r in (coarse, fine))  # status_along's
    n0, n1 = (nearest_status(scene, pts, r.interface) for r in (coarse, fine))
    either = np.any(s0 == PARTIAL) or np.any(s1 == PARTIAL)
    names = REPORTED_STATUS_NAMES if either else REPORTED_STATUS_NAMES[:PARTIAL]
    shares = lambda s: {n: float(np.mean(s == i)) for i, n in enumerate(names)}  # noqa: E731
    differ = (s0 != s1) | (n0 != n1)
    return {"coarse": shares(s0), "fine": shares(s1), "differ": int(np.sum(differ)),
            "differ_profile": int(np.sum(s0 != s1)), "differ_points": int(np.sum(n0 != n1)),
            "at": stretches(s, differ), "parameter": parameter, "samples": len(s0), "h": list(hs) if hs else None}


def status_warning(change: dict | None, length: str = "m") -> list[str]:
    """A line when the two compared runs' status differs somewhere along Γ:
    the open/closed (stick/slip) split moved between them, and with it the
    whole answer (the bodies' rigid shift under a tie: unil_partopen's
    bulk u_x read 0.078-0.33 of its error at h = 0.05 -> 0.025, 2026-11-29),
    so the line names no quantity: every estimate of the run is an
    indication only (:class:`~contactcore.estimate.runs.Estimate`'s
    ``unsettled`` takes them all).  It gives the runs' h (in the scene's
    unit named ``length``), how many samples differ and the profile's
    shares of each status that moved; which samples and which of the
    solve's points differ are summary.json's (``estimate.status``), the
    explanation docs/error-estimates.md's row "status"."""
    if not change or change["differ"] == 0:
        return []
    runs = (f"from h = {change['h'][0]:g} {length} to {change['h'][1]:g} {length}" if change.get("h")
            else "between the two finest runs")
    coarse, fine = change["coarse"], change["fine"]
    moved = ", ".join(f"{k} {100 * coarse.get(k, 0.0):.0f}→{fine.get(k, 0.0):.0%}"
                      for k in dict.fromkeys([*coarse, *fine]) if f"{coarse.get(k, 0.0):.0%}" != f"{fine.get(k, 0.0):.0%}")
    return [f"the status along Γ differs {runs} at {change['differ']} of {change['samples']} samples"
            + (f" ({moved})" if moved else "") + f": no estimate of this run is asymptotic; refine{see('status')}"]
