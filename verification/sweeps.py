"""``python -m verification sweeps``: stiff and extreme cases.

Each sweep varies one input far beyond its usual range on a case whose
answer is known exactly, and records for every method and value the error,
the solver's condition estimate and backward error, and the outcome of
:mod:`verification.outcomes` (accurate, warned, refused — or wrong, which is
a bug).  The sweeps:

Every case is solved at ``h = H`` (0.1) but ``false_tN``, at scene B's own
h (0.05).

* ``kN``, ``kT``: one spring stiffness ``k = α·E/h`` (E the stiffer
  material's modulus, h the method's cell size or node spacing) with α
  from 1e-12 to 1e12 on the inclined interface patch (exact for every
  method and every k) and from 1e-3 to 1e8 on the curved closed forms
  (``kN`` on the pressurised rod, ``kT`` on the twisted rod);
* ``contrast``: ``E⁺/E⁻`` from 1e-12 to 1e12 on the patch and from 1e-4 to
  1e4 on the pressurised rod;
* ``cut``: Γ at ``y = 0.5 + f·h`` with f from 1e-1 down to 1e-10 (cells of
  XFEM and node rows of EFGM cut into slivers), through a row of nodes and
  along edges (f = 0), and diagonally through nodes;
* ``dmax``: EFGM's support dilation from 1.1 to 4, circular and rectangular
  supports, on the patch; ``perturb``: EFGM nodes moved at random by up to
  0.4 h;
* ``false_tN``: scene B's false normal traction (its exact t_N is zero)
  against ``k_N/k_T`` from 1 to 1e4, relative to max |t_T|;
* ``kN_coulomb``, ``kT_coulomb``: the ``kN``/``kT`` sweeps repeated with the
  ``coulomb`` law, on the layered closed form (pressure, stick, slip,
  reversal: 20 Newton-solved increments), error in the final displacement;
  here α is taken with the softer material's E, as the methods' limits on
  Coulomb springs are.

Writes ``DIR/sweeps.csv``, ``DIR/sweeps.md`` (one table per sweep and the
range each method handles) and ``DIR/<sweep>.png``.
"""
from __future__ import annotations

import dataclasses
import functools
import logging
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from contactcore import LineInterface, LinearLaw, Material, load_scene, sample_profile
from contactcore import tolerances as tol
from contactcore.budget import check_together, estimate
from contactcore.geometry import Rectangle
from contactcore.scene import InterfaceProfile

from contactcore.discretisation import Reuse

from . import files, methods, pool
from .closed_forms import interface_patch, layered_slip, pressurised_rod, twisted_rod
from .norms import l2_error, max_errors
from .outcomes import Incomplete, accuracy_bound, attempt, classify, health

log = logging.getLogger("verification")

#: Cell size (node spacing for EFGM) of the sweeps: the patch's pins lie on
#: its nodes, and every solve stays under a second.
H = 0.1
#: The patch's pins, on nodes of every grid of size H (XFEM needs pins at nodes).
PATCH_PINS = ((0.1, 0.1), (0.5, 0.1))
DIAGONAL_PINS = ((0.3, 0.1), (0.7, 0.1))  # below a Γ along the diagonal y = x
#: Spring factors α of k = α·E/h, contrasts E⁺/E⁻, sliver fractions f.
PENALTY_FACTORS = tuple(float(f"1e{k}") for k in range(-3, 9))
CONTRASTS = tuple(float(f"1e{k}") for k in range(-4, 5))
#: The extremes of the solve-health policy on the (cheap, exact) patch: springs 1e-12..1e12
#: E/h and contrasts 1e±12, each accurate, warned or refused with a reason.
EXTREME_PENALTY_FACTORS = (1e-12, 1e-9, 1e-6) + PENALTY_FACTORS + (1e10, 1e12)
EXTREME_CONTRASTS = (1e-12, 1e-8) + CONTRASTS + (1e8, 1e12)
CUT_FRACTIONS = (1e-1, 1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 0.0)
DILATIONS = (1.1, 1.25, 1.5, 2.0, 3.0, 4.0)
PERTURBATIONS = (0.0, 0.1, 0.2, 0.3, 0.4)
STIFFNESS_RATIOS = (1.0, 10.0, 100.0, 1e3, 1e4)


@dataclass
class Case:
    """One point of a sweep: the scene, its exact answer, the method options."""

    value: float | str
    scene: object
    exact: object | None = None
    options: dict = dataclasses.field(default_factory=dict)


@dataclass
class Sweep:
    """A named family of cases, the methods it applies to and its nominal value.

    ``error(case, result)`` measures a result; the nominal case's error sets
    the accuracy bound (:func:`verification.outcomes.accuracy_bound`) unless
    ``bound`` fixes it."""

    name: str
    parameter: str
    what: str
    cases: Callable[[], list[Case]]
    methods: tuple[str, ...] = ("fe", "xfem", "efgm")
    nominal: float | str | None = None
    bound: float | None = None
    logx: bool = True


def displacement_error(case: Case, result) -> float:
    """Relative displacement error against the closed form: the largest at
    random points on a rectangle, the L2 norm on a disc."""
    if isinstance(case.scene.domain, Rectangle):
        return max_errors(case.scene, result.fields, case.exact)[0]
    err, ref = l2_error(case.scene, result.fields, case.exact, h=H / 2)
    return err / ref


def false_normal_traction(case: Case, result) -> float:
    """max |t_N| / max |t_T| on Γ (the exact t_N is zero)."""
    prof = sample_profile(case.scene, result.fields, InterfaceProfile("gamma", ("tN", "tT")), result.interface)
    return float(np.max(np.abs(prof.columns["tN"])) / np.max(np.abs(prof.columns["tT"])))


def _stiffest(scene) -> float:
    return max(m.E for m in scene.materials.values())


def _patch(**kw):
    return interface_patch(30.0, pins=PATCH_PINS, **kw)


def _springs(build, which: str, h: float = H, factors=PENALTY_FACTORS):
    """Cases of ``build`` (a closed form taking kN, kT) with one spring swept."""
    nominal = build()
    law = nominal.scene.law
    cases = []
    for alpha in factors:
        k = alpha * _stiffest(nominal.scene) / h
        c = build(kN=k, kT=law.kT) if which == "kN" else build(kN=law.kN, kT=k)
        cases.append(Case(alpha, c.scene, c))
    return cases


def _friction_springs(which: str):
    """The layered closed form with one spring k = α E₋/h, at its last
    increment: E₋ the softer material's modulus, the α by which a method
    refuses Coulomb springs (:func:`contactcore.health.check_friction_springs`)."""
    cases = []
    for alpha in PENALTY_FACTORS:
        k = alpha * layered_slip().scene.softer_modulus / H
        c = layered_slip(**{which: k})
        cases.append(Case(alpha, c.scene, c.fields(c.history()[-1])))
    return cases


def _contrasts(build, minus: str, plus: str, nu_plus: float, contrasts=CONTRASTS):
    """Cases of ``build`` with the + material's E⁺ = r E⁻ (``minus`` and
    ``plus``: the keyword names of the two materials in ``build``)."""
    out = []
    for r in contrasts:
        c = build(**{minus: Material(2e11, 0.3), plus: Material(2e11 * r, nu_plus)})
        out.append(Case(r, c.scene, c))
    return out


def horizontal_patch(y: float):
    """The patch with a horizontal Γ at height y (pins below it)."""
    p0 = interface_patch(0.0, pins=PATCH_PINS)
    scene = p0.scene.with_changes(interface=LineInterface((0.5, y), (0.0, 1.0)))
    return dataclasses.replace(p0, scene=scene, origin=np.array([0.5, y]))


def _cuts():
    cases = [Case(f, c.scene, c) for f in CUT_FRACTIONS for c in [horizontal_patch(0.5 + f * H)]]
    diagonal = interface_patch(45.0, pins=DIAGONAL_PINS)
    cases.append(Case("diagonal through nodes", diagonal.scene, diagonal))
    return cases


def _dilations(support: str):
    c = _patch()
    return [Case(d, c.scene, c, {"dmax": d, "support": support}) for d in DILATIONS]


def _perturbations():
    from efgm.nodes import perturbed_nodes

    c = _patch()
    return [Case(f, c.scene, c, {"nodes": perturbed_nodes(c.scene, H, f, seed=3)}) for f in PERTURBATIONS]


def _stiffness_ratios():
    scene = load_scene("B")
    return [Case(r, scene.with_changes(law=LinearLaw(r * scene.law.kT, scene.law.kT))) for r in STIFFNESS_RATIOS]


def sweeps() -> list[Sweep]:
    """Every sweep of the study, in report order."""
    return [
        Sweep("kN_patch", "α (k_N = α E/h)", "normal spring, inclined patch (closed form)",
              lambda: _springs(_patch, "kN", factors=EXTREME_PENALTY_FACTORS), nominal=1.0),
        Sweep("kT_patch", "α (k_T = α E/h)", "tangential spring, inclined patch (closed form)",
              lambda: _springs(_patch, "kT", factors=EXTREME_PENALTY_FACTORS), nominal=1.0),
        Sweep("kN_rod", "α (k_N = α E/h)", "normal spring, pressurised rod (curved Γ, closed form)",
              lambda: _springs(pressurised_rod, "kN"), nominal=1.0),
        Sweep("kT_rod", "α (k_T = α E/h)", "tangential spring, twisted rod (curved Γ, closed form)",
              lambda: _springs(twisted_rod, "kT"), nominal=1.0),
        Sweep("contrast_patch", "E⁺/E⁻", "material contrast, inclined patch (closed form)",
              lambda: _contrasts(_patch, "minus", "plus", 0.2, EXTREME_CONTRASTS),
              nominal=1.0),
        Sweep("contrast_rod", "E⁺/E⁻", "material contrast, pressurised rod (closed form)",
              lambda: _contrasts(pressurised_rod, "rod", "matrix", 0.25),
              nominal=1.0),
        Sweep("cut", "f (Γ at y = 0.5 + f h)", "slivers, Γ through nodes and along edges (patch, closed form)",
              _cuts, nominal=0.1, logx=False),
        Sweep("dmax_circular", "dmax", "EFGM support dilation, circular supports (patch)",
              lambda: _dilations("circular"), methods=("efgm",), nominal=2.0),
        Sweep("dmax_rectangular", "dmax", "EFGM support dilation, rectangular supports (patch)",
              lambda: _dilations("rectangular"), methods=("efgm",), nominal=2.0),
        Sweep("perturb", "node perturbation / h", "EFGM nodes moved at random (patch)", _perturbations,
              methods=("efgm",), nominal=0.0, logx=False),
        Sweep("false_tN", "k_N/k_T", "scene B: false t_N / max |t_T| (exact t_N = 0)", _stiffness_ratios,
              bound=tol.FALSE_TN_ACCEPTABLE),
        Sweep("kN_coulomb", "α (k_N = α E₋/h, E₋ the softer)", "normal spring, coulomb law, layered closed form (20 increments)",
              lambda: _friction_springs("kN"), nominal=1.0),
        Sweep("kT_coulomb", "α (k_T = α E₋/h, E₋ the softer)", "tangential spring, coulomb law, layered closed form "
              "(20 increments)", lambda: _friction_springs("kT"), nominal=1.0),
    ]


def run_sweep(sweep: Sweep, degree: int = 1, method_names=None) -> list[dict]:
    """Every case of ``sweep`` with every method: one row per solve."""
    error = false_normal_traction if sweep.name == "false_tN" else displacement_error
    rows = []
    cases = sweep.cases()
    for name in [m for m in sweep.methods if method_names is None or m in method_names]:
        solve, comm = pool.solver(name)
        solve = functools.partial(solve, **comm)
        h = None if sweep.name == "false_tN" else H
        reuse = Reuse()  # a sweep of springs builds each discretisation once
        try:
            tried = [attempt(solve, c.scene, h, degree=degree, estimate_condition=True, reuse=reuse, **c.options)
                     for c in cases]
        finally:
            reuse.close()
        errors = [float("nan") if t.refused else error(c, t.result) for c, t in zip(cases, tried)]
        bound = sweep.bound
        if bound is None:
            nominal = [e for c, e in zip(cases, errors) if c.value == sweep.nominal]
            bound = accuracy_bound(nominal[0] if nominal and np.isfinite(nominal[0]) else 0.0)
        for c, t, e in zip(cases, tried, errors):
            outcome = classify(t, e, bound)
            message = t.message or "; ".join(t.result.solver.warnings)
            rows.append({"sweep": sweep.name, "method": name, "degree": degree, "value": c.value, "error": e,
                         "bound": bound, **health(t), "outcome": outcome, "message": message})
            log.info("%s %s %s: %s, error %.2e (bound %.1e)%s", sweep.name, name, c.value, outcome, e, bound,
                     f" — {message}" if message else "")
    return rows


def handled_range(rows: list[dict]) -> str:
    """The values of one sweep and method, grouped by outcome: each outcome's
    values in runs of neighbours (in the sweep's order, by value when the
    values are numbers) with no other outcome between them, a run of three
    or more numbers as "first … last (n values)", shorter runs value by
    value.  A range never spans another outcome's values: refused values on
    both sides of the accurate ones read "1e-12, 1e+10, 1e+12", not
    "1e-12 … 1e+12"."""
    numeric = all(isinstance(r["value"], float) for r in rows)
    ordered = sorted(rows, key=lambda r: r["value"]) if numeric else list(rows)
    runs: list[tuple[str, list]] = []
    for r in ordered:
        if runs and runs[-1][0] == r["outcome"]:
            runs[-1][1].append(r["value"])
        else:
            runs.append((r["outcome"], [r["value"]]))
    parts = []
    for outcome in ("accurate", "warned", "refused", "wrong"):
        texts = []
        for _, vals in (run for run in runs if run[0] == outcome):
            if numeric and len(vals) > 2:
                texts.append(f"{files.cell(vals[0])} … {files.cell(vals[-1])} ({len(vals)} values)")
            else:
                texts += [files.cell(v) for v in vals]
        if texts:
            parts.append(f"{outcome}: {', '.join(texts)}")
    return "; ".join(parts)


COLUMNS = ["sweep", "method", "degree", "value", "error", "bound", "outcome", "condition", "backward_error",
           "residual", "dofs", "total", "message"]


def _plot(path: Path, sweep: Sweep, rows: list[dict]) -> None:
    from .plots import pyplot, save

    fig, ax = pyplot().subplots(figsize=(6.5, 4.2))
    values = [r["value"] for r in rows]
    numeric = all(isinstance(v, float) for v in values)
    for name in dict.fromkeys(r["method"] for r in rows):
        mine = [r for r in rows if r["method"] == name]
        xs = [r["value"] for r in mine] if numeric else list(range(len(mine)))
        line, = ax.plot(xs, [r["error"] for r in mine], "-", label=name, alpha=0.6)
        for x, r in zip(xs, mine):
            marker = {"accurate": "o", "warned": "s", "refused": "x", "wrong": "*"}[r["outcome"]]
            y = r["error"] if np.isfinite(r["error"]) else r["bound"]
            ax.plot([x], [y], marker, color=line.get_color(), mfc="none" if r["outcome"] == "warned" else None)
    if numeric and sweep.logx and min(values) > 0:
        ax.set_xscale("log")
    if not numeric:
        labels = [files.cell(r["value"]) for r in rows if r["method"] == rows[0]["method"]]
        ax.set_xticks(range(len(labels)), labels, rotation=30, ha="right", fontsize=7)
    ax.set_yscale("log")
    ax.axhline(rows[0]["bound"], color="grey", lw=0.8, ls="--")
    ax.set_xlabel(sweep.parameter)
    ax.set_ylabel("error")
    ax.set_title(f"{sweep.name}: {sweep.what}\n(o accurate, □ warned, x refused, * wrong)", fontsize=9)
    ax.grid(which="both", alpha=0.3)
    ax.legend()
    save(fig, path)


def markdown(rows: list[dict], selected: list[Sweep], measured_by: str = "1 worker") -> str:
    """The sweeps' section: the range each method handles, then the tables;
    it says how many workers measured the times (``measured_by``,
    :func:`verification.pool.workers_label`)."""
    md = ["## Stiff and extreme cases", "",
          "Outcomes: *accurate* (error within the bound), *warned* (answered with a warning), *refused* (a clear "
          f"error), *wrong* (silently beyond the bound: a bug). Bound: {tol.ACCURATE_FACTOR:g}× the method's error "
          f"at the nominal value, at least {tol.ACCURATE_FLOOR:g}; false t_N: {tol.FALSE_TN_ACCEPTABLE:g}. Times "
          f"(`total` in sweeps.csv, s) measured by {measured_by} at once (sweeps beside each other share the "
          "cores).", "",
          "| sweep | method | range handled |", "|---|---|---|"]
    for sw in selected:
        for name in dict.fromkeys(r["method"] for r in rows if r["sweep"] == sw.name):
            mine = [r for r in rows if r["sweep"] == sw.name and r["method"] == name]
            md.append(f"| {sw.name} | {name} | {handled_range(mine)} |")
    for sw in selected:
        mine = [r for r in rows if r["sweep"] == sw.name]
        if not mine:
            continue
        md += ["", f"### {sw.name}: {sw.what}", "", f"![{sw.name}]({sw.name}.png)", "",
               files.markdown_table(mine, ["method", "value", "error", "outcome", "condition", "backward_error",
                                           "dofs", "message"],
                                    ["method", sw.parameter, "error", "outcome", "condition", "backward error",
                                     "DOFs", "message"])]
    return "\n".join(md) + "\n"


def _sweep_by_name(name: str, degree: int, method_names) -> list[dict]:
    """:func:`run_sweep` of the sweep called ``name``: a picklable case of the
    pool (a sweep holds the functions that build its cases)."""
    return run_sweep(next(s for s in sweeps() if s.name == name), degree, method_names)


def memory(sweep: Sweep, degree: int = 1, method_names=None) -> float:
    """The estimated memory in bytes of ``sweep``, one case of the pool:
    its largest solve (:func:`contactcore.budget.estimate`; its solves run
    one after another)."""
    return max((estimate(c.scene, c.scene.h if sweep.name == "false_tN" else H, methods.budgeted(name, degree)).memory
                for c in sweep.cases() for name in sweep.methods if method_names is None or name in method_names),
               default=0.0)


def run_sweeps(out: Path, names=None, method_names=None, degree: int = 1, workers: int | None = None,
               argv=(), strict: bool = False) -> str:
    """Run the sweeps (all, or those named), one case each on
    :mod:`verification.pool`, write the tables and plots, and return the
    Markdown section; ``workers`` sweeps at once must fit this machine
    (:func:`contactcore.budget.check_together`, before any solve).  A
    *refused* or *warned* case is data (the sweeps map
    where each method stops); a *wrong* one is a bug: with ``strict`` (the
    CLI), once everything is written, it raises
    :class:`~verification.outcomes.Incomplete` (exit status 1)."""
    selected = [s for s in sweeps() if names is None or s.name in names]
    check_together([memory(sw, degree, method_names) for sw in selected], workers or 1, offer_allow_large=False)
    rows = []
    runs = pool.map_cases(functools.partial(_sweep_by_name, degree=degree, method_names=method_names),
                          [sw.name for sw in selected], workers)
    for k, (sw, mine) in enumerate(zip(selected, runs), 1):
        log.info("sweep %d/%d: %s (%s): %d solves", k, len(selected), sw.name, sw.what, len(mine))
        if mine:
            _plot(Path(out) / f"{sw.name}.png", sw, mine)
        rows += mine
    files.write_csv(Path(out) / "sweeps.csv", rows, COLUMNS)
    measured_by = pool.workers_label(workers)
    text = markdown(rows, selected, measured_by)
    files.write_text(Path(out) / "sweeps.md", text)
    files.write_json(Path(out) / "run.json", {**files.provenance(list(argv)), "workers": measured_by})
    wrong = sum(r["outcome"] == "wrong" for r in rows)
    if strict and wrong:
        raise Incomplete(f"sweeps: {wrong} of {len(rows)} cases are wrong (beyond the bound with no warning: a "
                         "bug; their rows in sweeps.csv)")
    return text
