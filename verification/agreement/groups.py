"""What a quantity is measured against: the size of its vector or tensor
(:data:`GROUPS`) at each sample (:func:`group_size`), Γ's traction and gap
gathered over the profiles that sample the same points
(:func:`components`), floored by :mod:`~verification.agreement.sizes`
(:func:`scale_of`), and its name in words (:func:`scale_name`)."""
from __future__ import annotations

import numpy as np

from contactcore import ProfileData, Scene
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


def scale_name(pid: str, q: str, profiles: dict) -> str:
    """What :func:`scale_of` measures ``q`` against, in words: ``tT`` alone,
    ``|(tN, tT)|`` with its group."""
    names = list(components(pid, q, profiles))
    return q if len(names) == 1 else "|(" + ", ".join(sorted(names, key=group_of(q).index)) + ")|"


def scale_of(scene: Scene, pid: str, q: str, profiles: dict, floor: float = 0.0) -> np.ndarray:
    """The per-sample values ``q`` of profile ``pid`` of ``profiles`` is
    measured against: its group's size (:func:`group_size`) floored by an
    exact law's gap floor (:func:`measured_against`) or ``floor`` (a
    user's, in q's unit), the larger, and by round-off of the scene's
    scale (:func:`roundoff`).  A frictional law's t_T too is measured
    against |t|, not its slip bound (review17, 2026-11-29: against the
    bound, a slip reversal that a method spreads over a cell read 23 % on
    C-coulomb, xfem P2 at h = 0.05, and at μ > 1 a t_T error 10 times
    smaller than against |t|); a wrong friction shows in the status map
    (:mod:`~verification.agreement.status`)."""
    size = np.hypot(group_size(pid, q, profiles), max(measured_floor(scene, q), floor))
    return np.hypot(size, roundoff(scene, q))
