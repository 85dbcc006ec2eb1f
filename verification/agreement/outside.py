"""An outside code's answer against the project's, with the project's
estimated error: whose error a difference is (issue 34; docs/api.md, "An
outside code's answer").

:func:`compare_outside` solves a scene with one method at ``h`` and
``h/2`` (and ``h/4``), estimates the finest run's error per profile sample
(:func:`contactcore.estimate.estimate_runs`, what ``run --estimate``
writes as ``q_err``), and sets the user's samples beside it
(:func:`judge`, no solve): per profile and quantity the agreement's worst
sample and RMS (:func:`~verification.agreement.records.profile_agreements`,
its scales, the same samples left out near singular points), the
project's estimated error there, and a verdict per region along ``s``:

* ``outside``: ``|difference| >`` :data:`BLAME_MULTIPLE` times the
  project's estimated error: the difference is at least mostly the
  outside code's error;
* ``agree``: within it: the two agree within the project's error;
* ``outside (estimate warned)``: the estimate is warned
  (:attr:`contactcore.estimate.Estimate.unsettled`) but ``|difference| >``
  :data:`WARNED_MULTIPLE` times it (the outside code's even if the
  estimate is as low as the lowest effectivity the docs record);
* ``warned``: the estimate is warned and the difference within that:
  no verdict;
* ``left out``: within ``exclude`` of a singular point, as the agreement
  leaves it out.

The user's profiles (:func:`outside_profiles`: a mapping id -> columns or
a CSV path, :func:`read_outside`) are refused, before any solve, with a
one-line :class:`~contactcore.ContactError` (a
:class:`~contactcore.SceneError` naming the profile) for an unknown
profile id, no position column, an unknown quantity, a value that is not
a finite number, a position off the profile and too few samples.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from contactcore import ContactError, ProfileData, Scene, SceneError, load_scene
from contactcore.estimate.runs import ERROR_SUFFIX
from contactcore.estimate.singular import far_from_singular, singular_regions
from contactcore.geometry import CircleInterface
from contactcore.scene import BODIES, LineProfile, Units
from contactcore.scene.vocabulary import QUANTITIES
from contactcore.spelling import hint
from contactcore.tolerances import ESTIMATE_TRUST

from .api import estimate_arguments, estimated_runs, label, variant
from .records import Agreement, profile_agreements
from .samples import check_exclusion, default_exclusion
from .sizes import size_floor, user_floors

#: A difference beyond this many times the project's estimated error is
#: the outside code's, at least mostly.  Where the estimate is trusted, the
#: project's true error |e_p| lies within ESTIMATE_TRUST (2) of it either
#: way (docs/error-estimates.md, the closed forms' range), so a difference
#: |d| > 2·ESTIMATE_TRUST·e leaves the outside code an error |e_o| >= |d| −
#: |e_p| > ESTIMATE_TRUST·e >= |e_p|: at least as large as the project's,
#: at least half of the difference.  Within it, the two agree within the
#: project's error (the difference is no more than the project's error
#: could be together with an outside error no larger).
BLAME_MULTIPLE = 2 * ESTIMATE_TRUST

#: The project's estimate at a sample is the largest ``q_err`` within this
#: many of the coarse run's cells along the profile, either side: the
#: Richardson estimate ``|q_{h/2} − q_h|/(2^p − 1)`` vanishes where the two
#: runs cross, at the coarse cells' scale (docs/error-estimates.md: ``q_err``
#: is an indicator, not a bound, at a sample), so a sample there would blame
#: any difference.  Measured (2026-11-29, fe P2 at h = 0.1 and 0.05 on the
#: cylinder, A, B, C, every profile quantity, the project's own answer at
#: h/4 as the outside one, all 101 samples): the largest |difference| /
#: estimate of an unwarned quantity read 4.39-4.54 with one cell (G's g_T,
#: t_N, t_T on the cylinder: one sample each blamed wrongly, an exact law's
#: traction varying at the fine cells' scale), 3.68 with 1.5, 2.52 with two
#: cells (none blamed), 2.17 with three.  Within the same body: a profile
#: crossing Γ samples two fields, and the runs' error where Γ cuts it
#: (scene C's C3 σyy) is not the other side's.  Among kept samples only
#: (:func:`_envelope`; outside2, 2026-11-29): the same figures at h = 0.1;
#: at h = 0.05 A, B, C blame none (2.50 at most) and the cylinder's Γ 7
#: single samples (up to 13.5; 3 cells: 2), as before the change
#: (docs/error-estimates-log.md, "the outside verdict's window").
ESTIMATE_WINDOW_CELLS = 2.0

#: The lowest effectivity (estimate / true error) docs/error-estimates.md
#: records of a warned estimate ("Known limits": an exact law's traction on
#: Γ, 0.09 the rebuilt wedge-coulomb-slip-exact's xfem P2 ``t_T`` at
#: h = 0.1 -> 0.05, 2026-11-29, 0.11 before its degree-2 traction took
#: order 2 away from status changes; until then 0.19, a held-out wedge's):
#: a warned estimate may be this many times too small.
WARNED_EFFECTIVITY = 0.09

#: Where the project's estimate is warned, a difference beyond this many
#: times it is still the outside code's: even if the estimate is
#: :data:`WARNED_EFFECTIVITY` of the true error, the difference exceeds
#: :data:`BLAME_MULTIPLE` times that true error (newuser34: a wrong μ's
#: G ``g_T`` at 311×, C4 ``t_N`` of the wrong sign at 7.05e4×, read
#: ``warned`` before).  Below it a warned quantity reads ``warned``.
WARNED_MULTIPLE = BLAME_MULTIPLE / WARNED_EFFECTIVITY

#: And, where the estimate is warned, a difference above this share of the
#: quantity's size (the agreement's, :class:`~verification.agreement.Agreement`'s
#: ``size``): a warned estimate can be near zero beside a status change,
#: which no multiple bounds (review18, 2026-11-29: fe P2 at h = 0.0125 judged
#: against fe P2 at 0.025 on exact C-coulomb, one C4 t_N sample next to
#: where Γ closes at 22.9 × a 0.0192 Pa estimate, 2e-5 of t_N's size).  50
#: times that, and 20 times below the smallest outside error the tests and
#: newuser34 put in (2 % of the size).
WARNED_MIN_SHARE = 1e-3

#: A profile whose ``outside`` samples span more than this share of its
#: kept length (in ``s``) gets a hint to check s's unit and direction and
#: the sign conventions: an error in the outside code is rarely that wide,
#: a misread input is (newuser34: C4's s as R θ in m, s reversed, a sign
#: flipped).
WIDE_OUTSIDE_SHARE = 0.5

#: A sample given by ``x, y`` lies on the profile when it is within this
#: share of the scene's diameter of it (and a sample given both ``s`` and
#: ``x, y``, when they name points this close): coordinates printed to six
#: significant digits (``%g``) land within 5e-6 of their size.
OFF_PROFILE_SHARE = 1e-5

#: The fewest samples a profile may give: one sample is a point, not a
#: profile (its regions and RMS say nothing along s), and a file read as
#: one row or none is far likelier a mistake (newuser33's header-only file
#: ended in ``max() arg is an empty sequence``).
MIN_SAMPLES = 2

#: The verdicts of a region, in words (docs/api.md).
VERDICTS = {
    "outside": f"|difference| > {BLAME_MULTIPLE:g} × the project's estimated error: the difference is at least "
               "mostly the outside code's error",
    "agree": f"|difference| within {BLAME_MULTIPLE:g} × the project's estimated error: the two agree within the "
             "project's error",
    "outside (estimate warned)": f"the project's estimate is warned but |difference| > {WARNED_MULTIPLE:.3g} × it "
                                 f"({BLAME_MULTIPLE:g} / {WARNED_EFFECTIVITY:g}, the lowest effectivity "
                                 "docs/error-estimates.md records) and > "
                                 f"{WARNED_MIN_SHARE:g} of the quantity's size: the outside code's error even if the "
                                 "estimate is that far too small",
    "warned": f"the project's estimate of this quantity is warned (below) and |difference| is within "
              f"{WARNED_MULTIPLE:.3g} × it: no verdict",
    "left out": "within the exclusion distance of a singular point, as the agreement table leaves it out",
}

_POSITIONS = ("s", "x", "y")


@dataclass(frozen=True)
class Region:
    """Consecutive samples along ``s`` (``s_from`` to ``s_to``, ``samples``
    of them) with one ``verdict`` (:data:`VERDICTS`); ``ratio`` is
    RMS(difference) / RMS(the project's estimated error) over them (NaN
    where left out)."""

    verdict: str
    s_from: float
    s_to: float
    samples: int
    ratio: float


@dataclass(frozen=True)
class OutsideRow:
    """One profile quantity of the outside answer against the project's.
    ``agreement`` holds the agreement's figures (worst sample, RMS, where,
    both values there: :class:`~verification.agreement.records.Agreement`);
    ``estimate`` the RMS of the project's estimated error over the kept
    samples, in the quantity's unit, ``ratio`` RMS(difference) / that;
    ``regions`` the verdicts along ``s``; ``warnings`` what makes the
    project's estimate untrusted (empty: trusted); ``hints`` what the
    verdict adds about the input (what ``s`` was taken as where it was
    given alone; where ``outside`` spans most of the profile, what to check
    first); ``columns`` per outside
    sample (in ``s`` order): ``s, x, y, outside, project, estimate,
    difference, verdict``."""

    agreement: Agreement
    estimate: float
    ratio: float
    regions: tuple[Region, ...]
    warnings: tuple[str, ...]
    columns: dict = field(repr=False, compare=False, default_factory=dict)
    hints: tuple[str, ...] = ()

    @property
    def profile(self) -> str:
        return self.agreement.profile

    @property
    def quantity(self) -> str:
        return self.agreement.quantity

    def verdicts(self) -> dict[str, list[tuple[float, float]]]:
        """Verdict -> the ``(s_from, s_to)`` of its regions."""
        out: dict[str, list[tuple[float, float]]] = {}
        for r in self.regions:
            out.setdefault(r.verdict, []).append((r.s_from, r.s_to))
        return out


def _warned_lines(rows) -> list[str]:
    """Each estimate warning of ``rows`` once, as a list item: the warning
    as the estimate wrote it where it names every quantity it is given
    for, else after those quantities (newuser35: "G:tT: G:tN, G:tT: an
    exact law's traction …" repeated the key the warning names)."""
    keys: dict[str, list[str]] = {}
    for r in rows:
        for w in r.warnings:
            keys.setdefault(w, []).append(f"{r.profile}:{r.quantity}")
    return [f"- {w}" if all(k in w for k in ks) else f"- {', '.join(ks)}: {w}" for w, ks in keys.items()]


@dataclass(frozen=True)
class OutsideTable:
    """The outside answer against ``method``'s finest run (at ``hs[-1]``;
    ``hs`` the runs estimated, coarse to fine): one :class:`OutsideRow`
    per profile and quantity given; samples within ``exclude`` of the
    singular ``regions`` left out; ``multiple`` is :data:`BLAME_MULTIPLE`."""

    scene: str
    method: str
    hs: tuple[float, ...]
    exclude: float
    multiple: float
    regions: tuple
    rows: tuple[OutsideRow, ...]
    warnings: tuple[str, ...] = ()
    units: Units = Units()

    def row(self, profile: str, quantity: str) -> OutsideRow:
        """The row of ``profile``'s ``quantity``."""
        return next(r for r in self.rows if (r.profile, r.quantity) == (profile, quantity))

    def markdown(self, conventions: str = "") -> str:
        """The verdict in Markdown (what ``against`` writes as outside.md,
        its ``conventions`` paragraph ``run``'s summary.md's,
        :func:`verification.run.conventions`, after the title)."""
        from ..files import column_unit
        from .measures import percent
        length = self.units.length
        where = ("; ".join(f"{name} " + ", ".join(f"({x:.4g}, {y:.4g})" for x, y in pts) for name, pts in self.regions)
                 if self.regions else "")
        left = (f"samples within {self.exclude:.3g} {length} of these singular points are left out: {where}"
                if self.regions else "no sample is left out (the scene has no singular point)")
        opening = ([conventions.rstrip("\n") + " s is a profile's parameter: the arc length from its start, or "
                    "Γ's polar angle in rad on a circle (docs/scenes.md, \"Profiles and their samples\").", ""]
                   if conventions else [])
        lines = [f"# An outside answer against {self.method} on scene {self.scene}", "", *opening,
                 f"The project's answer: {self.method} at h = {self.hs[-1]:g} {length}, its error estimated from "
                 f"the runs at h = {', '.join(f'{h:g}' for h in self.hs)} {length} (Richardson, "
                 "docs/error-estimates.md), taken at each sample as the largest `q_err` within "
                 f"{ESTIMATE_WINDOW_CELLS:g} coarse cells either side along the profile in the same body among the "
                 "samples compared (none within the exclusion distance of a singular point), plus the "
                 f"error of interpolating the project's samples to the outside's; {left}.", "",
                 "Verdicts: " + "; ".join(f"`{k}`: {v}" for k, v in VERDICTS.items()) + ".", "",
                 "| profile | quantity | worst | RMS | project's estimated error (RMS) | difference / estimate "
                 "(RMS) | verdicts along s |", "|---|---|---|---|---|---|---|"]
        for r in self.rows:
            a, unit = r.agreement, column_unit(r.quantity, self.units) or ""
            s_unit = f" {a.s_unit}" if a.s_unit else ""
            regions = "; ".join(f"{g.verdict} {g.s_from:.4g}–{g.s_to:.4g}{s_unit} ({g.samples}"
                                + ("" if math.isnan(g.ratio) else f", {g.ratio:.3g}×") + ")" for g in r.regions)
            lines.append(f"| {a.profile} | {a.quantity} | {percent(a.worst)} at s = {a.s:.4g}{s_unit} | "
                         f"{percent(a.rms)} | {r.estimate:.3g} {unit} | {r.ratio:.3g} | {regions} |")
        hints = [f"- {r.profile}:{r.quantity}: {h}" for r in self.rows for h in r.hints]
        if hints:
            lines += ["", "About the input:", *hints]
        warned = _warned_lines(self.rows)
        if warned:
            lines += ["", f"The project's estimate is warned (a verdict there only beyond {WARNED_MULTIPLE:.3g} × "
                      "the estimate):", *warned]
        lines += ["", "worst: the largest |difference| over the project's largest scale (the agreement table's, "
                  "docs/api.md); RMS: the RMS difference over the RMS scale; a region's figure: RMS(difference) / "
                  "RMS(the project's estimated error) over its samples."]
        return "\n".join(lines) + "\n"

    def csv_rows(self) -> list[dict]:
        """One dict per outside sample: ``profile, quantity, s, s_unit, x,
        y, outside, project, estimate, difference, unit, verdict``
        (``s_unit``: s's, m or rad by profile; ``unit``: the quantity's, of
        outside, project, estimate and difference)."""
        from ..files import column_unit
        names = ("s", "x", "y", "outside", "project", "estimate", "difference", "verdict")
        return [{"profile": r.profile, "quantity": r.quantity, "s_unit": r.agreement.s_unit or self.units.length,
                 "unit": column_unit(r.quantity, self.units) or "", **{n: r.columns[n][i] for n in names}}
                for r in self.rows for i in range(len(r.columns["s"]))]


# --- the outside profiles: read and checked -------------------------------------------------------------------


class OutsideFiles(dict):
    """Profile id -> columns as :func:`read_outside` read them; ``lines``:
    id -> (the file, the file line of each sample, counted from 1 with the
    header line 1), so that an error names the line to open."""

    def __init__(self, columns=(), lines=None):
        super().__init__(columns)
        self.lines = dict(lines or {})


def read_outside(path) -> OutsideFiles:
    """Profile id -> columns of a CSV file (its id the file's stem, ``C4.csv``
    -> ``C4``: the project's own ``METHOD/profiles/ID.csv``) or of every
    ``*.csv`` in a folder; a header row of column names, then one row a
    sample (a leading UTF-8 byte-order mark, as spreadsheets write, is
    read past).  A file that cannot be read, a folder without CSVs, a
    header naming a column twice, or a cell that is not a number is refused
    naming the file, row and column."""
    path = Path(path)
    if path.is_dir():
        files = sorted(path.glob("*.csv"))
        if not files:
            raise ContactError(f"outside: no *.csv file in folder {path} (one CSV a profile, named ID.csv)")
    elif path.is_file():
        files = [path]
    else:
        raise ContactError(f"outside: {path} is neither a CSV file nor a folder of them")
    out, lines = {}, {}
    for f in files:
        try:
            with open(f, newline="", encoding="utf-8-sig") as fh:  # a spreadsheet's byte-order mark is no name
                rows = [(i, r) for i, r in enumerate(csv.reader(fh), start=1) if any(c.strip() for c in r)]
        except (OSError, UnicodeDecodeError) as exc:
            raise ContactError(f"outside: cannot read {f}: {exc}") from None
        if not rows:
            raise ContactError(f"outside: {f} is empty (a header row of column names, then one row a sample)")
        header = [c.strip() for c in rows[0][1]]
        twice = sorted({name for name in header if header.count(name) > 1})
        if twice:
            raise ContactError(f"outside: {f} line {rows[0][0]}: the header names {', '.join(twice)} more than once")
        columns = {name: [] for name in header}
        for i, r in rows[1:]:
            if len(r) != len(header):
                raise ContactError(f"outside: {f} line {i}: {len(r)} cells, the header names {len(header)}")
            for name, cell in zip(header, r):
                try:
                    columns[name].append(float(cell))
                except ValueError:
                    raise ContactError(f"outside: {f} line {i}, column {name}: {cell.strip()!r} is not a "
                                       "number") from None
        out[f.stem] = columns
        lines[f.stem] = (f, [i for i, _ in rows[1:]])
    return OutsideFiles(out, lines)


class CheckedProfiles(dict):
    """Profile id -> :class:`~contactcore.ProfileData` as
    :func:`outside_profiles` checked them; ``s_only``: the ids whose
    positions were given as ``s`` alone (nothing to check s's unit, origin
    or direction against: :func:`judge` says what s was taken as)."""

    def __init__(self, profiles=(), s_only=()):
        super().__init__(profiles)
        self.s_only = frozenset(s_only)


#: What a header naming a unit is told: the columns are bare names.
BARE_NAMES = ("headers are bare names (s, x, y and the quantities as the project's profile CSVs name them, e.g. "
              "sxx, tN), without a unit: every value is in the scene's units (docs/api.md, \"An outside code's "
              "answer\")")


def _unit_in(name: str) -> bool:
    """Whether a column name carries more than a name (a unit in brackets,
    a space): ``s [m]``, ``sxx (Pa)``."""
    return any(c in name for c in "[]() ")


def _sample(lines, pid: str, i: int) -> str:
    """Sample ``i`` (in input order) of ``pid``: its file and line where
    it was read from a file (:class:`OutsideFiles`), else its index."""
    if pid in lines:
        f, numbers = lines[pid]
        return f"sample on line {numbers[i]} of {f}"
    return f"sample {i}"


class _Line:
    """A profile's geometry: ``s`` from ``a`` along the segment to ``b``."""

    periodic = False

    def __init__(self, a, b):
        self.a, self.b = np.asarray(a, float), np.asarray(b, float)
        self.length = float(np.linalg.norm(self.b - self.a))
        self.span = self.length
        self.per_length = 1.0  # s units per length unit

    def points(self, s):
        return self.a + (np.asarray(s, float) / self.length)[:, None] * (self.b - self.a)

    def parameter(self, xy):
        t = (self.b - self.a) / self.length
        d = np.asarray(xy, float) - self.a
        s = d @ t
        return s, np.abs(d @ np.array([-t[1], t[0]]))


class _Circle:
    """A circular Γ: ``s`` the polar angle (rad) or the arc length ``R θ``,
    anticlockwise from +x about the centre."""

    periodic = True

    def __init__(self, itf: CircleInterface, angle: bool):
        self.itf, self.radius = itf, float(itf.radius)
        self.per_length = 1.0 / self.radius if angle else 1.0
        self.span = 2 * np.pi * (1.0 if angle else self.radius)

    def points(self, s):
        return self.itf.points_at_angles(np.asarray(s, float) / (self.per_length * self.radius))

    def parameter(self, xy):
        d = np.asarray(xy, float) - np.asarray(self.itf.centre, float)
        theta = np.mod(np.arctan2(d[:, 1], d[:, 0]), 2 * np.pi)
        return theta * self.per_length * self.radius, np.abs(np.hypot(d[:, 0], d[:, 1]) - self.radius)


def _geometry(scene: Scene, profile):
    """The geometry along which ``profile``'s ``s`` runs (docs/scenes.md,
    "Profiles and their samples")."""
    if isinstance(profile, LineProfile):
        return _Line(profile.start, profile.end)
    itf = scene.interface
    if isinstance(itf, CircleInterface):
        return _Circle(itf, profile.parameter == "angle")
    a, b = itf.chord(scene.domain)
    return _Line(a, b)


def _taken_as(scene: Scene, profile) -> str:
    """What a profile's ``s`` was taken as (unit, origin, direction), for
    an outside answer that gave ``s`` alone."""
    length, geo = scene.units.length, _geometry(scene, profile)
    if isinstance(geo, _Circle):
        c = ", ".join(f"{v:.4g}" for v in geo.itf.centre)
        what = "the polar angle in rad" if geo.per_length != 1.0 else f"the arc length R θ in {length}"
        return (f"s was taken as {what}, from +x anticlockwise about Γ's centre ({c}) {length}, 0 to "
                f"{geo.span:.4g}")
    a, b = (", ".join(f"{v:.4g}" for v in end) for end in (geo.a, geo.b))
    along = "along Γ from Γ's first end" if not isinstance(profile, LineProfile) else "from the profile's start"
    return f"s was taken as the arc length in {length} {along} ({a}) towards ({b}), 0 to {geo.span:.4g}"


def _column(pid: str, name: str, values, lines=None) -> np.ndarray:
    """A column as a 1-D float array, or a SceneError naming it."""
    try:
        arr = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise SceneError(f"outside[{pid!r}].{name}", "must be numbers") from None
    if arr.ndim != 1:
        raise SceneError(f"outside[{pid!r}].{name}", f"must be one number a sample (got shape {arr.shape})")
    bad = np.flatnonzero(~np.isfinite(arr))
    if len(bad):
        raise SceneError(f"outside[{pid!r}].{name}", f"{_sample(lines or {}, pid, int(bad[0]))} is "
                         f"{arr[bad[0]]:g}, not a finite number "
                         f"({len(bad)} of {len(arr)} samples are not)")
    return arr


def outside_profiles(scene: Scene, outside) -> dict[str, ProfileData]:
    """The outside answer (profile id -> columns: a mapping of names to
    sequences, or a :class:`~contactcore.ProfileData`; or a CSV path,
    :func:`read_outside`) checked against ``scene``'s profiles, as
    ProfileData sorted by ``s`` with ``s, x, y`` then the quantities given.
    A position is ``s`` (the profile's parameter, in its unit: length or
    rad) or ``x, y`` (projected onto the profile), or all three (which must
    name the same point).  Columns ending ``_err`` (the project's own
    estimates, in its CSVs) are ignored.  Anything else is a
    :class:`SceneError` naming the profile and the problem."""
    if isinstance(outside, (str, Path)):
        outside = read_outside(outside)
    lines = getattr(outside, "lines", {})
    if not hasattr(outside, "items") or isinstance(outside, ProfileData):
        raise ContactError(f"outside: a mapping of profile id -> columns, or a CSV path (got "
                           f"{type(outside).__name__})")
    if not outside:
        raise ContactError("outside: no profile given")
    known = {p.id: p for p in scene.profiles}
    tol = OFF_PROFILE_SHARE * scene.length_scale
    out, s_only = {}, []
    for pid, given in outside.items():
        if pid not in known:
            raise SceneError(f"outside[{pid!r}]", f"scene {scene.name} has no profile {pid!r}{hint(str(pid), known)} "
                             f"(its profiles: {', '.join(known)})")
        profile = known[pid]
        cols = given.columns if isinstance(given, ProfileData) else given
        if not hasattr(cols, "items"):
            raise SceneError(f"outside[{pid!r}]", f"a mapping of column name -> values (got {type(cols).__name__})")
        names = [n for n in cols if not str(n).endswith(ERROR_SUFFIX)]
        quantities = [n for n in names if n not in _POSITIONS]
        for q in quantities:
            if q not in profile.quantities:
                where = (f"scene {scene.name}'s profile {pid} samples {', '.join(profile.quantities)}"
                         if q in QUANTITIES else f"known quantities: {', '.join(QUANTITIES)}")
                bare = f"; {BARE_NAMES}" if _unit_in(str(q)) else ""
                raise SceneError(f"outside[{pid!r}]", f"unknown quantity {q!r}"
                                 f"{hint(str(q), profile.quantities)} ({where}; position columns: s, x, y{bare})")
        if not quantities:
            raise SceneError(f"outside[{pid!r}]", f"no quantity given (profile {pid} samples "
                             f"{', '.join(profile.quantities)}; columns given: {', '.join(map(str, names)) or 'none'})")
        has_s, has_xy = "s" in names, "x" in names and "y" in names
        if not has_s and not has_xy:
            raise SceneError(f"outside[{pid!r}]", "no position column: give s (the profile's parameter, "
                             "docs/scenes.md) or x and y" + (f" (only {'x' if 'x' in names else 'y'} given)"
                                                             if "x" in names or "y" in names else ""))
        data = {n: _column(pid, n, cols[n], lines) for n in (["s"] if has_s else []) + (["x", "y"] if has_xy else [])
                + quantities}
        lengths = {n: len(v) for n, v in data.items()}
        if len(set(lengths.values())) > 1:
            raise SceneError(f"outside[{pid!r}]", "columns of different lengths: "
                             + ", ".join(f"{n} {k}" for n, k in lengths.items()))
        n = next(iter(lengths.values()))
        if n < MIN_SAMPLES:
            raise SceneError(f"outside[{pid!r}]", f"{n} sample{'s' if n != 1 else ''}: give at least "
                             f"{MIN_SAMPLES} (one sample is a point, not a profile: no region or RMS along s)")
        geo = _geometry(scene, profile)
        unit = "rad" if geo.per_length != 1.0 else scene.units.length
        if has_xy:
            xy = np.column_stack([data["x"], data["y"]])
            s_xy, off = geo.parameter(xy)
            i = int(np.argmax(off))
            if off[i] > tol:
                raise SceneError(f"outside[{pid!r}]", f"{_sample(lines, pid, i)} (x = {xy[i, 0]:.6g}, y = {xy[i, 1]:.6g} "
                                 f"{scene.units.length}) lies {off[i]:.3g} {scene.units.length} off profile {pid} "
                                 f"(more than {tol:.3g})")
        s = data["s"] if has_s else s_xy
        span_tol = tol * geo.per_length
        off_range = np.flatnonzero((s < -span_tol) | (s > geo.span + span_tol))
        if len(off_range):
            i = off_range[0]
            raise SceneError(f"outside[{pid!r}]", f"{_sample(lines, pid, int(i))}: s = {s[i]:.6g} {unit} lies off profile {pid}, "
                             f"whose s runs from 0 to {geo.span:.6g} {unit} ({len(off_range)} of {n} samples off; "
                             "s's origin and direction: docs/scenes.md, \"Profiles and their samples\")")
        s = np.clip(s, 0.0, geo.span)
        points = geo.points(s)
        if has_s and has_xy:
            gap = np.hypot(*(points - np.column_stack([data["x"], data["y"]])).T)
            i = int(np.argmax(gap))
            if gap[i] > tol:
                raise SceneError(f"outside[{pid!r}]", f"{_sample(lines, pid, i)}: s = {s[i]:.6g} {unit} is the point "
                                 f"({points[i, 0]:.6g}, {points[i, 1]:.6g}) of profile {pid}, {gap[i]:.3g} "
                                 f"{scene.units.length} from the x, y given ({data['x'][i]:.6g}, {data['y'][i]:.6g}):"
                                 " s's origin or direction differs from the project's (docs/scenes.md, \"Profiles "
                                 "and their samples\"); give s or x, y alone")
        order = np.argsort(s, kind="stable")
        columns = {"s": s[order], "x": points[order, 0], "y": points[order, 1],
                   **{q: data[q][order] for q in quantities}}
        out[pid] = ProfileData(pid, "angle" if unit == "rad" else "arclength", columns)
        if has_s and not has_xy:
            s_only.append(pid)
    return CheckedProfiles(out, s_only)


# --- the project's answer at the outside samples --------------------------------------------------------------


def _periodic(geo, s: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The project's samples, closed around a circle (its first sample
    repeated one period on) so that interpolation wraps."""
    if not geo.periodic:
        return s, values
    return np.append(s, s[0] + geo.span), np.append(values, values[0])


def _interpolated(geo, s_p: np.ndarray, q_p: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The project's ``q_p`` at its samples ``s_p`` interpolated linearly to
    ``s``, and the interpolation's error there: ``α(1 − α)/2 · |Δ²q|`` (the
    linear interpolant's error of a quadratic, ``α`` the share of the
    interval, ``Δ²q`` the larger second difference at its ends): 0 at the
    project's own samples."""
    sp, qp = _periodic(geo, s_p, q_p)
    if geo.periodic:
        d2 = np.abs(np.roll(q_p, 1) - 2 * q_p + np.roll(q_p, -1))
        d2 = np.append(d2, d2[0])
    else:
        d2 = np.zeros_like(q_p)
        d2[1:-1] = np.abs(q_p[:-2] - 2 * q_p[1:-1] + q_p[2:])
        d2[0], d2[-1] = d2[1], d2[-2]
    value = np.interp(s, sp, qp)
    j = np.clip(np.searchsorted(sp, s, side="right") - 1, 0, len(sp) - 2)
    alpha = np.clip((s - sp[j]) / (sp[j + 1] - sp[j]), 0.0, 1.0)
    return value, alpha * (1 - alpha) / 2 * np.maximum(d2[j], d2[j + 1])


def _envelope(geo, s_p: np.ndarray, err: np.ndarray, window: float, body: np.ndarray,
              kept: np.ndarray) -> np.ndarray:
    """The largest ``err`` within ``window`` (in ``s``'s unit) of each
    sample, among the ``kept`` samples (those the agreement compares: the
    runs' error near a singular point, left out, would swell the estimate
    of samples beside it, newuser34's A3 σxx 22× its true error) in the same
    ``body`` (a profile crossing Γ samples two fields: the runs' error where
    Γ cuts it is not the other side's)."""
    d = np.abs(s_p[:, None] - s_p[None, :])
    if geo.periodic:
        d = np.minimum(d, geo.span - d)
    near = (d <= window) & (body[:, None] == body[None, :]) & kept[None, :]
    return np.max(np.where(near, err[None, :], 0.0), axis=1)


def _regions(s: np.ndarray, verdict: np.ndarray, diff: np.ndarray, budget: np.ndarray) -> tuple[Region, ...]:
    """Consecutive samples of one verdict, with RMS(diff)/RMS(budget) over each."""
    out, start = [], 0
    for i in range(1, len(s) + 1):
        if i == len(s) or verdict[i] != verdict[start]:
            part = slice(start, i)
            if verdict[start] == "left out":
                ratio = float("nan")
            else:
                d, b = np.sqrt(np.mean(diff[part] ** 2)), np.sqrt(np.mean(budget[part] ** 2))
                ratio = float(d / b) if b > 0 else (0.0 if d == 0 else float("inf"))
            out.append(Region(str(verdict[start]), float(s[start]), float(s[i - 1]), i - start, ratio))
            start = i
    return tuple(out)


def _hints(scene: Scene, profile, s: np.ndarray, keep: np.ndarray, verdict: np.ndarray, s_only: bool
           ) -> tuple[str, ...]:
    """What a row's verdict adds about its input: what ``s`` was taken as
    where it was given alone (:func:`_taken_as`), and where the ``outside``
    samples span more than :data:`WIDE_OUTSIDE_SHARE` of the kept samples'
    s range (in s, the input's own positions), to check s's unit and
    direction (s alone) and the sign conventions."""
    out = [_taken_as(scene, profile)] if s_only else []
    blamed = np.array([str(v).startswith("outside") for v in verdict])
    span = np.ptp(s[keep]) if keep.sum() > 1 else 0.0
    if blamed.sum() > 1 and span > 0 and np.ptp(s[blamed]) > WIDE_OUTSIDE_SHARE * span:
        check = "s's unit, origin and direction, and " if s_only else ""
        out.append(f"outside over more than {WIDE_OUTSIDE_SHARE:.0%} of the profile: check {check}the sign "
                   "conventions (g_N > 0 an opening, t_N > 0 tension, g_T and t_T along t = (n_y, −n_x); "
                   "docs/scenes.md) before blaming the code")
    return tuple(out)


def judge(scene: Scene, outside: dict[str, ProfileData], project: dict[str, ProfileData], est, method: str,
          exclude: float | None = None, floors: dict | None = None) -> OutsideTable:
    """The :class:`OutsideTable` of ``outside`` (id -> ProfileData, checked:
    :func:`outside_profiles`) against ``project`` (id -> ProfileData, the
    finest run ``est`` estimated: a :class:`contactcore.estimate.Estimate`)
    labelled ``method``; no solve.  ``exclude`` (default
    :func:`default_exclusion`) and ``floors`` as for
    :func:`~verification.agreement.table`: a difference below a quantity's
    floor (round-off, or the user's) is agreement."""
    exclude = default_exclusion(scene) if exclude is None else exclude
    check_exclusion(scene, exclude)
    given = user_floors(floors)
    known = {p.id: p for p in scene.profiles}
    window_length = ESTIMATE_WINDOW_CELLS * est.hs[-2]
    s_only = getattr(outside, "s_only", frozenset())
    ref, rows = {}, []
    for pid, got in outside.items():
        geo, mine = _geometry(scene, known[pid]), project[pid]
        s = got.columns["s"]
        keep = far_from_singular(scene, np.column_stack([got.columns["x"], got.columns["y"]]), exclude)
        if not keep.any():
            raise SceneError(f"outside[{pid!r}]", f"all {len(s)} samples lie within {exclude:.3g} "
                             f"{scene.units.length} of a singular point, where none is compared: give samples "
                             "farther from them, or a smaller exclude")
        ref[pid] = ProfileData(pid, mine.parameter, {
            "s": s, "x": got.columns["x"], "y": got.columns["y"],
            **{q: _interpolated(geo, mine.columns["s"], mine.columns[q], s)[0] for q in mine.names[3:]}})
    agreements = {(a.profile, a.quantity): a for a in profile_agreements(scene, method, outside, ref, exclude,
                                                                         floors=given)}
    for pid, got in outside.items():
        geo, mine = _geometry(scene, known[pid]), project[pid]
        s = got.columns["s"]
        keep = far_from_singular(scene, np.column_stack([got.columns["x"], got.columns["y"]]), exclude)
        for q in got.names[3:]:
            value, interpolation = _interpolated(geo, mine.columns["s"], mine.columns[q], s)
            error = est.profiles[pid][q].error
            points = np.column_stack([mine.columns["x"], mine.columns["y"]])
            body = scene.body_of(points, known[pid].side if known[pid].side in BODIES else BODIES[1])
            envelope = _envelope(geo, mine.columns["s"], error, window_length * geo.per_length, body,
                                 far_from_singular(scene, points, exclude))
            budget = _interpolated(geo, mine.columns["s"], envelope, s)[0] + interpolation
            diff = got.columns[q] - value
            floor = size_floor(q, given, project, scene=scene)
            key = f"{pid}:{q}"
            warned = key in est.unsettled
            notes = tuple(w for w in est.warnings if key in w) or (
                tuple(w for w in est.warnings if not w.startswith("energy")) if warned else ())
            least = WARNED_MIN_SHARE * agreements[pid, q].size if warned else 0.0
            beyond = np.abs(diff) > np.maximum((WARNED_MULTIPLE if warned else BLAME_MULTIPLE) * budget,
                                               max(floor, least))
            verdict = np.where(~keep, "left out", np.where(
                beyond, "outside (estimate warned)" if warned else "outside",
                "warned" if warned else "agree")).astype(object)
            d_rms, e_rms = np.sqrt(np.mean(diff[keep] ** 2)), np.sqrt(np.mean(budget[keep] ** 2))
            ratio = float(d_rms / e_rms) if e_rms > 0 else (0.0 if d_rms == 0 else float("inf"))
            columns = {"s": s, "x": got.columns["x"], "y": got.columns["y"], "outside": got.columns[q],
                       "project": value, "estimate": budget, "difference": diff, "verdict": verdict}
            rows.append(OutsideRow(agreements[pid, q], float(e_rms), ratio, _regions(s, verdict, diff, budget),
                                   notes if warned else (), columns,
                                   _hints(scene, known[pid], s, keep, verdict, pid in s_only)))
    regions = tuple((name, tuple(map(tuple, pts.tolist()))) for name, pts in singular_regions(scene))
    return OutsideTable(scene.name, method, tuple(est.hs), float(exclude), BLAME_MULTIPLE, regions, tuple(rows),
                        tuple(est.warnings), scene.units)


def compare_outside(scene, outside, *, method="fe:2", h: float | None = None, levels: int = 2,
                    exclude: float | None = None, floors: dict | None = None, **options) -> OutsideTable:
    """An outside code's answer on ``scene`` (a Scene, a shipped scene's
    name or a TOML path) against ``method``'s (``"fe:2"``, ``("xfem",
    2)``, ...): ``outside`` is profile id -> columns (``s``, or ``x`` and
    ``y``, and quantities named as the project's CSV headers, in the
    scene's units) or a CSV path (:func:`read_outside`).  The method is
    solved at ``h`` (default the scene's) and ``h/2`` (and ``h/4`` with
    ``levels=3``), the finest run's error estimated
    (:func:`contactcore.estimate.estimate_runs`, ``run --estimate``'s), and
    the outside samples judged against it (:func:`judge`).  Bad input is
    refused before any solve (:func:`outside_profiles`; a bad method,
    ``levels``, exclusion, floor or option as :func:`compare_estimates`
    refuses them)."""
    from .. import methods as known
    user_floors(floors)
    scene = load_scene(scene)
    name, degree = variant(method)
    exclude, h = estimate_arguments(scene, h, levels, exclude)
    known.check_options([name], **options)
    given = outside_profiles(scene, outside)
    _, estimate = estimated_runs(scene, name, degree, h, levels, exclude, options)
    return judge(scene, given, {p.id: p for p in estimate.sampled}, estimate, label(name, degree), exclude,
                 floors)
