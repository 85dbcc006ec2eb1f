"""``python -m meshes SCENE --h H --out FILE.msh``: write a scene's fitted mesh."""
import argparse
import logging
import sys

from contactcore import ContactError, load_scene

from .build import Grading, write_mesh


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m meshes", description=__doc__)
    parser.add_argument("scene", help="built-in scene name (A, B, C) or a scene TOML file")
    parser.add_argument("--h", type=float, help="element size (default: the scene's h)")
    parser.add_argument("--out", required=True, help="the .msh file to write")
    parser.add_argument("--order", type=int, default=1, choices=(1, 2), help="geometry order (2: curved)")
    parser.add_argument("--grade", type=float, metavar="FACTOR", help="size on Γ and corners as a fraction of h")
    parser.add_argument("--grade-distance", type=float, help="distance over which the size grows back to h")
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    try:
        scene = load_scene(args.scene)
        h = args.h if args.h is not None else scene.h
        if h is None:
            parser.error("the scene gives no default h: pass --h")
        grading = None
        if args.grade is not None:
            grading = Grading(args.grade, args.grade_distance or 4 * h)
        out = write_mesh(scene, h, args.out, order=args.order, grading=grading)
    except ContactError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    logging.info("wrote %s", out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
