"""``python -m meshes SCENE --h H --out FILE.msh``: write a scene's fitted mesh."""
import argparse
import logging
import math
import signal
import sys

from contactcore import ContactError, load_scene
from contactcore import tolerances as tol
from contactcore.budget import Counted, check_budget
from contactcore.endings import INTERRUPTED, TERMINATED, Terminated
from contactcore.scene import check_resolution, smallest_dimension

from .build import Grading, check_mesh_path, write_mesh


def _raise_terminated(signum, frame) -> None:
    raise Terminated


def main(argv=None) -> int:
    """:func:`_command`, ended by Ctrl-C or SIGTERM in one line
    (``interrupted`` or ``terminated``, exit 130 or 143), never a
    traceback, and no temporary file left beside ``--out``."""
    previous = signal.signal(signal.SIGTERM, _raise_terminated)
    try:
        return _command(argv)
    except KeyboardInterrupt as exc:
        print("terminated" if isinstance(exc, Terminated) else "interrupted", file=sys.stderr)
        return TERMINATED if isinstance(exc, Terminated) else INTERRUPTED
    finally:
        signal.signal(signal.SIGTERM, previous)


def fe_solve(order: int) -> Counted:
    """What :func:`contactcore.budget.check_budget` reads of fe's solve on
    the mesh of ``order``: fe's facts (:class:`xdolfinx.options.FE`, which
    ``meshes`` may not import: xdolfinx imports meshes), one field per
    body, ``order²`` nodes a cell; tests/test_method_facts.py holds them
    to FE's."""
    return Counted("fe", order, field_copies=2)


def _command(argv=None) -> int:
    """The command: refuse, before any meshing and with one ``error:`` line
    and exit 2, an output path that cannot take the mesh
    (:func:`meshes.build.check_mesh_path`), and an ``h`` that ``python -m
    verification run`` refuses too: not a finite number > 0, larger than the
    domain or below its geometric tolerance
    (:func:`contactcore.scene.check_resolution`), or a mesh too large for
    the machine (:func:`contactcore.budget.check_budget`, fe's, unless
    ``--allow-large``); then mesh and write it (0)."""
    parser = argparse.ArgumentParser(prog="python -m meshes", description=__doc__)
    parser.add_argument("scene", help="built-in scene name (A, B, C) or a scene TOML file")
    parser.add_argument("--h", type=float, help="element size (default: the scene's h)")
    parser.add_argument("--out", required=True, help="the mesh file to write: .msh for run --mesh / FE(mesh=...) (another format gmsh "
                        "writes, e.g. .vtk to view it, keeps no physical group names: fe refuses it)")
    parser.add_argument("--order", type=int, default=1, choices=(1, 2), help="geometry order (2: curved)")
    parser.add_argument("--grade", type=float, metavar="FACTOR", help="size on Γ and corners as a fraction of h")
    parser.add_argument("--grade-distance", type=float, help="distance over which the size grows back to h")
    parser.add_argument("--allow-large", action="store_true",
                        help="mesh even when the estimated memory of solving on it exceeds what this machine has")
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    try:
        out = check_mesh_path(args.out)
        scene = load_scene(args.scene)
        h = args.h if args.h is not None else scene.h
        if h is None:
            parser.error("the scene gives no default h: pass --h")
        check_resolution(scene, h, "--h")
        if args.grade is None and args.grade_distance is not None:
            raise ContactError("--grade-distance: grades nothing without --grade FACTOR")
        grading = None if args.grade is None else check_grading(scene, h, args.grade, args.grade_distance)
        if not args.allow_large:  # at the graded size: a safe upper bound, as if the whole domain took it
            check_budget(scene, h if grading is None else h * grading.factor, fe_solve(args.order),
                         "--h" if grading is None else f"--h {h:g} × --grade {grading.factor:g}: the size")
        out = write_mesh(scene, h, out, order=args.order, grading=grading)
    except ContactError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    logging.info("wrote %s", out)
    return 0


def check_grading(scene, h: float, factor: float, distance: float | None) -> Grading:
    """The :class:`~meshes.build.Grading` of ``--grade FACTOR`` and
    ``--grade-distance`` (default 4 h), or a ContactError naming the option:
    a factor not a finite number in (0, 1], a size on Γ (h × factor) below
    :data:`~contactcore.tolerances.MESH_MIN_GRADED_SIZE` of the domain's
    smallest dimension (gmsh aborts the process on one far smaller), a
    distance not a finite number > 0 (``inf`` graded the whole domain)."""
    if not (math.isfinite(factor) and 0.0 < factor <= 1.0):
        raise ContactError(f"--grade: the factor must be a finite number in (0, 1] (got {factor:g})")
    top = smallest_dimension(scene.domain)
    if h * factor < tol.MESH_MIN_GRADED_SIZE * top:
        raise ContactError(f"--grade: {factor:g} makes the size on Γ h × {factor:g} = {h * factor:.3g}, below "
                           f"{tol.MESH_MIN_GRADED_SIZE:g} of the domain's smallest dimension {top:g}, the smallest "
                           "gmsh is known to mesh (it aborts on smaller ones); use a larger factor")
    if distance is None:
        distance = 4 * h
    elif not (math.isfinite(distance) and distance > 0.0):
        raise ContactError(f"--grade-distance: must be a finite number > 0 (got {distance:g})")
    return Grading(factor, distance)


if __name__ == "__main__":
    sys.exit(main())
