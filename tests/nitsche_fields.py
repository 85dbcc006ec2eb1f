"""Helpers of the Nitsche traction tests: a scene's law enforced exactly,
the built system's ``S`` and ``γ`` per method, and the unknowns of a field
given separately on each side of Γ.

fe (xdolfinx.conforming) has one Lagrange field per body on the whole
fitted mesh; ``S`` reads field k in the cell on k's side of each Γ facet,
so ``unknowns("fe", …)`` sets every dof of field k to ``f_k`` at its node.
Its traction takes the mesh's own normal ``n_h`` (the chord's on P1
cells, the curved map's on P2 cells), recovered here from each facet's
points by :func:`fe_mesh_normals`.

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
    """The built system of ``method`` ("efgm", "xfem" or "fe") for ``scene``."""
    if method == "fe":
        from xdolfinx import conforming
        from xdolfinx.options import FE
        return conforming.build(scene, FE(degree=degree, **options), Resolution(h), Timings())
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
    if method == "fe":
        return _fe_unknowns(built, f)
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


def _fe_unknowns(built, f) -> np.ndarray:
    """fe's unknowns (the mixed space's dofs this rank owns, ``S``'s
    owned columns) of ``f``: ``built.fields`` collapses each body's field
    out of the mixed space, so fed the owned dofs' global indices it hands
    back, per body, which global dof each local node's x and y value is
    (exact: integers below 2⁵³; a ghost's from its owner), beside the
    collapsed space's node coordinates.  Under mpirun, ``S`` reads these
    owned values forwarded to the ghosts (``GhostExchange.forward``)."""
    size = built.system.size
    ranks = built.system.collective
    start = sum(ranks.comm.allgather(size)[:ranks.rank]) if ranks.parallel else 0  # owned ranges in rank order
    x = np.zeros(size)
    for b, ub in enumerate(built.fields(np.arange(start, start + size, dtype=float)).displacements):
        index = ub.x.array.astype(np.int64).reshape(-1, 2) - start  # (nodes, x|y), the collapsed blocked order
        values = f(b, ub.function_space.tabulate_dof_coordinates()[:, :2])
        mine = (index >= 0) & (index < size)
        x[index[mine]] = values[mine]
    return x


def fe_facet_curves(points: np.ndarray, P: int, order: int) -> np.ndarray:
    """The coefficients (F, order + 1, 2) of ``x(ξ) = Σ c_k ξ^k`` through
    each fe Γ facet's ``P`` points (consecutive in ``points``, at the
    parameters ξ of contactcore.cutcell.gauss01(P) along the cell's edge):
    the facet's own geometry map of ``order`` (exact: P > order)."""
    from contactcore.cutcell import gauss01
    xi, _ = gauss01(P)
    pts = points.reshape(-1, P, 2)
    coef, *_ = np.linalg.lstsq(np.vander(xi, order + 1, increasing=True), pts.transpose(1, 0, 2).reshape(P, -1),
                               rcond=None)
    return coef.reshape(order + 1, -1, 2).transpose(1, 0, 2)


def fe_mesh_normals(points: np.ndarray, normals: np.ndarray, P: int, order: int) -> np.ndarray:
    """fe's mesh normal ``n_h`` (m, 2) at Γ's ``points``: normal to each
    facet's curve (:func:`fe_facet_curves`), turned to the side of the
    level set's ``normals`` (xdolfinx.conforming._mesh_normals, rebuilt
    from the points alone)."""
    from contactcore.cutcell import gauss01
    xi, _ = gauss01(P)
    coef = fe_facet_curves(points, P, order)
    d = np.einsum("pk,fki->fpi", np.column_stack([k * xi ** max(k - 1, 0) for k in range(order + 1)]), coef)
    t = d.reshape(-1, 2) / np.linalg.norm(d.reshape(-1, 2), axis=1)[:, None]
    n = np.column_stack([t[:, 1], -t[:, 0]])
    return n * np.sign(np.sum(n * normals, axis=1))[:, None]


def frame_traction(sigma: np.ndarray, normals: np.ndarray, acting: np.ndarray | None = None) -> np.ndarray:
    """``[n·σm, t·σm]`` (P, 2) of Voigt stresses (P, 3), ``t = (n_y, −n_x)``,
    ``m`` the normal σ ``acting`` on (``n`` unless given: fe's mesh normal)."""
    n = np.asarray(normals, float)
    m = n if acting is None else np.asarray(acting, float)
    sn = np.column_stack([sigma[:, 0] * m[:, 0] + sigma[:, 2] * m[:, 1], sigma[:, 2] * m[:, 0] + sigma[:, 1] * m[:, 1]])
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
