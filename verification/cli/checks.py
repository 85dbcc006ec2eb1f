"""The checks every command makes on its parsed arguments before it runs,
before any solve and before its result folder is made.

Contract: :func:`check` runs them in one fixed order (the first problem
found is the one reported); each reads only the arguments its command has
(``getattr`` with a default: a command without ``--h`` has nothing to
check there) and refuses with a :class:`ContactError` that names the
option, which ``main`` prints as one line with exit status 2.
"""
from __future__ import annotations

import math

from contactcore import ContactError, load_scene
from contactcore.budget import check_processes

from .. import methods

#: What each ``Command.ranks`` says when the command is started under mpirun with several ranks.
UNDER_MPIRUN = {
    "pool": "mpirun: '{}' spreads its cases over a pool, not over mpirun's ranks: run it with --workers K, or "
            "under mpiexec -n K python -m mpi4py.futures -m verification",
    "launcher": "mpirun: '{}' launches mpirun itself, once per rank count: run it without mpirun",
    "serial": "mpirun: '{}' solves its cases one after another in one process, not over mpirun's ranks: run it "
              "without mpirun",
}


def check(args, command: str, ranks: str) -> None:
    """Every check, in order: mpirun's ranks, sizes, workers, counts, cells, rank counts."""
    check_ranks(command, ranks)
    check_sizes(args)
    check_workers(args)
    check_counts(args)
    check_cell(args)
    check_ranks_list(args)
    check_mesh(args)


def check_ranks(command: str, ranks: str) -> None:
    """Under mpirun with several ranks, the commands that spread their
    solves over the ranks run on all of them; the others are refused here,
    once, before any rank writes (:data:`UNDER_MPIRUN`)."""
    from ..pool import distributed
    if distributed() and ranks in UNDER_MPIRUN:
        raise ContactError(UNDER_MPIRUN[ranks].format(command))


def check_sizes(args) -> None:
    """``--h`` and ``--ref-h`` (one value or a ladder): each a finite number > 0."""
    for name in ("h", "ref_h"):
        value = getattr(args, name, None)
        for h in value if isinstance(value, list) else [value]:
            if h is not None and not (math.isfinite(h) and h > 0):
                raise ContactError(f"--{name.replace('_', '-')}: must be a finite number > 0 (got {h})")


def check_workers(args) -> None:
    """``--workers``: at least 1, and (unless ``--allow-large``) no more
    processes than this machine's memory holds
    (:func:`contactcore.budget.check_processes`)."""
    workers = getattr(args, "workers", None)
    if workers is not None and workers < 1:
        raise ContactError(f"--workers: must be at least 1 (got {workers})")
    if workers is not None and not getattr(args, "allow_large", False):
        check_processes(workers, "--workers", hasattr(args, "allow_large"))


def check_counts(args) -> None:
    """``shapes``' sizes: a grid of at least 3 nodes a side (a linear
    basis needs 3 nodes off one line in every support), at least one point
    and one timed evaluation."""
    for name, least in (("grid", 3), ("points", 1), ("repeats", 1)):
        value = getattr(args, name, None)
        if value is not None and value < least:
            raise ContactError(f"--{name}: must be at least {least} (got {value})")


def check_cell(args) -> None:
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


def check_ranks_list(args) -> None:
    """``scaling``'s ``--ranks``: every rank count at least 1."""
    if any(k < 1 for k in getattr(args, "ranks", None) or ()):
        raise ContactError(f"--ranks: every rank count must be at least 1 (got {args.ranks})")
    if getattr(args, "ranks", None) and not getattr(args, "allow_large", False):
        check_processes(max(args.ranks), "--ranks", hasattr(args, "allow_large"))


def check_mesh(args) -> None:
    """``run --mesh FILE``: fe's mesh from the user's file, which fixes h
    (its largest cell diameter).  Refused by name with another method
    (xfem's and efgm's discretisations are their own: run them without
    ``--mesh``), with ``--h`` or ``--paper`` (the file fixes the
    resolution) and with ``--estimate`` (which solves at h/2 and h/4: a
    finer mesh of the same family the file does not give)."""
    mesh = getattr(args, "mesh", None)
    if mesh is None:
        return
    chosen = methods.expand(getattr(args, "method", None) or ["fe"])
    others = [m for m in chosen if m != "fe"]
    if others:
        builds = "builds its" if len(others) == 1 else "build their"
        raise ContactError(f"--mesh: is fe's mesh, and {', '.join(others)} {builds} own discretisation: run "
                           f"--method fe with --mesh, and {', '.join(others)} in a run of their own")
    for option, given in (("--h", getattr(args, "h", None) is not None), ("--paper", getattr(args, "paper", False)),
                          ("--estimate", getattr(args, "estimate", None) is not None)):
        if given:
            raise ContactError(f"--mesh: {option} means nothing with a mesh file" + (
                ", which fixes the resolution (h is its largest cell diameter)" if option != "--estimate" else
                ": the estimate solves at h/2 (and h/4), finer meshes of the same family, which the file does "
                "not give; write them with python -m meshes --h and run each"))
