"""The PETSc options of a factorisation: its defaults, MUMPS's switches, and
the checks that name an option PETSc does not know, cannot use or never
read.

Defaults (:data:`DEFAULT_OPTIONS`): ``preonly`` with MUMPS, by LDLᵀ
(:data:`SYMMETRIC`) for a matrix its owner says is symmetric, by LU
otherwise, with the ordering :data:`MUMPS_ORDERING` and, for rows in node
pairs, the graph compressed by :data:`BLOCKS`.  Any PETSc option may be
overridden (``{"pc_factor_mat_solver_type": "superlu"}``,
``{"ksp_type": "gmres", ...}``).  With MUMPS, two of its features are
switched on (:func:`_options`): null-pivot detection (ICNTL(24), threshold
CNTL(3) = NULL_PIVOT), and — only when asked for (``estimate_condition``)
— its error analysis (ICNTL(11) = 1), whose condition estimate (RINFOG(10),
Arioli–Demmel–Duff) is reported.

Options are checked before the solve: a type PETSc does not list
(:data:`TYPED_OPTIONS`, :func:`check_options`), or an option PETSc refuses
while setting up (:data:`OPTION_ERRORS`: an unparsable value, a
factorisation package this build lacks, :func:`_refused`), is a
:class:`PETScOptionError` that names the option; an option PETSc never
read (misspelt, or not for this solver; :func:`unused_options`) is a
warning in the report.  Each factorisation keeps its options in PETSc's
options database under its owner's ``prefix`` (:data:`DEFAULT_PREFIX` when
it names none) and a number of its own, and removes them when destroyed
(:class:`~contactcore.linear_solver.factorisation.Factorisation`).
"""
from __future__ import annotations

import ctypes
import re

from petsc4py import PETSc

from contactcore.errors import SolverOptionError
from contactcore import tolerances as tol

from .library import _petsc_function


DEFAULT_OPTIONS = {"ksp_type": "preonly", "pc_type": "lu", "pc_factor_mat_solver_type": "mumps"}


#: MUMPS's fill-reducing ordering (ICNTL(7)): 2 = AMF.  Measured on the
#: 2D elasticity systems here (best of 3, solve stage): XFEM P2 on scene C
#: at 5.4e3 / 2.0e4 / 7.9e4 / 3.1e5 unknowns 0.027 / 0.100 / 0.50 / 2.52 s,
#: against 0.038 / 0.148 / 0.63 / 3.05 s with MUMPS's automatic choice
#: and 2.76 s with METIS at 3.1e5; XFEM P1 on scene A at 1.3e5: 0.70 s
#: against 0.94 s.
MUMPS_ORDERING = 2


#: The factorisation of a symmetric tangent (every method's, while its
#: interface law's tangent is symmetric): MUMPS's LDLᵀ for general symmetric
#: matrices (PETSc ``cholesky`` on an AIJ matrix not flagged SPD: MUMPS
#: SYM = 2, with two-by-two pivots, so EFGM's indefinite saddle point and
#: the positive definite fe and xfem tangents take the same code).  Half of
#: LU's operations; measured, XFEM P2 on scene B at 9.9e5 unknowns, one
#: process: solve stage 13.6 s (LU) against 8.1 s; EFGM on scene C at h =
#: 0.0125 (7.9e4 unknowns, best of 3, no condition estimate): 1.9 s against
#: LU 2.6 s and SuperLU (:mod:`efgm.sparse_solver`) 13.5 s.
SYMMETRIC = {"pc_type": "cholesky"}


#: MUMPS's analysis on the graph compressed by 2 × 2 blocks (ICNTL(15) =
#: −2: a node's x and y), used when the factorised rows come in such pairs
#: (:meth:`Tangent._paired`).  Measured: EFGM on scene C at h = 0.0125, LDLᵀ
#: 2.12 → 2.0 s (paired in one process, median of 4); XFEM P2 on scene B at
#: 9.9e5 unknowns, LDLᵀ, MUMPS's analysis 0.71 → 0.51 s on one rank and
#: 1.03–1.08 → 0.55 s on two (its serial part).  PORD (ICNTL(7) = 4) needs
#: half AMF's operations there (6.1e10 against 1.1–1.5e10) but its own
#: analysis takes 2.4 s, and it ends the whole process, without an
#: exception, on a small dense graph ("Error in function orderMinPriority:
#: no valid number of stages in multisector"; every size from 2 to 20
#: measured), which a coarse EFGM run can give: not used.
BLOCKS = {"mat_mumps_icntl_15": -2}


#: The options prefix of a factorisation whose maker names no owner.
DEFAULT_PREFIX = "contactcore_"


#: Options whose value names a PETSc type, and where petsc4py lists the types.
TYPED_OPTIONS = {"ksp_type": PETSc.KSP.Type, "pc_type": PETSc.PC.Type,
                 "pc_factor_mat_solver_type": PETSc.Mat.SolverType,
                 "pc_factor_mat_ordering_type": PETSc.Mat.OrderingType}


#: PETSc error codes that mean "this option cannot be used": PETSC_ERR_SUP
#: (56), PETSC_ERR_ARG_WRONG (62), PETSC_ERR_ARG_OUTOFRANGE (63, an
#: unparsable value), PETSC_ERR_ARG_UNKNOWN_TYPE (86), PETSC_ERR_MISSING_FACTOR
#: (92, no such factorisation package or kind in this build).
OPTION_ERRORS = (56, 62, 63, 86, 92)


class PETScOptionError(SolverOptionError):
    """A PETSc option that PETSc does not know or cannot use; the message names it."""


def _type_names(kinds) -> list[str]:
    return sorted({v for k, v in vars(kinds).items() if not k.startswith("_") and isinstance(v, str)})


def check_options(opts: dict) -> None:
    """Raise :class:`PETScOptionError` for a key that is not a plain option
    name or a type-valued option (:data:`TYPED_OPTIONS`) naming a type PETSc
    does not list."""
    for key, value in opts.items():
        if not isinstance(key, str) or not re.fullmatch(r"[A-Za-z]\w*", key):
            raise PETScOptionError(f"petsc option {key!r}: not an option name (letters, digits and _, "
                                   "without the leading -)")
        if key in TYPED_OPTIONS and str(value) not in _type_names(TYPED_OPTIONS[key]):
            raise PETScOptionError(f"petsc option {key}: unknown type {value!r}; PETSc knows "
                                   + ", ".join(_type_names(TYPED_OPTIONS[key])))


def _refused(exc: PETSc.Error, opts: dict) -> PETScOptionError:
    """The option PETSc refused while setting up: the one whose value its
    message quotes (else all of them), with PETSc's reason (its last line)."""
    reason = str(exc).strip().splitlines()[-1].removeprefix("[0] ").strip()
    words = set(re.findall(r"[\w.+-]+", reason))
    named = [f"{k}={v}" for k, v in opts.items() if str(v) in words] or [f"{k}={v}" for k, v in opts.items()]
    return PETScOptionError(f"petsc option {', '.join(named)}: PETSc cannot use it (error {exc.ierr}): {reason}")


def _options_used():
    """``PetscOptionsUsed``, or None where it cannot be found."""
    return _petsc_function("PetscOptionsUsed", ctypes.c_void_p, ctypes.c_char_p, ctypes.POINTER(ctypes.c_int))


def unused_options(prefix: str, opts: dict) -> list[str] | None:
    """The keys of ``opts`` (set under ``prefix``) that PETSc never read,
    or None if that cannot be asked."""
    used = _options_used()
    if used is None:
        return None
    flags = {key: ctypes.c_int(0) for key in opts}
    if any(used(None, (prefix + key).encode(), ctypes.byref(flag)) for key, flag in flags.items()):
        return None
    return [key for key, flag in flags.items() if not flag.value]


def _options(user: dict | None, estimate_condition: bool, paired: bool, symmetric: bool) -> dict:
    """The PETSc options: the defaults, then ``user``'s; with MUMPS, the
    :data:`SYMMETRIC` factorisation for a ``symmetric`` matrix unless the
    user chose one, :data:`BLOCKS` for a ``paired`` one, and the checks."""
    opts = {**DEFAULT_OPTIONS, **(user or {})}
    mumps = opts.get("pc_factor_mat_solver_type") == "mumps"
    if mumps and symmetric:
        opts.update({key: value for key, value in SYMMETRIC.items() if key not in (user or {})})
    if mumps and opts.get("pc_type") in ("lu", "cholesky"):
        opts.setdefault("mat_mumps_icntl_7", MUMPS_ORDERING)
        if paired:
            opts.update({key: value for key, value in BLOCKS.items() if key not in opts})
        opts.setdefault("mat_mumps_icntl_24", 1)
        opts.setdefault("mat_mumps_cntl_3", tol.NULL_PIVOT)
        if estimate_condition:
            opts.setdefault("mat_mumps_icntl_11", 1)
    return opts
