"""``python -m verification efficiency``: error against run time.

For one scene: a refined conforming reference (P2, curved cells, at
``--ref-h``), then each method on a ladder of resolutions.  The error of a
run is the worst, over the scene's profiles and quantities, of the relative
RMS difference to the reference (:mod:`verification.agreement`: samples
within ``2·h_ref_exclusion`` of corners and of the ends of Γ left out, a
quantity that is exactly zero measured against its companion).  Writes
``DIR/efficiency.csv``, ``DIR/efficiency.md`` and ``DIR/efficiency.png``
(error against total wall time, log-log, one line per method and degree).
"""
from __future__ import annotations

import logging
from pathlib import Path

from contactcore import load_scene, sample_profiles

from . import files, methods
from .agreement import agreements

log = logging.getLogger("verification")

COLUMNS = ["method", "degree", "h", "dofs", "total", "error", "worst"]


def worst_error(scene, got: dict, ref: dict, exclude: float) -> tuple[float, str]:
    """The largest relative RMS difference over every profile and quantity."""
    pid, q, _, err = max(agreements(scene, got, ref, exclude), key=lambda row: row[3])
    return err, f"{pid}:{q}"


def efficiency(scene_name: str, method_names: list[str], degrees: list[int], hs: list[float], ref_h: float,
               exclude: float, out: Path, argv=()) -> list[dict]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    scene = load_scene(scene_name)
    reference = methods.solver("fe")(scene, ref_h, degree=2, estimate_condition=False)
    ref = {p.id: p for p in sample_profiles(scene, reference.fields)}
    log.info("reference: fe P2 h=%g, %d DOFs, %.1f s", ref_h, reference.dofs, reference.timings.total)
    rows = []
    for name in methods.expand(method_names):
        solve = methods.solver(name)
        for degree in degrees:
            solve(scene, max(hs), degree=degree, estimate_condition=False)  # warm-up (JIT)
            for h in sorted(hs, reverse=True):
                res = solve(scene, h, degree=degree, estimate_condition=False)
                got = {p.id: p for p in sample_profiles(scene, res.fields)}
                err, where = worst_error(scene, got, ref, exclude)
                rows.append({"method": name, "degree": degree, "h": h, "dofs": res.dofs,
                             "total": res.timings.total, "error": err, "worst": where})
                log.info("%s p%d h=%g: %d DOFs, %.2f s, worst error %.2e (%s)", name, degree, h, res.dofs,
                         res.timings.total, err, where)
    out = Path(out)
    files.write_text(out / "efficiency.csv", ",".join(COLUMNS) + "\n"
                     + "".join(",".join(str(r[c]) for c in COLUMNS) + "\n" for r in rows))
    md = [f"# Error against run time, scene {scene.name}", "",
          f"Reference: fe P2, h = {ref_h:g} ({reference.dofs} DOFs). Error: worst relative RMS difference over "
          f"the profiles, samples within {exclude:g} of corners and of the ends of Γ left out.", "",
          "| method | degree | h | DOFs | total (s) | error | worst at |", "|---|---|---|---|---|---|---|"]
    md += [f"| {r['method']} | {r['degree']} | {r['h']:g} | {r['dofs']} | {r['total']:.2f} | {r['error']:.2e} | "
           f"{r['worst']} |" for r in rows]
    files.write_text(out / "efficiency.md", "\n".join(md) + "\n")
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for key in sorted({(r["method"], r["degree"]) for r in rows}):
        pts = [(r["total"], r["error"]) for r in rows if (r["method"], r["degree"]) == key]
        ax.loglog(*zip(*pts), "o-", label=f"{key[0]} (p{key[1]})")
    ax.set_xlabel("total wall time (s)")
    ax.set_ylabel("worst profile error (relative RMS)")
    ax.set_title(f"Scene {scene.name}: error against run time")
    ax.grid(which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    with files.atomic_path(out / "efficiency.png") as tmp:
        fig.savefig(tmp, dpi=110, format="png")
    plt.close(fig)
    files.write_json(out / "run.json", files.provenance(list(argv)))
    return rows
