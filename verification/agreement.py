"""How two methods' profiles are compared, in one place.

The measure is the RMS of the difference over a profile relative to the RMS
of the reference profile.  Samples closer than ``exclude`` to a *singular
point* — a corner of the domain, or a point where Γ meets the outer boundary
— are left out: there the stresses have boundary layers or singularities
that no method resolves at these resolutions, so a pointwise difference
there measures resolution, not agreement.  A quantity whose exact value is
zero (scene B's t_N) has no relative measure; it is compared against the
scale of another quantity instead (``scale``).
"""
from __future__ import annotations

import numpy as np

from contactcore import ProfileData, Scene
from contactcore.estimate import far_from_singular


#: Samples closer than this fraction of the scene's diameter L to a singular
#: point are left out by default: 0.14, 0.28 and 0.36 m on scenes A, B and
#: C, about three cells of the paper's grids (0.053, 0.1 and 0.1 m), where
#: the corners' boundary layers live.
EXCLUDE_FRACTION = 0.1


def default_exclusion(scene: Scene) -> float:
    """The distance from singular points inside which samples are left out."""
    return EXCLUDE_FRACTION * scene.length_scale


def kept_samples(scene: Scene, profile: ProfileData, exclude: float) -> np.ndarray:
    """Mask of the samples at least ``exclude`` from every singular point
    (:func:`contactcore.estimate.singular_points`)."""
    xy = np.column_stack([profile.columns["x"], profile.columns["y"]])
    return far_from_singular(scene, xy, exclude)


def quantity_class(scene: Scene, profile, quantity: str) -> str:
    """``interface`` (gaps, tractions), ``contact`` (g_N, g_T, t_N of a law
    that opens: they have kinks where Γ opens, which cost a P2 method its
    higher order there), ``contact edge`` (t_T of such a law, which jumps from
    0 to k_T(g_T − s) where Γ closes: methods whose contact edges lie O(h)
    apart differ there by the whole jump), ``edge`` (a stress on a segment of
    the outer boundary) or ``interior`` (any other stress or displacement)."""
    if quantity in ("tN", "tT", "gN", "gT") and not scene.law.is_linear:
        return "contact edge" if quantity == "tT" else "contact"
    if quantity in ("tN", "tT", "gN", "gT"):
        return "interface"
    if hasattr(profile, "start"):
        ends = np.array([profile.start, profile.end])
        if np.all(np.abs(scene.domain.distance_to_boundary(ends)) <= 1e-12 * scene.length_scale):
            mid = ends.mean(axis=0, keepdims=True)
            if abs(scene.domain.distance_to_boundary(mid)[0]) <= 1e-12 * scene.length_scale:
                return "edge"
    return "interior"


def relative_rms(scene: Scene, got: ProfileData, ref: ProfileData, quantity: str, exclude: float,
                 scale: np.ndarray | None = None) -> float:
    """RMS of ``got − ref`` over the kept samples, relative to the RMS of
    ``scale`` (default: the reference quantity itself)."""
    keep = kept_samples(scene, ref, exclude)
    diff = got.columns[quantity][keep] - ref.columns[quantity][keep]
    base = ref.columns[quantity][keep] if scale is None else np.asarray(scale)
    return float(np.sqrt(np.mean(diff ** 2)) / np.sqrt(np.mean(base ** 2)))


#: Quantities whose exact value is zero, measured against the scale of a
#: companion: (profile id, quantity) -> (profile id, quantity).
COMPANIONS = {("B6", "tN"): ("B5", "tT"), ("B6", "gN"): ("B5", "gT")}


def agreements(scene: Scene, got: dict, ref: dict, exclude: float) -> list[tuple[str, str, str, float]]:
    """``(profile id, quantity, class, relative RMS)`` for every quantity of
    every profile; the class is ``zero`` for a quantity measured against its
    companion (see COMPANIONS), else :func:`quantity_class`."""
    profiles = {p.id: p for p in scene.profiles}
    rows = []
    for pid, prof in got.items():
        for q in prof.names[3:]:
            companion = COMPANIONS.get((pid, q))
            if companion:
                scale = ref[companion[0]].columns[companion[1]]
                rows.append((pid, q, "zero", relative_rms(scene, prof, ref[pid], q, exclude, scale=scale)))
            else:
                rows.append((pid, q, quantity_class(scene, profiles[pid], q),
                             relative_rms(scene, prof, ref[pid], q, exclude)))
    return rows


def _rms(x: np.ndarray) -> float:
    return float(np.sqrt(np.mean(x ** 2))) if len(x) else 0.0


def within_estimates(scene: Scene, a: dict, err_a: dict, b: dict, err_b: dict, exclude: float
                     ) -> list[tuple[str, str, float, bool]]:
    """Two methods' profiles (``{id: ProfileData}``) against their estimated
    errors (``{id: {quantity + "_err": per-sample error}}``,
    :meth:`contactcore.estimate.Estimate.error_columns`): per profile and
    quantity, ``RMS(q_a − q_b) / RMS(e_a + e_b)`` over the kept samples
    (RMS, not the worst sample: a pointwise estimate vanishes where the
    runs at h and h/2 cross) and whether it exceeds 1 (they differ by more
    than their estimated errors allow)."""
    rows = []
    for pid, prof in a.items():
        keep = kept_samples(scene, prof, exclude)
        for q in prof.names[3:]:
            diff = (prof.columns[q] - b[pid].columns[q])[keep]
            bound = (err_a[pid][f"{q}_err"] + err_b[pid][f"{q}_err"])[keep]
            ratio = _rms(diff) / max(_rms(bound), np.finfo(float).tiny)
            rows.append((pid, q, ratio, ratio > 1.0))
    return rows
