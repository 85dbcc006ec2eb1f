"""Direct factorisations with PETSc/MUMPS and an honest report of their health.

Defaults: ``preonly`` with MUMPS, by LDLᵀ (:data:`SYMMETRIC`) for a matrix
its owner says is symmetric while the interface tangent is symmetric too,
by LU otherwise.  Any PETSc option may be overridden
(``{"pc_factor_mat_solver_type": "superlu"}``, ``{"ksp_type": "gmres", ...}``).
With MUMPS, two of its features are switched on: null-pivot detection
(ICNTL(24), threshold CNTL(3)), which turns a singular system into a clear
error instead of garbage, and — only when asked for (``estimate_condition``)
— its error analysis (ICNTL(11)=1), whose condition estimate (RINFOG(10), Arioli–Demmel–Duff)
is reported and warned about above :data:`~contactcore.tolerances.CONDITION_WARN`.

Options are checked before the solve: a type PETSc does not list, or an
option PETSc refuses while setting up (an unparsable value, a factorisation
package this build lacks), is a :class:`PETScOptionError` that names the
option; an option PETSc never read (misspelt, or not for this solver) is a
warning in the report.  Each factorisation keeps its options in PETSc's
options database under its owner's ``prefix`` (the method that made the
matrix) and a number of its own, and removes them when destroyed.

Under mpirun every rank judges a solve alike: its residual by PETSc's
norms over the ranks, and its KSP reason and preconditioner failure
reduced over them (:func:`_outcome`), so that a factorisation that fails
on one rank's block only (``pc_type`` ``bjacobi`` or ``asm``) is refused
with the same message on every rank.

Every PETSc object made here is destroyed here, and every petsc4py handle
on a part of one (``ksp.getPC()``, ``pc.getFactorMatrix()``) is released
before its owner is destroyed: with petsc4py 3.18 a handle that outlives the
KSP keeps the PC and the MUMPS factor alive for good (measured: 2.4 MB per
solve of a 4 900-unknown Laplacian, ~0.3 GB per solve of a 1.4e5-unknown P2
system, and flat once the factor is destroyed before the KSP).  Neither
dolfinx nor MPI is imported: the matrices come from their owners (dolfinx's
for fe and xfem; EFGM's scipy matrices made PETSc's by
:mod:`efgm.petsc_matrices`), distributed or not.

One idea a module, each with its sources:

- :mod:`~contactcore.linear_solver.options`: the PETSc options, their
  defaults and MUMPS's switches, and the checks that name an option PETSc
  does not know, cannot use or never read;
- :mod:`~contactcore.linear_solver.diagnosis`: what MUMPS and PETSc say of
  a factorisation and a solve (MUMPS's status, null pivots, the KSP reason
  and the PC's failure, reduced over the ranks; the condition estimate;
  the residual), and how a failure is named;
- :mod:`~contactcore.linear_solver.factorisation`: :class:`Factorisation`,
  one KSP kept for a run, refactorised and solved;
- :mod:`~contactcore.linear_solver.tangent`: :class:`Tangent`, Newton's
  ``J = K + K_Γ`` refilled into kept slots and factorised;
- :mod:`~contactcore.linear_solver.library`: PETSc's C functions petsc4py
  does not wrap.

The arrows: ``tangent`` → ``factorisation`` → ``options``, ``diagnosis`` →
``library``.  Only this package imports petsc4py in contactcore, and only the
methods import this package.

The package's public names, imported here as
``contactcore.linear_solver.NAME``, are its modules' public functions,
classes and constants; a module's private helpers stay in their home.
"""
from .diagnosis import (KSP_DIVERGED, MUMPS_ERRORS, MUMPS_RELAXATIONS, MUMPS_WORKSPACE, PC_FAILURES, SINGULAR,
                        NullPivots)
from .factorisation import Factorisation
from .options import (BLOCKS, DEFAULT_OPTIONS, DEFAULT_PREFIX, MUMPS_ORDERING, OPTION_ERRORS, SYMMETRIC,
                      TYPED_OPTIONS, PETScOptionError, check_options, unused_options)
from .tangent import Tangent, is_symmetric

__all__ = [
    # options
    "BLOCKS", "DEFAULT_OPTIONS", "DEFAULT_PREFIX", "MUMPS_ORDERING", "OPTION_ERRORS", "SYMMETRIC", "TYPED_OPTIONS",
    "PETScOptionError", "check_options", "unused_options",
    # diagnosis
    "KSP_DIVERGED", "MUMPS_ERRORS", "MUMPS_RELAXATIONS", "MUMPS_WORKSPACE", "PC_FAILURES", "SINGULAR", "NullPivots",
    # factorisation
    "Factorisation",
    # tangent
    "Tangent", "is_symmetric",
]
