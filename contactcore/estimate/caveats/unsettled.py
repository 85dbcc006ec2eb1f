"""Two runs that are not yet asymptotic because the coarser one's stencil
(:func:`~contactcore.estimate.caveats.reach.stencil_radius`) is not small
against what it resolves (:func:`unsettled`): within
:data:`~contactcore.tolerances.REACH_STENCILS` stencils of a singular
point, over 1/:data:`~contactcore.tolerances.FEATURE_STENCILS` of the
scene's smallest feature (:func:`feature_size`), or across a thin body
(:func:`thinnest_body`).  Richardson cannot see either from two runs."""
from __future__ import annotations

from collections.abc import Set

import numpy as np

from ... import tolerances as tol
from ...geometry import Rectangle
from ...profiles import ProfileData
from ...result import MethodFacts
from ...scene import Scene
from ...scaling import Sizes
from ...scene.resolution import body_thickness
from ..extrapolation import QuantityEstimate, rms, roundoff_floor
from ..orders import lower_end
from ..singular import far_from_singular, stress_singular_points, unknown_ends
from .lines import see
from .reach import distances, stencil_radius


def feature_size(scene: Scene) -> float:
    """The scene's smallest feature: the domain's smallest extent (a
    rectangle's shorter side, a disc's diameter), or a circular Γ's
    diameter where that is less."""
    domain = scene.domain
    size = float(min(domain.size)) if isinstance(domain, Rectangle) else domain.length_scale
    radius = getattr(scene.interface, "radius", None)
    return min(size, 2.0 * float(radius)) if radius is not None else size


def thinnest_body(scene: Scene) -> float:
    """The thinner body's thickness across a straight Γ
    (:func:`~contactcore.scene.resolution.body_thickness`: a layer between
    Γ and a parallel edge, a corner cut off), infinite for a curved Γ
    (its disc is in :func:`feature_size`)."""
    thickness = body_thickness(scene)
    return min(thickness.values()) if thickness else np.inf


def roundoff_runs(scene: Scene, levels: list[list[ProfileData]]) -> set[str]:
    """The ``PID:Q`` whose two finest runs differ only at round-off: at
    every sample ``|q_{h/2} − q_h| ≤ max(ε s, f)`` with ``s`` the
    quantity's largest ``|q|`` in either run, ``ε``
    :data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF`, and ``f``
    :data:`~contactcore.tolerances.NEGLIGIBLE_SHARE` of the scene's size
    of its kind (:func:`~contactcore.estimate.extrapolation.roundoff_floor`):
    the thresholds at which :func:`~contactcore.estimate.caveats.residues`
    and :func:`~contactcore.estimate.caveats.cell_scale_orders` skip a
    difference, here at every sample.  The estimate is then round-off too,
    and so is the error where the method is exact (fe and xfem on an
    inclined crack in slip: both 1e-14 of scale, fix37); a warning that
    names such a quantity is noise (:func:`unsettled`,
    :func:`~contactcore.estimate.caveats.exact_tractions`)."""
    if len(levels) < 2:
        return set()
    sizes, out = Sizes.of(scene), set()
    for coarse, fine in zip(levels[-2], levels[-1]):
        for q in fine.names[3:]:
            a, b = fine.columns[q], coarse.columns[q]
            scale = max(float(np.max(np.abs(a))), float(np.max(np.abs(b)))) if len(a) else 0.0
            if float(np.max(np.abs(a - b), initial=0.0)) <= max(tol.ESTIMATE_ROUNDOFF * scale,
                                                                roundoff_floor(sizes, q)):
                out.add(f"{fine.id}:{q}")
    return out


def unsettled(scene: Scene, levels: list[list[ProfileData]], record: dict, facts: MethodFacts,
              exclude: float, estimates: dict[str, dict[str, QuantityEstimate]] | None = None, *,
              roundoff: Set[str] = frozenset()) -> dict[str, dict[str, tuple[float, float]]]:
    """The quantities whose two-run estimate is not asymptotic, by cause,
    from the coarser run (``record``, its discretisation; ``facts``, its
    method's :class:`~contactcore.result.MethodFacts`) of the pair that
    makes it: ``{"reach": {PID:Q: (ρ, h_ok)}, "coarse": {...}, "thin": {...}}``
    with ``ρ`` the quantity's :func:`~contactcore.estimate.caveats.reach.stencil_radius` in that run and
    ``h_ok`` the coarse run's h from which the cause is gone (ρ scales
    with h).  ``reach``: a sample kept (at least ``exclude`` from the
    singular points) lies within
    :data:`~contactcore.tolerances.REACH_STENCILS` stencils of a singular
    point, where that run's error is still the singular point's own.
    ``coarse``: the stencil exceeds
    1/:data:`~contactcore.tolerances.FEATURE_STENCILS` of the scene's
    :func:`feature_size`.  ``thin``: a body is less than
    :data:`~contactcore.tolerances.THIN_BODY_STENCILS` stencils thick
    (:func:`thinnest_body`), so the coarse run hardly resolves a field
    across it (grader25b's layer 0.15 thick on xfem P1 cells of 0.1: the
    estimate of ``u_y`` read 0.127 of its error).  A tie within
    :data:`~contactcore.tolerances.GEOMETRY` (relative) is no cause: h =
    0.05 with supports of 2h on a feature of 0.8 sits on the threshold,
    and round-off must not decide it; nor is a quantity in ``roundoff``,
    the ``PID:Q`` whose two finest runs differ only at round-off
    (:func:`roundoff_runs` of ``levels``, made once per estimate by
    :func:`~contactcore.estimate.runs.estimate_runs`; none by default)."""
    sing, feature, h = stress_singular_points(scene), feature_size(scene), float(record["h"])
    thin = thinnest_body(scene)
    out = {"reach": {}, "coarse": {}, "thin": {}}
    coarse_run = {p.id: p for p in levels[-2]} if len(levels) > 1 else {}
    for prof in levels[-1]:
        xy = np.column_stack([prof.columns["x"], prof.columns["y"]])
        kept = far_from_singular(scene, xy, exclude)
        dist = distances(xy, sing)
        near = np.min(dist[kept]) if np.any(kept) else np.inf
        for q in (q for q in prof.names[3:] if f"{prof.id}:{q}" not in roundoff):
            rho = stencil_radius(record, facts, q)
            within = kept & (dist < tol.REACH_STENCILS * rho * (1 - tol.GEOMETRY))
            local = rho <= h * (1 + tol.GEOMETRY) and not _lower_end(scene, estimates, prof.id, q, h)
            if np.any(within) and not _spread(prof, coarse_run.get(prof.id), q, within, kept & ~within, local):
                out["reach"][f"{prof.id}:{q}"] = (rho, h * near / (tol.REACH_STENCILS * rho))
            if rho * tol.FEATURE_STENCILS > feature * (1 + tol.GEOMETRY):
                out["coarse"][f"{prof.id}:{q}"] = (rho, h * feature / (tol.FEATURE_STENCILS * rho))
            if rho * tol.THIN_BODY_STENCILS > thin * (1 + tol.GEOMETRY):
                out["thin"][f"{prof.id}:{q}"] = (rho, h * thin / (tol.THIN_BODY_STENCILS * rho))
    return out


def _lower_end(scene: Scene, estimates: dict[str, dict[str, QuantityEstimate]] | None, pid: str, q: str,
               h: float) -> bool:
    """Whether the estimate of ``PID:Q`` takes the lower end of its range
    (:func:`~contactcore.estimate.orders.lower_end`: a bulk displacement
    on a scene whose straight Γ ends under an exact law,
    :func:`~contactcore.estimate.singular.exact_interface_ends`, or under
    springs stiff at the scale of the coarse run's cells ``h``,
    :func:`~contactcore.estimate.singular.stiff_spring_ends`): an end
    of an exponent not taken, whose error may pollute the whole domain,
    so that where the runs differ most says nothing of it.  On the nine
    held-out scenes the exact unilateral wedge's xfem P2 `u_x` (3.25,
    its runs' difference 1.8 times as large within reach as beyond) was
    named by the reach cause alone (docs/error-estimates.md, "Which
    estimates to warn of")."""
    e = (estimates or {}).get(pid, {}).get(q)
    return e is not None and lower_end(q, e.theory, unknown_ends(scene, h))


def _spread(fine: ProfileData, coarse: ProfileData | None, q: str, within: np.ndarray, beyond: np.ndarray,
            one_cell: bool) -> bool:
    """Whether the runs contradict the reach cause of :func:`unsettled`
    for a stencil of ``one_cell`` (fe, and xfem but for its recovered
    stress): their difference over the kept samples ``within`` reach of
    a singular point is no more than
    :data:`~contactcore.tolerances.REACH_CONCENTRATION` times (RMS) that
    ``beyond`` it, so the coarse run's error there is not the singular
    point's own.  False for a wider stencil (EFGM's supports, a recovery
    patch), without a coarse run, with no sample beyond, or where the
    difference is at round-off of the quantity."""
    if not one_cell or coarse is None or not np.any(beyond):
        return False
    d = fine.columns[q] - coarse.columns[q]
    scale = max(float(np.max(np.abs(fine.columns[q]))), float(np.max(np.abs(coarse.columns[q]))))
    far = rms(d[beyond])
    if far <= tol.ESTIMATE_ROUNDOFF * scale:
        return False
    return rms(d[within]) <= tol.REACH_CONCENTRATION * far


def unsettled_warnings(found: dict[str, dict[str, tuple[float, float]]], h: float, feature: float,
                       length: str = "m", thin: float = np.inf) -> list[str]:
    """One line per cause of :func:`unsettled` and per stencil, naming the
    quantities and the coarse h from which the cause is gone; each length
    followed by the scene's unit named ``length``
    (:class:`~contactcore.scene.Units`): the coarse run's ``h``, the
    stencil, the scene's smallest ``feature`` and ``thin``, its thinnest
    body's thickness.  A stencil is a cell, a support or a recovery patch
    (:func:`~contactcore.estimate.caveats.reach.stencil_radius`; docs/error-estimates.md, "The warnings")."""
    lines, u = [], f" {length}"
    for cause, entries in found.items():
        for rho in sorted({v[0] for v in entries.values()}):
            names = [k for k, v in entries.items() if v[0] == rho]
            h_ok = min(entries[k][1] for k in names)
            stencils = f"stencils of {rho:.3g}{u} at h = {h:g}{u}"
            why = {"reach": f"within {tol.REACH_STENCILS * rho:.3g}{u} of a singular point "
                            f"({tol.REACH_STENCILS:g} {stencils})",
                   "coarse": f"{stencils} over 1/{tol.FEATURE_STENCILS:g} of the smallest feature "
                             f"({feature:.3g}{u})",
                   "thin": f"{tol.THIN_BODY_STENCILS:g} {stencils} over the thinner body across Γ "
                           f"({thin:.3g}{u})"}[cause]
            lines.append(f"{', '.join(names)}: {why}: not asymptotic; start below h = {h_ok:.3g}{u}"
                         f"{see('stencil')}")
    return lines
