"""The command table: every command of ``python -m verification``, its
arguments, what it runs and how it meets mpirun's ranks.

Contract: declarative, one :class:`Command` a command in :func:`commands`
(a new command is one entry there and its runner in
:mod:`verification.cli.runners`); the parser is built from it
(:mod:`verification.cli.parser`), and the choices that need a driver's
tables import that driver when the table is built, not when this module is.
"""
from __future__ import annotations

import argparse
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from contactcore.reaction_flux import FLUXES
from xdolfinx.options import XFEM_CELLS

from .. import methods
from ..pool import DEFAULT_WORKERS
from . import runners
from .arguments import floor, folder, number_or_word, petsc_option, reference


@dataclass(frozen=True)
class Arg:
    """One argument of a command: its flags (or name) and argparse's keywords."""

    flags: tuple[str, ...]
    options: dict


def arg(*flags: str, **options) -> Arg:
    """An :class:`Arg`: ``flags`` and ``options`` as ``argparse``'s
    ``add_argument`` takes them, kept for the command table (:func:`commands`)."""
    return Arg(flags, options)


@dataclass(frozen=True)
class Command:
    """One command of the CLI: its help line, its arguments, what it runs
    (``run(args, argv)``), and how it meets mpirun's ranks (``ranks``): it
    spreads its solves over them (``"spread"``), spreads its cases over a
    pool instead (``"pool"``: refused under mpirun), solves them one after
    another in one process (``"serial"``: refused under mpirun), or
    launches mpirun itself (``"launcher"``: refused under mpirun;
    :data:`verification.cli.checks.UNDER_MPIRUN`).  ``epilog`` follows the
    options in ``--help``, line by line (:func:`explained`)."""

    help: str
    args: tuple[Arg, ...]
    run: Callable[[argparse.Namespace, list], None]
    ranks: str = "pool"
    epilog: str = ""  # below the options in --help, as written (the choices explained)


def explained(option: str, choices: dict[str, str]) -> str:
    """``--help``'s list of an option's choices, one line each: the name, then what it is."""
    width = max(map(len, choices))
    return f"{option}:\n" + "\n".join(f"  {name:<{width}}  {what}" for name, what in choices.items())


def commands() -> dict[str, Command]:
    """The command table: every command, its arguments and its runner
    (declarative; the choices that need a driver's tables import it here,
    when the parser is built)."""
    from ..convergence import CASES
    from ..study_parameters import PARAMETERS
    from ..sweeps import sweeps

    method = arg("--method", nargs="+", default=["all"], choices=[*methods.METHODS, "all"],
                 help="the methods to run (default: all)")
    degree = arg("--degree", type=int, default=1, choices=(1, 2), help="polynomial degree (default 1)")
    degrees = arg("--degree", nargs="+", type=int, default=[1], choices=(1, 2), help="polynomial degrees (default 1)")
    ladder = arg("--h", nargs="+", type=float, required=True, help="the resolutions of the ladder, coarse to fine")
    cell = arg("--cell", choices=XFEM_CELLS, help="XFEM background cells (default quad on a rectangle; on a disc "
                                                        "gmsh, the only choice there)")
    scenes = arg("--scene", nargs="+", default=["A", "B", "C"], choices=["A", "B", "C"],
                 help="the paper's scenes (default: A B C)")
    out = arg("--out", type=folder, required=True,
              help="result folder (built aside, put in place only if the run succeeds)")

    workers = arg("--workers", type=int, default=DEFAULT_WORKERS, metavar="K",
                  help=f"run the independent cases on K local processes (default {DEFAULT_WORKERS}: one after "
                       "another in this process); under mpiexec -n K python -m mpi4py.futures, on its K − 1 workers")

    allow_large = arg("--allow-large", action="store_true",
                      help="run even when the estimated memory exceeds what this machine has")

    return {
        "run": Command("solve one scene with one or more methods", (
            arg("scene", help="built-in scene name (A, B, C, ...) or a scene TOML file"), method, degree,
            arg("--h", type=float, help="resolution for every method (default: the scene's h)"),
            arg("--paper", action="store_true", help="use the paper's discretisations"),
            arg("--fields", action="store_true",
                help="also write VTU field files (per body; Γ per step, PVD) for ParaView and meshio"),
            arg("--petsc-option", type=petsc_option, action="append", default=[], metavar="KEY=VALUE",
                help="override a PETSc option of the linear solves of fe and xfem "
                     "(e.g. pc_factor_mat_solver_type=superlu); repeat for several"),
            cell, arg("--dmax", type=float, help="EFGM support dilation (default: by basis degree)"),
            arg("--basis", choices=("linear", "quadratic"),
                help="EFGM's MLS basis (default: linear for --degree 1, quadratic for --degree 2)"),
            arg("--nodes", type=Path, help="EFGM node set: a text file of x y rows (default: a grid)"),
            arg("--mesh", type=Path, metavar="FILE.msh",
                help="fe's mesh from a gmsh file in the scene's units, with the physical groups body_minus, "
                     "body_plus, interface and boundary_NAME of each boundary a support or load acts on, by name "
                     "(as `python -m meshes` writes them): checked against the scene before solving; h is its "
                     "largest cell diameter; with --method fe alone, without --h, --paper or --estimate"),
            arg("--flux", choices=FLUXES,
                help="the Nitsche flux of an exactly enforced law, for fe, xfem and efgm: stress (default, the "
                     "cells' stress at Γ's Gauss points) or reaction (fe: Γ's nodes, each node's reaction; xfem, "
                     "efgm: a multiplier mesh on Γ and the least-squares reaction: the answer does not move with "
                     "β; efgm's on one process only)"),
            arg("--no-plots", dest="draw", action="store_false", help="write no figures"),
            allow_large,
            arg("--estimate", type=int, nargs="?", const=2, choices=(2, 3), metavar="{2,3}",
                help="also solve at h/2 (3: and h/4), write the finest run with its estimated errors"),
            arg("--reference", type=reference, default="fe:2", metavar="METHOD:DEGREE",
                help="the run the Δ panels and summary.md's agreement table compare with, solved at the same "
                     "h if not among the methods (default fe:2; 'none': fe at its highest degree run)"),
            arg("--against-exact", action="store_true",
                help="a unilateral or coulomb law enforced by its springs: also solve each method with the law "
                     "enforced exactly (Nitsche) at the same discretisation, and say in summary.md and each "
                     "summary.json how far the penalty answer is from it"),
            arg("--floor", type=floor, action="append", default=[], metavar="Q=VALUE",
                help="measure quantity Q in the agreement table, the Δ panels and the estimates' verdicts "
                     "against sqrt(Q_ref² + VALUE²), VALUE > 0 in Q's unit in the scene's units (e.g. sxy=1e3 in an "
                     "SI scene's Pa): for a quantity zero in the reference, whose round-off would else be its "
                     "scale; repeat for several"),
            out), runners.run, "spread"),
        "against": Command("an outside code's profiles judged against one method's answer and its estimated error", (
            arg("outside", type=Path, help="the outside answer: a CSV (named ID.csv for profile ID; columns s, or x "
                                           "and y, then quantities as the project's profile CSVs, bare names) or a folder of "
                                           "them; values in the scene's units, signs as docs/scenes.md's"),
            arg("scene", help="built-in scene name or a scene TOML file"),
            arg("--method", default="fe", choices=list(methods.METHODS), help="the project's method (default fe)"),
            arg("--degree", type=int, default=2, choices=(1, 2), help="its degree (default 2)"),
            arg("--h", type=float, help="the coarser run's resolution; the answer compared is at h/2 (default: the "
                                        "scene's h)"),
            arg("--estimate", type=int, default=2, choices=(2, 3), metavar="{2,3}",
                help="the runs the project's error is estimated from: h, h/2 (3: and h/4), as run's --estimate; "
                     "default 2 (Python: levels=)"),
            arg("--exclude", type=float, help="distance from corners and Γ's ends left out (default 0.1 L)"),
            arg("--floor", type=floor, action="append", default=[], metavar="Q=VALUE",
                help="a difference in Q below VALUE (in Q's unit) counts as agreement; repeat for several"),
            cell, arg("--dmax", type=float, help="EFGM support dilation (default: by basis degree)"), out),
            runners.against, ranks="serial"),
        "paper": Command("the paper's figures and an agreement table against a refined reference", (
            scenes, arg("--ref-h", type=float, help="cell size of the P2 reference (default: a quarter of the "
                                                    "scene's h)"), out, workers, allow_large), runners.paper),
        "closed": Command("closed-form cases on refinement ladders, with observed rates", (
            arg("--case", nargs="+", default=list(CASES), choices=list(CASES), help="the cases (default: all)"),
            method, arg("--degree", nargs="+", type=int, default=[1, 2], choices=(1, 2),
                        help="polynomial degrees (default 1 2)"), out), runners.closed, ranks="serial"),
        "efficiency": Command("error against run time, against a refined reference or estimated without one", (
            arg("scene", help="built-in scene name or a scene TOML file"), method, degrees, ladder,
            arg("--ref-h", type=float,
                help="element size of the P2 reference (default: none, the errors are estimated)"),
            arg("--exclude", type=float, help="distance from corners and Γ's ends left out (default 0.1 L)"),
            out, workers, allow_large), runners.efficiency),
        "effectivity": Command("the error estimates against fe P2 at a fine h, on the paper's scenes or others", (
            arg("--scene", nargs="+", default=["A", "B", "C"],
                help="built-in scene names or scene TOML files (default: the paper's A B C)"),
            arg("--h", type=float, help="the coarsest run, in each scene's length unit (default: the domain's "
                                        "smaller side/20, 0.05 on scene A)"),
            arg("--ref-h", type=float, help="cell size of the fe P2 truth (default: the finest run's h/4, 0.00625 "
                                            "on scene A)"),
            arg("--levels", type=int, default=2, choices=(2, 3), help="runs h, h/2 (3: and h/4); default 2"),
            allow_large, out), runners.effectivity, ranks="serial"),
        "sweeps": Command("stiff and extreme cases: error, condition and outcome", (
            arg("--sweep", nargs="+", choices=[s.name for s in sweeps()], metavar="NAME",
                help="the sweeps (default: all; each explained below)"),
            method, degree, out, workers), runners.sweeps,
            epilog=explained("--sweep NAME", {s.name: s.what for s in sweeps()})),
        "study": Command("inputs varied over their product (geometry through gmsh, h, springs, materials)", (
            arg("scene", help="built-in scene name or a scene TOML file"),
            arg("--param", required=True, choices=list(PARAMETERS), action="append", metavar="NAME",
                help="repeat --param NAME --values ... for a Cartesian product (each NAME explained below)"),
            arg("--values", nargs="+", type=number_or_word, required=True, action="append",
                help="the values of the --param just before"),
            method, degree, arg("--h", type=float, help="resolution (default: the scene's h)"), cell,
            arg("--estimate", action="store_true",
                help="also solve every point at 2h and estimate the run at h: study.csv's est_* columns "
                     "(Γ's estimated error, the estimate's warnings, whether the status moved between 2h and h)"),
            out, workers, allow_large), runners.study,
            epilog=explained("--param NAME", {p: what for p, (what, _) in PARAMETERS.items()})),
        "report": Command("every verification, gathered into DIR/report.md", (
            out, arg("--quick", action="store_true", help="short ladders: a smoke test of the whole chain"),
            workers), runners.report),
        "benchmark": Command("error against run time beside GetFEM's level-set XFEM", (
            scenes, out, workers), runners.benchmark),
        "timing": Command("wall time against DOFs on a ladder of resolutions", (
            arg("scene", nargs="+", help="one or more scenes, measured in one run (e.g. C C-coulomb)"),
            method, degrees, ladder, out, allow_large), runners.timing, "spread"),
        "shapes": Command("EFGM's shape functions with gradients: points per second", (
            arg("--basis", nargs="+", default=["linear", "quadratic"], choices=["linear", "quadratic"],
                help="the MLS bases (default: both)"),
            arg("--grid", type=int, default=101, help="nodes per side of the unit square (default 101)"),
            arg("--points", type=int, default=200_000, help="random points evaluated (default 200000)"),
            arg("--repeats", type=int, default=5, help="timed evaluations; the median is reported (default 5)"),
            out, allow_large), runners.shapes, "spread"),
        "scaling": Command("strong scaling: the timing ladder under mpirun on each rank count, one BLAS thread "
                           "per rank", (
            arg("scene", help="built-in scene name or a scene TOML file"), method, degrees, ladder,
            arg("--ranks", nargs="+", type=int, default=[1, 2], help="rank counts (default 1 2)"), out, allow_large),
            runners.scaling, "launcher"),
    }
