"""The methods a driver can run, by name, imported only when used.

:data:`METHODS` names each method's typed options class
(:class:`contactcore.discretisation.Discretisation`), from modules that
import no numerics; every fact about a method — its implementing module,
its field output, whether it spreads over mpirun's ranks, whether it needs
MPI — is a class attribute there, read through :func:`discretisation`.
The implementing module (the class's ``module``) has ``build(scene,
options, resolution, timings)`` and ``solve(scene, h=None, *,
paper=False, **options) -> contactcore.Result``, the contract's one solve
with the method's options; a method needs nothing else here.  The
shipped method modules also define ``METHOD`` (their options' ``name``),
which no driver reads: a new method needs none (only the GetFEM contact
peer's ``METHOD`` is used, its name in results; docs/architecture.md,
"A new method").  Lazy import keeps an ``efgm`` run free of dolfinx and
gmsh.
"""
from __future__ import annotations

import importlib
import inspect

from contactcore import ContactError
from contactcore.budget import Counted
from contactcore.discretisation import check_solvable as solvable, make, option_names

#: Method name -> its options class, as ``module:Class``, in the order plots list them.
METHODS = {
    "fe": "xdolfinx.options:FE",
    "xfem": "xdolfinx.options:XFEM",
    "efgm": "efgm.options:EFGM",
}

#: Peers run beside the methods by the benchmark only (never in "all"): their modules.
PEERS = {"getfem": "verification.peer_getfem"}

#: The command-line flag of each option.
FLAGS = {"petsc_options": "--petsc-option", "cell": "--cell", "dmax": "--dmax", "nodes": "--nodes",
         "basis": "--basis", "mesh": "--mesh", "flux": "--flux"}


def discretisation(name: str) -> type:
    """Method ``name``'s options class; an unknown ``name`` is refused
    with a :class:`ContactError` naming the methods."""
    if not isinstance(name, str) or name not in METHODS:
        raise ContactError(f"method {name!r}: unknown (known: {', '.join(METHODS)})")
    module, cls = METHODS[name].split(":")
    return getattr(importlib.import_module(module), cls)


def budgeted(name: str, degree: int):
    """What :mod:`contactcore.budget` reads of a solve by method ``name``
    at ``degree``: its options, which declare its facts (field copies,
    nodes a cell), or for a peer, which has none, a
    :class:`contactcore.budget.Counted` of one field."""
    if name in METHODS:
        return make(discretisation(name), degree=degree)
    return Counted(name, degree)


def solver(name: str):
    """The ``solve`` function of method (or peer) ``name``: a method's is
    ``solve(scene, h=None, *, paper=False, progress=None, reuse=None,
    **options)`` (:func:`contactcore.discretisation.solve`'s), ``h`` the
    cell size or node spacing in the scene's length unit (None: the
    scene's own), the options the method's (:func:`takes`; ``degree``, 1
    or 2, 1 unless given, is one of them); it refuses
    and fails as :func:`contactcore.discretisation.solve` does (a
    :class:`~contactcore.ContactError` naming the problem: a bad scene or
    ``h``, an option the method does not take, a failed solve).  An unknown
    ``name`` is refused with a ContactError."""
    module = PEERS[name] if name in PEERS else discretisation(name).module
    return importlib.import_module(module).solve


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
            raise ContactError(f"{FLAGS.get(option, option)}: means nothing for {', '.join(names)} "
                               + (f"(only {', '.join(takers)} take it)" if takers else "(no method takes it)"))


def check_launch(names: list[str], distributed: bool) -> None:
    """Refuse, under mpirun (``distributed``), a method whose solve does not
    spread over the ranks: each rank would solve it whole, alongside."""
    serial = [n for n in names if distributed and not discretisation(n).distributed]
    if serial:
        raise ContactError(f"mpirun: {', '.join(serial)} does not spread over mpirun's ranks: run it without mpirun")


def check_solvable(names: list[str], scene, h, degree: int, paper: bool, **given) -> None:
    """Refuse, before any method solves, a scene that one of the methods
    ``names`` refuses at its resolution (its options from ``given``, None
    not given): the checks its solve makes first
    (:func:`contactcore.discretisation.check_solvable`), so that a run of
    several methods does not solve some and then stop at another."""
    for name in names:
        solvable(scene, make(discretisation(name), degree=degree, **options_for(name, **given)), h, paper=paper)


def expand(names: list[str]) -> list[str]:
    """``all`` means every method built so far."""
    return list(METHODS) if "all" in names else names
