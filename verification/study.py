"""``python -m verification study``: inputs varied, every method solved.

    python -m verification study SCENE --param NAME --values V1 V2 ... [--param NAME2 --values ...]
        [--method ...] [--degree 1] [--h H] [--workers K] --out DIR

Parameters (:data:`PARAMETERS`): the mesh size ``h``; the law's springs
``kN``, ``kT`` and friction ``mu``; how the law is enforced, ``enforcement``
(penalty or exact), and an exact law's ``stabilisation`` β (within
``NITSCHE_STABILISATION_RANGE``); ``load``, a factor on every load;
the number of ``increments``; the materials ``E_minus``, ``nu_minus``, ``E_plus``, ``nu_plus``;
and the geometry of Γ — ``radius`` of a circular Γ, ``offset`` of a straight
Γ along its normal, ``angle`` of a straight Γ (degrees a from the x axis,
counter-clockwise: the scene's Γ turned about the middle of its chord from
its own angle a₀ in (−90°, 90°], its normal turning with it, so the + body
stays on the scene's side for |a − a₀| < 90°: :func:`_angle`).  Several ``--param`` pairs run their
Cartesian product (the last parameter varies fastest), one row per point
and method.  A geometry change is a new scene,
so the conforming method meshes it afresh through gmsh (and XFEM with
``--cell gmsh`` too); the scene's own profiles may no longer lie on the moved
Γ, so the study reads Γ's own points: for each point it records DOFs, wall
time, solver health, and the largest |g_N|, |g_T|, |t_N|, |t_T| over Γ's
quadrature points with the mean t_N and t_T.  Every point's scene is built and validated before
any solve (:func:`check_points`): a bad value (a radius that leaves the
domain, a fractional increment count, β outside its range) refuses the
whole study in one line naming it.  The cases run on :mod:`verification.pool` (``--workers K``
or an mpi4py.futures pool), each in a process of its own; they are logged
in case order as their results arrive; a point whose solve is refused or
does not converge is recorded with its message and the study goes on.  Writes ``DIR/study.csv``, ``DIR/study.md`` and one plot per parameter,
the others as series, warned points ringed and failed ones crossed on the x axis: ``DIR/study.png`` for one parameter,
``DIR/study_<param>.png`` for several.  ``kN``, ``kT`` play no part under
exact enforcement, and ``stabilisation`` none under penalty: varied on a
law enforced the other way they are refused, and where the study also
varies ``enforcement`` the points enforced the other way leave them aside
(the row's message says so) while the others take them.
"""
from __future__ import annotations

import dataclasses
import itertools
import logging
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from contactcore import CircleInterface, LineInterface, SceneError, load_scene, scene_text
from contactcore import tolerances as tol
from contactcore.budget import check_budget, check_together
from contactcore.discretisation import Reuse
from contactcore.enforcement import ENFORCEMENTS, make_law
from contactcore.exact import BONDED, EXACT_LAWS, checked_stabilisation, is_exact
from contactcore.laws import LAWS
from contactcore.scene import Units, check_resolution
from contactcore.scene.loads import scaled_load

from . import files, methods, pool
from .against_exact import exact_law, penalty_counterpart
from .study_plots import _shown, plot as _plot
from .study_gamma import COLUMNS as GAMMA_COLUMNS, ESTIMATE_COLUMNS, PARTIAL_SHARE, estimated_row, gamma_columns
from .outcomes import Incomplete, attempt, health

log = logging.getLogger("verification")

OUTPUTS = ["max_gN", "max_gT", "max_tN", "max_tT", "mean_tN", "mean_tT"]
#: study.md's headers of :data:`OUTPUTS` (each followed by its unit in the scene's).
OUTPUT_HEADERS = ["max |g_N|", "max |g_T|", "max |t_N|", "max |t_T|", "mean t_N", "mean t_T"]


def _material(scene, body: str, key: str, value: float):
    mats = dict(scene.materials)
    mats[body] = dataclasses.replace(mats[body], **{key: value})
    return {"materials": mats}


#: The penalty's springs: an exact law has none.
SPRINGS = ("kN", "kT")
#: The parameters that play no part under each enforcement: a penalty law's
#: springs where it is enforced exactly, Nitsche's β where by its springs.
UNUSED_UNDER = {"exact": SPRINGS, "penalty": ("stabilisation",)}


def _law(scene, key: str, value: float):
    if key == "stabilisation" and not is_exact(scene.law):
        how = ("vary it where --param enforcement is exact, or on a scene with enforcement = \"exact\""
               if scene.law.name in EXACT_LAWS else 'its limit k → ∞ is type = "bonded"')
        raise SceneError("--param stabilisation", f"applies to enforcement = \"exact\" only, and the scene's "
                         f"'{scene.law.name}' law is enforced by its springs here ({how})")
    if key == "stabilisation":
        value = checked_stabilisation(value, "--param stabilisation")
    if key in SPRINGS and is_exact(scene.law):
        how = (penalty_counterpart(scene.law) if scene.law.name in BONDED
               else f"vary {key} where --param enforcement is penalty")
        raise SceneError(f"--param {key}", f"plays no part under enforcement = \"exact\" (Nitsche's β is --param "
                         f"stabilisation; {how})")
    if key not in scene.law.parameters:
        raise SceneError(f"--param {key}", f"the '{scene.law.name}' law has no parameter {key}")
    return {"law": dataclasses.replace(scene.law, **{key: value})}


def _enforcement(scene, value):
    """The scene's law enforced ``value``-ly: ``exact`` drops its springs
    (:mod:`contactcore.exact`); ``penalty`` needs the scene's own springs."""
    law = scene.law
    if value not in ENFORCEMENTS:
        raise SceneError("--param enforcement", f"must be {' or '.join(ENFORCEMENTS)} (got {value!r})")
    if value == law.enforcement:
        return {"law": law}
    if value == "penalty":
        springs = dict(getattr(law, "given_springs", ()))
        missing = [k for k in ("kN", "kT") if k not in springs]
        if missing:
            raise SceneError("--param enforcement", f"penalty: the scene's '{law.name}' law is enforced exactly and "
                             f"its file gives no {' or '.join(missing)} to enforce it by: add "
                             f"{' and '.join(missing)} to its [interface.law] ({penalty_counterpart(law)})")
        params = {k: getattr(law, k) for k in law.parameters if k != "stabilisation"}
        return {"law": make_law({"type": law.name, "enforcement": "penalty", **params, **springs},
                                "--param enforcement: interface.law")}
    return {"law": exact_law(law, "--param enforcement: interface.law")}


def _radius(scene, value: float):
    if not isinstance(scene.interface, CircleInterface):
        raise SceneError("--param radius", "needs a circular interface")
    return {"interface": CircleInterface(scene.interface.centre, value)}


def _line(scene, name: str):
    if not isinstance(scene.interface, LineInterface):
        raise SceneError(f"--param {name}", "needs a straight interface")
    return scene.interface


def _finite(name: str, value: float) -> None:
    """Refuse a non-finite ``value`` of ``--param name`` in its own words
    (a load times inf is nan where a component is 0, and a line shifted by
    nan "misses the domain": grader13 #6)."""
    if not math.isfinite(value):
        raise SceneError(f"--param {name}", f"must be a finite number (got {value:g})")


def _offset(scene, value: float):
    itf = _line(scene, "offset")
    _finite("offset", value)
    n = np.asarray(itf.normal, float) / np.linalg.norm(itf.normal)
    return {"interface": LineInterface(tuple(np.asarray(itf.point) + value * n), tuple(n))}


def plus_on_left(normal) -> bool:
    """Whether a straight Γ of unit ``normal`` has its + body on the left
    of its direction at its own angle a₀ in (−90°, 90°] from the x axis:
    where the normal points up (n_y > 0), or along −x on a vertical Γ."""
    return normal[1] > 0 or (normal[1] == 0 and normal[0] < 0)


def _angle(scene, value: float):
    """Γ at ``value`` = a degrees from the x axis, counter-clockwise
    positive, through the middle of its chord: the scene's Γ turned by
    a − a₀ about that point, a₀ its own angle in (−90°, 90°], its normal
    turning with it.  The normal is (−sin a, cos a) where the scene's +
    body lies on the left of Γ's direction at a₀ (:func:`plus_on_left`:
    above a Γ whose normal points up), else (sin a, −cos a): the + body
    stays on the scene's side for |a − a₀| < 90° (the normal was
    (−sin a, cos a) whatever the scene's, which swapped the bodies of a
    scene whose normal pointed down or along +x)."""
    itf = _line(scene, "angle")
    mid = itf.chord(scene.domain).mean(axis=0)
    _finite("angle", value)
    a, side = np.radians(value), 1.0 if plus_on_left(itf.normal) else -1.0
    return {"interface": LineInterface(tuple(mid), (-side * np.sin(a), side * np.cos(a)))}


def _scaled(load, value: float):
    """``load`` times ``value``: each parameter of a magnitude it declares
    (:func:`contactcore.scene.loads.scaled_load`; a point stays put)."""
    return scaled_load(load, value)


def _load(scene, value: float):
    """Every load times ``value``, its path unchanged."""
    _finite("load", value)
    return {"loads": tuple(_scaled(ld, value) for ld in scene.loads)}


def _resolution(scene, value: float):
    """``h`` is the solve's, not the scene's: only checked here."""
    check_resolution(scene, value, "--param h")
    return {}


def _increments(scene, value: float):
    if not math.isfinite(value) or value != int(value) or value < 1:
        raise SceneError("--param increments", f"must be a whole number >= 1 (got {value:g})")
    return {"increments": int(value)}


#: What each parameter is, without its unit, and what it changes in a scene:
#: name -> (description, changes(scene, value) -> dict).
CHANGES = {
    "h": ("cell size or node spacing", _resolution),
    "kN": ("normal spring k_N", lambda s, v: _law(s, "kN", v)),
    "kT": ("tangential spring k_T", lambda s, v: _law(s, "kT", v)),
    "enforcement": ("how the law is enforced: penalty (its springs) or exact (Nitsche)", _enforcement),
    "stabilisation": ("Nitsche's β of an exact law (× the method's E/h)", lambda s, v: _law(s, "stabilisation", v)),
    "mu": ("friction coefficient μ of a coulomb law", lambda s, v: _law(s, "mu", v)),
    "load": ("factor on every load", _load),
    "increments": ("load increments", _increments),
    "E_minus": ("Young's modulus of the − body", lambda s, v: _material(s, "minus", "E", v)),
    "nu_minus": ("Poisson's ratio of the − body", lambda s, v: _material(s, "minus", "nu", v)),
    "E_plus": ("Young's modulus of the + body", lambda s, v: _material(s, "plus", "E", v)),
    "nu_plus": ("Poisson's ratio of the + body", lambda s, v: _material(s, "plus", "nu", v)),
    "radius": ("radius of a circular Γ", _radius),
    "offset": ("shift of a straight Γ along its normal, in the scene's length unit", _offset),
    "angle": ("angle of a straight Γ to the x axis, in degrees, counter-clockwise, Γ turned about the middle of its "
              "chord, its + body on the scene's side", _angle),
}
#: Every other parameter a registered law declares (its ``parameters``,
#: contactcore.laws' contract), so that a new law's is a --param as it is
#: registered: ``_law`` refuses it on a scene whose law lacks it.
for _kind in (*LAWS.values(), *EXACT_LAWS.values()):
    for _key in _kind.parameters:
        if _key not in CHANGES:
            CHANGES[_key] = (f"parameter {_key} of the '{_kind.name}' law ({_kind.dimensions[_key]})",
                             lambda s, v, key=_key: _law(s, key, v))
del _kind, _key
#: The units of a scene as the help names them: any consistent set
#: (docs/scenes.md, "Units"); a study's tables and plots name its scene's.
ANY_UNITS = Units(length="length", stress="stress")


def described(param: str, units: Units = ANY_UNITS) -> str:
    """What ``param`` is, with its unit in the scene's ``units``
    (:func:`verification.files.labelled`) if it has one."""
    return files.labelled(CHANGES[param][0], param, units)


#: What each parameter changes in a scene: name -> (description with its
#: unit in any scene's words, changes(scene, value) -> dict).
PARAMETERS = {param: (described(param), change) for param, (_, change) in CHANGES.items()}


def _check(param: str) -> None:
    if param not in PARAMETERS:
        raise SceneError("--param", f"unknown parameter {param!r} (known: {', '.join(PARAMETERS)})")


def scene_at(scene, point: dict):
    """``scene`` with each parameter of ``point`` (name -> value) set, in
    order but the enforcement first (the law's μ and β are then set on the
    law as enforced), without profiles (the study records Γ's points,
    :func:`_outputs`), validated.  Each step sees no profile already: the
    scene's own profiles may not fit a moved Γ (an angle first, then
    another parameter, failed on scene A's profiles along y = 0.5)."""
    changes = {}
    for param, value in sorted(point.items(), key=lambda item: item[0] != "enforcement"):
        _check(param)
        change = PARAMETERS[param][1]
        if param not in left_aside(point, changes.get("law", scene.law)):
            changes.update(change(scene.with_changes(profiles=(), **changes), value))
    return scene.with_changes(profiles=(), **changes)


def left_aside(point: dict, law) -> list[str]:
    """The parameters ``point`` gives that its ``law``, as enforced, leaves
    aside (:data:`UNUSED_UNDER`): where the point also sets the enforcement,
    k_N and k_T play no part at its exact points and β none at its penalty
    ones; the study's points enforced the other way use them."""
    return [p for p in UNUSED_UNDER[law.enforcement] if p in point] if "enforcement" in point else []


def _outputs(scene, result) -> dict:
    """The largest |g|, |t| over Γ's quadrature points at the last step
    (interface.csv's: the solve's own, not a profile's evaluation of a
    penalty law at its samples, which a stiff spring amplifies on a curved
    Γ) and the mean t over Γ weighted by the quadrature (increments.csv's
    means)."""
    final = result.interface.final
    (g_n, g_t), (t_n, t_t) = np.max(np.abs(final.jump), axis=0), np.max(np.abs(final.traction), axis=0)
    mean_tN, mean_tT = result.interface.means(final)[:2]
    return {"max_gN": float(g_n), "max_gT": float(g_t), "max_tN": float(t_n), "max_tT": float(t_t),
            "mean_tN": float(mean_tN), "mean_tT": float(mean_tT), **gamma_columns(scene, result)}


STATS = ["method", "degree", "status", "dofs", "total", "condition", "backward_error", *OUTPUTS, *GAMMA_COLUMNS,
         "message"]


def stats_of(rows: list[dict], estimate: bool = False) -> list[str]:
    """study.csv's columns after the point's: :data:`STATS`, with
    ``partial_share`` after the slip share where a row has it, and
    ``study --estimate``'s columns before the message."""
    partial = any(PARTIAL_SHARE in r for r in rows)
    columns = [c for k in STATS for c in ([k, PARTIAL_SHARE] if k == "slip_share" and partial else [k])]
    return [*columns[:-1], *(ESTIMATE_COLUMNS if estimate else []), columns[-1]]


def point_columns(params: list[str]) -> list[str]:
    """The columns naming a point: one per parameter, named after it, so
    that ``units.json`` and study.md give each its unit
    (:func:`verification.files.column_unit`: ``h (mm)``, ``angle (degree)``;
    a one-parameter study's was ``value``, with none: grader11's fault 4)."""
    return list(params)


@dataclass(frozen=True)
class Case:
    """One point and one method: picklable (a scene name, not a scene)."""

    scene: str
    point: tuple  # ((param, value), ...)
    method: str
    degree: int
    h: float | None
    cell: str | None
    keep: bool = True  # a later case of the study may reuse its system (:func:`shared`)
    estimate: bool = False  # also solved at 2h and the run at h estimated (:mod:`verification.study_gamma`)


#: This process's systems kept between the cases it solves: a point that
#: changes only the law's parameters reuses its method's mesh, shape
#: functions and matrices (contactcore.discretisation.Reuse).
_REUSE = Reuse()

#: The parameters a built system does not depend on (every registered law's
#: parameters, not its enforcement, and the load path:
#: contactcore.discretisation.Reuse's key leaves them out): two cases that
#: differ only in these share one.
SYSTEM_FREE = ("increments", *sorted({key for kind in (*LAWS.values(), *EXACT_LAWS.values())
                                      for key in kind.parameters}))


def system_of(method: str, point) -> tuple:
    """What a case's built system depends on among what a study varies:
    its method and the point's parameters but :data:`SYSTEM_FREE`."""
    return method, tuple((p, v) for p, v in point if p not in SYSTEM_FREE)


def shared(cases: list) -> list:
    """``cases`` (study order) each with ``keep`` set: whether a later case
    shares its system (:func:`system_of`).  The last case of each system
    releases it after its solve, and a case no other shares (every case of
    ``--param h``) keeps nothing: a study of four h values held the three
    systems before beside the one it solved (822 MB against 379 MB for
    one; review6's fault 1)."""
    keys = [system_of(c.method, c.point) for c in cases]
    return [dataclasses.replace(c, keep=key in keys[k + 1:]) for k, (c, key) in enumerate(zip(cases, keys))]


def solve_case(case: Case) -> dict:
    """The row of one case (its scene valid: :func:`check_points`), solved
    in this process on its own communicator; a refused solve is a row with
    its message.  With ``case.estimate`` the point is also solved at 2h
    and the run at h estimated, in the same task
    (:func:`verification.study_gamma.estimated_row`); the row's
    ``est_messages`` are the estimate's warnings (study.md lists them)."""
    point = dict(case.point)
    row = {"method": case.method, "degree": case.degree}
    scene = scene_at(load_scene(case.scene), point)
    solve, comm = pool.solver(case.method)
    options = {**methods.options_for(case.method, cell=case.cell), **comm}
    _REUSE.keep = case.keep
    h = point.get("h", case.h if case.h is not None else scene.h)
    tried = attempt(solve, scene, h, degree=case.degree, reuse=_REUSE, **options)
    row.update(health(tried))
    if tried.refused:
        return {**row, "status": "failed", "message": tried.message}
    status = "warned" if tried.result.solver.warnings else "ok"
    aside = [f"{p} not applied: it plays no part under enforcement = \"{scene.law.enforcement}\""
             for p in left_aside(point, scene.law)]
    estimated, warnings, why = {}, [], ""
    if case.estimate:
        estimated, warnings, why = estimated_row(solve, scene, h, tried.result, _REUSE, degree=case.degree,
                                                 **options)
    said = [*aside, *tried.result.solver.warnings, *([why] if why else [])]
    return {**row, "status": status, "message": "; ".join(said), **_outputs(scene, tried.result), **estimated,
            **({"est_messages": warnings} if case.estimate else {})}


def check_given_once(field: str, values, name: str = "") -> None:
    """Refuse with a :class:`SceneError` naming ``field`` (and ``name``, the
    parameter the values belong to, if any) a value given more than once: a
    repeated value ran the same case twice and wrote its row twice (the
    one check of ``study --values`` and ``efficiency --method/--degree/--h``)."""
    values = list(values)
    twice = sorted({f"{v:g}" if isinstance(v, float) else str(v) for v in values if values.count(v) > 1})
    if twice:
        raise SceneError(field, f"{name + ': ' if name else ''}each value may be given once "
                                f"({', '.join(twice)} given twice)")


def study(scene_name: str, params: list[tuple[str, list[float]]], method_names: list[str], out: Path, *,
          degree: int = 1, h: float | None = None, cell: str | None = None, workers: int | None = None,
          allow_large: bool = False, strict: bool = False, estimate: bool = False, argv=()) -> str:
    """Run the study over the Cartesian product of ``params`` ((name, values)
    pairs; the last varies fastest) on :mod:`verification.pool`, and write
    its table and plots; return the Markdown section.  Every point is
    checked first (:func:`check_points`), and unless ``allow_large`` each
    point's solve against this machine's memory (:func:`check_sizes`), and
    ``workers`` of them at once (:func:`contactcore.budget.check_together`).
    A point that fails is a row with its message and the study goes on;
    with ``strict`` (the CLI), once everything is written, any failed point
    raises :class:`~verification.outcomes.Incomplete` (exit status 1).
    With ``estimate`` every point is also solved at 2h, its h the finer
    (:mod:`verification.study_gamma`), 2h checked against the domain first."""
    names = [p for p, _ in params]
    if len(set(names)) != len(names):
        raise SceneError("--param", f"each parameter may be given once (got {', '.join(names)})")
    for name, values in params:
        check_given_once("--values", values, name)
    base = load_scene(scene_name)
    if h is not None:
        check_resolution(base, h)
    labels = point_columns(names)
    points = list(itertools.product(*(values for _, values in params)))
    scenes = check_points(base, names, points)
    if estimate:
        check_coarse(scenes, names, points, h)
    cases = shared([Case(scene_name, tuple(zip(names, pt)), m, degree, h, cell, estimate=estimate) for pt in points
                    for m in methods.expand(method_names)])
    if not allow_large:
        check_memory(cases, check_sizes(scenes, names, points, methods.expand(method_names), degree, h,
                                        every=True), workers)
    rows = []
    try:
        for k, (case, row) in enumerate(zip(cases, pool.map_cases(solve_case, cases, workers)), 1):
            where = ", ".join(f"{p} = {_shown(v)}" for p, v in case.point)
            if row["status"] == "failed":
                log.warning("[%d/%d] %s, %s: failed: %s", k, len(cases), where, case.method, row["message"])
            else:
                log.info("[%d/%d] %s, %s: %s, %d DOFs, %.2f s", k, len(cases), where, case.method, row["status"],
                         row["dofs"], row["total"])
            rows.append({**dict(zip(labels, (v for _, v in case.point))), **row})
    finally:
        _REUSE.close()  # the systems this process kept (a worker's end with it)
    out = Path(out)
    files.write_csv(out / "study.csv", rows, [*labels, *stats_of(rows, estimate)])
    for param, label in zip(names, labels):
        _plot(out / _plot_name(names, param), base, param, label, [lb for lb in labels if lb != label], rows)
    text = markdown(base.name, names, rows, base.units, pool.workers_label(workers), estimate)
    files.write_text(out / "study.md", text)
    files.write_text(out / files.SCENE_FILE, scene_text(scene_name))  # the units of study.csv's columns
    files.write_json(out / "run.json", {**files.provenance(list(argv)), "scene": base.name,
                                        "params": {p: list(v) for p, v in params},
                                        "methods": methods.expand(method_names), "degree": degree, "h": h,
                                        "estimate": estimate, "workers": pool.workers_label(workers)})
    failed = sum(r["status"] == "failed" for r in rows)
    if strict and failed:
        raise Incomplete(f"study: {failed} of {len(rows)} points failed; the study is written, each failed row "
                         "of study.csv says why")
    return text


def check_points(base, names: list[str], points: list[tuple]) -> list:
    """Every point's scene built and validated (:func:`scene_at`; no
    mesh, no solve), in study order: the first that cannot be ends the
    study with a SceneError naming it, by the parameter and value where
    the message does not already (a scene's own field, such as
    ``interface``, names neither).  Returns the scenes."""
    scenes = []
    for point in points:
        try:
            scenes.append(scene_at(base, dict(zip(names, point))))
        except SceneError as exc:
            if exc.field.startswith("--param"):
                raise
            raise SceneError(f"--param {_where(names, point)}", str(exc)) from None
    return scenes


def check_coarse(scenes: list, names: list[str], points: list[tuple], h) -> None:
    """``study --estimate``: every point's 2h (its ``h`` parameter, else
    ``h``, else its scene's) fits the domain
    (:func:`contactcore.scene.check_resolution`), before any solve."""
    for scene, point in zip(scenes, points):
        at = dict(zip(names, point)).get("h", h if h is not None else scene.h)
        if at is None:
            raise SceneError("--estimate", f"scene {scene.name} gives no default h; give --h")
        given = (f"h = {_shown(at)}" if "h" in names else f"--h {_shown(at)}" if h is not None
                 else f"the scene's h {_shown(at)}")
        check_resolution(scene, 2 * at, f"--estimate: {given}, the coarse run at 2h")


def check_sizes(scenes: list, names: list[str], points: list[tuple], method_names: list[str], degree: int,
                h, every: bool = False) -> list:
    """Every point's solve (its scene of :func:`check_points`), with every
    method, within this machine's memory
    (:func:`contactcore.budget.check_budget`), before any solve: the first
    that is not ends the study with a TooLargeError naming it (``--param h
    --values 1e-9`` would otherwise mesh until the system stops the
    process).  Returns each case's estimated memory in bytes, for the
    check of several at once (with ``every``, one per case in study
    order, None for a case without h)."""
    memories = []
    for scene, point in zip(scenes, points):
        at = dict(zip(names, point)).get("h", h if h is not None else scene.h)
        if at is None:
            memories += [None] * len(method_names) if every else []
            continue  # refused by the solve itself, as a failed row, naming the missing h
        for name in method_names:
            memories.append(check_budget(scene, at, methods.budgeted(name, degree), field=f"--param {_where(names, point)}: h").memory)
    return memories


def check_memory(cases: list, memories: list, workers: int | None) -> None:
    """The study's cases (:func:`shared`; ``memories`` their estimates, in
    order, None for one the solve refuses) within this machine's memory,
    ``workers`` at once, with the systems each process keeps for the
    cases after (:func:`contactcore.budget.check_together`): a case that
    shares its system counts once per system, as many as
    :data:`~contactcore.tolerances.SYSTEMS_KEPT` of them a process; in
    one process, as many as are ever open at once in the study's order
    (from their first case to their last)."""
    keys = [system_of(c.method, c.point) for c in cases]
    sizes: dict = {}
    for key, memory in zip(keys, memories):
        if memory is not None:
            sizes.setdefault(key, []).append(memory)
    kept = [(max(m), len(m)) for m in sizes.values() if len(m) > 1]
    alone = [m[0] for m in sizes.values() if len(m) == 1]
    span = {key: (keys.index(key), len(keys) - 1 - keys[::-1].index(key)) for key in sizes}
    most_open = max((sum(a <= k <= b for a, b in span.values()) for k in range(len(keys))), default=1)
    serial = (workers or 1) == 1
    check_together(alone, workers, kept=kept, systems=min(tol.SYSTEMS_KEPT, most_open) if serial
                   else tol.SYSTEMS_KEPT)


def _where(names: list[str], point: tuple) -> str:
    """A point as the messages name it: ``kN = 1e+09, radius = 0.2``."""
    return ", ".join(f"{p} = {_shown(v)}" for p, v in zip(names, point))


def _plot_name(names: list[str], param: str) -> str:
    return "study.png" if len(names) == 1 else f"study_{param}.png"


def markdown(scene_name: str, names: list[str], rows: list[dict], units: Units = Units(),
             measured_by: str = "1 worker", estimate: bool = False) -> str:
    """The study's section: its plots and its table, in the scene's
    ``units``, and how many workers measured its times (``measured_by``,
    :func:`verification.pool.workers_label`); what the maxima and shares
    are (:data:`OUTPUTS_NOTE`); with ``estimate``, the estimate's columns
    and each warning once, after the points that gave it."""
    failed = [r for r in rows if r["status"] == "failed"]
    what = " × ".join(f"{p} ({described(p, units)})" for p in names)
    labels = point_columns(names)
    shares = [c for c in stats_of(rows) if c.endswith("_share")]
    extra = [*ESTIMATE_COLUMNS[:-1]] if estimate else []
    return (f"## Study: scene {scene_name}, {what}\n\n"
            + "".join(f"![study {p}]({_plot_name(names, p)})\n" for p in names) + "\n"
            + f"Times in s, measured by {measured_by} at once (cases beside each other share the cores).\n"
            + OUTPUTS_NOTE + (ESTIMATE_NOTE if estimate else "") + "\n"
            + files.markdown_table(rows, [*labels, "method", "status", "dofs", "total", *OUTPUTS, *shares,
                                          "stick_length", "max_tN_away", "max_tT_away", *extra, "message"],
                                   [*(files.labelled(p, p, units) for p in names), "method", "status", "DOFs",
                                    "total (s)",
                                    *(files.labelled(text, q, units) for text, q in zip(OUTPUT_HEADERS, OUTPUTS)),
                                    *(c.removesuffix("_share") for c in shares),
                                    *(files.labelled(text, q, units) for text, q in GAMMA_HEADERS),
                                    *(files.labelled(text, q, units) for text, q in ESTIMATE_HEADERS[:len(extra)]),
                                    "message"])
            + (f"\n{len(failed)} of {len(rows)} points failed; the study went on.\n" if failed else "")
            + (_estimate_warnings(names, rows) if estimate else ""))


#: study.md's headers of the Γ columns after the shares and of the estimate's.
GAMMA_HEADERS = [("stick length", "stick_length"), ("max |t_N| away from ends", "max_tN_away"),
                 ("max |t_T| away from ends", "max_tT_away")]
ESTIMATE_HEADERS = [("est. error (worst relative RMS)", "est_worst"), ("where", "est_worst_at"),
                    ("est. error t_N (RMS)", "est_tN"), ("est. error t_T (RMS)", "est_tT"),
                    ("estimate warnings", "est_warnings"), ("status changed (samples)", "status_changed")]
#: Under study.md's table: what its maxima and shares are.
OUTPUTS_NOTE = ("\nmax |g_N| … mean t_T are over Γ's quadrature points at the last increment, Γ's ends included: "
                "where Γ meets the domain's boundary the tractions of an exact or stiff law are singular, so "
                "max |t_N| and max |t_T| there follow the mesh more than the method. max |t_N| (|t_T|) away from "
                "ends leaves out Γ's points within the agreement's default distance of a singular point "
                "(`verification.agreement.default_exclusion` of the point's scene, the samples `run`'s "
                "agreement and estimates leave out). open, stick, slip (and partial) are the shares of Γ's length "
                "in each status at the last increment (increments.csv's `open_fraction`, `slip_fraction`); "
                "stick length is the sticking share's length.\n")
#: Under an estimated study's table: how the estimate is made.
ESTIMATE_NOTE = ("\nEstimated from each point's runs at 2h and h (the row is the run at h), as `run --h 2h --estimate` "
                 "estimates: the worst relative RMS error of Γ's profile gN, gT, tN, tT away from singular points "
                 "and which (summary.json's `worst`), the RMS estimated error of t_N and t_T there, the number of "
                 "the estimate's warnings (listed below), and at how many of Γ's profile samples the status "
                 "(open, stick, slip) differs between 2h and h: where it does, the split moved between the runs "
                 "and no estimate of the point is asymptotic, an indication only.\n")


def _estimate_warnings(names: list[str], rows: list[dict]) -> str:
    """Each estimate warning once, after the points and methods that gave it."""
    given: dict[str, list[str]] = {}
    for r in rows:
        where = ", ".join([*(f"{p} = {_shown(r[p])}" for p in names), r["method"]])
        for w in r.get("est_messages", []):
            given.setdefault(w, []).append(where)
    return ("\nEstimate warnings:\n\n" + "".join(f"- {'; '.join(at)}: {w}\n" for w, at in given.items())
            if given else "")
