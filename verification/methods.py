"""The methods a driver can run, by name, imported only when used.

Every entry names a module with ``METHOD`` and ``solve(scene, h=None, *,
paper=False, **options) -> contactcore.Result``, the contract's one solve
(:mod:`contactcore.discretisation`) with the method's typed options, whose
class is named in :data:`DISCRETISATIONS`.  Lazy import keeps an ``efgm``
run free of dolfinx and gmsh.
"""
from __future__ import annotations

import importlib
import inspect

from contactcore import ContactError
from contactcore.discretisation import option_names

#: Method name -> module implementing it, in the order plots list them.
METHODS = {
    "fe": "xdolfinx.conforming",
    "xfem": "xdolfinx.xfem",
    "efgm": "efgm.method",
}

#: Peers run beside the methods by the benchmark only (never in "all").
PEERS = {"getfem": "verification.peer_getfem"}

#: Each method's typed options (:mod:`contactcore.discretisation`), from
#: modules that import no numerics.
DISCRETISATIONS = {"fe": ("xdolfinx.options", "FE"), "xfem": ("xdolfinx.options", "XFEM"),
                   "efgm": ("efgm.options", "EFGM")}

#: The command-line flag of each option.
FLAGS = {"petsc_options": "--petsc-option", "cell": "--cell", "dmax": "--dmax", "nodes": "--nodes",
         "basis": "--basis"}

#: Methods whose fields live on a dolfinx mesh, so XDMF output exists.
WITH_XDMF = ("fe", "xfem")

#: Methods whose solve spreads over mpirun's ranks (fe and xfem: dolfinx
#: and PETSc own the partition; efgm: its cells, Γ's points and rows split
#: in fixed contiguous ranges, :mod:`efgm.distributed`); any other runs on
#: rank 0 while the rest wait.
DISTRIBUTED = ("fe", "xfem", "efgm")

#: Methods that start no MPI outside mpirun (their ``comm`` None is one
#: process there): a driver hands them a communicator only under a launcher.
MPI_FREE = ("efgm",)


def solver(name: str):
    """The ``solve`` function of method (or peer) ``name``."""
    return importlib.import_module({**METHODS, **PEERS}[name]).solve


def discretisation(name: str) -> type:
    """Method ``name``'s option class."""
    module, cls = DISCRETISATIONS[name]
    return getattr(importlib.import_module(module), cls)


def takes(name: str, option: str) -> bool:
    """Whether method (or peer) ``name`` takes ``option``."""
    if name in PEERS:
        return option in inspect.signature(solver(name)).parameters
    return option in option_names(discretisation(name))


def options_for(name: str, **given) -> dict:
    """The given options that method ``name`` takes (None means not given)."""
    return {k: v for k, v in given.items() if takes(name, k) and v is not None}


def check_options(names: list[str], **given) -> None:
    """Refuse an option (not None) that none of the methods ``names`` takes:
    it would be silently ignored."""
    for option, value in given.items():
        if value is not None and not any(takes(n, option) for n in names):
            takers = [m for m in METHODS if takes(m, option)]
            raise ContactError(f"{FLAGS[option]}: means nothing for {', '.join(names)} "
                               f"(only {', '.join(takers)} take it)")


def expand(names: list[str]) -> list[str]:
    """``all`` means every method built so far."""
    return list(METHODS) if "all" in names else names
