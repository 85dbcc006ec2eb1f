"""``python -m verification efficiency``: error against run time.

For one scene: a refined conforming reference (P2, curved cells, at
``--ref-h``), then each method and degree on a ladder of resolutions.  The
error of a run is the worst, over the scene's profiles and quantities, of
the relative RMS difference to the reference (:mod:`verification.agreement`:
samples near the scene's corners and the ends of a straight Γ left out, if
it has any: a disc with a circular Γ has none, each quantity measured
against its vector's or tensor's size: t_T against |t|).  Each run is timed by stage (mesh,
assembly, solve, total) after one warm-up solve per method and degree (the
one-off JIT compilation is not a steady cost); a run under a second is
repeated and its fastest repeat kept (:func:`verification.timing.fastest`).
The reference and the rungs run in this process when their memory
estimates (:mod:`contactcore.budget`), summed as if none were ever returned
to the system, fit in the machine; otherwise each runs in a fresh process,
whose memory goes back to the system when it ends.  The
log says which, and why (:func:`spawn_each`).  The rungs run on
:mod:`verification.pool` (``--workers K``, by default one at a time, or an
mpi4py.futures pool): rungs measured beside each other share the cores and
the memory bandwidth, so the table says how many workers measured it.  Writes
``DIR/efficiency.csv``, ``DIR/efficiency.md`` (the table and a sentence
saying which method reaches a common error level soonest) and
``DIR/efficiency.png`` (error against total wall time, log-log).

Every rung is also solved at h/2 (untimed) for the Richardson estimate of
its error (:mod:`contactcore.estimate`, the coarser run's error, samples
near singular points left out as for the true error).  Without a
reference (``ref_h`` None) the estimate is the error, drawn with an error
bar of :data:`~contactcore.tolerances.ESTIMATE_TRUST` either way, and the
table says so; with one, the table shows both and the effectivity of
the quantity whose true error is the worst ("worst at"): its own
estimate ÷ its own true error, both relative RMS, never one quantity's
estimate over another's true error (the estimate's worst, "estimate
worst at", may be another quantity).
"""
from __future__ import annotations

import functools
import logging
from pathlib import Path

from contactcore import estimate as estimates
from contactcore import SceneError, load_scene, sample_profiles, scene_text
from contactcore import tolerances as tol
from contactcore.budget import MEMORY_SHARE, check_budget, check_together, estimate, machine_memory
from contactcore.scaling import Sizes
from contactcore.scene import Units, check_resolution

from . import files, methods, pool
from .agreement import agreements, check_exclusion, first_largest, label, worst_estimate
from .effectivity import at_roundoff
from .plots import loglog_by_variant
from .study_checks import check_given_once
from .timing import REPEAT_BELOW, REPEATS, fastest

log = logging.getLogger("verification")

COLUMNS = ["method", "degree", "h", "dofs", "mesh", "assembly", "solve", "total", "error", "worst"]
#: With a reference, beside the true error.
ESTIMATE_COLUMNS = ["estimate", "estimate_worst", "effectivity"]

#: Default ladders of the report, by degree: the finest h gives every
#: method at least 1e5 unknowns (P1: about 2/h² per unit area, P2 four times
#: that), and the reference is P2 at half the finest P2 size at least
#: (about 1e6 unknowns).
LADDERS = {"A": {1: (0.1, 0.05, 0.025, 0.0125, 0.00625, 0.004), 2: (0.1, 0.05, 0.025, 0.0125, 0.00625)},
           "B": {1: (0.1, 0.05, 0.025, 0.0125, 0.008), 2: (0.1, 0.05, 0.025, 0.0125)},
           "C": {1: (0.1, 0.05, 0.025, 0.0125, 0.008), 2: (0.1, 0.05, 0.025, 0.0125)}}
REFERENCE_H = {"A": 0.003125, "B": 0.00625, "C": 0.00625}
#: (method, degree) pairs of the report.
VARIANTS = (("fe", 1), ("fe", 2), ("xfem", 1), ("xfem", 2), ("efgm", 1))

#: The benchmark against the peer (``python -m verification benchmark``):
#: our XFEM of both degrees, both EFGM bases, the conforming P2 reference
#: itself, and GetFEM's level-set XFEM of both degrees.
BENCHMARK_VARIANTS = (("fe", 2), ("xfem", 1), ("xfem", 2), ("efgm", 1), ("efgm", 2), ("getfem", 1), ("getfem", 2))

#: Quadratic EFGM stops one or two rungs short of the others: its cost grows
#: fast (measured 175 s for 4.3e4 unknowns on the pressurised rod's disc).
BENCHMARK_LADDERS = {s: {**lad, ("efgm", 2): lad[2][:3]} for s, lad in LADDERS.items()}


def worst_error(scene, got: dict, ref: dict, exclude: float) -> tuple[float, str]:
    """The largest relative RMS difference over every profile and quantity
    (the first of those within :data:`~verification.agreement.WORST_TIE`)."""
    pid, q, _, err = first_largest(agreements(scene, got, ref, exclude), key=lambda row: row[3])
    return err, f"{pid}:{q}"


#: The errors a user asks the advisor about (worst relative RMS profile error).
ADVISOR_TARGETS = (1e-2, 1e-3, 1e-4)


def advisor(rows: list[dict], targets=ADVISOR_TARGETS, units: Units = Units()) -> str:
    """A Markdown table: for each target error, the measured rung (method,
    degree, h in the scene's ``units``) that reached it in the least wall
    time, or that none did."""
    lines = [f"| target error | method | degree | {files.labelled('h', 'h', units)} | DOFs | total (s) | error |",
             "|---|---|---|---|---|---|---|"]
    for target in targets:
        hits = [r for r in rows if r["error"] <= target]
        if not hits:
            lines.append(f"| {target:.0e} | not reached on these ladders | | | | | |")
            continue
        r = min(hits, key=lambda row: row["total"])
        lines.append(f"| {target:.0e} | {r['method']} | {r['degree']} | {r['h']:g} | {r['dofs']} | "
                     f"{r['total']:.3g} | {r['error']:.2e} |")
    return "\n".join(lines) + "\n"


def soonest(rows: list[dict]) -> str:
    """Which variant reaches, first in wall time, the smallest error that
    every variant reaches on its ladder."""
    keys = list(dict.fromkeys((r["method"], r["degree"]) for r in rows))
    best = {k: min(r["error"] for r in rows if (r["method"], r["degree"]) == k) for k in keys}
    target = max(best.values())
    times = {k: min(r["total"] for r in rows if (r["method"], r["degree"]) == k and r["error"] <= target)
             for k in keys}
    order = sorted(keys, key=times.get)
    first, *rest = order
    others = ", ".join(f"{label(m, d)} {times[(m, d)]:.2f} s" for m, d in rest)
    return (f"At a worst-profile error of {target:.2e} (the best that every method reaches here), "
            f"{label(*first)} gets there soonest, in {times[first]:.2f} s"
            + (f"; then {others}." if rest else "."))


def _reference(scene_name: str, ref_h: float) -> tuple[dict, int, float]:
    """The reference's profiles, DOFs and run time."""
    scene = load_scene(scene_name)
    solve, comm = pool.solver("fe")
    reference = solve(scene, ref_h, degree=2, estimate_condition=False, **comm)
    return {p.id: p for p in sample_profiles(scene, reference.fields, reference.interface)}, reference.dofs, reference.timings.total


def check_budgets(scene, rungs, ref_h: float | None, estimated: bool, workers: int | None = None,
                  offer_allow_large: bool = True) -> None:
    """Refuse, before any solve, a rung (at its h, and at h/2 where
    ``estimated``) or the reference that alone would not fit this machine
    (:func:`contactcore.budget.check_budget`), or ``workers`` rungs at once
    that together would not (:func:`contactcore.budget.check_together`: a
    rung holds its run and, ``estimated``, the run at h/2; the reference
    runs alone, before them); :func:`spawn_each` then decides whether the
    ones that fit share a process.  The messages offer ``--allow-large``
    if ``offer_allow_large`` (``benchmark`` and ``report`` have none)."""
    if ref_h is not None:
        check_budget(scene, ref_h, methods.budgeted("fe", 2), "--ref-h", offer_allow_large)
    memories = []
    for name, degree, h, _ in rungs:
        memories.append(sum(check_budget(scene, at, methods.budgeted(name, degree), offer_allow_large=offer_allow_large).memory
                            for at in ((h, h / 2) if estimated else (h,))))
    check_together(memories, workers or 1, offer_allow_large=offer_allow_large)


def spawn_each(scene, rungs, ref_h: float | None, estimated: bool = False) -> bool:
    """Whether the reference and the rungs need a fresh process each: only
    when all of them together (with ``estimated``, each rung's run at
    h/2 too) (their memory estimates summed, as if none
    were ever returned to the system) would not fit in
    :data:`~contactcore.budget.MEMORY_SHARE` of this machine's memory.  The
    log says which, and why."""
    needed = ((estimate(scene, ref_h, methods.budgeted("fe", 2)).memory if ref_h else 0.0)
              + sum(estimate(scene, h, methods.budgeted(name, degree)).memory for name, degree, h, _ in rungs)
              + sum(estimate(scene, h / 2, methods.budgeted(name, degree)).memory for name, degree, h, _ in rungs if estimated))
    have = MEMORY_SHARE * machine_memory()
    if needed > have:
        log.info("efficiency: each run in a fresh process: together they may need %.3g GB, more than the %.3g GB "
                 "usable here", needed / 1e9, have / 1e9)
        return True
    log.info("efficiency: the runs in this process (together at most %.3g GB of the %.3g GB usable here)",
             needed / 1e9, have / 1e9)
    return False


def ladder_rungs(variants, ladders: dict) -> list[tuple]:
    """``(method, degree, h, warm_h)`` of every rung, each ladder coarse to fine."""
    rungs = []
    for name, degree in variants:
        hs = ladders.get((name, degree), ladders.get(degree))
        rungs += [(name, degree, h, max(hs)) for h in sorted(hs, reverse=True)]
    return rungs


def efficiency(scene_name: str, variants, ladders: dict, ref_h: float | None, exclude: float, out: Path,
               workers: int | None = None, estimated: bool = False, allow_large: bool = False, argv=(),
               offer_allow_large: bool = True) -> str:
    """Run the ladders (``ladders[(method, degree)]`` if given, else
    ``ladders[degree]``: the h of that variant) on ``workers``
    processes, write the table and the plot; return the Markdown section.
    ``estimated``: each rung's error also estimated (module doc); without
    ``ref_h`` it must be.  Unless ``allow_large``, every solve must fit
    the machine, and ``workers`` rungs at once too (:func:`check_budgets`;
    its messages offer ``--allow-large`` if ``offer_allow_large``)."""
    scene = load_scene(scene_name)
    check_given_once("--method, --degree", [label(*v) for v in variants])
    for hs in ladders.values():
        check_given_once("--h", hs)
        for h in hs:
            check_resolution(scene, h, "--h")
    rungs, rows = ladder_rungs(variants, ladders), []
    finest = min(h for _, _, h, _ in rungs)
    if ref_h is not None and ref_h > finest:
        raise SceneError("--ref-h", f"{ref_h:g} is coarser than the ladder's finest h, {finest:g}: the "
                         "reference stands for the exact answer, so it must be at least as fine as every rung")
    check_exclusion(scene, exclude, "--exclude")
    if not allow_large:
        check_budgets(scene, rungs, ref_h, estimated or ref_h is None, workers, offer_allow_large)
    fresh = spawn_each(scene, rungs, ref_h, estimated)
    ref = ref_dofs = None
    if ref_h is not None:
        [(ref, ref_dofs, ref_time)] = pool.map_cases(functools.partial(_reference, scene_name), [ref_h],
                                                     fresh=fresh)
        log.info("reference: fe P2 h=%g, %d DOFs, %.1f s", ref_h, ref_dofs, ref_time)
    measure = functools.partial(_measure, scene_name, ref=ref, exclude=exclude, estimated=estimated or ref is None)
    for k, row in enumerate(pool.map_cases(measure, rungs, workers, fresh=fresh), 1):
        log.info("[%d/%d] %s h=%g: %d DOFs, %.2f s, worst error %.2e (%s)%s", k, len(rungs),
                 label(row["method"], row["degree"]), row["h"], row["dofs"], row["total"], row["error"], row["worst"],
                 f", estimated {row['estimate']:.2e}" if "estimate" in row and ref is not None else "")
        rows.append(row)
    measured_by = pool.workers_label(workers)
    out = Path(out)
    columns = COLUMNS + (ESTIMATE_COLUMNS if ref is not None and "estimate" in rows[0] else [])
    files.write_csv(out / "efficiency.csv", rows, columns + (["error_low", "error_high"] if ref is None else [])
                    + (["warned"] if "warned" in rows[0] else []))
    loglog_by_variant(out / "efficiency.png", rows, "total", "error", "total wall time (s)",
                      "worst profile error (relative RMS)" + (", estimated" if ref is None else ""),
                      f"Scene {scene.name}: error against run time",
                      bars=("error_low", "error_high") if ref is None else None)
    headers = ["method", "degree", files.labelled("h", "h", scene.units), "DOFs", "mesh", "assembly", "solve",
               "total", "error" if ref is not None else "estimated error", "worst at"]
    text = (f"## Error against run time, scene {scene.name}\n\n"
            + _error_sentence(ref_h, ref_dofs, exclude, scene.units.length,
                              tuple(name for name, _ in estimates.singular_regions(scene)))
            + f" Times in s, after a warm-up solve; a run under {REPEAT_BELOW:g} s is the fastest of {REPEATS}; "
            f"measured by {measured_by} at once (rungs beside each other share the cores).\n\n"
            f"{soonest(rows)}\n\nWhich method to pick for a target error (the fastest measured rung that "
            f"reaches it):\n\n{advisor(rows, units=scene.units)}\n![efficiency {scene.name}](efficiency.png)\n\n"
            + files.markdown_table(rows, columns, headers + ["estimate", "estimate worst at", "effectivity at worst at"]
                                   [:len(columns) - len(COLUMNS)]) + _warnings_section(rows))
    files.write_text(out / "efficiency.md", text)
    files.write_text(out / files.SCENE_FILE, scene_text(scene_name))  # the units of efficiency.csv's columns
    files.write_json(out / "run.json", {**files.provenance(list(argv)), "workers": measured_by})
    return text


def _warnings_section(rows: list[dict]) -> str:
    """Under the table: each rung's estimate warnings (as `run --estimate`
    gives them; docs/error-estimates.md, "The warnings"), which say where
    its estimated error is not to be trusted."""
    lines = [f"- {label(r['method'], r['degree'])} h = {r['h']:g}: {w}" for r in rows for w in r.get("estimate_warnings", ())]
    return ("\n\nWarnings of the estimates (the rung's estimate is not to be trusted as it stands; "
            "docs/error-estimates.md, \"The warnings\"):\n\n" + "\n".join(lines) + "\n") if lines else ""


def _error_sentence(ref_h: float | None, ref_dofs: int | None, exclude: float, length: str = "m",
                    regions: tuple[str, ...] = ("corners", "ends of Γ")) -> str:
    """How the table's error was measured, its lengths in the scene's unit
    named ``length``; ``regions``, the names of the scene's singular points
    (:func:`contactcore.estimate.singular_regions`: none on a disc with a
    circular Γ, whose samples are all kept)."""
    if not regions or exclude <= 0:
        where = "no sample was left out (the scene has no singular point)." if not regions else \
            "no sample was left out."
    else:
        named = [name if name == "corners" else f"the {name}" for name in regions]
        where = f"samples within {exclude:.3g} {length} of {' and of '.join(named)} left out."
    if ref_h is None:
        return (f"No reference: the error is ESTIMATED (Richardson, each rung against a run at h/2 at the "
                f"method's theoretical order, contactcore.estimate), the worst relative RMS over the profiles, "
                f"{where} Error bars: a factor {tol.ESTIMATE_TRUST:g} either way, the range the estimate holds "
                f"on the closed forms.")
    return (f"Reference: fe P2, h = {ref_h:g} {length} ({ref_dofs} DOFs). Error: worst relative RMS difference "
            f"over the profiles, {where} Estimate: the same measure of the Richardson estimate (each rung against a run "
            f"at h/2); effectivity at worst at = the estimate of the quantity in \"worst at\" ÷ its true error "
            f"(the same quantity; the estimate's own worst may be another), both RMS over the samples its estimate "
            f"keeps (beyond the coarse run's reach of singular points too).")


def _estimated(scene, solve, res, h: float, degree: int, exclude: float) -> dict:
    """The rung's estimated error (the worst, relative) from an untimed run
    at h/2, with its error bar."""
    half = solve(scene, h / 2, degree=degree, estimate_condition=False)
    got = {p.id: p for p in sample_profiles(scene, res.fields, res.interface)}
    est = estimates.estimate_runs(scene, [res, half], exclude, energy=False, coarse=True)
    value, where = worst_estimate(scene, got, est)
    kept = {f"{pid}:{q}": (e.error[est.kept[pid][q]], est.kept[pid][q]) for pid, qs in est.profiles.items()
            for q, e in qs.items()}
    return {"estimate": value, "estimate_worst": where, "error_low": value / tol.ESTIMATE_TRUST,
            "error_high": value * tol.ESTIMATE_TRUST, "estimates": kept, "estimate_warnings": list(est.warnings),
            "warned": len(est.warnings)}


def _measure(scene_name: str, rung: tuple, ref: dict | None, exclude: float, estimated: bool = True) -> dict:
    """One rung ``(method, degree, h, warm_h)`` of a ladder, after a warm-up
    solve at ``warm_h`` (JIT, imports): solve, sample, compare with the
    reference, and (``estimated``) estimate; without a reference the
    estimate is the error."""
    name, degree, h, warm_h = rung
    scene = load_scene(scene_name)
    solve, comm = pool.solver(name)
    solve = functools.partial(solve, **comm)
    solve(scene, warm_h, degree=degree, estimate_condition=False)
    res = fastest(solve, scene, h, degree)
    t = res.timings
    row = {"method": name, "degree": degree, "h": h, "dofs": res.dofs, "mesh": t.mesh, "assembly": t.assembly,
           "solve": t.solve, "total": t.total}
    shares = {}
    if estimated:
        row.update(_estimated(scene, solve, res, h, degree, exclude))
        shares = row.pop("estimates")
    if ref is None:
        return {**row, "error": row["estimate"], "worst": row["estimate_worst"]}
    got = {p.id: p for p in sample_profiles(scene, res.fields, res.interface)}
    row["error"], row["worst"] = worst_error(scene, got, ref, exclude)
    if estimated:
        row["effectivity"] = effectivity_at(shares, row["worst"], got, ref, Sizes.of(scene))
    return row


#: The effectivity column's entry where the true error is round-off
#: (:func:`effectivity_at`).
ROUNDOFF = "round-off"


def effectivity_at(kept: dict[str, tuple], where: str, got: dict, ref: dict,
                   sizes: Sizes | None = None) -> float | str:
    """The effectivity of the quantity ``where`` (``"PID:Q"``, the worst
    true error's): ``rms(e_k) / rms(q_k − q_ref,k)`` over the samples ``k``
    its estimate is summarised over (``kept[where]`` = (``e_k``, the
    mask): ``Estimate.kept``, away from the singular points and beyond the
    coarse run's reach of them), the true error ``got`` − ``ref`` on those
    same samples, as ``verification.effectivity`` measures it (the scale
    of both cancels); NaN where the quantity has no estimate there;
    :data:`ROUNDOFF` where its true error is round-off
    (:func:`verification.effectivity.at_roundoff`, against ``ref``'s
    largest value there and the scene's ``sizes``), as the effectivity
    tool leaves such rows out: a method exact on the scene (fe and xfem P2
    on a layered block whose answer is piecewise quadratic) meets a
    reference exact too, and the ratio is round-off over round-off
    (grader34: 1.0e-5 and 0.44 beside real effectivities).  Never the estimate's worst, which may be another quantity's
    (grader21: scene A fe P1 at h = 0.05, A4:sxx's estimate 0.105 over
    A1:sxy's error 0.148 printed 0.711 where A1:sxy's own effectivity was
    0.555); never the estimate over one set of samples divided by the
    error over another (the kept samples of 2026-11-29 leave out the
    coarse run's reach, which the scene's exclusion does not)."""
    if where not in kept:
        return float("nan")
    error, keep = kept[where]
    pid, q = where.split(":")
    want = ref[pid].columns[q][keep]
    true = estimates.rms(got[pid].columns[q][keep] - want)
    return ROUNDOFF if at_roundoff(true, want, q, sizes) else estimates.rms(error) / true