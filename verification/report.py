"""``python -m verification report [--quick] --out DIR``: every verification, one file.

Runs, each into its own folder under DIR, the paper's figures
(:mod:`~verification.paper`), the closed forms (:mod:`~verification.convergence`),
error against run time on scenes A, B and C (:mod:`~verification.efficiency`),
the stiff and extreme sweeps (:mod:`~verification.sweeps`, the coulomb law's
among them), the friction scenes with every method (Newton iterations per
increment, status along Γ, :mod:`~verification.run`; C-coulomb's
penalty answer against the exact one, :mod:`~verification.against_exact`) and one parameter
study per scene (:mod:`~verification.study`), then gathers their sections
into ``DIR/report.md`` with the wall time of each part.  ``--quick`` runs
every part on short ladders (a smoke test of the whole chain, minutes not
tens of minutes); its figures are not the report's.  ``--workers K`` runs
each part's independent cases on K processes (:mod:`verification.pool`);
the parts themselves run one after another.
"""
from __future__ import annotations

import functools
import logging
import time
from dataclasses import dataclass
from pathlib import Path

from contactcore import load_scene
from contactcore.budget import check_together

from . import files, methods, pool
from .agreement import default_exclusion
from .convergence import CASES, closed
from .efficiency import LADDERS, REFERENCE_H, VARIANTS, efficiency, ladder_rungs
from .efficiency import check_budgets as efficiency_budgets
from .paper import SCENES, paper
from .paper import check_budgets as paper_budgets
from .run import run
from .study import study
from .study_checks import check_points, check_sizes
from .sweeps import memory, run_sweeps, sweeps

log = logging.getLogger("verification")


@dataclass(frozen=True)
class Plan:
    """What the report runs: ladders, variants, sweeps and studies."""

    ladders: dict
    reference_h: dict
    variants: tuple
    closed_cases: tuple
    closed_variants: tuple
    sweeps: tuple | None  # None: all
    paper_ref_h: float | None
    studies: tuple  # (scene, param, values, degree)
    friction: tuple = ("layered-slip", "A-cyclic", "C-coulomb")  # scenes run with every method
    against_exact: tuple = ("C-coulomb",)  # friction scenes also solved exactly, penalty against exact


FULL = Plan(ladders=LADDERS, reference_h=REFERENCE_H, variants=VARIANTS, closed_cases=tuple(CASES),
            closed_variants=VARIANTS, sweeps=None, paper_ref_h=None,
            studies=(("A", "angle", (-30.0, -15.0, 0.0, 15.0, 30.0), 1),
                     ("B", "radius", (0.15, 0.2, 0.25, 0.3, 0.35, 0.4), 1),
                     ("C", "kN", (1e8, 1e9, 1e10, 1e11, 1e12), 1)))
#: The smallest chain that runs every part once (a smoke test: the parts'
#: own tests check their numbers): one efficiency ladder, one closed form.
QUICK = Plan(ladders={"C": {1: (0.2,)}},
             reference_h={"C": 0.1}, variants=(("fe", 1), ("xfem", 1)),
             closed_cases=("patch",), closed_variants=(("fe", 1), ("xfem", 1), ("efgm", 1)),
             sweeps=("cut",), paper_ref_h=0.1,
             studies=(("B", "radius", (0.2, 0.3), 1),), friction=("layered-slip",), against_exact=("layered-slip",))


def _friction(scene: str, out: Path, against_exact: tuple = ()) -> str:
    """A friction scene with every method, into ``out/<scene>``: status,
    response and the Newton iterations per increment (:mod:`verification.interface`);
    for a scene in ``against_exact``, how far its penalty answer is from
    the exact one (:mod:`verification.against_exact`)."""
    text = run(scene, ["all"], out / scene, against_exact=scene in against_exact)
    return files.relink("#" + text + "\n![response](plots/response.png)\n", scene)


def _frictions(scenes, against_exact, workers):
    """The part that runs the friction scenes, one case each on the pool."""
    return lambda out: "\n\n".join(pool.map_cases(functools.partial(_friction, out=out, against_exact=against_exact),
                                                   scenes, workers))


def check_plan(plan: Plan, workers: int | None) -> None:
    """Before any part runs, what each part checks at its own start: every
    solve of the paper, the efficiency ladders, the sweeps and the studies
    fits this machine, and ``workers`` of a part's cases at once too
    (:func:`contactcore.budget.check_together`), so that a report too
    large is refused before its first part, not after the parts before it."""
    paper_budgets(SCENES, plan.paper_ref_h, workers, offer_allow_large=False)
    for scene in plan.ladders:
        efficiency_budgets(load_scene(scene), ladder_rungs(plan.variants, plan.ladders[scene]), plan.reference_h[scene],
                           False, workers, offer_allow_large=False)
    selected = [s for s in sweeps() if plan.sweeps is None or s.name in plan.sweeps]
    check_together([memory(sw) for sw in selected], workers or 1, offer_allow_large=False)
    for scene, param, values, degree in plan.studies:
        base, points = load_scene(scene), [(v,) for v in values]
        check_together(check_sizes(check_points(base, [param], points), [param], points, methods.expand(["all"]),
                                   degree, None), workers or 1, offer_allow_large=False)


def report(out: Path, quick: bool = False, workers: int | None = None, argv=()) -> Path:
    """Run every part into ``out`` (each part's cases on ``workers``
    processes) and write ``out/report.md``; the whole plan is checked
    against this machine's memory first (:func:`check_plan`)."""
    plan = QUICK if quick else FULL
    check_plan(plan, workers)
    out = Path(out)
    sections, times = [], {}

    def part(name: str, folder: str, run) -> None:
        log.info("report: %s", name)
        start = time.perf_counter()
        sections.append(files.relink(run(out / folder), folder))
        times[name] = time.perf_counter() - start

    part("paper", "paper", lambda d: paper(d, ref_h=plan.paper_ref_h, workers=workers))
    part("closed forms", "closed", lambda d: closed(d, plan.closed_cases, plan.closed_variants))
    for scene in plan.ladders:
        part(f"efficiency {scene}", f"efficiency/{scene}",
             lambda d, s=scene: efficiency(s, plan.variants, plan.ladders[s], plan.reference_h[s],
                                           default_exclusion(load_scene(s)), d, workers=workers))
    part("sweeps", "sweeps", lambda d: run_sweeps(d, plan.sweeps, workers=workers))
    part("friction " + ", ".join(plan.friction), "friction", _frictions(plan.friction, plan.against_exact, workers))
    for scene, param, values, degree in plan.studies:
        folder = f"study/{scene}-{param}"
        part(f"study {scene} {param}", folder,
             lambda d, s=scene, p=param, v=values, k=degree: study(s, [(p, list(v))], ["all"], d, degree=k,
                                                                    workers=workers))
    head = ["# Verification report", "", f"Command: `{files.provenance(list(argv))['command']}`"
            + (" (quick: short ladders, not the report's figures)" if quick else ""), "",
            f"Each part's cases ran on {pool.workers_label(workers)} at once (cases beside each other share the "
            "cores, and their timings with them).", "",
            "| part | wall time (s) |", "|---|---|"]
    head += [f"| {name} | {t:.1f} |" for name, t in times.items()]
    head += [f"| total | {sum(times.values()):.1f} |", ""]
    path = files.write_text(out / "report.md", "\n".join(head) + "\n" + "\n\n".join(sections) + "\n")
    files.write_json(out / "run.json", {**files.provenance(list(argv)), "quick": quick, "times": times,
                                        "workers": pool.workers_label(workers)})
    return path

