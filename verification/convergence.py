"""``python -m verification closed``: the closed forms on refinement ladders.

Three cases with exact solutions (derived in
:mod:`verification.closed_forms` and in docs/verification.md):

* ``patch`` — uniform stress across an inclined straight Γ (30°) between two
  materials, with a normal and a tangential jump: every method of degree ≥ 1
  should reproduce it to round-off (EFGM to its quadrature error);
* ``pressurised_rod`` — a normal jump on a circle (rod in a pressurised
  disc, normal springs);
* ``twisted_rod`` — a tangential jump on a circle (rod twisted inside a
  clamped disc, scene B's load and springs).

Each method and degree runs on the ladder; the error is the relative L2
norm of the displacement error on the exact geometry
(:func:`verification.norms.l2_error`), the rate the least-squares slope of
log error against log h.  Writes ``DIR/closed.csv``, ``DIR/closed.md`` and
``DIR/<case>.png``.
"""
from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

from contactcore import tolerances as tol
from contactcore.labels import run_label

from . import files, pool
from .closed_forms import interface_patch, pressurised_rod, twisted_rod
from .norms import fitted_rate, l2_error
from .outcomes import attempt
from .plots import loglog_by_variant
from .sweeps import PATCH_PINS

log = logging.getLogger("verification")

#: The cases, each with its ladder (the patch's pins lie on nodes of every h).
CASES = {
    "patch": (lambda: interface_patch(30.0, pins=PATCH_PINS), (0.1, 0.05, 0.025)),
    "pressurised_rod": (pressurised_rod, (0.2, 0.1, 0.05, 0.025)),
    "twisted_rod": (twisted_rod, (0.2, 0.1, 0.05, 0.025)),
}
VARIANTS = (("fe", 1), ("fe", 2), ("xfem", 1), ("xfem", 2), ("efgm", 1))


def rate_of(hs, errors) -> float | str:
    """The fitted rate of a complete ladder, "round-off" when every error is
    at round-off, "" when a rung was refused."""
    if len(errors) < len(hs):
        return ""
    return "round-off" if max(errors) <= tol.NEGLIGIBLE_SHARE else fitted_rate(hs, errors)


def last_rate_of(hs, errors) -> float | str:
    """The slope between the two finest rungs, as :func:`rate_of` says
    otherwise: the fitted slope hides a rate that falls toward a floor (EFGM
    on the twisted rod: fitted 3.11, its steps 4.55, 2.70, 2.21)."""
    rate = rate_of(hs, errors)
    if isinstance(rate, str):
        return rate
    return float(np.log(errors[-2] / errors[-1]) / np.log(hs[-2] / hs[-1]))


def run_case(name: str, variants=VARIANTS) -> list[dict]:
    """Every variant on the case's ladder: one row per solve, then the rate."""
    build, hs = CASES[name]
    case = build()
    rows = []
    for method, degree in variants:
        errors, mine = [], []
        solve, on_comm = pool.solver(method)  # this process alone, even as the master of an MPI pool
        for h in hs:
            tried = attempt(solve, case.scene, h, degree=degree, estimate_condition=False, **on_comm)
            if tried.refused:
                log.warning("%s %s h=%g: refused: %s", name, run_label(method, degree), h, tried.message)
                mine.append({"case": name, "method": method, "degree": degree, "h": h, "message": tried.message})
                continue
            err, ref = l2_error(case.scene, tried.result.fields, case, h=h / 2)
            errors.append(err / ref)
            mine.append({"case": name, "method": method, "degree": degree, "h": h, "dofs": tried.result.dofs,
                         "total": tried.result.timings.total, "error": err / ref,
                         "message": "; ".join(tried.result.solver.warnings)})
            log.info("%s %s h=%g: %d DOFs, L2 error %.2e", name, run_label(method, degree), h, tried.result.dofs,
                     err / ref)
        rate, last = rate_of(hs, errors), last_rate_of(hs, errors)
        for row in mine:
            row["rate"], row["last_rate"] = rate, last
        rows += mine
    return rows


COLUMNS = ["case", "method", "degree", "h", "dofs", "total", "error", "rate", "last_rate", "message"]


def markdown(rows: list[dict]) -> str:
    """The closed forms' section: the rates, then every run."""
    md = ["## Closed forms", "", "Relative L2 displacement error on the exact geometry; rate = fitted slope of "
          "log error against log h (expected k + 1 for degree k); last step = the slope between the two finest "
          "h, which shows a rate that falls toward a floor.", "",
          "| case | method | degree | errors (coarse → fine) | rate | last step |", "|---|---|---|---|---|---|"]
    for key in dict.fromkeys((r["case"], r["method"], r["degree"]) for r in rows):
        mine = [r for r in rows if (r["case"], r["method"], r["degree"]) == key]
        errs = ", ".join(files.cell(r["error"]) if "error" in r else "refused" for r in mine)
        md.append(f"| {key[0]} | {key[1]} | {key[2]} | {errs} | {files.cell(mine[0]['rate'])} | "
                  f"{files.cell(mine[0]['last_rate'])} |")
    for name in dict.fromkeys(r["case"] for r in rows):
        md += ["", f"![{name}]({name}.png)"]
    md += ["", files.markdown_table(rows, COLUMNS)]
    return "\n".join(md)


def closed(out: Path, cases=tuple(CASES), variants=VARIANTS, argv=()) -> str:
    """Run the cases, write the tables and plots; return the Markdown section."""
    rows = []
    for name in cases:
        mine = run_case(name, variants)
        loglog_by_variant(Path(out) / f"{name}.png", mine, "h", "error", "h (m)", "relative L2 error of u",
                          f"{name}: error against h")
        rows += mine
    files.write_csv(Path(out) / "closed.csv", rows, COLUMNS)
    text = markdown(rows)
    files.write_text(Path(out) / "closed.md", text)
    files.write_json(Path(out) / "run.json", files.provenance(list(argv)))
    return text
