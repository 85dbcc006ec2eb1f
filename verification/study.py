"""``python -m verification study``: inputs varied, every method solved.

    python -m verification study SCENE --param NAME --values V1 V2 ... [--param NAME2 --values ...]
        [--method ...] [--degree 1] [--h H] [--workers K] --out DIR

Parameters (:data:`~verification.study_parameters.PARAMETERS`): the mesh size ``h``; the law's springs
``kN``, ``kT`` and friction ``mu``; how the law is enforced, ``enforcement``
(penalty or exact), and an exact law's ``stabilisation`` β (within
``NITSCHE_STABILISATION_RANGE``); ``load``, a factor on every load;
the number of ``increments``; the materials ``E_minus``, ``nu_minus``, ``E_plus``, ``nu_plus``;
and the geometry of Γ — ``radius`` of a circular Γ, ``offset`` of a straight
Γ along its normal, ``angle`` of a straight Γ (degrees a from the x axis,
counter-clockwise: the scene's Γ turned about the middle of its chord from
its own angle a₀ in (−90°, 90°], its normal turning with it, so the + body
stays on the scene's side for |a − a₀| < 90°:
:func:`~verification.study_parameters._angle`).  Several ``--param`` pairs
run their Cartesian product (the last parameter varies fastest), one row per point
and method.  A geometry change is a new scene,
so the conforming method meshes it afresh through gmsh (and XFEM with
``--cell gmsh`` too); the scene's own profiles may no longer lie on the moved
Γ, so the study reads Γ's own points: for each point it records DOFs, wall
time, solver health, and the largest |g_N|, |g_T|, |t_N|, |t_T| over Γ's
quadrature points with the mean t_N and t_T.  Every point's scene is built and validated before
any solve (:func:`~verification.study_checks.check_points`): a bad value (a radius that leaves the
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

One idea a module: what a parameter changes in a scene
(:mod:`~verification.study_parameters`), the checks before any solve
(:mod:`~verification.study_checks`), study.csv's columns and study.md's
text (:mod:`~verification.study_table`), what is recorded of Γ
(:mod:`~verification.study_gamma`) and the plots
(:mod:`~verification.study_plots`); this module makes the cases
(:class:`Case`; :func:`shared`: which share a system), solves one
(:func:`solve_case`), checks their memory together (:func:`check_memory`)
and runs the study (:func:`study`).
"""
from __future__ import annotations

import dataclasses
import itertools
import logging
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from contactcore import SceneError, load_scene, scene_text
from contactcore import tolerances as tol
from contactcore.budget import check_together
from contactcore.discretisation import Reuse
from contactcore.exact import EXACT_LAWS
from contactcore.laws import LAWS
from contactcore.scene import check_resolution

from . import files, methods, pool
from .outcomes import Incomplete, attempt, health
from .study_checks import check_coarse, check_given_once, check_points, check_sizes
from .study_gamma import estimated_row, gamma_columns
from .study_parameters import left_aside, scene_at
from .study_plots import _shown, plot as _plot
from .study_table import markdown, plot_name, point_columns, stats_of

log = logging.getLogger("verification")


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
        _plot(out / plot_name(names, param), base, param, label, [lb for lb in labels if lb != label], rows)
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
