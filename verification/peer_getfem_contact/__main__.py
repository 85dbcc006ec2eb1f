"""The command line: ``.venv/bin/python -m verification.peer_getfem_contact SCENE``.

It prints :func:`~.tables.markdown` of :func:`~.runs.study` (the tables
of docs/peer-contact.md); a refused scene, h or size is one line on
stderr and exit status 2, never a traceback.  :func:`main` lives here, in
the command itself (tests/test_cli_layout.py: a module that imports
argparse is the command line's or a command of its own); the package
gives it as ``verification.peer_getfem_contact.main`` on first use, so
that ``python -m`` does not find this module imported before it runs.
"""
from __future__ import annotations

import sys

from contactcore import ContactError

from .runs import study
from .scenes import STUDIES
from .tables import markdown


def main(argv=None) -> int:
    """``python -m verification.peer_getfem_contact SCENE [--h H ...]
    [--methods M ...]``: print the study's tables (docs/peer-contact.md)."""
    import argparse
    parser = argparse.ArgumentParser(prog="python -m verification.peer_getfem_contact",
                                     description="GetFEM's Alart–Curnier contact against our exact answers")
    parser.add_argument("scene", choices=sorted(STUDIES), help="the scene, with its study law")
    parser.add_argument("--h", type=float, nargs="+", default=[0.05, 0.025], help="mesh sizes")
    parser.add_argument("--degree", type=int, default=2, choices=(1, 2), help="degree of every method")
    parser.add_argument("--methods", nargs="+", default=["fe"], choices=("fe", "xfem", "efgm"),
                        help="our methods compared with GetFEM")
    parser.add_argument("--allow-large", action="store_true",
                        help="run even when the estimated memory exceeds what this machine has")
    args = parser.parse_args(argv)
    try:
        tables = study(args.scene, args.h, args.degree, tuple(args.methods), args.allow_large)
    except ContactError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(markdown(*tables), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
