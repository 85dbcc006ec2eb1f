"""Command line of the verification drivers.

    python -m verification run SCENE_OR_TOML --method fe|xfem|efgm|all [--degree 1|2] [--cell quad|triangle|gmsh]
        [--h H] [--paper] [--xdmf] [--petsc-option KEY=VALUE ...] [--dmax D] [--nodes FILE] --out DIR
    python -m verification timing SCENE --method fe --degree 1 2 --h H1 H2 ... --out DIR
    python -m verification efficiency SCENE --method fe efgm --degree 1 2 --h H1 H2 ... --ref-h H --out DIR

Bad input ends with one line ``error: <field>: <problem>`` and exit status 2.
"""
from __future__ import annotations

import argparse
import logging
import sys
from pathlib import Path

from contactcore import ContactError, load_scene

from . import methods


def _petsc_option(text: str) -> tuple[str, str]:
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    return key.lstrip("-"), value


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="python -m verification")
    sub = parser.add_subparsers(dest="command", required=True)
    run = sub.add_parser("run", help="solve one scene with one or more methods")
    run.add_argument("scene", help="built-in scene name (A, B, C) or a scene TOML file")
    run.add_argument("--method", nargs="+", default=["all"], choices=[*methods.METHODS, "all"])
    run.add_argument("--degree", type=int, default=1, choices=(1, 2))
    run.add_argument("--h", type=float, help="resolution for every method (default: the scene's h)")
    run.add_argument("--paper", action="store_true", help="use the paper's discretisations")
    run.add_argument("--xdmf", action="store_true", help="also write XDMF per body for ParaView")
    run.add_argument("--petsc-option", type=_petsc_option, action="append", default=[], metavar="KEY=VALUE",
                     help="override a PETSc option of the fe solve (e.g. pc_factor_mat_solver_type=superlu)")
    run.add_argument("--cell", choices=("quad", "triangle", "gmsh"), help="XFEM background cells (default quad)")
    run.add_argument("--dmax", type=float, help="EFGM support dilation (default: by basis degree)")
    run.add_argument("--nodes", type=Path, help="EFGM node set: a text file of x y rows (default: a grid)")
    run.add_argument("--out", type=Path, required=True, help="result folder")
    tim = sub.add_parser("timing", help="wall time against DOFs on a ladder of resolutions")
    tim.add_argument("scene")
    tim.add_argument("--method", nargs="+", default=["all"], choices=[*methods.METHODS, "all"])
    tim.add_argument("--degree", nargs="+", type=int, default=[1], choices=(1, 2))
    tim.add_argument("--h", nargs="+", type=float, required=True)
    tim.add_argument("--out", type=Path, required=True)
    eff = sub.add_parser("efficiency", help="error against run time, against a refined reference")
    eff.add_argument("scene")
    eff.add_argument("--method", nargs="+", default=["all"], choices=[*methods.METHODS, "all"])
    eff.add_argument("--degree", nargs="+", type=int, default=[1], choices=(1, 2))
    eff.add_argument("--h", nargs="+", type=float, required=True)
    eff.add_argument("--ref-h", type=float, required=True, help="element size of the P2 reference")
    eff.add_argument("--exclude", type=float, help="distance from corners and Γ's ends left out (default 0.1 L)")
    eff.add_argument("--out", type=Path, required=True)
    return parser


def _configure_logging() -> None:
    """Our progress at INFO; everything else (ffcx's JIT goes through
    setuptools, which lowers the root logger's level) only from WARNING on,
    enforced on the handler, which setuptools does not touch."""
    fmt = logging.Formatter("%(levelname)s %(name)s: %(message)s")
    root = logging.StreamHandler()
    root.setLevel(logging.WARNING)
    root.setFormatter(fmt)
    logging.basicConfig(handlers=[root], force=True)
    ours = logging.getLogger("verification")
    ours.handlers[:] = [logging.StreamHandler()]
    ours.handlers[0].setFormatter(fmt)
    ours.setLevel(logging.INFO)
    ours.propagate = False


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    args = _parser().parse_args(argv)
    _configure_logging()
    from .efficiency import efficiency
    from .run import run
    from .timing import timing

    try:
        for h in (args.h if isinstance(args.h, list) else [args.h]) + [getattr(args, "ref_h", None)]:
            if h is not None and not h > 0:
                raise ContactError(f"--h: must be > 0 (got {h})")
        if args.command == "run":
            run(args.scene, args.method, args.out, h=args.h, degree=args.degree, paper=args.paper,
                xdmf=args.xdmf, petsc_options=dict(args.petsc_option), dmax=args.dmax,
                nodes_file=args.nodes, cell=args.cell, argv=argv)
        elif args.command == "timing":
            timing(args.scene, args.method, args.degree, args.h, args.out, argv=argv)
        else:
            scene = load_scene(args.scene)
            exclude = args.exclude if args.exclude is not None else 0.1 * scene.length_scale
            efficiency(args.scene, args.method, args.degree, args.h, args.ref_h, exclude, args.out, argv=argv)
    except ContactError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
