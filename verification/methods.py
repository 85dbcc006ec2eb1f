"""The methods a driver can run, by name, imported only when used.

Every entry names a module with ``METHOD`` and ``solve(scene, h=None, *,
degree=1, paper=False, ...) -> contactcore.Result``.  Lazy import keeps an
``efgm`` run free of dolfinx and gmsh.
"""
from __future__ import annotations

import importlib

from contactcore import ContactError

#: Method name -> module implementing it, in the order plots list them.
METHODS = {
    "fe": "xdolfinx.conforming",
    "xfem": "xdolfinx.xfem",
    "efgm": "efgm.method",
}

#: Peers run beside the methods by the benchmark only (never in "all").
PEERS = {"getfem": "verification.peer_getfem"}

#: Options of the command line that only some methods take.
OPTIONS = {
    "fe": ("petsc_options",),
    "xfem": ("petsc_options", "cell"),
    "efgm": ("dmax", "nodes", "basis"),
}

#: The command-line flag of each option.
FLAGS = {"petsc_options": "--petsc-option", "cell": "--cell", "dmax": "--dmax", "nodes": "--nodes",
         "basis": "--basis"}

#: Methods whose fields live on a dolfinx mesh, so XDMF output exists.
WITH_XDMF = ("fe", "xfem")


def solver(name: str):
    """The ``solve`` function of method (or peer) ``name``."""
    return importlib.import_module({**METHODS, **PEERS}[name]).solve


def options_for(name: str, **given) -> dict:
    """The given options that method ``name`` takes (None means not given)."""
    return {k: v for k, v in given.items() if k in OPTIONS[name] and v is not None}


def check_options(names: list[str], **given) -> None:
    """Refuse an option (not None) that none of the methods ``names`` takes:
    it would be silently ignored."""
    for option, value in given.items():
        if value is not None and not any(option in OPTIONS[n] for n in names):
            takers = [m for m, opts in OPTIONS.items() if option in opts]
            raise ContactError(f"{FLAGS[option]}: means nothing for {', '.join(names)} "
                               f"(only {', '.join(takers)} take it)")


def expand(names: list[str]) -> list[str]:
    """``all`` means every method built so far."""
    return list(METHODS) if "all" in names else names
