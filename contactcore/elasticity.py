"""Isotropic linear elasticity in 2D (plane stress or plane strain).

Voigt order everywhere: ``(xx, yy, xy)`` for stress and ``(xx, yy, 2xy)``
for strain, so that ``σ = D ε``.
"""
from __future__ import annotations

import numpy as np


def lame(E: float, nu: float, plane: str) -> tuple[float, float]:
    """Lamé constants ``(λ, μ)`` of the 2D model.

    Plane strain: ``λ = Eν/((1+ν)(1-2ν))``; plane stress replaces λ by
    ``λ* = Eν/(1-ν²) = 2λμ/(λ+2μ)`` (thickness 1, σ_zz = 0).
    """
    mu = E / (2.0 * (1.0 + nu))
    if plane == "stress":
        return E * nu / (1.0 - nu * nu), mu
    return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu


def voigt_matrix(E: float, nu: float, plane: str) -> np.ndarray:
    """The 3×3 matrix ``D`` with ``σ = D ε`` in Voigt notation
    ``(σxx, σyy, σxy)``, ``(εxx, εyy, γxy = 2εxy)``, from Young's modulus
    ``E`` (in the scene's stress unit; D has that unit) and Poisson's
    ratio ``nu``; ``plane`` is ``"stress"``, and any other value means
    plane strain (the scene's validation refuses others before; ν, E are
    not checked here, ν = 0.5 in plane strain divides by zero)."""
    lam, mu = lame(E, nu, plane)
    return np.array([[lam + 2 * mu, lam, 0.0], [lam, lam + 2 * mu, 0.0], [0.0, 0.0, mu]])


def compliance(E: float, nu: float, plane: str) -> np.ndarray:
    """The inverse of :func:`voigt_matrix` (same arguments): ``ε = C σ``,
    in the inverse of the stress unit; a singular ``D`` raises numpy's
    LinAlgError."""
    return np.linalg.inv(voigt_matrix(E, nu, plane))
