"""PETSc's C functions that petsc4py 3.18 does not wrap, found by name in the
library petsc4py runs on (the ``libpetsc`` mapped into this process,
``/proc/self/maps``) and called through ctypes: ``PetscOptionsUsed``
(:func:`~contactcore.linear_solver.options.unused_options`) and
``PCGetFailedReasonRank`` (:func:`~contactcore.linear_solver.diagnosis._pc_failure`).
Where one cannot be found, its caller says it could not ask.
"""
from __future__ import annotations

import ctypes
import functools


@functools.lru_cache(maxsize=None)
def _petsc_function(name: str, *argtypes):
    """The C function ``name`` of the PETSc library petsc4py runs on, for
    what petsc4py 3.18 does not wrap, or None where it cannot be found."""
    try:
        with open("/proc/self/maps") as maps:
            paths = [line.split()[-1] for line in maps if "/libpetsc" in line]
        function = getattr(ctypes.CDLL(paths[0]), name)
    except (OSError, IndexError, AttributeError):
        return None
    function.argtypes = list(argtypes)
    function.restype = ctypes.c_int
    return function
