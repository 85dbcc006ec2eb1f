"""Command line of the verification drivers.

    python -m verification run SCENE_OR_TOML --method fe|xfem|efgm|all [--degree 1|2] [--cell quad|triangle|gmsh]
        [--h H] [--paper] [--fields] [--petsc-option KEY=VALUE ...] [--dmax D] [--basis linear|quadratic]
        [--nodes FILE] [--estimate [2|3]] [--reference METHOD:DEGREE] [--against-exact] [--floor Q=VALUE ...]
        --out DIR
    python -m verification paper [--scene A B C] [--ref-h H] --out DIR
    python -m verification closed [--case patch pressurised_rod twisted_rod] [--method ...] [--degree 1 2] --out DIR
    python -m verification efficiency SCENE --method fe efgm --degree 1 2 --h H1 H2 ... --ref-h H --out DIR
    python -m verification effectivity [--scene A B C | SCENE_OR_TOML ...] [--h H] [--ref-h H] [--levels 2|3] --out DIR
    python -m verification sweeps [--sweep NAME ...] [--method ...] [--degree 1] --out DIR
    python -m verification study SCENE --param NAME --values V1 V2 ... [--param NAME2 --values ...] [--method ...]
        [--degree 1] [--h H] --out DIR
    python -m verification report [--quick] --out DIR
    python -m verification benchmark [--scene A B C] --out DIR      (needs python3-getfem)
    python -m verification timing SCENE [SCENE ...] --method fe --degree 1 2 --h H1 H2 ... --out DIR
    python -m verification shapes [--basis linear quadratic] [--grid 101] [--points 200000] [--repeats 5] --out DIR
    python -m verification scaling SCENE --method xfem --degree 2 --h H ... --ranks 1 2 --out DIR   (launches mpirun)

``study``, ``sweeps``, ``efficiency``, ``paper``, ``benchmark`` and ``report`` take
``--workers K`` (their cases on K local processes, :mod:`verification.pool`;
by default :data:`~verification.pool.DEFAULT_WORKERS`, one after another in
this process), or run under ``mpiexec -n K python -m mpi4py.futures -m verification ...``.

Bad input ends with one line ``error: <field>: <problem>`` and exit status 2;
Ctrl-C with one line ``interrupted`` and exit status 130 (128 + SIGINT),
SIGTERM with ``terminated`` and 143; under mpirun either with
``interrupted`` and mpirun's own status (:func:`_handlers`).  Under mpirun
rank 0 alone writes the results; the other ranks compute alongside it.
"""
from __future__ import annotations

import os
import signal
import sys


from . import STARTING, hold_signals_while_starting, interrupted_while_starting

#: Ctrl-C's start-up handler (:func:`verification.interrupted_while_starting`),
#: installed by the package under ``python -m verification`` before this
#: module was compiled; here where the package could not tell (run by
#: ``python -m mpi4py.futures -m verification``).
if __name__ == "__main__":
    hold_signals_while_starting()

import argparse
import logging
import math
import threading
from contextlib import ExitStack, contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from contactcore import ContactError, load_scene

from xdolfinx.options import XFEM_CELLS

from . import files, janitor, methods, petsc_env
from .pool import DEFAULT_WORKERS, LOG_FORMAT

log = logging.getLogger("verification")


def _folder(text: str) -> Path:
    """A result folder's path: an empty one names no folder (Path("") is
    the current folder)."""
    if not text.strip():
        raise argparse.ArgumentTypeError("must name a folder (got an empty path)")
    return Path(text)


def _petsc_option(text: str) -> tuple[str, str]:
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    return key.lstrip("-"), value


def _floor(text: str) -> tuple[str, float]:
    """``--floor Q=VALUE``: a profile quantity and its floor, a finite number > 0 in its unit
    (:func:`verification.agreement.floor_problem`, the rule of ``floors={...}`` too)."""
    from contactcore.scene import QUANTITIES
    name, sep, value = text.partition("=")
    if not sep or name not in QUANTITIES:
        raise argparse.ArgumentTypeError(f"expected Q=VALUE with Q one of {', '.join(QUANTITIES)} (got {text!r})")
    try:
        floor = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{name}: the floor must be a number (got {value!r})") from None
    from .agreement import floor_problem
    problem = floor_problem(name, floor)
    if problem:
        raise argparse.ArgumentTypeError(problem)
    return name, floor


def _floors(pairs: list[tuple[str, float]]) -> dict[str, float]:
    """The ``--floor`` pairs as a dict; a quantity given twice is refused."""
    floors = {}
    for name, value in pairs:
        if name in floors:
            raise ContactError(f"--floor: {name} given twice ({floors[name]:g} and {value:g})")
        floors[name] = value
    return floors


def _reference(text: str) -> tuple[str, int] | None:
    """``--reference METHOD:DEGREE`` (or ``none``)."""
    if text == "none":
        return None
    name, sep, degree = text.partition(":")
    if not sep or name not in methods.METHODS or degree not in ("1", "2"):
        raise argparse.ArgumentTypeError(f"expected METHOD:DEGREE with METHOD one of {', '.join(methods.METHODS)} "
                                         f"and DEGREE 1 or 2, or none (got {text!r})")
    return name, int(degree)


@dataclass(frozen=True)
class Arg:
    """One argument of a command: its flags (or name) and argparse's keywords."""

    flags: tuple[str, ...]
    options: dict


def arg(*flags: str, **options) -> Arg:
    """An :class:`Arg`: ``flags`` and ``options`` as ``argparse``'s
    ``add_argument`` takes them, kept for the command table (:func:`_commands`)."""
    return Arg(flags, options)


@dataclass(frozen=True)
class Command:
    """One command of the CLI: its help line, its arguments, what it runs
    (``run(args, argv)``), and how it meets mpirun's ranks (``ranks``): it
    spreads its solves over them (``"spread"``), spreads its cases over a
    pool instead (``"pool"``: refused under mpirun), solves them one after
    another in one process (``"serial"``: refused under mpirun), or
    launches mpirun itself (``"launcher"``: refused under mpirun).  ``epilog`` follows the
    options in ``--help``, line by line (:func:`explained`)."""

    help: str
    args: tuple[Arg, ...]
    run: Callable[[argparse.Namespace, list], None]
    ranks: str = "pool"
    epilog: str = ""  # below the options in --help, as written (the choices explained)


#: What each ``Command.ranks`` says when the command is started under mpirun with several ranks.
UNDER_MPIRUN = {
    "pool": "mpirun: '{}' spreads its cases over a pool, not over mpirun's ranks: run it with --workers K, or "
            "under mpiexec -n K python -m mpi4py.futures -m verification",
    "launcher": "mpirun: '{}' launches mpirun itself, once per rank count: run it without mpirun",
    "serial": "mpirun: '{}' solves its cases one after another in one process, not over mpirun's ranks: run it "
              "without mpirun",
}


def explained(option: str, choices: dict[str, str]) -> str:
    """``--help``'s list of an option's choices, one line each: the name, then what it is."""
    width = max(map(len, choices))
    return f"{option}:\n" + "\n".join(f"  {name:<{width}}  {what}" for name, what in choices.items())


def _commands() -> dict[str, Command]:
    """The command table: every command, its arguments and its runner
    (declarative; the choices that need a driver's tables import it here,
    when the parser is built)."""
    from .convergence import CASES
    from .study import PARAMETERS
    from .sweeps import sweeps

    method = arg("--method", nargs="+", default=["all"], choices=[*methods.METHODS, "all"],
                 help="the methods to run (default: all)")
    degree = arg("--degree", type=int, default=1, choices=(1, 2), help="polynomial degree (default 1)")
    degrees = arg("--degree", nargs="+", type=int, default=[1], choices=(1, 2), help="polynomial degrees (default 1)")
    ladder = arg("--h", nargs="+", type=float, required=True, help="the resolutions of the ladder, coarse to fine")
    cell = arg("--cell", choices=XFEM_CELLS, help="XFEM background cells (default quad on a rectangle; on a disc "
                                                        "gmsh, the only choice there)")
    scenes = arg("--scene", nargs="+", default=["A", "B", "C"], choices=["A", "B", "C"],
                 help="the paper's scenes (default: A B C)")
    out = arg("--out", type=_folder, required=True,
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
            arg("--petsc-option", type=_petsc_option, action="append", default=[], metavar="KEY=VALUE",
                help="override a PETSc option of the linear solves of fe and xfem "
                     "(e.g. pc_factor_mat_solver_type=superlu); repeat for several"),
            cell, arg("--dmax", type=float, help="EFGM support dilation (default: by basis degree)"),
            arg("--basis", choices=("linear", "quadratic"),
                help="EFGM's MLS basis (default: linear for --degree 1, quadratic for --degree 2)"),
            arg("--nodes", type=Path, help="EFGM node set: a text file of x y rows (default: a grid)"),
            arg("--no-plots", dest="draw", action="store_false", help="write no figures"),
            allow_large,
            arg("--estimate", type=int, nargs="?", const=2, choices=(2, 3), metavar="{2,3}",
                help="also solve at h/2 (3: and h/4), write the finest run with its estimated errors"),
            arg("--reference", type=_reference, default="fe:2", metavar="METHOD:DEGREE",
                help="the run the Δ panels and summary.md's agreement table compare with, solved at the same "
                     "h if not among the methods (default fe:2; 'none': fe at its highest degree run)"),
            arg("--against-exact", action="store_true",
                help="a unilateral or coulomb law enforced by its springs: also solve each method with the law "
                     "enforced exactly (Nitsche) at the same discretisation, and say in summary.md and each "
                     "summary.json how far the penalty answer is from it"),
            arg("--floor", type=_floor, action="append", default=[], metavar="Q=VALUE",
                help="measure quantity Q in the agreement table, the Δ panels and the estimates' verdicts "
                     "against sqrt(Q_ref² + VALUE²), VALUE > 0 in Q's unit in the scene's units (e.g. sxy=1e3 in an "
                     "SI scene's Pa): for a quantity zero in the reference, whose round-off would else be its "
                     "scale; repeat for several"),
            out), _run, "spread"),
        "paper": Command("the paper's figures and an agreement table against a refined reference", (
            scenes, arg("--ref-h", type=float, help="cell size of the P2 reference (default: a quarter of the "
                                                    "scene's h)"), out, workers), _paper),
        "closed": Command("closed-form cases on refinement ladders, with observed rates", (
            arg("--case", nargs="+", default=list(CASES), choices=list(CASES), help="the cases (default: all)"),
            method, arg("--degree", nargs="+", type=int, default=[1, 2], choices=(1, 2),
                        help="polynomial degrees (default 1 2)"), out), _closed, ranks="serial"),
        "efficiency": Command("error against run time, against a refined reference or estimated without one", (
            arg("scene", help="built-in scene name or a scene TOML file"), method, degrees, ladder,
            arg("--ref-h", type=float,
                help="element size of the P2 reference (default: none, the errors are estimated)"),
            arg("--exclude", type=float, help="distance from corners and Γ's ends left out (default 0.1 L)"),
            out, workers, allow_large), _efficiency),
        "effectivity": Command("the error estimates against fe P2 at a fine h, on the paper's scenes or others", (
            arg("--scene", nargs="+", default=["A", "B", "C"],
                help="built-in scene names or scene TOML files (default: the paper's A B C)"),
            arg("--h", type=float, help="the coarsest run, in each scene's length unit (default: the domain's "
                                        "smaller side/20, 0.05 on scene A)"),
            arg("--ref-h", type=float, help="cell size of the fe P2 truth (default: the finest run's h/4, 0.00625 "
                                            "on scene A)"),
            arg("--levels", type=int, default=2, choices=(2, 3), help="runs h, h/2 (3: and h/4); default 2"),
            allow_large, out), _effectivity, ranks="serial"),
        "sweeps": Command("stiff and extreme cases: error, condition and outcome", (
            arg("--sweep", nargs="+", choices=[s.name for s in sweeps()], metavar="NAME",
                help="the sweeps (default: all; each explained below)"),
            method, degree, out, workers), _sweeps,
            epilog=explained("--sweep NAME", {s.name: s.what for s in sweeps()})),
        "study": Command("inputs varied over their product (geometry through gmsh, h, springs, materials)", (
            arg("scene", help="built-in scene name or a scene TOML file"),
            arg("--param", required=True, choices=list(PARAMETERS), action="append", metavar="NAME",
                help="repeat --param NAME --values ... for a Cartesian product (each NAME explained below)"),
            arg("--values", nargs="+", type=_number_or_word, required=True, action="append",
                help="the values of the --param just before"),
            method, degree, arg("--h", type=float, help="resolution (default: the scene's h)"), cell, out,
            workers, allow_large), _study, epilog=explained("--param NAME", {p: what for p, (what, _) in PARAMETERS.items()})),
        "report": Command("every verification, gathered into DIR/report.md", (
            out, arg("--quick", action="store_true", help="short ladders: a smoke test of the whole chain"),
            workers), _report),
        "benchmark": Command("error against run time beside GetFEM's level-set XFEM", (
            scenes, out, workers), _benchmark),
        "timing": Command("wall time against DOFs on a ladder of resolutions", (
            arg("scene", nargs="+", help="one or more scenes, measured in one run (e.g. C C-coulomb)"),
            method, degrees, ladder, out), _timing, "spread"),
        "shapes": Command("EFGM's shape functions with gradients: points per second", (
            arg("--basis", nargs="+", default=["linear", "quadratic"], choices=["linear", "quadratic"],
                help="the MLS bases (default: both)"),
            arg("--grid", type=int, default=101, help="nodes per side of the unit square (default 101)"),
            arg("--points", type=int, default=200_000, help="random points evaluated (default 200000)"),
            arg("--repeats", type=int, default=5, help="timed evaluations; the median is reported (default 5)"),
            out), _shapes, "spread"),
        "scaling": Command("strong scaling: the timing ladder under mpirun on each rank count, one BLAS thread "
                           "per rank", (
            arg("scene", help="built-in scene name or a scene TOML file"), method, degrees, ladder,
            arg("--ranks", nargs="+", type=int, default=[1, 2], help="rank counts (default 1 2)"), out),
            _scaling, "launcher"),
    }


class OneLineParser(argparse.ArgumentParser):
    """argparse, whose refusal of a command line ends as every other bad
    input does: one line ``error: COMMAND: problem``, exit status 2 (not
    the usage block; ``--help`` shows it)."""

    def error(self, message: str):
        command = self.prog.removeprefix("python -m verification").strip()
        self.exit(2, f"error: {command + ': ' if command else ''}{message}\n")


def _parser(commands: dict[str, Command] | None = None) -> argparse.ArgumentParser:
    """The argparse parser of the command table (:func:`_commands` by default)."""
    commands = _commands() if commands is None else commands
    parser = OneLineParser(prog="python -m verification")
    common = OneLineParser(add_help=False)
    talk = common.add_mutually_exclusive_group()
    talk.add_argument("-q", "--quiet", action="store_const", dest="verbosity", const=-1, default=0,
                      help="errors and warnings only")
    talk.add_argument("-v", "--verbose", action="store_const", dest="verbosity", const=1,
                      help="also the debug messages of this tool")
    sub = parser.add_subparsers(dest="command", required=True)
    for name, command in commands.items():
        p = sub.add_parser(name, parents=[common], help=command.help, epilog=command.epilog or None,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        for a in command.args:
            p.add_argument(*a.flags, **a.options)
    return parser


def _run(args, argv) -> None:
    from .run import run
    run(args.scene, args.method, args.out, h=args.h, degree=args.degree, paper=args.paper, fields=args.fields,
        petsc_options=dict(args.petsc_option), dmax=args.dmax, nodes_file=args.nodes, cell=args.cell,
        basis=args.basis, allow_large=args.allow_large, draw=args.draw, estimate=args.estimate,
        reference=args.reference, against_exact=args.against_exact, floors=_floors(args.floor), argv=argv)


def _paper(args, argv) -> None:
    from .paper import paper
    paper(args.out, tuple(args.scene), args.ref_h, workers=args.workers, argv=argv)


def _closed(args, argv) -> None:
    from .convergence import closed
    closed(args.out, tuple(args.case), [(m, d) for m in methods.expand(args.method) for d in args.degree], argv=argv)


def _benchmark(args, argv) -> None:
    from .agreement import default_exclusion
    from .efficiency import BENCHMARK_LADDERS, BENCHMARK_VARIANTS, REFERENCE_H, efficiency
    from .peer_getfem import getfem_module
    getfem_module()  # before the long reference runs
    sections = [efficiency(s, BENCHMARK_VARIANTS, BENCHMARK_LADDERS[s], REFERENCE_H[s],
                           default_exclusion(load_scene(s)), args.out / s, workers=args.workers, argv=argv)
                for s in args.scene]
    files.write_text(args.out / "benchmark.md", "# Benchmark against GetFEM's level-set XFEM\n\n"
                     + "\n".join(t.replace("](efficiency.png)", f"]({s}/efficiency.png)")
                                 for s, t in zip(args.scene, sections)))


def _efficiency(args, argv) -> None:
    from .agreement import default_exclusion
    from .efficiency import efficiency
    from .study import check_given_once
    check_given_once("--method", args.method)
    check_given_once("--degree", args.degree)
    exclude = args.exclude if args.exclude is not None else default_exclusion(load_scene(args.scene))
    variants = [(m, d) for m in methods.expand(args.method) for d in args.degree]
    efficiency(args.scene, variants, {d: args.h for d in args.degree}, args.ref_h, exclude, args.out,
               workers=args.workers, estimated=True, allow_large=args.allow_large, argv=argv)


def _effectivity(args, argv) -> None:
    from .effectivity import scene_table
    scene_table(args.scene, args.h, args.ref_h, args.out, args.levels, args.allow_large, argv=argv)


def _sweeps(args, argv) -> None:
    from .sweeps import run_sweeps
    run_sweeps(args.out, args.sweep, methods.expand(args.method), args.degree, workers=args.workers, argv=argv)


def _study(args, argv) -> None:
    from .study import study
    study(args.scene, _study_params(args), args.method, args.out, degree=args.degree, h=args.h,
          cell=args.cell, workers=args.workers, allow_large=args.allow_large, argv=argv)


def _report(args, argv) -> None:
    from .report import report
    report(args.out, args.quick, workers=args.workers, argv=argv)


def _timing(args, argv) -> None:
    from .timing import timing
    timing(args.scene, args.method, args.degree, args.h, args.out, argv=argv)


def _shapes(args, argv) -> None:
    from .shapes import shapes
    shapes(args.basis, args.grid, args.points, args.repeats, args.out, argv=argv)


def _scaling(args, argv) -> None:
    from .scaling import scaling
    scaling(args.scene, methods.expand(args.method), args.degree, args.h, args.ranks, args.out, argv=argv)


class Repeats(logging.Filter):
    """Lets a message through once; counts its repeats (a sweep warns about
    the same thing in every case) for one line at the end."""

    def __init__(self):
        super().__init__()
        self.counts = {}

    def filter(self, record) -> bool:
        key = (record.levelno, record.getMessage())
        self.counts[key] = self.counts.get(key, 0) + 1
        return self.counts[key] == 1

    def summary(self) -> list[str]:
        return [f"(the {logging.getLevelName(level).lower()} \"{msg[:80]}…\" repeated {n - 1} more time(s))"
                for (level, msg), n in self.counts.items() if n > 1]


def _configure_logging(verbosity: int = 0) -> Repeats:
    """Our progress at INFO (WARNING with --quiet, DEBUG with --verbose,
    nothing at -2: the ranks after the first under mpirun);
    everything else (ffcx's JIT goes through setuptools, which lowers the
    root logger's level) only from WARNING on, enforced on the handler,
    which setuptools does not touch.  Repeated messages are collapsed."""
    fmt = logging.Formatter(LOG_FORMAT)
    root = logging.StreamHandler()
    root.setLevel(logging.WARNING)
    root.setFormatter(fmt)
    logging.basicConfig(handlers=[root], force=True)
    ours = logging.getLogger("verification")
    repeats = Repeats()
    ours.handlers[:] = [logging.StreamHandler()]
    ours.handlers[0].setFormatter(fmt)
    ours.handlers[0].addFilter(repeats)
    ours.setLevel({-2: logging.CRITICAL + 1, -1: logging.WARNING, 0: logging.INFO, 1: logging.DEBUG}[verbosity])
    ours.propagate = False
    return repeats


def _check_sizes(args) -> None:
    for name in ("h", "ref_h"):
        value = getattr(args, name, None)
        for h in value if isinstance(value, list) else [value]:
            if h is not None and not (math.isfinite(h) and h > 0):
                raise ContactError(f"--{name.replace('_', '-')}: must be a finite number > 0 (got {h})")


@contextmanager
def _result_folder(out: Path, rank: int, distributed: bool):
    """The folder the command writes into: on rank 0, which alone writes,
    ``out`` built aside and put in place whole (:func:`files.result_folder`,
    which refuses a bad ``out``); on mpirun's other ranks ``out`` itself, in
    which they write nothing (:func:`files.writes_here`).  They learn rank
    0's verdict on ``out`` first, so that none goes on into a solve whose
    collectives would wait for ever on the rank that stopped."""
    with ExitStack() as stack:
        refusal = None
        if rank == 0:
            try:
                out = stack.enter_context(files.result_folder(out, watched=distributed))
            except files.OutFolderError as exc:
                refusal = str(exc)
        if distributed:
            from mpi4py import MPI
            refusal = MPI.COMM_WORLD.bcast(refusal, root=0)
        if refusal is not None:
            raise files.OutFolderError(refusal)
        yield out


def _check_ranks_list(args) -> None:
    if any(k < 1 for k in getattr(args, "ranks", None) or ()):
        raise ContactError(f"--ranks: every rank count must be at least 1 (got {args.ranks})")


def _check_counts(args) -> None:
    """``shapes``' sizes: a grid of at least 3 nodes a side (a linear
    basis needs 3 nodes off one line in every support), at least one point
    and one timed evaluation."""
    for name, least in (("grid", 3), ("points", 1), ("repeats", 1)):
        value = getattr(args, name, None)
        if value is not None and value < least:
            raise ContactError(f"--{name}: must be at least {least} (got {value})")


def _check_cell(args) -> None:
    """``--cell quad|triangle`` names structured cells, which fill a
    rectangle only: a disc is meshed by gmsh alone (docs/methods/xfem.md),
    so asking for them there is refused rather than silently replaced.
    A ``--cell`` that no chosen method takes is refused first (``--method
    fe --cell quad`` on a disc: the cells mean nothing for fe, whatever the
    domain), as the command itself would refuse it once the disc is fixed."""
    cell = getattr(args, "cell", None)
    if cell is not None and getattr(args, "method", None) is not None:
        methods.check_options(methods.expand(args.method), cell=cell)
    if cell is None or cell == "gmsh" or getattr(args, "scene", None) is None:
        return
    from contactcore.geometry import Disc
    scene = load_scene(args.scene)
    if isinstance(scene.domain, Disc):
        raise ContactError(f"--cell {cell}: the domain of scene {scene.name} is a disc, which only gmsh meshes "
                           f"(structured {cell} cells fill a rectangle); use --cell gmsh or leave --cell out")


def _check_workers(args) -> None:
    workers = getattr(args, "workers", None)
    if workers is not None and workers < 1:
        raise ContactError(f"--workers: must be at least 1 (got {workers})")


def _number_or_word(text: str):
    """A study's value: a number, or a word (``--param enforcement``)."""
    try:
        return float(text)
    except ValueError:
        return text


def _study_params(args) -> list[tuple[str, list[float]]]:
    """The (--param, --values) pairs of ``study``, in the order given."""
    if len(args.param) != len(args.values):
        raise ContactError(f"--values: give one --values list after each --param ({len(args.param)} --param, "
                           f"{len(args.values)} --values)")
    return list(zip(args.param, args.values))


def _check_ranks(command: str, ranks: str) -> None:
    """Under mpirun with several ranks, the commands that spread their
    solves over the ranks run on all of them; the others are refused here,
    once, before any rank writes (:data:`UNDER_MPIRUN`)."""
    from .pool import distributed
    if distributed() and ranks in UNDER_MPIRUN:
        raise ContactError(UNDER_MPIRUN[ranks].format(command))


def _abort_on(exc: BaseException) -> None:
    """An unexpected error on one rank under mpirun would leave the others
    waiting in a collective for ever: print it and abort them all."""
    import traceback
    from mpi4py import MPI
    traceback.print_exception(exc)
    MPI.COMM_WORLD.Abort(1)


#: The exit status of a run ended by Ctrl-C: 128 + SIGINT, as a shell reports it.
INTERRUPTED = 130
#: ... and by SIGTERM (``kill``, ``timeout``, a batch scheduler): 128 + SIGTERM.
TERMINATED = 143
#: The signals that end a command, SIGTERM as Ctrl-C ends it.
ENDING = files.HELD_SIGNALS


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised where the process is, so that it ends as Ctrl-C does:
    the result folder discarded, the workers stopped, one line."""


def _raise_terminated(signum, frame) -> None:
    raise Terminated


def _end_now(signum, frame) -> None:
    """Rank 0 under mpirun, asked to end: one line (its own, or its
    janitor's if the janitor took the token first: :func:`janitor.told`),
    first, as mpirun forwards it only while this process lives; the result
    folder under way discarded (:func:`files.discard_unfinished`); exit
    now, without unwinding: the way out would meet collectives (a MUMPS
    factorisation's end is one) that the other ranks never join."""
    if not janitor.told(signum):
        print(janitor.INTERRUPTED_LINE, file=sys.stderr, flush=True)
    files.discard_unfinished()
    sys.stdout.flush()
    os._exit(INTERRUPTED)


def _handlers(rank: int, distributed: bool) -> dict:
    """How each of :data:`ENDING` ends the command.  In one process Ctrl-C
    raises KeyboardInterrupt and SIGTERM :class:`Terminated`.  mpirun
    passes on Ctrl-C and its own SIGTERM alike, to its ranks as SIGTERM,
    and kills them a second later (Open MPI's ``odls_base_sigkill_timeout``):
    rank 0 ends at once (:func:`_end_now`; its janitor puts its result
    folder right if mpirun kills it first), and the other ranks ignore
    both signals, so that they keep joining every collective rank 0 is in
    until it has ended (they hold nothing to discard) and mpirun kills them."""
    if not distributed:
        return {signal.SIGTERM: _raise_terminated}
    return dict.fromkeys(ENDING, _end_now if rank == 0 else signal.SIG_IGN)


@contextmanager
def _signals_end_the_command(rank: int, distributed: bool):
    """:func:`_handlers` while the block runs (the handlers before it
    restored after; only the main thread may set one)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    before = {sig: signal.signal(sig, handler) for sig, handler in _handlers(rank, distributed).items()}
    try:
        yield
    finally:
        for sig, handler in before.items():
            signal.signal(sig, handler)


#: PETSc's option that leaves every signal to the process (see :func:`_python_handles_signals`).
NO_PETSC_SIGNALS = "-no_signal_handler"


def _python_handles_signals() -> None:
    """PETSc, once started, catches SIGPIPE (with SIGSEGV, SIGFPE, …) and
    aborts with status 59: ``run … 2>&1 | head -1`` left its build folder
    behind.  Its handlers are turned off before it starts (``PETSC_OPTIONS``,
    which mpirun's ranks and a pool's workers inherit), so that Python's
    own handling applies: a closed pipe is an error the log ignores, and
    Ctrl-C and SIGTERM end the command in one line."""
    given = os.environ.get("PETSC_OPTIONS", "")
    if NO_PETSC_SIGNALS not in given.split():
        os.environ["PETSC_OPTIONS"] = f"{given} {NO_PETSC_SIGNALS}".strip()


def main(argv=None) -> int:
    """``python -m verification COMMAND ...`` (``argv``, default
    ``sys.argv[1:]``): the exit status, 0 when the command succeeded, 2
    after one ``error:`` line for bad input or a refused run (every
    :class:`ContactError`), and Ctrl-C's or SIGTERM's status after its line
    (the result folder under way discarded); argparse's own refusals exit 2
    by ``SystemExit``.  Any other exception is a bug, and propagates."""
    argv = sys.argv[1:] if argv is None else argv
    unread = petsc_env.unread()  # before _python_handles_signals adds its own to PETSC_OPTIONS
    _python_handles_signals()
    commands = _commands()
    args = _parser(commands).parse_args(argv)
    command = commands[args.command]
    from .pool import distributed, launched_rank
    rank = launched_rank()
    repeats = _configure_logging(args.verbosity if rank == 0 else -2)  # one log, rank 0's
    if unread:
        instead = ("pass --petsc-option KEY=VALUE instead (fe, xfem)" if hasattr(args, "petsc_option") else
                   f"{args.command} takes no solver options (only run does, for fe and xfem)")
        log.warning("%s, which the toolkit's solvers do not read (each reads its options under a prefix of its "
                    "own); %s", unread, instead)
    try:
        _hold_signals_in_slow_imports()
        _take_over_signals()
        with _signals_end_the_command(rank, distributed()):
            _main(args, argv, command, rank)
        _print_repeats(repeats)
    except ContactError as exc:
        _print_repeats(repeats)
        if rank == 0:  # every rank meets the same error (Newton's decisions are collective): one line
            print(f"error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:  # the result folder is already discarded; the workers stop with the pool
        _print_repeats(repeats)
        if rank == 0:
            print("terminated" if isinstance(exc, Terminated) else janitor.INTERRUPTED_LINE, file=sys.stderr)
        return TERMINATED if isinstance(exc, Terminated) else INTERRUPTED
    except Exception as exc:
        _print_repeats(repeats)
        if distributed():
            _abort_on(exc)
        raise
    return 0


#: The packages whose import runs long C initialisation (dolfinx loads its
#: C++ library, PETSc and MPI start, gmsh loads libgmsh): a Ctrl-C or
#: SIGTERM raised inside it came out as ``ImportError: initialization
#: failed`` with a 40-line traceback and exit 1 (grader8's fault 6: 2 of 9
#: SIGTERMs during dolfinx's lazy import).  :class:`_HeldImports` holds
#: both signals while one of them is imported.
HELD_IMPORTS = ("dolfinx", "petsc4py", "mpi4py", "gmsh", "basix", "ffcx", "ufl")


class _HeldLoader:
    """A module's loader whose ``exec_module`` runs with Ctrl-C and SIGTERM
    held (:func:`files.signals_held`): the first that came acts once the
    module is whole, as it would have between two statements (SIGTERM
    raises :class:`Terminated`, which the import passes on as it is)."""

    def __init__(self, loader):
        self._loader = loader

    def create_module(self, spec):
        return self._loader.create_module(spec)

    def exec_module(self, module):
        with files.signals_held():
            self._loader.exec_module(module)

    def __getattr__(self, name):
        return getattr(self._loader, name)


class _HeldImports:
    """A finder (first on ``sys.meta_path``) that finds :data:`HELD_IMPORTS`
    and their submodules through the finders after it and hands their
    loaders to :class:`_HeldLoader`."""

    def find_spec(self, name, path, target=None):
        if name.partition(".")[0] not in HELD_IMPORTS:
            return None
        for finder in sys.meta_path:
            if finder is self or not hasattr(finder, "find_spec"):
                continue
            spec = finder.find_spec(name, path, target)
            if spec is not None:
                if spec.loader is not None and hasattr(spec.loader, "exec_module"):
                    spec.loader = _HeldLoader(spec.loader)
                return spec
        return None


def _hold_signals_in_slow_imports() -> None:
    """Put :class:`_HeldImports` first on ``sys.meta_path`` (once): from
    start-up to the end a signal during one of :data:`HELD_IMPORTS` ends
    the command in one line."""
    if not any(isinstance(f, _HeldImports) for f in sys.meta_path):
        sys.meta_path.insert(0, _HeldImports())


def _take_over_signals() -> None:
    """From here on Ctrl-C raises KeyboardInterrupt, which :func:`main`
    turns into its one line once the result folder under way is discarded
    (the start-up's handlers, :data:`verification.STARTING`, put back as Python has them)."""
    for sig, handler in STARTING.items():
        if signal.getsignal(sig) is interrupted_while_starting:
            signal.signal(sig, handler)


def _print_repeats(repeats: Repeats) -> None:
    """The count of each repeated message, before the command's last line
    (an error, ``interrupted``): a failed run ends on why it failed."""
    for line in repeats.summary():
        print(line, file=sys.stderr)


def _main(args, argv, command: Command, rank: int) -> None:
    """The checks every command makes, then the command, its result folder
    built aside and put in place whole (:func:`_result_folder`: rank 0
    alone writes, the other ranks compute alongside)."""
    from .pool import distributed
    if distributed():  # PETSc starts collectively: every rank now, before any method needs it
        from petsc4py import PETSc  # noqa: F401
    _check_ranks(args.command, command.ranks)
    _check_sizes(args)
    _check_workers(args)
    _check_counts(args)
    _check_cell(args)
    _check_ranks_list(args)
    if getattr(args, "out", None) is None:
        command.run(args, argv)
        return
    final = args.out
    with _result_folder(final, rank, distributed()) as folder:
        args.out = folder
        command.run(args, argv)
        if rank == 0:
            if not (folder / files.MANIFEST).exists():  # every result folder says what made it
                files.write_json(folder / files.MANIFEST, files.provenance(list(argv)))
            files.write_units(folder)  # every CSV column's unit, beside the CSVs (their headers stay as read)
    log.info("wrote %s", final)


if __name__ == "__main__":
    status = main()
    # the command has ended (its line said, its folder in place or discarded): a late Ctrl-C while the
    # interpreter joins the pool's threads at exit would only be a traceback "ignored" there
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    sys.exit(status)
