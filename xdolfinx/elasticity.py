"""The UFL stress of linear elasticity, shared by fe and xfem (no gmsh:
an xfem run on structured cells never imports it)."""
from __future__ import annotations

import ufl

from contactcore.elasticity import lame


def sigma(w, E: float, nu: float, plane: str):
    """``σ(w) = 2μ ε(w) + λ tr ε(w) I`` with the Lamé constants of ``plane``
    stress or strain."""
    lam, mu = lame(E, nu, plane)
    eps = ufl.sym(ufl.grad(w))
    return 2.0 * mu * eps + lam * ufl.tr(eps) * ufl.Identity(2)
