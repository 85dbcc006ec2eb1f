"""xfem's ``flux="reaction"`` on PETSc: Γ's multiplier mesh and the
least-squares reaction (:mod:`contactcore.reaction_flux`) from ``K``, and
the matrix whose pattern holds its tangent beside ``K``'s."""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from contactcore import DiscretisationError
from contactcore import tolerances as tol
from contactcore.reaction_flux import multiplier_chain, multiplier_operator, serial_refusal
from contactcore.system import InterfaceOperator


def reaction_interface(scene, K, fixed: np.ndarray, operator: InterfaceOperator, h: float, parallel: bool,
                       method: str):
    """``(interface, work)``: the multiplier nodes at
    :data:`~contactcore.tolerances.MULTIPLIER_SPACING` ``h`` with the
    least-squares reaction of the bulk ``K`` (PETSc, one process; ``fixed``
    its prescribed unknowns) from the method's Gauss-point ``operator``,
    and :func:`working_pattern`; refused under mpirun (``parallel``)."""
    if parallel:
        raise DiscretisationError(serial_refusal(method))
    indptr, indices, values = K.getValuesCSR()
    A = sp.csr_matrix((values, indices, indptr), shape=K.getSize())
    chain = multiplier_chain(scene.interface, scene.domain, tol.MULTIPLIER_SPACING * h, method)
    interface = multiplier_operator(operator, A, fixed, chain, method)
    return interface, working_pattern(A, interface, K.getBlockSize())


def working_pattern(A: sp.csr_matrix, interface: InterfaceOperator, block: int):
    """A PETSc matrix (one process, block size ``block``, ``K``'s) with
    ``A``'s pattern and every entry the interface's tangent can reach
    (:meth:`~contactcore.system.InterfaceOperator.pattern`), values zero:
    ``SᵀWΓ⁻¹S`` couples every unknown near Γ, beyond ``K``'s pattern."""
    from petsc4py import PETSc
    ones = sp.csr_matrix((np.ones_like(A.data), A.indices, A.indptr), shape=A.shape)
    both = (ones + abs(interface.pattern())).tocsr()
    both.sort_indices()
    both.data[:] = 0.0
    return PETSc.Mat().createAIJ(both.shape, bsize=block, csr=(both.indptr.astype(PETSc.IntType),
                                                               both.indices.astype(PETSc.IntType), both.data),
                                 comm=PETSc.COMM_SELF)
