"""The UFL of linear elasticity shared by fe and xfem: the stress, and
whether a load's form vanishes (no gmsh: an xfem run on structured cells
never imports it)."""
from __future__ import annotations

import ufl

from contactcore.elasticity import lame


def sigma(w, E: float, nu: float, plane: str):
    """``σ(w) = 2μ ε(w) + λ tr ε(w) I`` with the Lamé constants of ``plane``
    stress or strain."""
    lam, mu = lame(E, nu, plane)
    eps = ufl.sym(ufl.grad(w))
    return 2.0 * mu * eps + lam * ufl.tr(eps) * ufl.Identity(2)


def vanishes(form) -> bool:
    """Whether every integrand of ``form`` is UFL's zero: a load of value
    zero, which UFL folds to ``Zero`` while keeping the integral, and for
    which dolfinx's assembler finds no kernel to call."""
    return all(isinstance(i.integrand(), ufl.constantvalue.Zero) for i in form.integrals())
