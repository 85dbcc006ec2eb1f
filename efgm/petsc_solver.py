"""EFGM's systems solved by PETSc + MUMPS, through the solver of fe and xfem.

:func:`tangent` converts the scipy matrix to PETSc AIJ and factorises it
with :class:`contactcore.linear_solver.Tangent`: the same options, checks,
reuse and health report as the dolfinx methods; that module imports petsc4py but neither dolfinx nor MPI.
Nothing here is imported before :func:`available` is asked, so ``efgm``
still imports with numpy and scipy alone.

EFGM's saddle point ``[[K, s Cᵀ], [s C, 0]]`` is symmetric indefinite while
the interface law is (linear, or Coulomb in stick); a Coulomb slip tangent
is not symmetric.  ``Tangent`` factorises a symmetric system by MUMPS's
LDLᵀ (its ``SYMMETRIC``, with two-by-two pivots), any other by LU, each on
the graph compressed by 2 × 2 blocks when the size is even (``BLOCKS``),
with the options, measurements and reasons written there.  EFGM's own
systems are symmetric by construction (:class:`efgm.method.EFGMSystem`:
the test cost 0.2 s on scene C at h = 0.0125, 7.9e4 unknowns); a matrix
from elsewhere is tested.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from contactcore.assembly import pattern_union

#: The options prefix of EFGM's factorisations in PETSc's options database.
PETSC_PREFIX = "efgm_"


def available() -> bool:
    """Whether petsc4py imports (then MUMPS solves EFGM's systems)."""
    try:
        import petsc4py.PETSc  # noqa: F401
    except ImportError:
        return False
    return True


def tangent(A: sp.csr_matrix, interface_pattern: sp.spmatrix, *, symmetric: bool | None = None,
            estimate_condition: bool = False, what: str = "linear system"):
    """Newton's ``J = A + K_Γ`` on MUMPS (:class:`contactcore.linear_solver.Tangent`):
    LDLᵀ while ``J`` is symmetric, else LU; every unknown is free.
    ``symmetric``: whether ``A`` is, known by construction, or None to
    test it (:func:`~contactcore.linear_solver.is_symmetric`)."""
    from contactcore import linear_solver

    from .petsc_matrices import to_petsc

    if symmetric is None:
        symmetric = linear_solver.is_symmetric(A)
    union = pattern_union(A, interface_pattern)  # K's and every K_Γ's entries
    return linear_solver.Tangent(to_petsc(A), np.arange(A.shape[0]), work=to_petsc(union),
                                 symmetric=symmetric, estimate_condition=estimate_condition, what=what,
                                 prefix=PETSC_PREFIX)
