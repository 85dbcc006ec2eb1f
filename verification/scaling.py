"""``python -m verification scaling``: strong scaling of one solve over
mpirun's ranks.

For each rank count K in turn, ``mpirun -n K python -m verification timing
...`` runs the same ladder (its warm-up at the coarsest h, then each h),
every rank with one BLAS thread (``OPENBLAS_NUM_THREADS`` and
``OMP_NUM_THREADS`` = 1), so that K ranks use K cores and one rank one core:
speed-ups then compare like with like (a lone process would otherwise
thread MUMPS's dense kernels over every core).  Each run's ``timing.csv`` is
read back, and ``DIR/scaling.csv`` and ``DIR/scaling.md`` give mesh,
assembly, solve and total time per rank count, with each stage's speed-up
over the fewest ranks; ``DIR/ranks_K/`` keeps each run's own files.  The
timings are rank 0's: every stage ends in a collective, so its wall time is
the slowest rank's to within that collective.  One job at a time: this is
the benchmark's harness, not a scheduler.
"""
from __future__ import annotations

import csv
import logging
import os
import shutil
import subprocess
import sys
from pathlib import Path

from contactcore import ContactError, load_scene
from contactcore.budget import check_spread
from contactcore.labels import run_label

from . import files
from .timing import COLUMNS as TIMING_COLUMNS
from .timing import check_budgets

log = logging.getLogger("verification")

#: The stages whose speed-up is reported.
STAGES = ("mesh", "assembly", "solve", "total")

#: One thread per rank for the BLAS under MUMPS (module doc).
ONE_THREAD = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}

COLUMNS = ["ranks", "scene", "method", "degree", "h", "dofs", *STAGES, *(f"speedup_{s}" for s in STAGES)]


def launcher(ranks: int) -> list[str]:
    """``mpirun -n ranks`` with one BLAS thread per rank; as root Open MPI
    needs ``--allow-run-as-root``, beyond this machine's cores
    ``--oversubscribe``."""
    mpirun = shutil.which("mpirun") or shutil.which("mpiexec")
    if mpirun is None:
        raise ContactError("scaling: no mpirun on the PATH (Open MPI comes with python3-dolfinx)")
    command = [mpirun] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    command += ["--oversubscribe"] if ranks > (os.cpu_count() or 1) else []
    for key, value in ONE_THREAD.items():
        command += ["-x", f"{key}={value}"]
    return command + ["-n", str(ranks)]


def _timing_run(ranks: int, scene: str, method_names, degrees, hs, folder: Path) -> list[dict]:
    """The ``timing`` ladder on ``ranks`` ranks, its rows read back."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "PMI_"))}
    env.update(ONE_THREAD)
    command = launcher(ranks) + [sys.executable, "-m", "verification", "timing", scene, "--method", *method_names,
                                 "--degree", *map(str, degrees), "--h", *map(repr, hs), "--out", str(folder),
                                 "--quiet", "--allow-large"]  # checked before the launch (scaling)
    log.info("scaling: %s", " ".join(command))
    done = subprocess.run(command, capture_output=True, text=True, env=env, stdin=subprocess.DEVNULL)
    if done.returncode != 0:
        said = [line for line in done.stderr.splitlines() if line.startswith("error:")] or done.stderr.splitlines()[-1:]
        raise ContactError(f"scaling: the run on {ranks} rank(s) failed (exit {done.returncode}): "
                           + (said[0].removeprefix("error: ") if said else "no message"))
    with open(folder / "timing.csv") as f:
        return [{k: _number(row[k]) for k in TIMING_COLUMNS} for row in csv.DictReader(f)]


def _number(text: str):
    """A CSV cell as the int or float it holds, else the text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def speedups(rows: list[dict]) -> list[dict]:
    """``rows`` with each stage's speed-up over the same case on the fewest ranks."""
    fewest = min(r["ranks"] for r in rows)
    key = lambda r: (r["scene"], r["method"], r["degree"], r["h"])  # noqa: E731
    base = {key(r): r for r in rows if r["ranks"] == fewest}
    out = []
    for r in rows:
        b = base[key(r)]
        out.append({**r, **{f"speedup_{s}": b[s] / r[s] if r[s] > 0 else float("nan") for s in STAGES}})
    return out


def scaling(scene: str, method_names, degrees, hs, ranks, out: Path, argv=(), allow_large: bool = False) -> list[dict]:
    """The ladder on each rank count of ``ranks`` (module doc).  Unless
    ``allow_large``, every rung must fit the machine, checked here before
    any launch (:func:`verification.timing.check_budgets`), with the most
    ranks' own memory beside it (:func:`contactcore.budget.check_spread`)."""
    out = Path(out)
    loaded = load_scene(scene)
    rows, units = [], loaded.units  # scaling.csv's h, in units.json (read before any run)
    if not allow_large:
        check_spread(check_budgets([loaded], method_names, degrees, hs), max(ranks, default=1))
    for k in ranks:
        rows += [{"ranks": k, **row} for row in _timing_run(k, scene, method_names, degrees, hs, out / f"ranks_{k}")]
    rows = speedups(rows)
    for r in rows:
        log.info("%s ranks, %s h=%s: %s DOFs, mesh %.2f s, assembly %.2f s, solve %.2f s, total %.2f s "
                 "(speed-up: assembly %.2f, solve %.2f, total %.2f)", r["ranks"], run_label(r["method"], r["degree"]),
                 r["h"],
                 r["dofs"], *(r[s] for s in STAGES), r["speedup_assembly"], r["speedup_solve"],
                 r["speedup_total"])
    files.write_csv(out / "scaling.csv", rows, COLUMNS)
    files.write_text(out / "scaling.md", "# Strong scaling over mpirun's ranks (one BLAS thread per rank)\n\n"
                     + files.markdown_table(rows, COLUMNS, ["ranks", "scene", "method", "degree", "h", "DOFs",
                                                            "mesh (s)", "assembly (s)", "solve (s)", "total (s)",
                                                            "speed-up mesh", "speed-up assembly", "speed-up solve",
                                                            "speed-up total"]))
    files.write_json(out / "run.json", {**files.provenance(list(argv)), **files.run_units(units)})
    return rows
