"""The consistent interface traction of Nitsche's method, the same for
every unfitted method: weights, stabilisation, and the map from each
body's Voigt stress to ``[n·{σ}n, t·{σ}n]``.

At a point of Γ with unit normal ``n`` (from − to +) and ``t = (n_y, −n_x)``
the traction the bodies exchange is the weighted average

    {σ}n = w₋ σ(u⁻) n + w₊ σ(u⁺) n,   w₋ + w₊ = 1,

in Γ's frame ``τ = [n·{σ}n, t·{σ}n]`` (the law's ``[t_N, t_T]``: the + body
receives ``−(t_N n + t_T t)``, :mod:`contactcore.laws`).  The weights and
the stabilisation are those of Annavarapu, Hautefeuille and Dolbow, "A
robust Nitsche's formulation for interface problems", CMAME 233 (2012)
(Eqs. 30 and 37; and CMAME 268 (2014) for frictional sliding), on the
cell ``e`` that holds the point, cut by Γ into ``Ω₋ᵉ`` and ``Ω₊ᵉ``:

    w_k = (|Ω_kᵉ| / E_k) / Σ_j (|Ω_jᵉ| / E_j),
    γ   = β γ₀,   γ₀ = 2 |Γᵉ| / Σ_j (|Ω_jᵉ| / E_j)        (Pa/m),

``|Γᵉ|`` the length of Γ in the cell and ``β`` the law's dimensionless
``stabilisation``: the methods give ``γ₀``, the exact laws multiply it.  A sliver
side (``|Ω_kᵉ| → 0``) gets a weight → 0, and ``γ₀`` stays bounded by
``2 |Γᵉ| E_big / |Ω_bigᵉ|``: the traction is read from the side that
resolves it, so no inf-sup condition is met or needed.  numpy and scipy only.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from .geometry import tangent_of


def nitsche_weights(areas: np.ndarray, moduli: np.ndarray, length: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(w, γ₀)`` of points (module doc) from the areas (m, 2) of the − and
    + parts of each point's cell, the Young's moduli (2,) of the − and +
    bodies and the length (m,) of Γ in the cell: ``w`` (m, 2) with rows
    summing to 1, ``γ₀ = γ/β`` (m,) in Pa/m."""
    compliance = np.asarray(areas, float) / np.asarray(moduli, float)[None, :]
    total = compliance.sum(axis=1)
    return compliance / total[:, None], 2.0 * np.asarray(length, float) / total


def traction_maps(normals: np.ndarray, D: np.ndarray, weights: np.ndarray) -> np.ndarray:
    """``M[k, p]`` (2, m, 2, 3): the weighted traction of body k's Voigt
    strain at point p, ``τ_p = Σ_k M[k, p] ε_k(x_p)``, i.e.
    ``M[k, p] = w_k[p] [n; t] P(n) D_k`` with ``σn = P(n) σ_Voigt``,
    ``P(n) = [[n_x, 0, n_y], [0, n_y, n_x]]``; ``D`` (2, 3, 3) the bodies'
    Voigt matrices, ``weights`` (m, 2)."""
    n = np.asarray(normals, float)
    zero = np.zeros(len(n))
    P = np.stack([np.column_stack([n[:, 0], zero, n[:, 1]]), np.column_stack([zero, n[:, 1], n[:, 0]])], axis=1)
    frame = np.stack([n, tangent_of(n)], axis=1)  # rows n, t
    FP = frame @ P  # (m, 2, 3)
    return np.stack([weights[:, k, None, None] * FP @ D[k] for k in range(2)])


def traction_operator(maps: np.ndarray, strains) -> sp.csr_matrix:
    """``S`` (2m × n) with ``τ = S u`` from :func:`traction_maps` and each
    body's strain operator (3m × n, rows ``3p…3p+2`` = ε_xx, ε_yy, γ_xy of
    point p): ``S = Σ_k blockdiag(M[k]) B_k``."""
    m = maps.shape[1]
    rows = np.broadcast_to(2 * np.arange(m)[:, None, None] + np.arange(2)[None, :, None], (m, 2, 3))
    cols = np.broadcast_to(3 * np.arange(m)[:, None, None] + np.arange(3)[None, None, :], (m, 2, 3))
    out = None
    for M, B in zip(maps, strains):
        block = sp.csr_matrix((M.ravel(), (rows.ravel(), cols.ravel())), shape=(2 * m, 3 * m))
        part = block @ sp.csr_matrix(B)
        out = part if out is None else out + part
    return out.tocsr()
