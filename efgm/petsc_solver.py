"""EFGM's systems solved by PETSc + MUMPS, through the solver of fe and xfem.

:func:`tangent` converts the scipy matrix to PETSc AIJ and factorises it
with :class:`contactcore.linear_solver.Tangent`: the same options, checks,
reuse and health report as the dolfinx methods; that module imports petsc4py but neither dolfinx nor MPI.
Nothing here is imported before :func:`available` is asked, so ``efgm``
still imports with numpy and scipy alone.

EFGM's saddle point ``[[K, s Cᵀ], [s C, 0]]`` is symmetric indefinite while
the interface law is (linear, or Coulomb in stick); a Coulomb slip tangent
is not symmetric.  A symmetric system is factorised by MUMPS's LDLᵀ for
general symmetric matrices (PETSc ``cholesky`` on an AIJ matrix not flagged
SPD: MUMPS SYM = 2, with two-by-two pivots), any other by LU.  Measured on
scene C at h = 0.0125, linear basis (79 660 unknowns, 7.2e6 entries, best
of 3, no condition estimate): LDLᵀ 1.9 s, LU 2.6 s, SuperLU
(:mod:`efgm.sparse_solver`) 13.5 s.  The symmetry check costs 0.23 s there.
Both factorisations compress the graph by 2 × 2 blocks (:data:`BLOCKS`).
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp


#: The factorisation of a symmetric (indefinite) system: MUMPS's LDLᵀ.
SYMMETRIC = {"pc_type": "cholesky"}

#: EFGM's systems are ordered by the shared AMF (contactcore.linear_solver.
#: MUMPS_ORDERING) on the graph compressed by 2 × 2 blocks (ICNTL(15) = −2,
#: an unknown's x and y; used when the size is even).  Measured on scene C
#: at h = 0.0125, linear basis (79 244 rows, 7.1e6 entries), paired in one
#: process, median of 4 under a load of 4 on 2 cores: LDLᵀ 2.12 s plain AMF,
#: 2.0 s with the compression.  PORD (ICNTL(7) = 4) was faster there (1.75
#: s; LU 3.78 → 2.70 s) but ends the whole process on a small dense graph
#: ("Error in function orderMinPriority: no valid number of stages in
#: multisector", then exit, no exception: every size from 2 to 20 measured),
#: which a coarse EFGM run can give: not used.
BLOCKS = {"mat_mumps_icntl_15": -2}


def options(size: int) -> dict:
    """The PETSc options of an EFGM system of ``size`` unknowns (global),
    serial or distributed alike: :data:`BLOCKS` when the size is even."""
    return BLOCKS if size % 2 == 0 else {}


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
                                 symmetric=SYMMETRIC if linear_solver.is_symmetric(A) else None,
                                 petsc_options=options(A.shape[0]), estimate_condition=estimate_condition, what=what)
