"""Γ's status map (open, stick, slip, partial) of a method against the
reference's, along Γ's profiles: the comparison a contact model's answers
need besides their values (newuser33, 2026-11-29: xfem at μ = 0.15, every
point of Γ sticking, against fe at μ = 0.1, 17 of 84 points slipping,
passed ``assert_methods_agree`` at rtol 0.02 on the values alone).

A run's map (:class:`StatusMap`, :func:`status_map`) is the status the
profile's tractions follow at each sample of a Γ profile
(:func:`contactcore.profiles.interface_status`: an exact law's nearest
quadrature point's, a penalty law's decided at the sample) with the run's
cell size h.  Two maps are compared over **all of Γ**: the samples near
singular points that the values' comparison leaves out
(:func:`~verification.agreement.samples.kept_samples`) are kept here, since
a status is a label, not a stress with a singularity, and Γ's ends are
where a slip zone starts.  A sample whose status differs counts unless it
lies within :data:`STATUS_ALLOWANCE_CELLS` cells (the coarser run's h) of a
status change of either run, measured along Γ: a boundary between two
zones moves by about a cell with the discretisation.  The share of Γ's
length that differs beyond that (:class:`StatusAgreement`'s ``share``)
fails :func:`~verification.agreement.api.assert_methods_agree` above
:data:`STATUS_TOLERATED_SHARE`, whatever ``rtol`` is (a share of Γ is no
relative difference of a value).  Both are contactcore.tolerances', with
their reasons and measurements."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from contactcore import ProfileData, Scene
from contactcore.geometry import CircleInterface
from contactcore.laws import REPORTED_STATUS_NAMES
from contactcore.profiles import interface_status, sample_points
from contactcore.scene import InterfaceProfile, LineProfile, Units
from contactcore.scene.vocabulary import INTERFACE_QUANTITIES
from contactcore.tolerances import STATUS_ALLOWANCE_CELLS

from .measures import percent


@dataclass(frozen=True)
class StatusMap:
    """One run's status along Γ's profiles: ``profiles`` (id -> the status
    at each sample, an index into ``REPORTED_STATUS_NAMES``) and the run's
    cell size ``h`` in the scene's length unit (the allowance's cell)."""

    h: float
    profiles: dict = field(default_factory=dict)


def on_gamma(profile) -> bool:
    """Whether ``profile`` samples Γ: an interface profile, or a segment
    that carries Γ's quantities (a scene's check holds such a segment to
    Γ: :mod:`contactcore.scene.check_profiles`; scene A's A5 is one)."""
    return isinstance(profile, InterfaceProfile) or (isinstance(profile, LineProfile)
                                                      and bool(set(profile.quantities) & set(INTERFACE_QUANTITIES)))


def gamma_profiles(scene: Scene) -> list:
    """The scene's profiles along Γ (:func:`on_gamma`), one of those that
    sample the same points (scene B's B5 and B6 sample the same Γ: one
    map).  Without one, nothing along Γ is compared (review17: a Γ
    sampled by a segment once gave no status row)."""
    seen, out = [], []
    for p in scene.profiles:
        if on_gamma(p):
            xy = sample_points(scene, p)[1]
            if not any(len(xy) == len(o) and np.array_equal(xy, o) for o in seen):
                seen.append(xy)
                out.append(p)
    return out


def status_map(scene: Scene, result) -> StatusMap | None:
    """``result``'s :class:`StatusMap` on ``scene`` (the scene it solved),
    or None where there is no status to compare: a linear law (bonded,
    linear springs: Γ neither opens nor slips), no Γ profile, or no
    interface history."""
    path = getattr(result, "interface", None)
    profiles = gamma_profiles(scene)
    if scene.law.is_linear or path is None or not path.steps or not profiles:
        return None
    h = result.discretisation.get("h") or scene.h
    return StatusMap(float(h), {p.id: np.asarray(interface_status(scene, result.fields, sample_points(scene, p)[1],
                                                                   path), int) for p in profiles})


def _along(xy: np.ndarray, closed: bool) -> tuple[np.ndarray, float]:
    """Each sample's distance along the profile from its first (chords
    between samples) and the profile's length (a closed Γ's with the
    chord from the last sample back to the first)."""
    steps = np.linalg.norm(np.diff(xy, axis=0), axis=1)
    d = np.concatenate([[0.0], np.cumsum(steps)])
    return d, float(d[-1] + (np.linalg.norm(xy[0] - xy[-1]) if closed else 0.0))


def _weights(d: np.ndarray, length: float, closed: bool) -> np.ndarray:
    """Each sample's share of the profile's length: half the way to each
    neighbour (the two ends of an open profile half a cell)."""
    mid = (d[1:] + d[:-1]) / 2
    lo = np.concatenate([[d[0] if not closed else (d[0] + d[-1] - length) / 2], mid])
    hi = np.concatenate([mid, [d[-1] if not closed else (d[-1] + length + d[0]) / 2]])
    return (hi - lo) / (hi - lo).sum()


def _change_distance(codes: np.ndarray, d: np.ndarray, length: float, closed: bool) -> np.ndarray:
    """Per sample, the distance along Γ to the nearest status change of
    ``codes`` (between two neighbouring samples whose statuses differ: the
    change lies somewhere between them, so both are at distance 0); inf
    where the status never changes."""
    n = len(codes)
    pairs = [(i, i + 1) for i in range(n - 1) if codes[i] != codes[i + 1]]
    if closed and codes[-1] != codes[0]:
        pairs.append((n - 1, 0))
    out = np.full(n, np.inf)
    for i, j in pairs:
        a, b = d[i], d[j] if j > i else d[j] + length
        for turn in ((-1, 0, 1) if closed else (0,)):  # a closed Γ: either way round
            at = d + turn * length
            out = np.minimum(out, np.maximum(0.0, np.maximum(a - at, at - b)))
    return out


def _stretches(mask: np.ndarray, closed: bool) -> list[np.ndarray]:
    """The runs of consecutive True samples of ``mask`` (indices in order),
    one across a closed profile's seam joined."""
    idx = np.flatnonzero(mask)
    if len(idx) == 0:
        return []
    runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
    if closed and len(runs) > 1 and runs[0][0] == 0 and runs[-1][-1] == len(mask) - 1:
        runs = [np.concatenate([runs[-1], runs[0]])] + runs[1:-1]
    return runs


@dataclass(frozen=True)
class StatusAgreement:
    """How one method's status along one Γ profile differs from the
    reference's, over all of Γ (no sample left out).

    ``share`` is the share of Γ's length (the profile's samples weighted by
    their share of its length) whose status differs farther than
    ``allowance`` (the coarser run's h times :data:`STATUS_ALLOWANCE_CELLS`)
    from a status change of either run; ``differs`` the share that differs
    at all.  The largest stretch beyond the allowance runs from ``start`` to
    ``end`` (the profile's parameter), its middle sample at ``x, y``, where
    the method's status is ``status`` and the reference's ``reference``
    (names; ``a/b`` where the stretch holds several).  ``samples`` were
    compared."""

    method: str
    profile: str
    share: float
    differs: float
    start: float
    end: float
    x: float
    y: float
    status: str
    reference: str
    allowance: float
    samples: int
    units: Units = Units()
    s_unit: str = ""

    quantity = "status"
    kind = "status"

    @property
    def worst(self) -> float:
        """The row's figure, as a value row's ``worst``: :attr:`share`."""
        return self.share

    def where(self) -> str:
        """The largest stretch beyond the allowance, in words (empty if none)."""
        if not self.share > 0:
            return ""
        s_unit = f" {self.s_unit}" if self.s_unit else ""
        return (f"s = {self.start:.4g} to {self.end:.4g}{s_unit} (middle x = {self.x:.4g} {self.units.length}, "
                f"y = {self.y:.4g} {self.units.length})")

    def describe(self, against: str = "the reference") -> str:
        """One line naming the profile, how much of Γ differs and where,
        and both statuses there."""
        allowance = (f"farther than {self.allowance:.3g} {self.units.length} ({STATUS_ALLOWANCE_CELLS:g} cell of "
                     "the coarser run) from a status change of either run")
        head = f"{self.method} against {against}: {self.profile} status (stick/slip/open, all of Γ compared)"
        if not self.share > 0:
            return (f"{head}: no sample differs {allowance} (differs on {percent(self.differs)} of Γ, all "
                    "nearer)")
        return (f"{head} differs on {percent(self.share)} of Γ's length {allowance} (on {percent(self.differs)} "
                f"in all); the largest stretch at {self.where()}: {self.status} against {self.reference}")


def _names(codes: np.ndarray) -> str:
    """The statuses among ``codes`` by name, the most frequent first."""
    values, counts = np.unique(codes, return_counts=True)
    return "/".join(REPORTED_STATUS_NAMES[v] for v in values[np.argsort(-counts, kind="stable")])


def compare_status(scene: Scene, label: str, pid: str, got: np.ndarray, ref: np.ndarray, reference: ProfileData,
                   allowance: float, s_unit: str = "") -> StatusAgreement:
    """Method ``label``'s statuses ``got`` at the samples of Γ profile
    ``pid`` against the reference's ``ref`` (both indices into
    ``REPORTED_STATUS_NAMES``; ``reference`` the reference's sampled profile,
    for its ``s, x, y``), a difference within ``allowance`` (a length) of a
    status change of either allowed (see :class:`StatusAgreement`)."""
    got, ref = np.asarray(got, int), np.asarray(ref, int)
    xy = np.column_stack([reference.columns["x"], reference.columns["y"]])
    closed = isinstance(scene.interface, CircleInterface)
    d, length = _along(xy, closed)
    w = _weights(d, length, closed)
    near = np.minimum(_change_distance(got, d, length, closed), _change_distance(ref, d, length, closed))
    differ = got != ref
    beyond = differ & (near > allowance)
    common = dict(units=scene.units, s_unit=s_unit)
    stretches = _stretches(beyond, closed)
    if not stretches:
        nan = float("nan")
        return StatusAgreement(label, pid, 0.0, float(w[differ].sum()), nan, nan, nan, nan, "", "", allowance,
                               len(got), **common)
    largest = max(stretches, key=lambda run: w[run].sum())
    s, mid = reference.columns["s"], largest[len(largest) // 2]
    return StatusAgreement(label, pid, float(w[beyond].sum()), float(w[differ].sum()), float(s[largest[0]]),
                           float(s[largest[-1]]), float(xy[mid, 0]), float(xy[mid, 1]), _names(got[largest]),
                           _names(ref[largest]), allowance, len(got), **common)


def status_agreements(scene: Scene, label: str, got: StatusMap, ref: StatusMap, reference: dict
                      ) -> list[StatusAgreement]:
    """Every Γ profile of ``got`` against ``ref`` (:class:`StatusMap`), as
    :class:`StatusAgreement` rows of method ``label``; ``reference`` the
    reference's sampled profiles (id -> ProfileData).  The allowance is
    :data:`STATUS_ALLOWANCE_CELLS` of the coarser run's h."""
    from ..files import parameter_unit
    allowance = STATUS_ALLOWANCE_CELLS * max(got.h, ref.h)
    return [compare_status(scene, label, pid, codes, ref.profiles[pid], reference[pid], allowance,
                           parameter_unit(reference[pid].parameter, scene.units))
            for pid, codes in got.profiles.items() if pid in ref.profiles and pid in reference]
