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

One idea a module: the input read (:mod:`~verification.agreement.outside_files`)
and checked against the scene (:mod:`~verification.agreement.outside_input`),
a profile's geometry along ``s`` (:mod:`~verification.agreement.profile_geometry`),
the project's answer and error at the outside samples
(:mod:`~verification.agreement.outside_budget`), the verdicts
(:mod:`~verification.agreement.outside_verdicts`) and the table
(:mod:`~verification.agreement.outside_table`); this module judges
(:func:`judge`, :func:`compare_outside`) and adds the hints about the
input (:data:`WIDE_OUTSIDE_SHARE`).  :func:`read_outside` and
:func:`outside_profiles` stay importable from here (docs/api.md).
"""
from __future__ import annotations

import numpy as np

from contactcore import ProfileData, Scene, SceneError, load_scene
from contactcore.estimate.singular import far_from_singular, singular_regions
from contactcore.scene import BODIES

from .api import estimate_arguments, estimated_runs, label, variant
from .outside_budget import ESTIMATE_WINDOW_CELLS, envelope, interpolated
from .outside_files import read_outside  # noqa: F401  (docs/api.md names it here)
from .outside_input import outside_profiles
from .outside_table import OutsideRow, OutsideTable
from .outside_verdicts import BLAME_MULTIPLE, sample_verdicts, verdict_regions
from .profile_geometry import geometry, taken_as
from .records import profile_agreements
from .samples import check_exclusion, default_exclusion
from .sizes import size_floor, user_floors

#: A profile whose ``outside`` samples span more than this share of its
#: kept length (in ``s``) gets a hint to check s's unit and direction and
#: the sign conventions: an error in the outside code is rarely that wide,
#: a misread input is (newuser34: C4's s as R θ in m, s reversed, a sign
#: flipped).
WIDE_OUTSIDE_SHARE = 0.5


def _hints(scene: Scene, profile, s: np.ndarray, keep: np.ndarray, verdict: np.ndarray, s_only: bool
           ) -> tuple[str, ...]:
    """What a row's verdict adds about its input: what ``s`` was taken as
    where it was given alone (:func:`taken_as`), and where the ``outside``
    samples span more than :data:`WIDE_OUTSIDE_SHARE` of the kept samples'
    s range (in s, the input's own positions), to check s's unit and
    direction (s alone) and the sign conventions."""
    out = [taken_as(scene, profile)] if s_only else []
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
        geo, mine = geometry(scene, known[pid]), project[pid]
        s = got.columns["s"]
        keep = far_from_singular(scene, np.column_stack([got.columns["x"], got.columns["y"]]), exclude)
        if not keep.any():
            raise SceneError(f"outside[{pid!r}]", f"all {len(s)} samples lie within {exclude:.3g} "
                             f"{scene.units.length} of a singular point, where none is compared: give samples "
                             "farther from them, or a smaller exclude")
        ref[pid] = ProfileData(pid, mine.parameter, {
            "s": s, "x": got.columns["x"], "y": got.columns["y"],
            **{q: interpolated(geo, mine.columns["s"], mine.columns[q], s)[0] for q in mine.names[3:]}})
    agreements = {(a.profile, a.quantity): a for a in profile_agreements(scene, method, outside, ref, exclude,
                                                                         floors=given)}
    for pid, got in outside.items():
        geo, mine = geometry(scene, known[pid]), project[pid]
        s = got.columns["s"]
        keep = far_from_singular(scene, np.column_stack([got.columns["x"], got.columns["y"]]), exclude)
        for q in got.names[3:]:
            value, interpolation = interpolated(geo, mine.columns["s"], mine.columns[q], s)
            error = est.profiles[pid][q].error
            points = np.column_stack([mine.columns["x"], mine.columns["y"]])
            body = scene.body_of(points, known[pid].side if known[pid].side in BODIES else BODIES[1])
            nearby = envelope(geo, mine.columns["s"], error, window_length * geo.per_length, body,
                              far_from_singular(scene, points, exclude))
            budget = interpolated(geo, mine.columns["s"], nearby, s)[0] + interpolation
            diff = got.columns[q] - value
            floor = size_floor(q, given, project, scene=scene)
            key = f"{pid}:{q}"
            warned = key in est.unsettled
            notes = tuple(w for w in est.warnings if key in w) or (
                tuple(w for w in est.warnings if not w.startswith("energy")) if warned else ())
            verdict = sample_verdicts(diff, budget, keep, warned, floor, agreements[pid, q].size)
            d_rms, e_rms = np.sqrt(np.mean(diff[keep] ** 2)), np.sqrt(np.mean(budget[keep] ** 2))
            ratio = float(d_rms / e_rms) if e_rms > 0 else (0.0 if d_rms == 0 else float("inf"))
            columns = {"s": s, "x": got.columns["x"], "y": got.columns["y"], "outside": got.columns[q],
                       "project": value, "estimate": budget, "difference": diff, "verdict": verdict}
            rows.append(OutsideRow(agreements[pid, q], float(e_rms), ratio,
                                   verdict_regions(s, verdict, diff, budget), notes if warned else (), columns,
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
