"""A run's stencil, and the samples a ``kept_rms`` leaves out near points
where the coarse run's error is still that point's own.

A stencil (a cell, EFGM's support, xfem P1's recovery patch:
:func:`stencil_radius`) sets how far a singular point's error reaches in a
run.  :func:`beyond_reach` keeps the samples beyond it; under an exact law
a point where Γ's final status changes is a weak singular point (the
solution no smoother than H^{5/2-ε} there), and a bulk quantity's samples
within :data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS` coarse
stencils of one are left out as a singular point's are
(:func:`near_status_changes`)."""
from __future__ import annotations

import numpy as np

from ... import tolerances as tol
from ...profiles import ProfileData
from ...result import MethodFacts
from ...scene import Scene
from ..orders import STRESSES
from ..singular import far_from_singular, stress_singular_points
from .lines import GAMMA, see


def stencil_radius(record: dict, facts: MethodFacts, quantity: str) -> float:
    """The radius around a point within which lie the unknowns that set a
    run's ``quantity`` there (the run's discretisation ``record`` and
    :class:`~contactcore.result.MethodFacts`): a support of ``dmax · h``
    for a ``meshfree`` method (``√2`` times that to a rectangular
    support's corner), the recovery patch of
    :data:`~contactcore.tolerances.RECOVERY_RINGS` vertex rings around the
    point's cell for a ``recovered_stress``, and one cell, ``h``,
    otherwise."""
    h = float(record["h"])
    if facts.meshfree:
        return float(record["dmax"]) * h * (np.sqrt(2.0) if record.get("support") == "rectangular" else 1.0)
    if quantity in STRESSES and facts.recovered_stress:
        return (tol.RECOVERY_RINGS + 1) * h
    return h


def distances(xy: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Each sample's (``xy``, (n, 2)) distance from the nearest of
    ``points`` ((m, 2)); infinite where there are none."""
    if not len(points):
        return np.full(len(xy), np.inf)
    return np.min(np.linalg.norm(xy[:, None] - points[None], axis=-1), axis=1)


def beyond_reach(scene: Scene, xy: np.ndarray, record: dict, facts: MethodFacts, quantity: str,
                 exclude: float, changes: np.ndarray | None = None) -> np.ndarray:
    """Mask of a profile's samples (``xy``) over which the estimate of
    ``quantity`` is summarised (its ``kept_rms``): at least ``exclude`` from
    every singular point (:func:`~contactcore.estimate.singular.far_from_singular`),
    and at least ``R = REACH_STENCILS · ρ`` from every point whose stress
    is singular (:func:`~contactcore.estimate.singular.stress_singular_points`),
    ``ρ`` the coarse run's :func:`stencil_radius` (``record``, its
    discretisation): a sample's value combines the unknowns within ``ρ``
    of it, each set by the equations within ``ρ`` of that unknown, so within
    ``R`` the coarse run's error is still the singular point's own and
    shrinks at no power of ``h`` that two runs can see
    (:data:`~contactcore.tolerances.REACH_STENCILS`).  ``R`` scales with
    the coarse ``h`` and the method's reach; it is at most
    :data:`~contactcore.tolerances.EXCLUDE_KEEP_SHARE` of the farthest
    sample's distance from those points, so that a profile keeps its
    middle; samples then still within reach are named by the reach cause
    of :func:`~contactcore.estimate.caveats.unsettled.unsettled`.  A sample at ``R`` within
    :data:`~contactcore.tolerances.GEOMETRY` (relative) is kept, as
    :func:`~contactcore.estimate.caveats.unsettled.unsettled` does not count it within reach.  ``exclude`` 0 keeps
    every sample: the caller left nothing out.

    ``changes``, the points where Γ's final status changes under an exact
    law (:func:`~contactcore.estimate.status.status_changes`), are treated
    alike for a bulk quantity (not Γ's :data:`~contactcore.estimate.caveats.lines.GAMMA`, whose tractions take
    order 1 near them instead): its samples within
    :data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS` stencils of one
    are left out too, capped on their own (:func:`near_status_changes`)."""
    kept = far_from_singular(scene, xy, exclude)
    if exclude <= 0 or not len(xy):
        return kept
    rho = stencil_radius(record, facts, quantity)
    kept &= _beyond(distances(xy, stress_singular_points(scene)), tol.REACH_STENCILS * rho)
    if changes is not None and quantity not in GAMMA:
        kept &= _beyond(distances(xy, changes), tol.STATUS_CHANGE_STENCILS * rho)
    return kept


def _beyond(dist: np.ndarray, reach: float) -> np.ndarray:
    """Mask of the samples at ``dist`` from some points at least ``reach``
    from them, ``reach`` at most
    :data:`~contactcore.tolerances.EXCLUDE_KEEP_SHARE` of the farthest
    sample's distance (a profile keeps its middle), within
    :data:`~contactcore.tolerances.GEOMETRY` (relative); all of them where
    there are no points (``dist`` infinite)."""
    if not np.any(np.isfinite(dist)):
        return np.ones(len(dist), bool)
    return dist >= min(reach, tol.EXCLUDE_KEEP_SHARE * float(np.max(dist))) * (1 - tol.GEOMETRY)


def near_status_changes(profiles: list[ProfileData], changes: np.ndarray, record: dict, facts: MethodFacts,
                        kept: dict[str, dict[str, np.ndarray]]) -> dict[str, tuple[float, bool]]:
    """``{PID:Q: (R, capped)}`` of the bulk quantities (not Γ's
    :data:`~contactcore.estimate.caveats.lines.GAMMA`) of ``profiles`` (the finest run's) with a sample within
    ``R`` = :data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS` coarse
    stencils (:func:`stencil_radius` of ``record``, the coarse run) of one
    of ``changes``, the points where Γ's final status changes under an
    exact law (:func:`~contactcore.estimate.status.status_changes`).
    There the solution is no smoother than H^{5/2-ε} (Moussaoui and Khodja
    1992): its stress is a weak singular point's, and a coarse run's error
    within reach of it is not ``C h^p`` (a vertical line that crossed an
    inclined bimaterial Γ where stick turned to slip,
    tests/scenes/stick_slip_crossing.toml: 99 % of fe P2's squared σyy
    error lay within one coarse cell of the crossing, estimated at 0.48 of
    it; :data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS`).
    :func:`beyond_reach` leaves those samples out of ``kept_rms``;
    ``capped`` says some are still ``kept`` (:data:`~contactcore.tolerances.EXCLUDE_KEEP_SHARE`),
    so that ``kept_rms`` itself is not asymptotic."""
    out = {}
    if not len(changes):
        return out
    for prof in profiles:
        dist = distances(np.column_stack([prof.columns["x"], prof.columns["y"]]), changes)
        for q in prof.names[3:]:
            reach = tol.STATUS_CHANGE_STENCILS * stencil_radius(record, facts, q)
            within = dist < reach * (1 - tol.GEOMETRY)
            if q not in GAMMA and np.any(within):
                out[f"{prof.id}:{q}"] = (reach, bool(np.any(within & kept[prof.id][q])))
    return out


def status_change_warnings(found: dict[str, tuple[float, bool]], length: str = "m") -> list[str]:
    """One line per reach of :func:`near_status_changes`, naming its
    quantities: their samples within that distance (in the scene's unit
    named ``length``) of a change of Γ's status are left out of
    ``kept_rms`` (or, capped, some kept: then not asymptotic), and their
    ``q_err`` there is an indication only."""
    lines = []
    for reach, capped in sorted(set(found.values())):
        names = [k for k, v in found.items() if v == (reach, capped)]
        left = "some kept: not asymptotic" if capped else "left out of kept_rms; q_err there not asymptotic"
        lines.append(f"{', '.join(names)}: samples within {reach:.3g} {length} of a change of Γ's status: {left}"
                     f"{see('near a status change')}")
    return lines
