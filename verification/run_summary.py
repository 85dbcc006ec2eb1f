"""``run``'s summary.md and the profile plots drawn from the same
agreement table (:func:`verification.run.run`).

Contract: :func:`write_summary` draws every profile (methods overlaid, Δ
against the reference, floored as the agreement table floors it) and the
response along the path, writes ``summary.md`` and returns its text.
Its parts are plain text functions of the runs' summaries and profiles,
with no solve and no file: the opening :func:`conventions` (units and
signs, also ``against``'s outside.md's), :func:`law_line`, the table of
runs with its notes and warnings, :func:`agreement_table` /
:func:`agreement_section`, the agreement within the estimated errors, and
the mark :data:`NOT_ESTIMATED_MARK` of a run not estimated.
"""
from __future__ import annotations

from pathlib import Path

from contactcore import Scene
from contactcore.labels import run_label

from . import against_exact as exact_gap
from . import agreement, files, interface, methods, plots
from .agreement import default_exclusion, within_estimates


def write_summary(out: Path, scene: Scene, summaries: list[dict], profiles: dict, paths: dict, estimated: dict,
                  ref: str | None, draw: bool, gaps: dict, floors: dict | None = None,
                  statuses: dict | None = None) -> str:
    """The plots of every profile (methods overlaid, Δ against ``ref``,
    floored as the agreement is: ``floors``) and of the response, and
    ``summary.md``; returns its text.  ``gaps``: each method's penalty
    against exact (label -> record), if asked."""
    titles, exclude = {p.id: p.title for p in scene.profiles}, default_exclusion(scene)  # the agreement table's
    table = agreement_table(scene, profiles, ref, floors, statuses)
    for pid, runs in profiles.items() if draw else ():
        left_out = ~agreement.kept_samples(scene, runs[plots.reference_of(runs, ref)], exclude)
        plots.plot_profile(out / "plots" / f"{pid}.png", titles[pid], runs, ref, agreement.floors(scene, floors),
                           scene.units, left_out, table.sizes(pid) if table else None)
    compared = agreement_section(table)
    text = (f"# Scene {plots.heading(scene.name, scene.title)}\n\n" + conventions(scene.units, files.ranks())
            + law_line(scene, summaries) + _summary_table(summaries, scene.units.length) + compared)
    if compared and not estimated:
        text += UNESTIMATED_AGREEMENT
    if len(estimated) > 1:
        ref_label = plots.reference_of(next(iter(profiles.values())), ref) if profiles else None
        reference = {pid: runs[ref_label] for pid, runs in profiles.items() if ref_label in runs}
        text += _estimates_section(scene, estimated, floors, (ref_label, reference) if reference else None)
    if gaps:
        text += exact_gap.section(scene, scene.law.name, gaps)
    if paths:
        if draw:
            interface.plot_response(out / "plots" / "response.png", scene, paths)
        text += ("\n## Newton iterations (final relative residual) per increment\n\n"
                 + interface.iterations_table(paths))
    files.write_text(out / "summary.md", text)
    return text


def _summary_table(summaries: list[dict], unit: str) -> str:
    """summary.md's table of the runs: each run's h in the scene's length
    ``unit`` (the discretisation's record; a ``--mesh`` file's largest cell
    diameter, the file named under the table: newuser34 #9, the status
    rows' "1 cell" could not be read in metres)."""
    estimated = any("estimate" in s for s in summaries)
    extra = " estimated error (worst relative RMS, away from singular points) | energy (ZZ, relative) |" if estimated else ""
    lines = [f"| method | degree | h ({unit}) | DOFs | mesh (s) | assembly (s) | solve (s) | total (s) |" + extra
             + " residual | condition |", "|---|---|---|---|---|---|---|---|" + "---|---|" * estimated + "---|---|"]
    for s in summaries:
        t, sv = s["timings"], s["solver"]
        cond = "—" if sv["condition"] is None else f"{sv['condition']:.2e}"
        h = s.get("discretisation", {}).get("h")
        lines.append(f"| {s.get('label', s['method'])} | {s['degree']} | {'—' if h is None else f'{h:.6g}'} | {s['dofs']} | "
                     f"{t['mesh']:.3f} | {t['assembly']:.3f} | "
                     f"{t['solve']:.3f} | {t['total']:.3f} |{_estimate_cells(s) if estimated else ''} "
                     f"{sv['residual']:.1e} | {cond} |")
    footnote = [NOT_ESTIMATED] if estimated and any("estimate" not in s for s in summaries) else []
    footnote += _ladder_note(summaries) if estimated else []
    footnote += _mesh_note(summaries, unit)
    footnote += _methods_note(summaries)
    footnote += _partial_note(summaries)
    warnings = _grouped_warnings(summaries)
    return "\n".join(lines + footnote + ([""] + ["Warnings:"] + warnings if warnings else [])) + "\n"


def _grouped_warnings(summaries: list[dict]) -> list[str]:
    """summary.md's warning lines: each text once, after the runs that
    gave it (``- fe P1, xfem P1: ...``, each run's
    :func:`~contactcore.labels.run_label`, the reference's and an exact
    twin's their rows' ``label``), in the order first given (a scene's own
    warning, the same for every method, is not repeated per method)."""
    runs: dict[str, list[str]] = {}
    for s in summaries:
        run = s.get("label", run_label(s["method"], s["degree"]))
        for w in s["solver"]["warnings"] + s.get("estimate", {}).get("warnings", []):
            if run not in runs.setdefault(w, []):
                runs[w].append(run)
    return [f"- {', '.join(names)}: {w}" for w, names in runs.items()]


def _mesh_note(summaries: list[dict], unit: str) -> list[str]:
    """Under the table, with ``--mesh``: the file each run solved on, its h
    and what that h measures (run.json's ``mesh``)."""
    lines = [f"- {s.get('label', s['method'])}: on the mesh file {m['file']} ({m['cells']} cells; h = {m['h']:.6g} "
             f"{unit}, its {m['h_measure']})" for s in summaries if (m := s.get("discretisation", {}).get("mesh"))]
    return ["", "Mesh:", *lines] if lines else []


def _methods_note(summaries: list[dict]) -> list[str]:
    """Under the table: what each method run is (its options class's
    ``about``; not the reference's row, which its ``label`` names), and
    what the condition column holds."""
    names = list(dict.fromkeys(s["method"] for s in summaries if s["method"] in methods.METHODS and "label" not in s))
    lines = [f"- {n}: {methods.discretisation(n).about}" for n in names if methods.discretisation(n).about]
    return ["", "Methods:", *lines, "- condition: MUMPS's estimate of the tangent's condition number, computed only "
            "where asked (the `sweeps` driver, or `estimate_condition=True` in the Python API; — here)"] if lines else []


def _partial_note(summaries: list[dict]) -> list[str]:
    """Under the table, only where a run's last increment has points of
    the unilateral law's partial answer (contactcore.newton.partial): the
    run's status counts on Γ and each partial point with its θ."""
    lines = []
    for s in summaries:
        if s.get("partial"):
            counts = ", ".join(f"{v} {k}" for k, v in s["status"].items())
            points = "; ".join(f"({p['x']:.4g}, {p['y']:.4g}) θ = {p['theta']:.3g}" for p in s["partial"])
            lines.append(f"- {s['method']}: status on Γ at the last increment {counts}; partial: {points}")
    return ["", "Partial points (y_N = 0 with a share θ of the tie's shear, interface.csv's status `partial`):",
            *lines] if lines else []


def _ladder_note(summaries: list[dict]) -> list[str]:
    """Under an estimated table: the runs' h, which of them the figures
    are, and how each estimate is made."""
    ladder = next(s["estimate"]["h"] for s in summaries if "estimate" in s)
    return [f"\nEstimated from runs at h = {', '.join(f'{h:g}' for h in ladder)}: every figure here is the run at "
            f"{ladder[-1]:g}. A quantity's error is Richardson's at the order in summary.json (a degree-1 stress "
            "between its two orders), the energy's Zienkiewicz–Zhu's (docs/error-estimates.md)."]


#: The mark of a row's estimate cells where its run was not estimated, and
#: the footnote under the table saying why: the only run of an estimate
#: solved at one h is the reference of the comparisons (the penalty runs
#: and their exact twins are solved at every h).
NOT_ESTIMATED_MARK = "†"


NOT_ESTIMATED = (f"\n{NOT_ESTIMATED_MARK} not estimated: the reference the runs are compared with is solved once, "
                 "at the answer's h (the finest), so it has no coarser run to estimate from.")


#: Under an agreement table of runs not estimated: whose error a difference is.
UNESTIMATED_AGREEMENT = ("\nThe reference is solved at the same h and has an error of its own, so a difference above "
                         "is both runs' errors together. `run --estimate` also solves each chosen method at h/2, "
                         "reports that run with its own estimated error, and says where two methods differ by "
                         "more than their estimates (docs/error-estimates.md).\n")


def conventions(units, ranks: int = 1) -> str:
    """``summary.md``'s opening paragraph: the units and sign conventions
    every figure below uses (docs/scenes.md defines them) and, on several
    ranks, that the run was parallel."""
    parallel = (f" Solved on {ranks} MPI ranks (mpirun), whose numbers are the serial run's to round-off."
                if ranks > 1 else "")
    return (f"Lengths, displacements and gaps in {units.length}, stresses and tractions in {units.stress} "
            "(`units.json` names every column's unit). Γ's normal n points from the − body into the + body and "
            "its tangent is t = (n_y, −n_x); g_N = [[u]]·n > 0 is an opening, g_T = [[u]]·t the + body's slip "
            "along t; t_N > 0 is tension (the pressure is −t_N) and t_T has the sign of the slip that causes it; "
            f"stresses are tension positive (docs/scenes.md).{parallel}\n\n")


def law_line(scene: Scene, summaries: list[dict] = ()) -> str:
    """``summary.md``'s line naming Γ's law, its enforcement and its
    parameters as the scene gives them (springs in stress/length, β a
    multiple of the method's γ₀: docs/contact-enforcement.md) and, for an
    exact law that a method solved with ``flux = "reaction"`` (the
    ``summaries``' ``discretisation``), that its answer does not move with β."""
    law = scene.law
    values = ", ".join(f"{p} = {getattr(law, p):g}" for p in law.parameters
                       if isinstance(getattr(law, p, None), (int, float)))
    how = "exactly (Nitsche)" if law.enforcement == "exact" else "by its springs (penalty)"
    reaction = list(dict.fromkeys(s["method"] for s in summaries if law.enforcement == "exact"
                                  and s.get("discretisation", {}).get("flux") == "reaction"))
    flux = (f"; {', '.join(reaction)} with the reaction flux (`--flux reaction`: fe's at Γ's nodes, xfem's and "
            "efgm's at Γ's multiplier nodes), whose answers do not move with β" if reaction else "")
    return f"Γ's law: `{law.name}`, enforced {how}" + (f"; {values}" if values else "") + flux + ".\n\n"


def agreement_table(scene: Scene, profiles: dict, reference: str | None = None, floors: dict | None = None,
                    statuses: dict | None = None):
    """The agreement of every run with the reference of the plots'
    difference panels (``reference``, else fe at its highest degree, else
    the first run): :func:`verification.agreement.table` of ``profiles``
    (id -> label -> ProfileData) with ``floors`` (quantity -> value in its
    unit) and ``statuses`` (label -> Γ's status map,
    :func:`verification.agreement.status_map`), the figures
    :func:`~verification.agreement.compare` gives; None for one run
    (nothing compared)."""
    runs = {}
    for pid, by_label in profiles.items():
        for label, prof in by_label.items():
            runs.setdefault(label, {})[pid] = prof
    if len(runs) < 2:
        return None
    return agreement.table(scene, runs, plots.reference_of(runs, reference), floors=floors, statuses=statuses)


def agreement_section(compared) -> str:
    """``summary.md``'s section of :func:`agreement_table`'s table
    ``compared`` ("" for None)."""
    return "" if compared is None else "\n## Agreement with the reference\n\n" + compared.markdown()


def _estimate_cells(summary: dict) -> str:
    """The estimated-error cells of a method's row: the worst estimated
    relative RMS error and where (``"worst"`` of :func:`~verification.run_files.estimate_record`),
    and the ZZ energy estimate relative to the energy norm; a footnote
    mark where the run was not estimated (:data:`NOT_ESTIMATED`)."""
    est = summary.get("estimate")
    if est is None:
        return f" —{NOT_ESTIMATED_MARK} | —{NOT_ESTIMATED_MARK} |"
    worst = est["worst"]
    energy = est["energy"]["relative"] if est.get("energy") else float("nan")
    return f" {worst['relative']:.2e} ({worst['at'] or '—'}) | {energy:.2e} |"


def _estimates_section(scene, runs: dict, floors: dict | None = None, reference: tuple | None = None) -> str:
    """Per pair of methods, the profile quantities on which they differ by
    more than the sum of their estimated errors (samples near singular
    points left out, a difference below ``floors`` or round-off within any
    estimate: :func:`verification.agreement.within_estimates`), whether
    either estimate is warned (``runs``: label -> (profiles, errors,
    warned ``PID:Q``)), and, given a ``reference`` run ``(label,
    {id: ProfileData})``, each method's distance from it over its own
    estimate (:func:`verification.agreement.beyond_own_estimate`): where
    a pair differs beyond the estimates, a method above 1 there is the
    likelier one whose estimate is too small."""
    names, exclude = list(runs), default_exclusion(scene)
    ref_label, ref = reference if reference else (None, None)
    err_ref = runs[ref_label][1] if ref_label in runs else None  # an estimated reference's own error counts
    own = {n: agreement.beyond_own_estimate(scene, *runs[n][:2], ref, exclude, floors, err_ref)
           for n in names if ref is not None and n != ref_label}
    head = "| methods | profile | quantity | RMS Δ / RMS (e₁ + e₂) | beyond the estimates | estimate warned |"
    against = "its and the reference's estimates" if err_ref is not None else "its estimate"
    lines = [head + (f" each from {ref_label} ÷ {against} |" if own else ""),
             "|---|---|---|---|---|---|" + ("---|" if own else "")]
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            for pid, q, ratio, beyond in within_estimates(scene, *runs[a][:2], *runs[b][:2], exclude, floors):
                warned = ", ".join(n for n in (a, b) if f"{pid}:{q}" in runs[n][2]) or "no"
                row = f"| {a} – {b} | {pid} | {q} | {ratio:.2f} | {'yes' if beyond else 'no'} | {warned} |"
                if own:
                    row += " " + ", ".join(f"{own[n][pid, q]:.2f}" if n in own else "reference" for n in (a, b)) + " |"
                lines.append(row)
    said = ((f" The last column sets each method's distance from {ref_label} against its own estimate and "
             f"{ref_label}'s: where a pair differs beyond its estimates, a method above 1 there, the other not, "
             "is the likelier one whose estimate is too small (or the reference's)." if err_ref is not None else
             f" The last column sets each method's distance from {ref_label} (which has an error of its own) "
             "against its own estimate: where a pair differs beyond its estimates, the method above 1 there is the "
             "likelier one whose estimate is too small.") if own else "")
    return ("\n## Agreement within the estimated errors\n\nWhere two methods differ by more than the sum of "
            "their estimated errors, at least one estimate is too small: that difference is not resolution. "
            "A warned estimate (summary.json's warnings) is an indication only." + said + "\n\n"
            + "\n".join(lines) + "\n")
