"""``python -m verification paper``: the paper's figures, reproduced.

For each of scenes A, B and C: the conforming method (P1), XFEM (P1) and
EFGM at the paper's discretisations (XFEM 19×19, 20×20, 20×30 quads; EFGM
20×20, 21×21, 21×31 nodes; fe at the XFEM cell size), and a refined
conforming reference (P2, curved cells, at a quarter of the scene's default
h unless ``--ref-h`` says otherwise).  Writes::

    DIR/figures/figNN_<ID>.png    each paper figure (Figs. 8–11, 15–18, 22–23), methods overlaid
    DIR/figures/extra_<ID>.png    the extra profiles of docs/scenes.md (A5, B5, B6, C3, C4)
    DIR/<scene>/<method>/profiles/<ID>.csv, DIR/<scene>/<method>/summary.json
    DIR/<scene>/scene.toml        the scene as read
    DIR/agreement.csv, DIR/paper.md

The agreement table gives, for each profile, quantity and method, the RMS
of the difference to the reference relative to the RMS of the reference
(:mod:`verification.agreement`), twice: over all samples, and with the
samples closer than ``exclude`` to a singular point (a corner of the
domain, or an end of Γ on the outer boundary) left out.  There the exact
stresses are singular or have boundary layers that none of these
discretisations resolves, so the pointwise difference measures resolution,
not agreement; the second figure is the one to judge the methods by, the
first shows how much the corners weigh.
"""
from __future__ import annotations

import functools
import logging
import re
from pathlib import Path

from contactcore import load_scene, sample_profiles, scene_text
from contactcore.budget import check_budget, check_together
from contactcore.labels import reference_text, run_label

from . import files, methods, plots, pool
from .agreement import agreements, default_exclusion, profile_agreements

log = logging.getLogger("verification")

SCENES = ("A", "B", "C")
#: The reference's cell size, as a fraction of the scene's default h.
REFERENCE_REFINEMENT = 4


def figure_name(profile) -> str:
    """``figNN_<ID>`` for a profile whose title cites a paper figure, else ``extra_<ID>``."""
    found = re.search(r"Fig\. (\d+)", profile.title)
    return f"fig{int(found.group(1)):02d}_{profile.id}" if found else f"extra_{profile.id}"


def _label(name: str, result) -> str:
    return methods.discretisation(name).label(result)


def _solve(scene, name: str, out: Path, role: str, **kwargs):
    solve, comm = pool.solver(name)
    result = solve(scene, **kwargs, **comm)
    profiles = sample_profiles(scene, result.fields, result.interface)
    for prof in profiles:
        files.write_profile_csv(out / "profiles" / f"{prof.id}.csv", prof)
    files.write_json(out / "summary.json", result.summary())
    for w in result.solver.warnings:
        log.warning("scene %s, %s: %s", scene.name, role, w)
    log.info("scene %s, %s: %d DOFs, %.2f s", scene.name, role, result.dofs, result.timings.total)
    return result, {p.id: p for p in profiles}


def reproduce_scene(scene_name: str, out: Path, ref_h: float | None = None) -> tuple[list[dict], list[str]]:
    """One scene: solve, plot its figures; return the agreement rows and the
    warnings the solvers gave."""
    scene = load_scene(scene_name)
    ref_h = ref_h or scene.h / REFERENCE_REFINEMENT
    reference, ref = _solve(scene, "fe", out / scene.name / "reference", reference_text(run_label("fe", 2)), h=ref_h, degree=2,
                            estimate_condition=False)
    runs, warnings = {}, []
    for name in methods.METHODS:
        result, got = _solve(scene, name, out / scene.name / name, name, paper=True)
        runs[name] = (_label(name, result), got)
        warnings += [f"scene {scene.name}, {name}: {w}" for w in result.solver.warnings]
    files.write_text(out / scene.name / files.SCENE_FILE, scene_text(scene_name))
    exclude = default_exclusion(scene)
    rows = []
    for name, (label, got) in runs.items():
        everywhere = {(p, q): v for p, q, _, v in agreements(scene, got, ref, 0.0)}
        for pid, q, kind, value in agreements(scene, got, ref, exclude):
            rows.append({"scene": scene.name, "profile": pid, "quantity": q, "class": kind, "method": label,
                         "all_samples": everywhere[(pid, q)], "away_from_singular_points": value,
                         "exclude": exclude})
    sizes = profile_agreements(scene, "", next(iter(runs.values()))[1], ref, exclude)  # the reference's alone
    for prof in scene.profiles:
        overlay = {label: got[prof.id] for label, got in runs.values()}
        overlay[f"{run_label('fe', 2)}, h = {ref_h:g} ({reference.dofs} DOFs)"] = ref[prof.id]  # drawn as the reference
        plots.plot_profile(out / "figures" / f"{figure_name(prof)}.png", prof.title, overlay,
                           sizes={a.quantity: (a.size, a.against) for a in sizes if a.profile == prof.id})
    return rows, warnings


COLUMNS = ["scene", "profile", "quantity", "class", "method", "all_samples", "away_from_singular_points", "exclude"]


def markdown(rows: list[dict], warnings: list[str]) -> str:
    """The paper's section: its figures and the agreement table."""
    md = ["## The paper's figures", "",
          "Each figure overlays the three methods at the paper's discretisations and the refined conforming "
          "reference (fe P2). The table gives the RMS of each profile's difference to the reference, relative "
          "to the reference's RMS, over all samples and with the samples within `exclude` of a corner or of an "
          "end of Γ left out (there the exact stresses are singular or have boundary layers none of these "
          "discretisations resolves). Each quantity is measured against its vector's size: B6's t_N and g_N, exactly "
          "zero, against |t| and |g| with B5's t_T and g_T.", ""]
    for scene_name in dict.fromkeys(r["scene"] for r in rows):
        for prof in load_scene(scene_name).profiles:
            md.append(f"![{prof.id}](figures/{figure_name(prof)}.png)")
    md += ["", files.markdown_table(rows, ["scene", "profile", "quantity", "class", "method", "all_samples",
                                           "away_from_singular_points", "exclude"],
                                    ["scene", "profile", "quantity", "class", "method", "all samples",
                                     "away from singular points", "exclude (m)"])]
    if warnings:
        md += ["Solver warnings:", ""] + [f"- {w}" for w in warnings] + [""]
    return "\n".join(md)


def check_budgets(scenes, ref_h: float | None, workers: int | None = None, offer_allow_large: bool = True) -> None:
    """Refuse, before any solve, a reference (fe P2 at ``ref_h``, else
    the scene's h / REFERENCE_REFINEMENT) that would not fit this machine
    (:func:`contactcore.budget.check_budget`), or ``workers`` scenes at
    once whose references together would not
    (:func:`contactcore.budget.check_together`); the paper's own grids are
    fixed and small.  The messages offer ``--allow-large`` if
    ``offer_allow_large`` (``report`` has none)."""
    memories = []
    for name in scenes:
        scene = load_scene(name)
        at = ref_h or scene.h / REFERENCE_REFINEMENT
        memories.append(check_budget(scene, at, methods.budgeted("fe", 2), "--ref-h" if ref_h else f"scene {scene.name}'s reference h",
                                     offer_allow_large).memory)
    check_together(memories, workers or 1, offer_allow_large=offer_allow_large)


def paper(out: Path, scenes=SCENES, ref_h: float | None = None, workers: int | None = None, argv=(),
          allow_large: bool = False) -> str:
    """Reproduce the paper's scenes, one case each on :mod:`verification.pool`;
    write the figures and the agreement table.  Unless ``allow_large``,
    each reference must fit the machine, and ``workers`` of them at once
    (:func:`check_budgets`)."""
    out = Path(out)
    if not allow_large:
        check_budgets(scenes, ref_h, workers)
    rows, warnings = [], []
    log.info("paper: scenes %s on %s", ", ".join(scenes), pool.workers_label(workers))
    for got, warned in pool.map_cases(functools.partial(reproduce_scene, out=out, ref_h=ref_h), scenes, workers):
        rows += got
        warnings += warned
    files.write_csv(out / "agreement.csv", rows, COLUMNS)
    text = markdown(rows, warnings)
    files.write_text(out / "paper.md", text)
    files.write_json(out / "run.json", {**files.provenance(list(argv)), "scenes": list(scenes), "ref_h": ref_h})
    return text
