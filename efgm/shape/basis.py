"""The MLS polynomial basis: monomials of degree 1 or 2, shifted and scaled.

The basis ``p`` of the moving least-squares fit (Lancaster & Šalkauskas,
Math. Comp. 37, 1981; in EFG, Belytschko, Lu & Gu, IJNME 37, 1994) is
complete to degree 1 (``1, ξ, η``) or 2 (``… ξ², ξη, η²``).  It is taken
*shifted and scaled*, ``p̃(y) = p((y − x̄)/s)`` (the paper's §VII; the
package's doc, :mod:`efgm.shape`): the shape functions do not depend on
``x̄`` and ``s``, the moment matrix's conditioning does.
:func:`_shift` moves a basis taken at one centre and scale to another,
``p(ρ (u − v)) = M p(u)``, so that a moment matrix summed once for a
group of points (:meth:`efgm.shape.MLS.cell_shape`) is moved to each
point's own, ``A = M Â Mᵀ``.

Contract: :func:`basis_size` is the number m of monomials (3 or 6);
:func:`_basis` stacks them first, (m, *ξ.shape); :data:`_SYMMETRIC`
places the m(m+1)/2 distinct products ``p_i p_j`` in an m × m symmetric
matrix; :func:`_shift` returns ``M`` (…, m, m).  The monomials' order is
the same in all four.
"""
from __future__ import annotations

import numpy as np


def basis_size(degree: int) -> int:
    """The number of monomials of the MLS basis of ``degree``: 3 for the
    linear basis (1, ξ, η), 6 for the quadratic; another degree is a
    KeyError (the options refuse it first,
    :func:`contactcore.discretisation.check_degree`)."""
    return {1: 3, 2: 6}[degree]


def _basis(xi: np.ndarray, eta: np.ndarray, degree: int) -> np.ndarray:
    """The monomials of ``degree`` at (ξ, η), stacked first: (m, *ξ.shape)."""
    cols = [np.ones_like(xi), xi, eta]
    if degree == 2:
        cols += [xi * xi, xi * eta, eta * eta]
    return np.stack(cols, axis=0)


#: For m = 3, 6: the position among the distinct products ``p_i p_j``
#: (i ≤ j, row by row) of each entry of an m × m symmetric matrix.
_SYMMETRIC = {}
for _m in (3, 6):
    _SYMMETRIC[_m] = np.zeros((_m, _m), int)
    _SYMMETRIC[_m][np.triu_indices(_m)] = np.arange(_m * (_m + 1) // 2)
    _SYMMETRIC[_m] = np.maximum(_SYMMETRIC[_m], _SYMMETRIC[_m].T).ravel()


def _shift(v: np.ndarray, rho: np.ndarray, degree: int) -> np.ndarray:
    """``M`` (…, m, m) with ``p(ρ (u − v)) = M p(u)`` for the monomials of
    ``degree``: v (…, 2), ρ (…)."""
    a, b = v[..., 0], v[..., 1]
    one, zero = np.ones_like(a), np.zeros_like(a)
    rows = [[one, zero, zero], [-rho * a, rho, zero], [-rho * b, zero, rho]]
    if degree == 2:
        r2 = rho * rho
        rows = [row + [zero, zero, zero] for row in rows] + [
            [r2 * a * a, -2 * r2 * a, zero, r2, zero, zero],
            [r2 * a * b, -r2 * b, -r2 * a, zero, r2, zero],
            [r2 * b * b, zero, -2 * r2 * b, zero, zero, r2]]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)
