"""How two methods' profiles are compared, in one place, and the public
agreement check built on it.

Per profile and quantity, two figures over the *kept* samples:

* the **RMS** of the difference relative to the RMS of the reference;
* the **worst sample**: the largest |difference| relative to the reference's
  largest |value|, with where it lies (s, x, y) and both values there.

Samples closer than ``exclude`` to a *singular point* — a corner of the
domain, or a point where a straight Γ meets the outer boundary — are left
out: there the stresses have boundary layers or singularities that no
method resolves at these resolutions, so a pointwise difference there
measures resolution, not agreement.  A quantity is a component of a vector
or tensor (:data:`GROUPS`), and is measured against that vector's or
tensor's size at each sample (:func:`scale_of`): t_N and t_T against |t|,
g_N and g_T against |g| (at a point of Γ, whichever profiles sample them:
scene B's B6 t_N against B5's t_T), a stress against the size of the
stresses its profile samples, a displacement against |u|.  So a component
zero by symmetry (scene B's t_N, a pressed disc's t_T) is measured against
the size of its vector, not its own residue (scene B's are labelled class
``zero``, :data:`KNOWN_ZEROS`).  Under an exactly enforced law the gaps g_N, g_T of a
closed, sticking Γ are zero but for the enforcement's residue, so a gap is
measured against its size floored by a share of the scene's displacement
scale (:func:`measured_against`); and every size is floored by round-off of
the scene's own scale (:func:`roundoff`), so a run whose values are all
round-off (a Γ pulled open, stress-free) reports no error.

:func:`compare` solves a scene with several methods and a reference and
returns the :class:`AgreementTable`; :func:`assert_methods_agree` is the
pytest helper built on it (docs/api.md).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contactcore import ContactError, ProfileData, Scene, SceneError, load_scene, sample_profiles
from contactcore.scene import DISPLACEMENT_QUANTITIES, STRESS_QUANTITIES, Units
from contactcore.estimate.extrapolation import rms
from contactcore.estimate.runs import ERROR_SUFFIX
from contactcore.estimate.singular import far_from_singular, singular_points, singular_regions
from contactcore.profiles import sample_points
from contactcore.exact import is_exact
from contactcore.scaling import Sizes, softer_displacement
# The comparison's tolerances, with their reasons, are contactcore.tolerances'
# and stay importable from here (tests and users import them from this module).
from contactcore.tolerances import EXACT_GAP_FLOOR, EXCLUDE_FRACTION, EXCLUDE_KEEP_SHARE, NEGLIGIBLE_SHARE, WORST_TIE  # noqa: F401


#: The kinds whose largest value floors a quantity's scale (:func:`negligible`).
KINDS = (STRESS_QUANTITIES + ("tN", "tT"), DISPLACEMENT_QUANTITIES + ("gN", "gT"))


def roundoff(scene: Scene | None, quantity: str) -> float:
    """:data:`NEGLIGIBLE_SHARE` of ``scene``'s own size of ``quantity``'s
    kind (:class:`contactcore.scaling.Sizes`: the stress Σ of its largest
    load or prescribed displacement for a stress or traction, the
    displacement U they cause in the softer body for a displacement or
    gap); 0 without a scene.  A run whose values are all round-off (a Γ
    pulled open and stress-free: σ ~ 1e-14 MPa where Σ = 200 MPa) has no
    scale of its own: measured against it, round-off read as 60 % errors."""
    if scene is None:
        return 0.0
    sizes = Sizes.of(scene)
    return NEGLIGIBLE_SHARE * (sizes.stress if quantity in KINDS[0] else sizes.displacement)


def negligible(profiles: dict, quantity: str, scene: Scene | None = None) -> float:
    """:data:`NEGLIGIBLE_SHARE` of the largest |value| that any quantity of
    ``quantity``'s kind (:data:`KINDS`) takes on ``profiles`` (id ->
    ProfileData), or of ``scene``'s own size of that kind
    (:func:`roundoff`), the larger: the size below which its error is
    round-off."""
    kind = next(k for k in KINDS if quantity in k)
    sizes = [np.max(np.abs(p.columns[q])) for p in profiles.values() for q in p.names[3:] if q in kind
             and len(p.columns[q])]
    return max(NEGLIGIBLE_SHARE * max(sizes, default=0.0), roundoff(scene, quantity))


def size_floor(quantity: str, given: dict, *runs: dict, scene: Scene | None = None) -> float:
    """The size below which ``quantity`` does not count: the user's floor
    in ``given`` (checked, :func:`user_floors`) or round-off of its kind
    on any of ``runs`` (id -> ProfileData) or of ``scene``'s own scale
    (:func:`negligible`), the largest."""
    return max([given.get(quantity, 0.0), roundoff(scene, quantity),
                *(negligible(run, quantity) for run in runs)])


def displacement_scale(scene: Scene) -> float:
    """``U`` (m) of the loads at full value, in the softer body
    (:func:`contactcore.scaling.softer_displacement`)."""
    return softer_displacement(scene)


def gap_floor(scene: Scene) -> float:
    """The floor of an exactly enforced law's gaps on ``scene``:
    :data:`EXACT_GAP_FLOOR` times the displacement scale of its loads (m,
    :func:`displacement_scale`)."""
    return EXACT_GAP_FLOOR * displacement_scale(scene)


def gap_floors(scene: Scene) -> dict[str, float]:
    """``{"gN": f, "gT": f}``, ``f`` = :func:`gap_floor` of ``scene``: the
    floors of its law's gaps enforced exactly (``run --against-exact``
    measures a penalty run against that)."""
    return dict.fromkeys(("gN", "gT"), gap_floor(scene))


def floors(scene: Scene, given: dict | None = None) -> dict[str, float]:
    """Quantity -> the floor its values are measured against on ``scene``
    (:func:`measured_against`): the gaps of an exactly enforced law, none
    otherwise; with ``given`` (quantity -> value in its unit,
    :func:`user_floors`) the larger of the two where both name one."""
    own, user = (gap_floors(scene) if is_exact(scene.law) else {}), user_floors(given)
    return {q: max(own.get(q, 0.0), user.get(q, 0.0)) for q in {**own, **user}}


def measured_floor(scene: Scene, quantity: str) -> float:
    """The floor :func:`measured_against` gives ``quantity`` on ``scene`` (0 if none)."""
    return floors(scene).get(quantity, 0.0)


def measured_against(scene: Scene, quantity: str, values: np.ndarray) -> np.ndarray:
    """The per-sample values a profile quantity is measured against: its
    own ``values``, but an exactly enforced law's gap ``sqrt(g² + f²)``,
    ``f`` = :func:`gap_floor` (see :data:`EXACT_GAP_FLOOR`)."""
    floor = measured_floor(scene, quantity)
    return np.hypot(values, floor) if floor else np.asarray(values, float)


def default_exclusion(scene: Scene) -> float:
    """The distance from singular points inside which samples are left out:
    ``EXCLUDE_FRACTION`` of the scene's diameter L, at most
    ``EXCLUDE_KEEP_SHARE`` of the distance from the singular points of each
    profile's farthest sample, so that every profile keeps samples (its
    middle, where both its ends are singular points)."""
    sing = singular_points(scene)
    if len(sing) == 0:
        return EXCLUDE_FRACTION * scene.length_scale
    reach = min((float(np.max(np.min(np.linalg.norm(points[:, None, :] - sing[None], axis=-1), axis=1)))
                 for points in (sample_points(scene, p)[1] for p in scene.profiles)), default=np.inf)
    return min(EXCLUDE_FRACTION * scene.length_scale, EXCLUDE_KEEP_SHARE * reach)


def check_exclusion(scene: Scene, exclude: float, name: str = "exclude") -> None:
    """Refuse, before any solve, an exclusion (the argument ``name``) that is
    not a finite distance >= 0, or that leaves every sample of a profile out
    (its agreement would have nothing to measure)."""
    if not (exclude >= 0 and np.isfinite(exclude)):
        raise SceneError(name, f"must be a finite distance >= 0 (got {exclude:g})")
    for profile in scene.profiles:
        if not far_from_singular(scene, sample_points(scene, profile)[1], exclude).any():
            raise SceneError(name, f"{exclude:g} leaves out every sample of profile {profile.id}: "
                             f"give less (the default is {default_exclusion(scene):.3g})")


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
    ``scale`` (default: the reference quantity itself; the table's measure
    is its group's size, :func:`scale_of`)."""
    keep = kept_samples(scene, ref, exclude)
    diff = got.columns[quantity][keep] - ref.columns[quantity][keep]
    base = measured_against(scene, quantity, ref.columns[quantity][keep]) if scale is None else np.asarray(scale)
    return share(float(np.sqrt(np.mean(diff ** 2))), float(np.sqrt(np.mean(base ** 2))))


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
    scale (:func:`roundoff`)."""
    size = np.hypot(group_size(pid, q, profiles), max(measured_floor(scene, q), floor))
    return np.hypot(size, roundoff(scene, q))


#: The paper's scenes' quantities whose exact value is zero, by scene name:
#: the class ``zero`` they are labelled with (tests/test_agreement.py bounds
#: them by tolerances.FALSE_TN).  A label only: every quantity, these too,
#: is measured against its group's size (:func:`scale_of`); the numbers
#: cannot tell a zero by symmetry from a small component (scene B's fe P2
#: t_N is 0.42 % of |t| at h = 0.1, scene C's C4 t_T, not zero, 0.94 %).
KNOWN_ZEROS = {"B": {("B6", "tN"), ("B6", "gN")}}


def is_zero(scene: Scene, pid: str, q: str, profiles: dict) -> bool:
    """Whether ``pid``'s ``q`` is one of :data:`KNOWN_ZEROS` of ``scene``
    and ``profiles`` hold another component of its group at its samples
    (class ``zero``)."""
    return (pid, q) in KNOWN_ZEROS.get(scene.name, ()) and len(components(pid, q, profiles)) > 1


def agreements(scene: Scene, got: dict, ref: dict, exclude: float) -> list[tuple[str, str, str, float]]:
    """``(profile id, quantity, class, relative RMS)`` for every quantity of
    every profile; the class is ``zero`` for a known zero (:func:`is_zero`),
    else :func:`quantity_class`."""
    return [(a.profile, a.quantity, a.kind, a.rms) for a in profile_agreements(scene, "", got, ref, exclude)]


def estimated_shares(scene: Scene, profiles: dict, est, exclude: float, floors: dict | None = None
                     ) -> dict[tuple[str, str], tuple[float, float]]:
    """``(profile id, quantity) -> (RMS of the estimated error, RMS of its
    scale)`` over the samples of ``profiles`` (id -> ProfileData, the runs
    ``est`` estimated, a :class:`contactcore.estimate.Estimate`) at least
    ``exclude`` from the singular points: the scale is its group's size
    (:func:`scale_of`: |t| for t_N, t_T), as :func:`profile_agreements`
    measures a true error, floored by ``floors`` (quantity -> value in its
    unit, :func:`user_floors`) and by :func:`negligible` (of the run and of
    the scene's scale)."""
    shares, given = {}, user_floors(floors)
    for pid, qs in est.profiles.items():
        keep = kept_samples(scene, profiles[pid], exclude)
        for q, e in qs.items():
            scale = scale_of(scene, pid, q, profiles, size_floor(q, given, profiles, scene=scene))
            shares[pid, q] = rms(e.error[keep]), rms(scale[keep])
    return shares


def first_largest(items, key):
    """The first of ``items`` (in their order) whose ``key`` (≥ 0) lies
    within :data:`WORST_TIE` of the largest."""
    items = list(items)
    top = max(key(i) for i in items)
    return next(i for i in items if key(i) >= top * (1 - WORST_TIE))


def worst_estimate(scene: Scene, profiles: dict, est, exclude: float, floors: dict | None = None
                   ) -> tuple[float, str]:
    """The largest estimated relative RMS error over every profile and
    quantity of :func:`estimated_shares` (with ``floors``) and where
    (``"B5:tT"``; the first in the scene's order of those within
    :data:`WORST_TIE`); ``(0, "")`` when no quantity has a scale."""
    rows = [(error / scale, f"{pid}:{q}") for (pid, q), (error, scale)
            in estimated_shares(scene, profiles, est, exclude, floors).items() if scale > 0]
    return first_largest(rows, key=lambda row: row[0]) if rows else (0.0, "")


def share(difference: float, size: float) -> float:
    """``difference / size``; 0 where both are 0, infinite where only the
    size is (a zero the compared run misses)."""
    return difference / size if size > 0 else (0.0 if difference == 0 else float("inf"))


def percent(fraction: float) -> str:
    """A relative difference in per cent, to three significant digits."""
    return f"{100 * fraction:.3g} %"


@dataclass(frozen=True)
class Agreement:
    """How one method's quantity on one profile differs from the reference's.

    ``rms`` is RMS(got − ref)/RMS(scale) and ``worst`` max|got − ref|/max|scale|
    over the kept samples, ``scale`` the reference's size of the
    quantity's group (``against``: ``|(tN, tT)|``, or the quantity alone;
    :func:`scale_of`: an exact law's gaps floored, round-off of the scene's
    scale the least); the worst sample lies at ``s`` (the
    profile's parameter) and ``x, y``, where the method gives ``value`` and
    the reference ``reference``.  ``kept`` of ``samples`` were compared."""

    method: str
    profile: str
    quantity: str
    kind: str
    rms: float
    worst: float
    s: float
    x: float
    y: float
    value: float
    reference: float
    kept: int
    samples: int
    floor: float = 0.0  # the floor of the scale (an exact law's gap, measured_against), 0 if none
    units: Units = Units()  # the names of the scene's units, which the floor is in
    against: str = ""  # what the scale is the size of (scale_name: "|(tN, tT)|"); "" the quantity itself

    def describe(self, against: str = "the reference") -> str:
        """One line naming the profile, the quantity, the worst sample and its values."""
        from .files import column_unit
        unit = column_unit(self.quantity, self.units)
        name = self.against or self.quantity
        scale = (f"sqrt({name}² + ({self.floor:.3g} {unit})²) (floored)" if self.floor
                 else name if name.startswith("|") else f"|{name}|")
        return (f"{self.method} against {against}: {self.profile} {self.quantity} at s = {self.s:.4g} "
                f"(x = {self.x:.4g}, y = {self.y:.4g}): {self.value:.4g} against {self.reference:.4g}, a difference "
                f"of {percent(self.worst)} of the reference's largest {scale} (RMS {percent(self.rms)})")


def _compared(scene: Scene, label: str, pid: str, q: str, got: ProfileData, ref: ProfileData,
              exclude: float, scale: np.ndarray, floor: float = 0.0, against: str = "") -> Agreement:
    """One profile quantity of ``got`` against ``ref``, measured against
    ``scale`` (per sample; ``floor`` and ``against`` name it, see
    :class:`Agreement`)."""
    keep = kept_samples(scene, ref, exclude)
    diff = got.columns[q][keep] - ref.columns[q][keep]
    base = np.asarray(scale)[keep]
    if not keep.any():
        nan = float("nan")
        return Agreement(label, pid, q, "", nan, nan, nan, nan, nan, nan, nan, 0, len(keep), units=scene.units)
    i = int(np.argmax(np.abs(diff)))
    where = np.flatnonzero(keep)[i]
    worst = share(float(abs(diff[i])), float(np.max(np.abs(base))))
    return Agreement(label, pid, q, "", relative_rms(scene, got, ref, q, exclude, scale=base),
                     worst, float(ref.columns["s"][where]), float(ref.columns["x"][where]),
                     float(ref.columns["y"][where]), float(got.columns[q][where]), float(ref.columns[q][where]),
                     int(keep.sum()), len(keep), floor, scene.units, against)


def profile_agreements(scene: Scene, label: str, got: dict, ref: dict, exclude: float,
                       scales: dict | None = None, floors: dict | None = None) -> list[Agreement]:
    """Every quantity of every profile of ``got`` (id -> ProfileData)
    against ``ref``, as :class:`Agreement` rows of method ``label``, each
    measured against the reference's size of its group (:func:`scale_of`,
    floored by ``floors``: quantity -> value in its unit, checked);
    ``scales`` ((profile id, quantity) -> per-sample values) measures a
    quantity against those values instead."""
    profiles, given = {p.id: p for p in scene.profiles}, floors or {}
    rows = []
    for pid, prof in got.items():
        for q in prof.names[3:]:
            kind = "zero" if is_zero(scene, pid, q, ref) else quantity_class(scene, profiles[pid], q)
            if (pid, q) in (scales or {}):
                row = _compared(scene, label, pid, q, prof, ref[pid], exclude, scales[pid, q])
            else:
                floor = max(measured_floor(scene, q), given.get(q, 0.0))
                row = _compared(scene, label, pid, q, prof, ref[pid], exclude,
                                scale_of(scene, pid, q, ref, given.get(q, 0.0)), floor, scale_name(pid, q, ref))
            rows.append(Agreement(**{**row.__dict__, "kind": kind}))
    return rows


@dataclass(frozen=True)
class AgreementTable:
    """Methods against a reference on one scene: one :class:`Agreement` per
    method, profile and quantity; samples within ``exclude`` of the named
    singular ``regions`` left out."""

    scene: str
    reference: str
    exclude: float
    regions: tuple[tuple[str, tuple[tuple[float, float], ...]], ...]
    rows: tuple[Agreement, ...]
    gap_floor: float = 0.0  # an exact law's gaps' floor (measured_against), in length; 0 for a penalty law
    floors: tuple[tuple[str, float], ...] = ()  # the floors given (quantity, value in its unit): table's floors
    units: Units = Units()  # the names of the scene's units, which the floors are in

    def worst(self, measure: str = "worst") -> Agreement:
        """The row with the largest ``measure`` (``"worst"`` or ``"rms"``;
        the first of those within :data:`WORST_TIE`)."""
        return first_largest(self.rows, key=lambda a: getattr(a, measure))

    def excluded(self) -> str:
        """Which samples were left out, in words."""
        if not self.regions:
            return "no sample was left out (the scene has no singular point)"
        where = "; ".join(f"{name} " + ", ".join(f"({x:.4g}, {y:.4g})" for x, y in pts)
                          for name, pts in self.regions)
        return (f"samples within {self.exclude:.3g} {self.units.length} of these singular points were left out: "
                f"{where}")

    def _below_gap_floor(self, quantity: str, value: float) -> bool:
        """Whether a floor given for ``quantity`` is one of the gaps' and no
        larger than the exactly enforced law's own (:func:`floors` keeps the larger)."""
        return bool(self.gap_floor) and quantity in ("gN", "gT") and value <= self.gap_floor

    def markdown(self) -> str:
        """The table in Markdown, worst sample and RMS in % of the reference's scale."""
        from .files import column_unit
        floor = (f" Γ's gaps (an exactly enforced law: zero where Γ is closed and sticking) are measured "
                 f"against sqrt(g² + ({self.gap_floor:.3g} {self.units.length})²), {EXACT_GAP_FLOOR:g} of the "
                 "displacement scale." if self.gap_floor else "")
        floor += "".join(f" {q}'s floor given ({v:.3g} {column_unit(q, self.units)}) lies below the law's own "
                         "and is not used." if self._below_gap_floor(q, v) else
                         f" {q} is measured against sqrt({q}² + ({v:.3g} {column_unit(q, self.units)})²) "
                         "(a floor given)." for q, v in self.floors)
        floor += (" Each quantity is measured against its vector's or tensor's size at each sample (t_N and t_T "
                  "against |t|, a stress against the stresses its profile samples), at least "
                  f"{NEGLIGIBLE_SHARE:g} of the scene's own scale (round-off).")
        lines = [f"Against {self.reference}; {self.excluded()}.{floor}", "",
                 "| method | profile | quantity | class | worst sample | at s (x, y) | RMS |",
                 "|---|---|---|---|---|---|---|"]
        lines += [f"| {a.method} | {a.profile} | {a.quantity} | {a.kind} | {percent(a.worst)} | {a.s:.4g} "
                  f"({a.x:.4g}, {a.y:.4g}) | {percent(a.rms)} |" for a in self.rows]
        return "\n".join(lines) + "\n"


def floor_problem(q: str, value) -> str | None:
    """What is wrong with ``value`` as quantity ``q``'s floor, or None: the
    one rule and text of a floor, for ``floors={...}`` in Python and
    ``--floor Q=VALUE`` on the command line: a finite number > 0 in ``q``'s
    unit (a floor of 0 is no floor: leave the quantity out)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value) or value <= 0:
        shown = f"{value:g}" if isinstance(value, (int, float)) and not isinstance(value, bool) else repr(value)
        return f"{q}: the floor must be a finite number > 0 in {q}'s unit (got {shown})"
    return None


def user_floors(floors: dict | None) -> dict[str, float]:
    """``floors`` (quantity -> a value in its unit, > 0: :func:`floor_problem`)
    checked: a ContactError names a quantity that does not exist or a bad value."""
    from contactcore.scene import QUANTITIES
    checked = {}
    for q, value in (floors or {}).items():
        if q not in QUANTITIES:
            raise ContactError(f"floors: unknown quantity {q!r} (known: {', '.join(QUANTITIES)})")
        problem = floor_problem(q, value)
        if problem:
            raise ContactError(f"floors: {problem}")
        checked[q] = float(value)
    return checked


def table(scene: Scene, runs: dict[str, dict], reference: str, exclude: float | None = None,
          floors: dict | None = None) -> AgreementTable:
    """The :class:`AgreementTable` of sampled profiles ``runs`` (label ->
    id -> ProfileData), ``runs[reference]`` the reference.  ``floors``
    (quantity -> value in its unit) measures a quantity against
    ``sqrt(q_ref² + floor²)``: the size below which a difference does not
    count, for a quantity that is zero in the reference (a patch test's
    σxy), where its own round-off would be its scale.  ``reference`` is a
    label among ``runs``' keys; anything else is refused with a
    :class:`ContactError` naming the labels."""
    if not isinstance(runs, dict):
        raise ContactError(f"runs: a dict of label -> {{profile id: ProfileData}} (got {type(runs).__name__})")
    labels = ", ".join(map(repr, runs))
    if not isinstance(reference, str):
        raise ContactError(f"reference: the label of one of runs ({labels}), not its profiles (got a "
                           f"{type(reference).__name__})")
    if reference not in runs:
        raise ContactError(f"reference: {reference!r} is not a label of runs (they are {labels})")
    exclude = default_exclusion(scene) if exclude is None else exclude
    check_exclusion(scene, exclude)
    ref, given = runs[reference], user_floors(floors)
    rows = [row for label, got in runs.items() if label != reference
            for row in profile_agreements(scene, label, got, ref, exclude, floors=given)]
    regions = tuple((name, tuple(map(tuple, pts.tolist()))) for name, pts in singular_regions(scene))
    return AgreementTable(scene.name, reference, exclude, regions, tuple(rows), measured_floor(scene, "gN"),
                          tuple(given.items()), scene.units)


def variant(spec) -> tuple[str, int]:
    """``(method, degree)`` of ``"xfem:2"``, ``"xfem"`` (degree 1) or ``("xfem", 2)``."""
    from . import methods
    name, _, degree = spec.partition(":") if isinstance(spec, str) else (spec[0], ":", spec[1])
    if name not in methods.METHODS:
        raise ContactError(f"method {name!r}: unknown (known: {', '.join(methods.METHODS)})")
    try:
        degree = int(degree or 1)
    except ValueError:
        raise ContactError(f"method {spec!r}: the degree after ':' must be 1 or 2") from None
    if degree not in (1, 2):
        raise ContactError(f"method {spec!r}: the degree must be 1 or 2 (got {degree})")
    return name, degree


def label(name: str, degree: int) -> str:
    """How a (method, degree) is named in tables and plots: ``xfem p2``."""
    return f"{name} p{degree}"


def sampled(scene: Scene, result) -> dict:
    """A Result's profiles of ``scene``, by id."""
    return {p.id: p for p in sample_profiles(scene, result.fields, result.interface)}


def compared_variants(methods, reference: tuple[str, int]) -> list[tuple[str, int]]:
    """The ``(method, degree)`` of each of ``methods`` (:func:`variant`),
    refused with a :class:`ContactError`, before any solve, when they
    compare nothing with ``reference``: an empty list, or the reference
    alone (a check over no method passed having checked nothing, grader9
    #3); a string, which would be read a letter a method, is refused too."""
    if isinstance(methods, str):
        raise ContactError(f"methods: a list of methods, not one string (got {methods!r}; write [{methods!r}])")
    try:
        variants = [variant(m) for m in methods]
    except TypeError:
        raise ContactError(f"methods: a list of methods such as ['fe', 'xfem:2'] (got {methods!r})") from None
    if not any(v != reference for v in variants):
        given = "none is given" if not variants else f"only the reference {label(*reference)} itself is given"
        raise ContactError(f"methods: {given}: name at least one method to compare with the reference "
                           f"{label(*reference)} (nothing would be compared, and the check would pass having "
                           "checked nothing)")
    return variants


#: The measures of :func:`assert_methods_agree`: an :class:`Agreement`'s
#: worst sample and its RMS, both relative to the reference's scale.
MEASURES = ("worst", "rms")


def check_rtol(rtol, measure: str) -> float:
    """``rtol`` and ``measure`` of :func:`assert_methods_agree`, refused with a
    :class:`ContactError` (before any solve) unless ``measure`` is one of
    :data:`MEASURES` and ``rtol`` a finite number > 0 (a NaN or negative
    rtol failed every row, an infinite one passed every row)."""
    if not isinstance(measure, str) or measure not in MEASURES:
        raise ContactError(f"measure: {measure!r} is not a measure of agreement (known: "
                           f"{', '.join(MEASURES)})")
    if isinstance(rtol, bool) or not isinstance(rtol, (int, float)) or not math.isfinite(rtol) or rtol <= 0:
        raise ContactError(f"rtol: must be a finite number > 0 (got {rtol!r})")
    return float(rtol)


def compare(scene, methods, h: float | None = None, *, reference="fe:2", exclude: float | None = None,
            floors: dict | None = None, **options) -> AgreementTable:
    """Solve ``scene`` (a Scene, a shipped scene's name or a TOML path) with
    each of ``methods`` (``"fe"``, ``"xfem:2"``, ``("efgm", 2)``, ...) and
    with ``reference`` at resolution ``h`` (default: the scene's), sample its
    profiles, and return the :class:`AgreementTable` of the methods against
    the reference (``floors``: see :func:`table`).  ``options``
    (``cell="triangle"``, ``dmax=3``, ...) go to the methods that take
    them; one that none takes is refused."""
    from . import methods as known
    user_floors(floors)  # a bad floor ends here, before any solve
    scene = load_scene(scene)
    if exclude is not None:
        check_exclusion(scene, exclude)
    ref = variant(reference)
    variants = compared_variants(methods, ref)
    names = sorted({n for n, _ in [ref, *variants]})
    known.check_options(names, **options)
    runs = {}
    for name, degree in dict.fromkeys([ref, *variants]):
        result = known.solver(name)(scene, h, degree=degree, **known.options_for(name, **options))
        runs[label(name, degree)] = sampled(scene, result)
    return table(scene, runs, label(*ref), exclude, floors)


def assert_methods_agree(scene, methods, h: float | None = None, rtol: float = 0.05, *, reference="fe:2",
                         measure: str = "worst", exclude: float | None = None, floors: dict | None = None,
                         **options) -> AgreementTable:
    """Assert that every method agrees with ``reference`` on every profile
    and quantity of ``scene`` to ``rtol``, measured as ``measure``: the worst
    sample (``"worst"``, the default) or the RMS (``"rms"``), relative to the
    reference's scale (see :func:`compare`).  The AssertionError names the
    worst offender first (method, profile, quantity, the sample and both
    values), then the others; the table is returned when all agree.
    ``floors`` (quantity -> value in its unit): see :func:`table`.  A
    ``measure`` not in :data:`MEASURES`, an ``rtol`` that is not a finite
    number > 0 and ``methods`` that compare nothing (:func:`compared_variants`)
    are refused with a :class:`ContactError` before any solve."""
    check_rtol(rtol, measure)
    result = compare(scene, methods, h, reference=reference, exclude=exclude, floors=floors, **options)
    failed = sorted((a for a in result.rows if not getattr(a, measure) <= rtol),
                    key=lambda a: -getattr(a, measure))
    if failed:
        lines = [a.describe(result.reference) for a in failed]
        raise AssertionError(f"{len(failed)} of {len(result.rows)} profile quantities differ by more than "
                             f"rtol = {rtol:g} ({measure}): " + "\n".join(lines)
                             + f"\n({result.excluded()})")
    return result


def within_estimates(scene: Scene, a: dict, err_a: dict, b: dict, err_b: dict, exclude: float,
                     floors: dict | None = None) -> list[tuple[str, str, float, bool]]:
    """Two methods' profiles (``{id: ProfileData}``) against their estimated
    errors (``{id: {quantity + "_err": per-sample error}}``,
    :meth:`contactcore.estimate.Estimate.error_columns`): per profile and
    quantity, ``RMS(q_a − q_b) / max(RMS(e_a + e_b), f)`` over the kept
    samples (RMS, not the worst sample: a pointwise estimate vanishes where
    the runs at h and h/2 cross), ``f`` the larger of the quantity's floor
    in ``floors`` (:func:`user_floors`) and :func:`negligible` of the runs
    and of the scene's scale (a difference at round-off is within any
    estimate), and whether it
    exceeds 1 (they differ by more than their estimated errors allow)."""
    rows, given = [], user_floors(floors)
    for pid, prof in a.items():
        keep = kept_samples(scene, prof, exclude)
        for q in prof.names[3:]:
            diff = (prof.columns[q] - b[pid].columns[q])[keep]
            bound = (err_a[pid][f"{q}{ERROR_SUFFIX}"] + err_b[pid][f"{q}{ERROR_SUFFIX}"])[keep]
            floor = max(size_floor(q, given, a, b, scene=scene), np.finfo(float).tiny)
            ratio = rms(diff) / max(rms(bound), floor)
            rows.append((pid, q, ratio, ratio > 1.0))
    return rows
