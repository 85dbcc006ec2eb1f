"""Helpers of the Nitsche traction tests: a scene's law enforced exactly,
the built system's ``S`` and ``γ`` per method, and the unknowns of a field
given separately on each side of Γ.

``unknowns_*`` set the nodal values so that each body's approximation is
``f_k`` wherever the basis reproduces it: a node on side s carries
``u_I = f_s(x_I)`` and, enriched, ``a_I = (f_o − f_s)(x_I) / (H_o − H_s)``
(o the other side), so that ``u_I + (H_k − H_I) a_I = f_k(x_I)`` for both
bodies k (the shifted Heaviside of both methods).
"""
from __future__ import annotations

import numpy as np

from contactcore.discretisation import Resolution
from contactcore.enforcement import make_law
from contactcore.result import Timings


def exact(scene):
    """``scene`` with a unilateral law enforced exactly."""
    return scene.with_changes(law=make_law({"type": "unilateral", "enforcement": "exact"}))


def build(method: str, scene, degree: int, h: float, **options):
    """The built system of ``method`` ("efgm" or "xfem") for ``scene``."""
    if method == "efgm":
        from efgm.method import build as efgm_build
        from efgm.options import EFGM
        return efgm_build(scene, EFGM(degree=degree, **options), Resolution(h), Timings())
    from xdolfinx import xfem
    from xdolfinx.options import XFEM
    return xfem.build(scene, XFEM(degree=degree, **options), Resolution(h), Timings())


def _values(side: np.ndarray, f, x: np.ndarray, enriched: np.ndarray):
    """(own values (N, 2), enriched values (E, 2)) of nodes at ``x`` on ``side`` (±1)."""
    own = np.where(side[:, None] > 0, f(1, x), f(0, x))
    other = np.where(side[:, None] > 0, f(0, x), f(1, x))
    return own, (other[enriched] - own[enriched]) / (-2.0 * side[enriched])[:, None]


def unknowns(method: str, built, f) -> np.ndarray:
    """The unknowns (``S``'s columns, serial) of the fields ``f(body, x)``."""
    fields = built.fields(np.zeros(built.system.size))
    if method == "efgm":
        approx = fields.approx
        enr = approx.enr
        own, a = _values(enr.node_side, f, approx.mls.nodes, enr.index >= 0)
        x = np.zeros(built.system.size)
        x[:own.size] = own.ravel()
        x[own.size + 2 * enr.index[enr.index >= 0, None] + np.arange(2)] = a
        return x
    space = fields.space
    own, a = _values(space.cells.node_side, f, space.V.tabulate_dof_coordinates()[:, :2], space.enriched)
    return np.concatenate([own.ravel(), a.ravel()])  # a in node order: the enriched blocks' order


def frame_traction(sigma: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """``[n·σn, t·σn]`` (P, 2) of Voigt stresses (P, 3), ``t = (n_y, −n_x)``."""
    n = np.asarray(normals, float)
    sn = np.column_stack([sigma[:, 0] * n[:, 0] + sigma[:, 2] * n[:, 1], sigma[:, 2] * n[:, 0] + sigma[:, 1] * n[:, 1]])
    t = np.column_stack([n[:, 1], -n[:, 0]])
    return np.column_stack([np.sum(sn * n, axis=1), np.sum(sn * t, axis=1)])


class PolynomialFields:
    """Seeded fields of ``degree`` 1 or 2, one per body:
    ``f_k(x) = c_k + A_k x + Q_k(x, x)``, and their stresses."""

    def __init__(self, degree: int, seed: int = 0, scale: float = 1e-3):
        rng = np.random.default_rng(seed)
        self.c, self.A = rng.normal(size=(2, 2)) * scale, rng.normal(size=(2, 2, 2)) * scale
        self.Q = rng.normal(size=(2, 2, 2, 2)) * scale * (degree == 2)

    def __call__(self, body: int, x: np.ndarray) -> np.ndarray:
        return self.c[body] + x @ self.A[body].T + np.einsum("ijk,pj,pk->pi", self.Q[body], x, x)

    def stress(self, body: int, x: np.ndarray, D: np.ndarray) -> np.ndarray:
        """Voigt σ (P, 3) of body ``body``'s field at ``x``, ``D`` (2, 3, 3)."""
        Q = self.Q[body]
        grad = self.A[body][None] + np.einsum("ijk,pk->pij", Q + Q.transpose(0, 2, 1), x)
        eps = np.column_stack([grad[:, 0, 0], grad[:, 1, 1], grad[:, 0, 1] + grad[:, 1, 0]])
        return eps @ D[body].T
