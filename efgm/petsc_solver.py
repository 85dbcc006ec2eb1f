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
with the options, measurements and reasons written there.  The symmetry
check costs 0.23 s on scene C at h = 0.0125 (7.9e4 unknowns).
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp


def available() -> bool:
    """Whether petsc4py imports (then MUMPS solves EFGM's systems)."""
    try:
        import petsc4py.PETSc  # noqa: F401
    except ImportError:
        return False
    return True


def tangent(A: sp.csr_matrix, interface_pattern: sp.spmatrix, *, estimate_condition: bool = False,
            what: str = "linear system"):
    """Newton's ``J = A + K_Γ`` on MUMPS (:class:`contactcore.linear_solver.Tangent`):
    LDLᵀ while ``J`` is symmetric, else LU; every unknown is free."""
    from contactcore import linear_solver

    union = (abs(A) + abs(sp.csr_matrix(interface_pattern))).tocsr()  # K's and every K_Γ's entries
    union.data[:] = 0.0
    return linear_solver.Tangent(linear_solver.to_petsc(A), np.arange(A.shape[0]), work=linear_solver.to_petsc(union),
                                 symmetric=linear_solver.is_symmetric(A), estimate_condition=estimate_condition,
                                 what=what)
