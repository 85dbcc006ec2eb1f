"""What a quantity is measured against: the size of its vector or tensor
(:data:`GROUPS`) at each sample (:func:`group_size`), Γ's traction and gap
gathered over the profiles that sample the same points
(:func:`components`), floored by :mod:`~verification.agreement.sizes`
(:func:`scale_of`), and its name in words (:func:`scale_name`)."""
from __future__ import annotations

import numpy as np

from contactcore import ProfileData, Scene
from contactcore.laws import frictionless
from contactcore.scene import DISPLACEMENT_QUANTITIES, STRESS_QUANTITIES

from .sizes import measured_floor, roundoff


#: The components of one vector or tensor: each is measured against the
#: size (root sum of squares) of the components of its group sampled at the
#: same points (:func:`scale_of`).
GROUPS = (("tN", "tT"), ("gN", "gT"), STRESS_QUANTITIES, DISPLACEMENT_QUANTITIES)


#: The groups of Γ: a point of Γ has one traction and one gap, whichever
#: profiles sample their components (scene B's B5 holds t_T and g_T, B6 t_N
#: and g_N, at the same points); a stress is measured against the stresses
#: its own profile samples (scene B's B2 σxx and B3 σxy on one line stay
#: apart).
ON_GAMMA = GROUPS[:2]


def group_of(quantity: str) -> tuple[str, ...]:
    """The :data:`GROUPS` entry that holds ``quantity``."""
    return next(g for g in GROUPS if quantity in g)


def _same_points(a: ProfileData, b: ProfileData) -> bool:
    """Whether two profiles sample the same points (the same Γ sampled
    by the same code: equal bit for bit, or not the same samples)."""
    return all(len(a.columns[c]) == len(b.columns[c]) and np.array_equal(a.columns[c], b.columns[c])
               for c in ("x", "y"))


def components(pid: str, q: str, profiles: dict) -> dict[str, np.ndarray]:
    """The components of ``q``'s group (:data:`GROUPS`) at the samples of
    profile ``pid`` of ``profiles`` (id -> ProfileData): those it holds
    and, for Γ's traction and gap, those of any other profile sampling the
    same points; ``q`` itself first."""
    prof, group = profiles[pid], group_of(q)
    here = [prof] + ([p for k, p in profiles.items() if k != pid and _same_points(p, prof)]
                     if group in ON_GAMMA else [])
    out = {q: np.asarray(prof.columns[q], float)}
    for p in here:
        for c in group:
            if c in p.columns:
                out.setdefault(c, np.asarray(p.columns[c], float))
    return out


def group_size(pid: str, q: str, profiles: dict) -> np.ndarray:
    """Per sample, the root sum of squares of :func:`components`: |t| for
    t_N or t_T, |g| for a gap, |u|, the size of the stresses sampled
    (summed in the group's order: t_N's size and t_T's are the same bits)."""
    parts = components(pid, q, profiles)
    return np.sqrt(sum(parts[c] ** 2 for c in group_of(q) if c in parts))


#: How :func:`scale_name` names a frictional law's t_T scale (:func:`slip_bound_size`).
SLIP_BOUND = "slip bound μ max(−tN, 0)"


def slip_bound_size(scene: Scene | None, pid: str, q: str, profiles: dict) -> np.ndarray | None:
    """A frictional law's t_T scale at the samples of ``pid``: the law's
    slip bound there, ``slip_bound(t_N)`` (Coulomb's ``μ max(−t_N, 0)``,
    the largest |t_T| a closed point can carry), of ``profiles``' t_N at
    those points (:func:`components`); None for any other quantity, a law
    that is not frictional or frictionless (μ = 0: t_T is zero, its
    residue is measured against |t|), or no t_N sampled there.  Against
    |t| a friction error read μ times smaller (newuser33, 2026-11-29: a
    wrong μ, 20 % of the slip bound, read 2.0 % of |t|, within rtol 0.05,
    where the methods' discretisation errors read 0.06-0.42 % of |t| and
    0.58-4.1 % of the slip bound; docs/verification.md)."""
    law = getattr(scene, "law", None)
    if q != "tT" or not getattr(law, "frictional", False) or frictionless(law):
        return None
    parts = components(pid, q, profiles)
    return np.asarray(law.slip_bound(parts["tN"]), float) if "tN" in parts else None


def scale_name(pid: str, q: str, profiles: dict, scene: Scene | None = None) -> str:
    """What :func:`scale_of` measures ``q`` against, in words: ``tT`` alone,
    ``|(tN, tT)|`` with its group, :data:`SLIP_BOUND` for a frictional
    law's t_T on ``scene`` (:func:`slip_bound_size`)."""
    if slip_bound_size(scene, pid, q, profiles) is not None:
        return SLIP_BOUND
    names = list(components(pid, q, profiles))
    return q if len(names) == 1 else "|(" + ", ".join(sorted(names, key=group_of(q).index)) + ")|"


def scale_of(scene: Scene, pid: str, q: str, profiles: dict, floor: float = 0.0) -> np.ndarray:
    """The per-sample values ``q`` of profile ``pid`` of ``profiles`` is
    measured against: its group's size (:func:`group_size`), but a
    frictional law's t_T its slip bound (:func:`slip_bound_size`), floored
    by an exact law's gap floor (:func:`measured_against`) or ``floor`` (a
    user's, in q's unit), the larger, and by round-off of the scene's
    scale (:func:`roundoff`)."""
    bound = slip_bound_size(scene, pid, q, profiles)
    own = group_size(pid, q, profiles) if bound is None else bound
    size = np.hypot(own, max(measured_floor(scene, q), floor))
    return np.hypot(size, roundoff(scene, q))
