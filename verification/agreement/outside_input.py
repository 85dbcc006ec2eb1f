"""An outside answer checked against a scene's profiles, before any solve
(docs/api.md, "An outside code's answer").

Contract: :func:`outside_profiles` takes profile id -> columns (a mapping
of names to numbers, or a :class:`~contactcore.ProfileData`) or a CSV path
(:func:`~verification.agreement.outside_files.read_outside`) and returns
:class:`CheckedProfiles`: id -> ProfileData sorted by ``s``, with ``s, x,
y`` then the quantities given (positions given as ``x, y`` projected onto
the profile), and ``s_only``, the ids given ``s`` alone.  Anything else is
refused with a one-line :class:`~contactcore.SceneError` naming the
profile (and the file and line where read from a file): an unknown profile
or quantity, no position or no quantity column, a value that is not a
finite number, columns of different lengths, fewer than
:data:`MIN_SAMPLES` samples, a position off the profile (farther than
:data:`OFF_PROFILE_SHARE` of the scene's size), and ``s`` and ``x, y``
naming different points.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from contactcore import ContactError, ProfileData, Scene, SceneError
from contactcore.estimate.runs import ERROR_SUFFIX
from contactcore.scene.vocabulary import QUANTITIES
from contactcore.spelling import hint

from .outside_files import read_outside
from .profile_geometry import geometry

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

_POSITIONS = ("s", "x", "y")


class CheckedProfiles(dict):
    """Profile id -> :class:`~contactcore.ProfileData` as
    :func:`outside_profiles` checked them; ``s_only``: the ids whose
    positions were given as ``s`` alone (nothing to check s's unit, origin
    or direction against: :func:`~verification.agreement.outside.judge` says what s was taken as)."""

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
    it was read from a file (:class:`~verification.agreement.outside_files.OutsideFiles`), else its index."""
    if pid in lines:
        f, numbers = lines[pid]
        return f"sample on line {numbers[i]} of {f}"
    return f"sample {i}"


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
    :func:`~verification.agreement.outside_files.read_outside`) checked against ``scene``'s profiles, as
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
        geo = geometry(scene, profile)
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
