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
measures resolution, not agreement.  A quantity whose exact value is zero
(scene B's t_N) has no relative measure; it is compared against the scale of
another quantity instead (``COMPANIONS``).  Under an exactly enforced law
the gaps g_N, g_T of a closed, sticking Γ are zero but for the
enforcement's residue, so a gap is measured against its own values floored
by a share of the scene's displacement scale (:func:`measured_against`).

:func:`compare` solves a scene with several methods and a reference and
returns the :class:`AgreementTable`; :func:`assert_methods_agree` is the
pytest helper built on it (docs/api.md).
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from contactcore import ContactError, ProfileData, Scene, load_scene, sample_profiles
from contactcore.scene import DISPLACEMENT_QUANTITIES, STRESS_QUANTITIES, Units
from contactcore.estimate import ERROR_SUFFIX, far_from_singular, rms, singular_regions
from contactcore.exact import is_exact
from contactcore.scaling import Scales
# The comparison's tolerances, with their reasons, are contactcore.tolerances'
# and stay importable from here (tests and users import them from this module).
from contactcore.tolerances import EXACT_GAP_FLOOR, EXCLUDE_FRACTION, NEGLIGIBLE_SHARE, WORST_TIE  # noqa: F401


#: The kinds whose largest value floors a quantity's scale (:func:`negligible`).
KINDS = (STRESS_QUANTITIES + ("tN", "tT"), DISPLACEMENT_QUANTITIES + ("gN", "gT"))


def negligible(profiles: dict, quantity: str) -> float:
    """:data:`NEGLIGIBLE_SHARE` of the largest |value| that any quantity of
    ``quantity``'s kind (:data:`KINDS`) takes on ``profiles`` (id ->
    ProfileData): the size below which its error is round-off."""
    kind = next(k for k in KINDS if quantity in k)
    sizes = [np.max(np.abs(p.columns[q])) for p in profiles.values() for q in p.names[3:] if q in kind
             and len(p.columns[q])]
    return NEGLIGIBLE_SHARE * max(sizes, default=0.0)


def size_floor(quantity: str, given: dict, *runs: dict) -> float:
    """The size below which ``quantity`` does not count: the user's floor
    in ``given`` (checked, :func:`user_floors`) or round-off of its kind
    on any of ``runs`` (id -> ProfileData, :func:`negligible`), the larger."""
    return max([given.get(quantity, 0.0), *(negligible(run, quantity) for run in runs)])


def displacement_scale(scene: Scene) -> float:
    """``U = max(L τ/E, |ū|)`` (m), E the softer body's modulus: the
    displacement the loads cause in the softer body, or the largest
    prescribed displacement ū if larger (:class:`contactcore.scaling.Scales`'
    U, taken with the softer modulus; a stiff disc in a 100× softer block
    moves with the block, 100 times the stiff body's L τ/E, while a
    prescribed displacement is the same whichever body is softer)."""
    soft = scene.softer_modulus
    return Scales.of(scene.with_changes(materials={b: replace(m, E=soft) for b, m in scene.materials.items()})
                     ).displacement


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
    base = measured_against(scene, quantity, ref.columns[quantity][keep]) if scale is None else np.asarray(scale)
    return share(float(np.sqrt(np.mean(diff ** 2))), float(np.sqrt(np.mean(base ** 2))))


#: Quantities whose exact value is zero, measured against the scale of a
#: companion: (profile id, quantity) -> (profile id, quantity).
COMPANIONS = {("B6", "tN"): ("B5", "tT"), ("B6", "gN"): ("B5", "gT")}


def companion(pid: str, q: str, profiles: dict) -> tuple[str, str] | None:
    """The :data:`COMPANIONS` entry of ``pid``'s ``q`` where ``profiles``
    (id -> ProfileData) holds it, else None: a scene of the user's that
    names a profile B6 and none B5 is measured against its own values."""
    pair = COMPANIONS.get((pid, q))
    return pair if pair and pair[0] in profiles and pair[1] in profiles[pair[0]].columns else None


def agreements(scene: Scene, got: dict, ref: dict, exclude: float) -> list[tuple[str, str, str, float]]:
    """``(profile id, quantity, class, relative RMS)`` for every quantity of
    every profile; the class is ``zero`` for a quantity measured against its
    companion (see COMPANIONS), else :func:`quantity_class`."""
    return [(a.profile, a.quantity, a.kind, a.rms) for a in profile_agreements(scene, "", got, ref, exclude)]


def estimated_shares(scene: Scene, profiles: dict, est, exclude: float, floors: dict | None = None
                     ) -> dict[tuple[str, str], tuple[float, float]]:
    """``(profile id, quantity) -> (RMS of the estimated error, RMS of its
    scale)`` over the samples of ``profiles`` (id -> ProfileData, the runs
    ``est`` estimated, a :class:`contactcore.estimate.Estimate`) at least
    ``exclude`` from the singular points: the scale is the quantity's own
    values (:func:`measured_against`) or, for a zero quantity, its
    companion's (:data:`COMPANIONS`), as :func:`profile_agreements`
    measures a true error, floored by ``floors`` (quantity -> value in its
    unit, :func:`user_floors`) and by :func:`negligible`."""
    shares, given = {}, user_floors(floors)
    for pid, qs in est.profiles.items():
        keep = kept_samples(scene, profiles[pid], exclude)
        for q, e in qs.items():
            spid, sq = companion(pid, q, profiles) or (pid, q)
            floor = size_floor(q, given, profiles)
            scale = np.hypot(measured_against(scene, sq, profiles[spid].columns[sq][keep]), floor)
            shares[pid, q] = rms(e.error[keep]), rms(scale)
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
    over the kept samples, ``scale`` the reference's own values (or its
    companion's, class ``zero``; an exact law's gaps floored,
    :func:`measured_against`); the worst sample lies at ``s`` (the
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

    def describe(self, against: str = "the reference") -> str:
        """One line naming the profile, the quantity, the worst sample and its values."""
        from .files import column_unit
        unit = column_unit(self.quantity, self.units)
        scale = (f"sqrt({self.quantity}² + ({self.floor:.3g} {unit})²) (floored)" if self.floor
                 else f"|{self.quantity}|")
        return (f"{self.method} against {against}: {self.profile} {self.quantity} at s = {self.s:.4g} "
                f"(x = {self.x:.4g}, y = {self.y:.4g}): {self.value:.4g} against {self.reference:.4g}, a difference "
                f"of {percent(self.worst)} of the reference's largest {scale} (RMS {percent(self.rms)})")


def _compared(scene: Scene, label: str, pid: str, q: str, got: ProfileData, ref: ProfileData,
              exclude: float, scale: np.ndarray | None) -> Agreement:
    """One profile quantity of ``got`` against ``ref`` (see :class:`Agreement`)."""
    keep = kept_samples(scene, ref, exclude)
    diff = got.columns[q][keep] - ref.columns[q][keep]
    base = measured_against(scene, q, ref.columns[q][keep]) if scale is None else np.asarray(scale)[keep]
    if not keep.any():
        nan = float("nan")
        return Agreement(label, pid, q, "", nan, nan, nan, nan, nan, nan, nan, 0, len(keep), units=scene.units)
    i = int(np.argmax(np.abs(diff)))
    where = np.flatnonzero(keep)[i]
    worst = share(float(abs(diff[i])), float(np.max(np.abs(base))))
    return Agreement(label, pid, q, "", relative_rms(scene, got, ref, q, exclude, scale=None if scale is None
                                                      else np.asarray(scale)[keep]),
                     worst, float(ref.columns["s"][where]), float(ref.columns["x"][where]),
                     float(ref.columns["y"][where]), float(got.columns[q][where]), float(ref.columns[q][where]),
                     int(keep.sum()), len(keep), measured_floor(scene, q) if scale is None else 0.0, scene.units)


def profile_agreements(scene: Scene, label: str, got: dict, ref: dict, exclude: float,
                       scales: dict | None = None) -> list[Agreement]:
    """Every quantity of every profile of ``got`` (id -> ProfileData)
    against ``ref``, as :class:`Agreement` rows of method ``label``;
    ``scales`` ((profile id, quantity) -> per-sample values) measures a
    quantity against those values instead of its own (or its companion's)."""
    profiles = {p.id: p for p in scene.profiles}
    rows = []
    for pid, prof in got.items():
        for q in prof.names[3:]:
            pair = companion(pid, q, ref)
            scale = measured_against(scene, pair[1], ref[pair[0]].columns[pair[1]]) if pair else None
            scale = (scales or {}).get((pid, q), scale)
            kind = "zero" if pair else quantity_class(scene, profiles[pid], q)
            row = _compared(scene, label, pid, q, prof, ref[pid], exclude, scale)
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

    def markdown(self) -> str:
        """The table in Markdown, worst sample and RMS in % of the reference's scale."""
        from .files import column_unit
        floor = (f" Γ's gaps (an exactly enforced law: zero where Γ is closed and sticking) are measured "
                 f"against sqrt(g² + ({self.gap_floor:.3g} {self.units.length})²), {EXACT_GAP_FLOOR:g} of the "
                 "displacement scale." if self.gap_floor else "")
        floor += "".join(f" {q} is measured against sqrt({q}² + ({v:.3g} {column_unit(q, self.units)})²) "
                         "(a floor given)." for q, v in self.floors)
        lines = [f"Against {self.reference}; {self.excluded()}.{floor}", "",
                 "| method | profile | quantity | class | worst sample | at s (x, y) | RMS |",
                 "|---|---|---|---|---|---|---|"]
        lines += [f"| {a.method} | {a.profile} | {a.quantity} | {a.kind} | {percent(a.worst)} | {a.s:.4g} "
                  f"({a.x:.4g}, {a.y:.4g}) | {percent(a.rms)} |" for a in self.rows]
        return "\n".join(lines) + "\n"


def user_floors(floors: dict | None) -> dict[str, float]:
    """``floors`` (quantity -> a value in its unit, ≥ 0) checked: a
    ContactError names a quantity that does not exist or a bad value."""
    from contactcore.scene import QUANTITIES
    checked = {}
    for q, value in (floors or {}).items():
        if q not in QUANTITIES:
            raise ContactError(f"floors: unknown quantity {q!r} (known: {', '.join(QUANTITIES)})")
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value) or value < 0:
            raise ContactError(f"floors: {q} must be a finite number ≥ 0 in its unit (got {value!r})")
        checked[q] = float(value)
    return checked


def table(scene: Scene, runs: dict[str, dict], reference: str, exclude: float | None = None,
          floors: dict | None = None) -> AgreementTable:
    """The :class:`AgreementTable` of sampled profiles ``runs`` (label ->
    id -> ProfileData), ``runs[reference]`` the reference.  ``floors``
    (quantity -> value in its unit) measures a quantity against
    ``sqrt(q_ref² + floor²)``: the size below which a difference does not
    count, for a quantity that is zero in the reference (a patch test's
    σxy), where its own round-off would be its scale."""
    exclude = default_exclusion(scene) if exclude is None else exclude
    ref, given = runs[reference], user_floors(floors)
    floor = {(pid, q): max(given[q], measured_floor(scene, q)) for pid, prof in ref.items()
             for q in prof.names[3:] if q in given and not companion(pid, q, ref)}
    scales = {key: np.hypot(ref[key[0]].columns[key[1]], f) for key, f in floor.items()}
    rows = [Agreement(**{**row.__dict__, "floor": floor.get((row.profile, row.quantity), row.floor)})
            for label, got in runs.items() if label != reference
            for row in profile_agreements(scene, label, got, ref, exclude, scales)]
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
    variants = [variant(m) for m in methods]
    ref = variant(reference)
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
    ``floors`` (quantity -> value in its unit): see :func:`table`."""
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
    in ``floors`` (:func:`user_floors`) and :func:`negligible` (a
    difference at round-off is within any estimate), and whether it
    exceeds 1 (they differ by more than their estimated errors allow)."""
    rows, given = [], user_floors(floors)
    for pid, prof in a.items():
        keep = kept_samples(scene, prof, exclude)
        for q in prof.names[3:]:
            diff = (prof.columns[q] - b[pid].columns[q])[keep]
            bound = (err_a[pid][f"{q}{ERROR_SUFFIX}"] + err_b[pid][f"{q}{ERROR_SUFFIX}"])[keep]
            floor = max(size_floor(q, given, a, b), np.finfo(float).tiny)
            ratio = rms(diff) / max(rms(bound), floor)
            rows.append((pid, q, ratio, ratio > 1.0))
    return rows
