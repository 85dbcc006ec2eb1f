"""``python -m verification run``: solve one scene with one or more methods.

Writes, under ``--out DIR``::

    DIR/run.json                  command, MPI ranks, versions, options
    DIR/scene.toml                the scene as read
    DIR/<method>/summary.json     DOFs, MPI ranks, timings, solver health
    DIR/<method>/profiles/<ID>.csv
    DIR/<method>/fields/          (with --fields) VTU per body, Γ per step + PVD
    DIR/plots/<ID>.png            each profile, methods overlaid
    DIR/summary.md                a table of the runs
    (with --estimate, :mod:`contactcore.estimate`: each method also solved at
    h/2 (and h/4), the finest run written; ``q_err`` beside every quantity
    ``q`` in the profile CSVs, ``"estimate"`` in summary.json, the estimated
    error beside the time in summary.md, and whether the methods agree
    within their estimated errors)
    (a nonlinear law, :mod:`verification.interface`:)
    DIR/<method>/increments.csv, interface.csv
    DIR/plots/status_<method>.png, response.png; Newton iterations in summary.md
    (with --against-exact, a unilateral or coulomb law enforced by its springs,
    :mod:`verification.against_exact`: each method also solved with the law
    enforced exactly at the same discretisation, into DIR/<method>/exact/
    (summary.json, profiles/, increments.csv, interface.csv), each profile
    penalty against exact in DIR/plots/exact_<method>_<ID>.png; how far apart
    they are in summary.md's "Penalty against exact" and under
    ``"against_exact"`` in DIR/<method>/summary.json)

Contract: :func:`run` is the order of the work, each step its own module's:
the refusals before any solve (:mod:`verification.run_checks`), each method
solved (:func:`_solve`, the estimate's ladder and failures named by
:mod:`verification.run_solve`) and written (:mod:`verification.run_files`),
its exact twin (:func:`_against_exact`), the reference
(:mod:`verification.run_reference`), summary.md and the plots
(:mod:`verification.run_summary`), then scene.toml and run.json.
"""
from __future__ import annotations

import logging
from pathlib import Path

from contactcore import Scene, load_scene, scene_text
from contactcore import estimate as estimates
from contactcore.labels import run_label

from . import against_exact as exact_gap
from . import agreement, files, interface, methods, plots, pool
from .run_checks import check, check_floors, estimated_h, read_nodes
from .run_files import written_profiles, write_method
from .run_reference import DEFAULT_REFERENCE, as_reference, reference_label, solve_reference
from .run_solve import named, progress, solve_estimated
from .run_summary import write_summary

log = logging.getLogger("verification")


def run(scene_name, method_names: list[str], out: Path, *, h=None, degree=1, paper=False,
        fields=False, petsc_options=None, dmax=None, nodes_file=None, cell=None, basis=None, mesh=None,
        flux=None, allow_large=False,
        draw=True, estimate=None, reference=DEFAULT_REFERENCE, against_exact=False, floors=None, argv=()) -> str:
    """Solve ``scene_name`` (a scene, a built-in name or a TOML file),
    sample the scene's profiles, write everything; return the Markdown
    section (``summary.md``'s text).  Before any work (:func:`~verification.run_checks.check`):
    every option must mean something to a chosen method, ``h`` must fit
    the domain, every method must take the scene at every h it solves
    (:func:`methods.check_solvable` at each of an estimate's h: xfem's pins
    at nodes of its grid, efgm's springs), and the run must fit the machine
    (:func:`contactcore.budget.check_budget`, unless ``allow_large``).  The
    scene as read is written last (as TOML), with ``run.json``; no figure
    unless ``draw`` (matplotlib is then never imported), none on mpirun's
    ranks after the first, which write nothing (:func:`files.writes_here`;
    drawing takes no part in a collective).  Two runs or more
    are compared with ``reference`` (method, degree; None: fe at its
    highest degree among them), solved at the same h if it is not one of
    them, each quantity named in ``floors`` (quantity -> value in its unit,
    :func:`verification.agreement.table`) measured against its floor.  With
    ``against_exact`` (a unilateral or coulomb law enforced by
    its springs, else refused here) each method is solved again with the
    law enforced exactly, at the h of its answer, and compared
    (:func:`_against_exact`)."""
    scene = load_scene(scene_name)
    twin = exact_gap.exact_twin(scene) if against_exact else None
    draw = draw and files.writes_here()
    chosen = methods.expand(method_names)
    given = dict(petsc_options=petsc_options or None, dmax=dmax, cell=cell, basis=basis,
                 mesh=None if mesh is None else str(mesh), flux=flux)
    compared = reference is not None and len(chosen) > 1  # a reference only where methods are compared
    check(scene, chosen, h, degree, paper, allow_large, estimate, reference if compared else None,
          nodes=nodes_file, **given)
    check_floors(scene, chosen, floors, bool(estimate or against_exact))
    h = estimated_h(scene, h) if estimate else h
    finest = h / 2 ** (estimate - 1) if estimate else h  # the answer's h, where a reference is solved
    nodes = read_nodes(nodes_file, scene) if nodes_file else None
    for hk in estimates.levels_of(h, estimate) if estimate else [h]:  # every h solved, before any solve
        methods.check_solvable(chosen, scene, hk, degree, paper, nodes=nodes, **given)
    if compared:
        as_reference(reference, "compare the methods", methods.check_solvable, [reference[0]], scene, finest,
                     reference[1], paper, petsc_options=petsc_options or None, flux=flux)
    out = Path(out)
    profiles, summaries, paths, estimated, gaps, statuses = {}, [], {}, {}, {}, {}
    for name in chosen:
        options = methods.options_for(name, nodes=nodes, **given)
        result, est = named(chosen, name, _solve, scene, name, h, degree, paper, estimate, options)
        exact_row = (_against_exact(out, scene, twin, name, result, h, degree, paper, estimate, options, draw, gaps,
                                    floors)
                     if twin is not None else None)
        summaries.append(write_method(out, scene, name, result, est, fields, draw, profiles, paths, estimated, gaps,
                                      floors, statuses))
        summaries += [exact_row] if exact_row else []
    ref = reference_label(reference)
    if compared and profiles and ref not in {label for by_label in profiles.values() for label in by_label}:
        solve_reference(scene, reference, finest, paper, petsc_options or None, out, profiles, summaries, statuses,
                        flux)
    text = write_summary(out, scene, summaries, profiles, paths, estimated, ref, draw, gaps, floors, statuses)
    files.write_text(out / files.SCENE_FILE, scene_text(scene_name))
    files.write_json(out / "run.json", {**files.provenance(list(argv)),
                                        "scene": scene.name if isinstance(scene_name, Scene) else str(scene_name),
                                        "methods": chosen, "h": _recorded_h(scene, h, paper, summaries),
                                        "degree": degree, "mesh": _recorded_mesh(summaries),
                                        "paper": paper, "estimate": estimate,
                                        "petsc_options": petsc_options or {}, "dmax": dmax,
                                        "basis": basis, "flux": flux,
                                        "nodes": str(nodes_file) if nodes_file else None,
                                        "reference": ref, "against_exact": against_exact, "floors": floors or {},
                                        "cell": next((s["discretisation"]["cell"] for s in summaries
                                                      if "cell" in s["discretisation"]), cell)})
    return text


def _recorded_h(scene: Scene, h, paper: bool, summaries: list[dict] = ()) -> float | None:
    """``run.json``'s ``h``: the h that ran (with ``--estimate`` the
    coarsest of its runs), the scene's own where none was given (it
    recorded null, grader6 #8), a mesh file's own (``--mesh``: its largest
    cell diameter); None on the paper's grids, whose h is each method's
    own (its ``summary.json``'s ``discretisation``)."""
    mesh = _recorded_mesh(summaries)
    return None if paper else mesh["h"] if mesh else (scene.h if h is None else h)


def _recorded_mesh(summaries: list[dict]) -> dict | None:
    """``run.json``'s ``mesh``: the file of ``--mesh`` as fe's summary
    records it (name, path, sha256 of its content, h and what h measures),
    or None."""
    return next((s["discretisation"]["mesh"] for s in summaries if "mesh" in s.get("discretisation", {})), None)


def _solve(scene: Scene, name: str, h, degree: int, paper: bool, estimate, options: dict, shown: str | None = None):
    """Method ``name``'s result (the finest, with ``estimate``) and its
    estimate, logged (as ``shown``, default its label ``xfem P1`` as
    summary.md names it): a worker of an mpi4py.futures pool solves on its
    own communicator; mpirun's ranks share the world."""
    shown = shown or run_label(name, degree)
    log.info("scene %s: solving with %s%s", scene.name, shown, f" ({options['basis']} basis)" if "basis" in options
             else "")
    solve, on_comm = pool.solver(name) if pool.under_mpi_pool() else (methods.solver(name), {})
    result, est = solve_estimated(solve, scene, h, estimate, degree=degree, paper=paper,
                                  progress=progress(shown), **options, **on_comm)
    for w in list(result.solver.warnings) + (list(est.warnings) if est is not None else []):
        log.warning("%s: %s", shown, w)
    log.info("%s: %d DOFs, total %.2f s, residual %.1e", shown, result.dofs, result.timings.total,
             result.solver.residual)
    return result, est


def _against_exact(out: Path, scene: Scene, twin: Scene, name: str, result, h, degree: int, paper: bool,
                   estimate, options: dict, draw: bool, gaps: dict, floors: dict | None = None) -> dict:
    """Method ``name`` solved on ``twin`` (``scene`` with its law enforced
    exactly) at ``h`` with the penalty run's ``options`` and, with
    ``estimate``, at h/2 (, h/4) and estimated, as the penalty run was:
    the finest run is compared with the penalty run, which was solved
    there.  Its profiles (with their estimated errors), history and
    summary are written under ``out/<name>/exact``, each profile's penalty
    and exact curves drawn; how far ``result`` (the penalty run) is from
    it (:func:`verification.against_exact.record`, sizes floored by
    ``floors``) joins ``gaps`` under the run's label and its summary.json;
    its estimate is floored alike.  Returns the exact run's summary
    (a row of summary.md's table)."""
    label, shown = run_label(name, result.degree), f"{name} ({exact_gap.EXACT})"
    exact, est = _solve(twin, name, h, degree, paper, estimate, options, f"{label} ({exact_gap.EXACT})")
    summary, sampled = written_profiles(out / name / "exact", twin, exact, est, floors)
    penalty, exact_profiles = agreement.sampled(scene, result), {p.id: p for p in sampled}
    interface.write_history(out / name / "exact", twin, exact.interface)
    rows = exact_gap.differences(scene, label, penalty, exact_profiles, floors)
    gaps[label] = exact_gap.record(scene, rows, exact_profiles, result.interface, exact.interface, floors)
    summary["method"] = shown
    files.write_json(out / name / "exact" / "summary.json", summary)
    titles = {p.id: p.title for p in scene.profiles}
    for pid in penalty if draw else ():
        plots.plot_profile(out / "plots" / f"exact_{name}_{pid}.png", (titles[pid], f"{label}, penalty against exact"),
                           {label: penalty[pid], exact_gap.EXACT: exact_profiles[pid]}, exact_gap.EXACT,
                           agreement.floors(twin), scene.units,
                           sizes={a.quantity: (a.size, a.against) for a in rows if a.profile == pid})
    return summary
