"""The element-free Galerkin method ("efgm"), the paper's §VII (Eqs. 19–29).

MLS shape functions (:mod:`efgm.shape`) on a node set, Heaviside enrichment
of the nodes whose support reaches across Γ by more than a fraction of its
reach, the others not seen from across Γ (visibility; :mod:`efgm.operators`), integration on
background cells split exactly along Γ (:mod:`contactcore.quadrature`).  With the
operators ``N`` (displacement) and ``B`` (strain):

    K = Bᵀ W D B + Gᵀ W_Γ D_law G,   G = [n t]ᵀ (N₊ − N₋) on Γ,
    f = N_∂ᵀ W_∂ t̄ + N_Ωᵀ W_Ω b,

``W`` holding the quadrature weights.  MLS functions do not interpolate, so
essential conditions are imposed by Lagrange multipliers: on the supported
boundaries a hat function per knot of spacing ``h`` (weighted means of
``u − ū``, :func:`support_multipliers`, whose traction a linear field's
reaction is: the patch test passes), at the pins their points; no penalty
to tune.  The
saddle-point system is solved by MUMPS's LDLᵀ (the solver of fe and xfem)
when petsc4py imports, else by SuperLU (:mod:`efgm.sparse_solver`), through the
shared increments and Newton of :mod:`contactcore.newton` (one solve for the
linear law).  The history of a ``coulomb`` law is kept at the Gauss points
of Γ (``interface_rule``).  Under mpirun the cells, Γ's points and the
rows are split over the ranks (:mod:`efgm.distributed`).

numpy and scipy only: importing this package imports neither dolfinx,
petsc4py, mpi4py nor gmsh.
"""
from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse as sp

from contactcore import BODIES, ContactError, DiscretisationError, Result, Scene, Timings
from contactcore import discretisation
from contactcore.collective import SERIAL, Collective
from contactcore.discretisation import Built, Resolution, make
from contactcore import tolerances as tol
from contactcore.constraints import Constraints
from contactcore.system import ContactSystem, InterfaceOperator
from contactcore.geometry import tangent_of
from contactcore.interface_path import piece_centres
from contactcore.scene import BODY, body_force, edge_traction, place_of
from contactcore.result import check_points
from contactcore.scaling import Scales

from contactcore.exact import is_exact
from contactcore.reaction_flux import check_serial, multiplier_chain, multiplier_operator

from . import distributed, sparse_solver, traction
from .nodes import NodeSet, node_set, support_radii
from .operators import SYMMETRIC, Approximation, block_diagonal, find_enrichment
from .options import BASES, EFGM  # noqa: F401 (BASES re-exported: the bases by name)
from contactcore.cutcell import Rule, edge_crossings, gauss01
from contactcore.geometry import CircleInterface, Rectangle
from contactcore.quadrature import background_cells, boundary_rule, interface_rule, volume_rule
from .shape import MLS

METHOD = EFGM.name

#: Gauss points per direction in each background cell or sub-cell, and per
#: boundary segment, by basis degree.  The integrand of K is rational and the
#: cells ignore the supports, so the quadrature error decides the rate
#: (Dolbow & Belytschko 1999).  Measured on the pressurised rod (linear
#: basis, h = 0.1 → 0.025): L2 rates 1.56, 1.89 and 2.10 with 4, 5 and 6
#: points, at 2.8, 3.5 and 6.4 s on the finest set: 6 is the smallest that
#: keeps the optimal rate.  (A linear variationally consistent correction,
#: Chen et al. 2013, made the patch test exact with 2×2 points but, being
#: Petrov–Galerkin, turned its quadrature error into spurious reactions at
#: pins: rate 0.7 on the same case.  Not kept.)
GAUSS_POINTS = {1: 6, 2: 8}

#: Default dilation of the supports, ``r_I = dmax · c_I``: with the cubic
#: spline a linear basis needs about 12 nodes in a support (dmax = 2.0 on a
#: grid), a quadratic one about 28 (dmax = 3.0).
DMAX = {1: 2.0, 2: 3.0}


# ----- the discrete system --------------------------------------------------

class EFGMFields:
    """Displacement and stress of each body at arbitrary points."""

    def __init__(self, scene: Scene, approx: Approximation, U: np.ndarray):
        self.scene, self.approx, self.U = scene, approx, U
        self.D = scene.voigt_matrices()

    def displacement(self, points, bodies) -> np.ndarray:
        """``u`` (m, 2) of body ``bodies[i]`` (0 = −, 1 = +) at ``points[i]``
        ((m, 2)) on the method's dimensionless scene.  Only the arrays are
        checked here (shape, finite, bodies 0 or 1: FieldsError); where a
        point lies is checked by the Result's :class:`~contactcore.scaling.ScaledFields`
        before it arrives."""
        points, bodies = check_points(points, bodies)  # the arrays; the geometry is the Result's (ScaledFields)
        sv = self.approx.mls.evaluate(points, bodies)
        return (self.approx.displacement_operator(sv, bodies) @ self.U).reshape(-1, 2)

    def stress(self, points, bodies) -> np.ndarray:
        """``(σxx, σyy, σxy)`` (m, 3) of body ``bodies[i]`` at ``points[i]``,
        dimensionless; the arrays checked as for :meth:`displacement`."""
        points, bodies = check_points(points, bodies)
        sv = self.approx.mls.evaluate(points, bodies)
        eps = (self.approx.strain_operator(sv, bodies) @ self.U).reshape(-1, 3)
        return np.where(bodies[:, None] == 1, eps @ self.D[1].T, eps @ self.D[0].T)


def support_multipliers(scene: Scene, h: float, n: int):
    """The multipliers of the supported boundaries: on each piece of a
    supported boundary between the points where Γ meets it, hats (continuous,
    piecewise linear in arc length) on ``m = round(length / h)`` equal
    intervals, or one constant multiplier where ``m`` rounds to 0 (a piece
    at most h/2 long: Python rounds half to even); a
    closed rim that Γ does not meet is one periodic chain.  A row of the
    constraint is the hat's weighted mean of ``u_j − ū_j`` over its two
    intervals, each integrated with ``n`` Gauss points.  Returns, per
    multiplier, its support, component, knot (a point), and the matrix
    ``R`` (multipliers × Gauss points) of the normalised weights, with the
    Gauss points."""
    dom, itf = scene.domain, scene.interface
    g, gw = gauss01(n)
    owners, comps, knots, rows, cols, vals, pts = [], [], [], [], [], [], []
    count = 0
    for i, sup in enumerate(scene.supports):
        if isinstance(dom, Rectangle):
            a, b = {"bottom": (0, 1), "top": (3, 2), "left": (0, 3), "right": (1, 2)}[sup.boundary]
            a, b = dom.corners[a], dom.corners[b]
            curve = lambda t, a=a, b=b: a + t[:, None] * (b - a)  # noqa: E731
            length, closed = float(np.linalg.norm(b - a)), False
            breaks = sorted(edge_crossings(itf, a, b))
        else:
            c, R = np.asarray(dom.centre, float), dom.radius
            curve = lambda t, c=c, R=R: c + R * np.column_stack([np.cos(2 * np.pi * t), np.sin(2 * np.pi * t)])  # noqa: E731
            length, closed = 2 * np.pi * R, True
            chord = itf.chord(dom) if not isinstance(itf, CircleInterface) else None
            breaks = [] if chord is None else sorted((np.arctan2(*(chord - c).T[::-1]) / (2 * np.pi)) % 1.0)
        if closed and breaks:
            parts, periodic = list(zip(breaks, breaks[1:] + [breaks[0] + 1.0])), False
        elif closed:
            parts, periodic = [(0.0, 1.0)], True
        else:
            knots_t = [0.0] + [t for t in breaks if 0.0 < t < 1.0] + [1.0]
            parts, periodic = list(zip(knots_t[:-1], knots_t[1:])), False
        for t0, t1 in parts:
            m = int(round((t1 - t0) * length / h))
            edges = np.linspace(t0, t1, max(m, 1) + 1)
            tau = (edges[:-1, None] + g[None] * np.diff(edges)[:, None])  # (intervals, n)
            w = np.diff(edges)[:, None] * gw[None] * length
            first = sum(len(p) for p in pts)
            pts.append(curve(tau.ravel() % 1.0))
            q = first + np.arange(tau.size).reshape(tau.shape)
            if m == 0:  # one constant multiplier
                hats = [(q.ravel(), w.ravel())]
                where = [curve(np.array([0.5 * (t0 + t1)]) % 1.0)[0]]
            else:
                count_h = m if periodic else m + 1
                hats = [([], []) for _ in range(count_h)]
                for j in range(m):
                    hats[j][0].append(q[j]); hats[j][1].append(w[j] * (1 - g))
                    k = (j + 1) % count_h
                    hats[k][0].append(q[j]); hats[k][1].append(w[j] * g)
                hats = [(np.concatenate(a), np.concatenate(b)) for a, b in hats]
                where = list(curve(edges[:count_h] % 1.0))
            for comp in sup.fix:
                for (qq, ww), x in zip(hats, where):
                    rows.append(np.full(len(qq), count)); cols.append(qq); vals.append(ww / ww.sum())
                    owners.append(i); comps.append("xy".index(comp)); knots.append(x)
                    count += 1
    pts = np.concatenate(pts) if pts else np.zeros((0, 2))
    R = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(count, len(pts))) \
        if count else sp.csr_matrix((0, len(pts)))
    return np.asarray(owners, int), np.asarray(comps, int), np.reshape(knots, (-1, 2)), R, pts


def _constraints(scene: Scene, approx: Approximation, h: float, n: int, evaluated=None) -> Constraints:
    """The rows ``C u = g`` of the supports and the pins: the rows
    (``operator``), the values at full load, the support of each row (−1
    for a pin) and the point of each row.  A support is held in the mean
    over the hats of :func:`support_multipliers` (multipliers on the
    boundary, whose traction they carry: a traction linear along the edge
    is reproduced, so a linear field passes); a pin at its point (a pin
    carries no force in a balanced scene).  ``evaluated(count)``, if given,
    picks the rows whose shape functions are evaluated (a rank's own,
    :func:`efgm.distributed.owned_multipliers`); the others are zero."""
    nodes = approx.mls.nodes
    L = tol.NODE_MATCH * scene.length_scale
    for i, sup in enumerate(scene.supports):
        if not np.any(scene.domain.on_boundary(sup.boundary, nodes, L)):
            raise DiscretisationError(f"efgm: supports[{i}]: no node lies on boundary '{sup.boundary}' — the node "
                                      "set must include the supported boundaries")
    # two supports meeting at a corner, or a pin on a supported boundary, that prescribe one component differently
    held = []  # (point, component, value, owner) of the supports' ends, and the pins
    if isinstance(scene.domain, Rectangle):
        ends = {"bottom": (0, 1), "top": (3, 2), "left": (0, 3), "right": (1, 2)}
        for i, sup in enumerate(scene.supports):
            for c in ends[sup.boundary]:
                held += [(scene.domain.corners[c], "xy".index(comp), sup.value["xy".index(comp)], i) for comp in sup.fix]
    pins = []
    for pin in scene.pins:
        for comp in pin.fix:
            j = "xy".index(comp)
            on = [i for i, sup in enumerate(scene.supports) if comp in sup.fix
                  and scene.domain.on_boundary(sup.boundary, np.array([pin.point]), L)[0]]
            held.append((np.asarray(pin.point, float), j, 0.0, -1))
            if not on:  # a pin on a boundary that holds the same component is that boundary's
                pins.append((np.asarray(pin.point, float), j))
            else:
                held += [(np.asarray(pin.point, float), j, scene.supports[i].value[j], i) for i in on]
    for k, (p, j, v, o) in enumerate(held):
        for p2, j2, v2, o2 in held[:k]:
            if j == j2 and np.all(np.abs(p - p2) <= L) and (v != v2 or (v != 0 and o != o2)):
                raise DiscretisationError(f"efgm: two supports prescribe u_{'xy'[j]} at ({p[0]:.6g}, {p[1]:.6g}) "
                                          "with different values or load paths")
    owners, comps, knots, R, gpts = support_multipliers(scene, h, n)
    values = np.array([scene.supports[o].value[j] for o, j in zip(owners, comps)])
    owners = np.concatenate([owners, np.full(len(pins), -1)])
    comps = np.concatenate([comps, [j for _, j in pins]]).astype(int)
    values = np.concatenate([values, np.zeros(len(pins))])
    points = np.vstack([knots] + [p[None] for p, _ in pins])
    total = len(owners)
    if total == 0:
        return Constraints(np.zeros(0), np.zeros(0, int), operator=sp.csr_matrix((0, approx.ndofs)),
                           points=np.zeros((0, 2)))
    # every row as weights over points: the supports' Gauss points, then the pins
    W = sp.block_diag([R, sp.identity(len(pins))], format="csr") if len(pins) else R
    allpts = np.vstack([gpts] + [p[None] for p, _ in pins])
    rows = np.arange(total) if evaluated is None else evaluated(total)
    W = W[rows]
    used = np.unique(W.indices)
    W = W[:, used]
    bodies = scene.body_of(allpts[used])
    N = approx.displacement_operator(approx.mls.evaluate(allpts[used], bodies), bodies)
    pick = sp.diags((comps[rows] == 0).astype(float))
    C = pick @ W @ N[0::2] + (sp.identity(len(rows)) - pick) @ W @ N[1::2]
    if evaluated is not None:  # the rows in their places among all
        C = sp.csr_matrix((np.ones(len(rows)), (rows, np.arange(len(rows)))), shape=(total, len(rows))) @ C
    return Constraints(values, owners, operator=C.tocsr(), points=points)


def _body_forces(scene: Scene, vol: Rule) -> np.ndarray:
    """Each body force of the scene's loads (in order) at full value, times
    the weights of ``vol``'s points in its body: (P, L, 2)."""
    forces = []
    for load in scene.loads:
        if place_of(load) == BODY:
            mask = (vol.bodies == BODIES.index(load.body)) * vol.weights
            forces.append(mask[:, None] * np.column_stack(body_force(scene, load, vol.points[:, 0], vol.points[:, 1])))
    return np.stack(forces, axis=1) if forces else np.zeros((len(vol.weights), 0, 2))


def _load_vectors(scene: Scene, approx: Approximation, body_vectors: np.ndarray, h: float, n: int,
                  ranks: Collective = SERIAL) -> list[np.ndarray]:
    """One vector per load of the scene, at its full value: the body forces'
    from ``body_vectors`` (ndofs, L; summed with the stiffness,
    :meth:`~efgm.operators.Approximation.stiffness_and_forces`), the
    tractions' from this rank's share of each boundary's points."""
    vectors, body = [], iter(body_vectors.T)
    for load in scene.loads:
        kind = place_of(load)
        if kind == BODY:
            vectors.append(next(body))
            continue
        part = boundary_rule(scene, load.boundary, h, n)
        share = ranks.share(len(part[1]))
        pts, w, normals, bodies = (a[share] for a in part)
        t = edge_traction(scene, load, pts[:, 0], pts[:, 1], normals)
        N = approx.displacement_operator(approx.mls.evaluate(pts, bodies), bodies)
        vectors.append(N.T @ (w[:, None] * t).ravel())
    return vectors


class EFGMSystem(ContactSystem):
    """The saddle-point system ``[[K, s Cᵀ], [s C, 0]]`` as a
    :class:`~contactcore.system.ContactSystem`: every unknown is free (the
    supports are multiplier rows of the ``constraints``' operator, scaled by
    ``s`` = the largest E)."""

    def __init__(self, K, constraints: Constraints, loads, interface: InterfaceOperator, scale: float, coords, reach,
                 estimate_condition, what):
        self.scale, self.constraints = scale, constraints
        C = constraints.operator
        n, c = K.shape[0], C.shape[0]
        K = K.tocsr()  # padded to the full size without a copy of its entries, plus the constraint blocks
        padded = sp.csr_matrix((K.data, K.indices, np.concatenate([K.indptr, np.full(c, K.indptr[-1])])),
                               shape=(n + c, n + c))
        self.A = (padded + sp.bmat([[sp.csr_matrix((n, n)), self.scale * C.T], [self.scale * C, None]],
                                   format="csr")).tocsr()
        self.size = self.A.shape[0]
        self.ndofs = K.shape[0]
        self.constraint_rows = np.arange(self.ndofs, self.size)  # the multipliers' rows: s (C u − ū)
        self.loads = loads
        self.interface = dataclasses.replace(interface, G=widened(interface.G, self.size),
                                             S=widened(interface.S, self.size))
        self.fixed = np.zeros(0, int)
        self.coords, self.reach, self.estimate, self.what = coords, reach, estimate_condition, what
        self._tangent = None  # Newton's J and its factorisation, made at the first solve

    def fixed_values(self, support_factors) -> np.ndarray:
        return np.zeros(0)

    def external(self, load_factors, support_factors) -> np.ndarray:
        f = sum((lam * v for lam, v in zip(load_factors, self.loads)), np.zeros(self.ndofs))
        return np.concatenate([f, self.scale * self.constraints.at(support_factors)])

    def internal(self, u: np.ndarray) -> np.ndarray:
        return self.A @ u

    def solve(self, interface_tangent, rhs, force_scale=0.0, slot=0):
        if self._tangent is None:
            self._tangent = sparse_solver.tangent(self.A, self.interface.pattern(), coords=self.coords, reach=self.reach,
                                                  symmetric=SYMMETRIC, estimate_condition=self.estimate, what=self.what)
        return self._tangent.solve(interface_tangent, rhs, force_scale, slot)

    def column_budget(self, slot: int) -> int | None:
        """MUMPS solves a correction's columns as one block, as many as cost
        about one factorisation (:meth:`contactcore.linear_solver.Tangent.column_budget`);
        SuperLU solves them one by one (None)."""
        return self._tangent.column_budget(slot) if hasattr(self._tangent, "column_budget") else None

    def solve_columns(self, rhs: sp.spmatrix, slot: int) -> np.ndarray:
        if hasattr(self._tangent, "solve_columns"):
            return self._tangent.solve_columns(rhs, slot)
        return super().solve_columns(rhs, slot)

    def close(self) -> None:
        if self._tangent is not None:
            self._tangent.close()
        self._tangent = None


def reaction_interface(scene: Scene, system: EFGMSystem, h: float) -> InterfaceOperator:
    """``system``'s interface at Γ's multiplier nodes (spacing
    :data:`~contactcore.tolerances.MULTIPLIER_SPACING` ``h``) with the
    least-squares reaction as flux (:mod:`contactcore.reaction_flux`):
    ``R = A u − b`` of the saddle point, whose displacement rows hold the
    supports' multipliers' reactions ``s Cᵀ μ`` and on whose multiplier
    rows ``B`` is zero; every unknown is free."""
    chain = multiplier_chain(scene.interface, scene.domain, tol.MULTIPLIER_SPACING * h, METHOD)
    return multiplier_operator(system.interface, system.A, system.fixed, chain, METHOD)


def widened(M: sp.csr_matrix | None, size: int) -> sp.csr_matrix | None:
    """``M`` with ``size`` columns (the multipliers' after the unknowns'), its entries shared."""
    return None if M is None else sp.csr_matrix((M.data, M.indices, M.indptr), shape=(M.shape[0], size))


def build(scene: Scene, options: EFGM, resolution: Resolution, timings: Timings) -> Built:
    """The EFGM system of ``scene`` (:class:`~contactcore.discretisation.Discretisation`'s
    ``build``; :class:`efgm.options.EFGM` for the options)."""
    degree = options.degree
    n = GAUSS_POINTS[degree] if options.gauss is None else options.gauss
    dmax = DMAX[degree] if options.dmax is None else options.dmax
    ranks = Collective(distributed.communicator(options.comm))  # serial unless mpirun gave several ranks
    with timings.measure("mesh"):
        ns = node_set(scene, resolution, options.nodes)
        radii = support_radii(ns, dmax, options.support == "rectangular")
        vol = volume_rule(scene, ns.h, n)
        gam_pts, gam_w, gam_n = interface_rule(scene, ns.h, n)
    with timings.measure("assembly"):
        enrichment = find_enrichment(scene, ns.x, radii, vol.points, vol.bodies)
        mls = MLS(ns.x, radii, degree=degree, weight=options.weight, dilation=dmax, seen_from=enrichment.seen_from,
                  to_user=Scales.of(scene.user).to_user if scene.source is not None else None)
        approx = Approximation(mls, enrichment)
        D = scene.voigt_matrices()
        lo, hi = background_cells(scene, ns.h)
        origin, step = lo.min(axis=0), hi[0] - lo[0]
        mine = distributed.cell_share(vol.points, origin, step, ranks)  # this rank's cells (all in serial)
        cells = Rule(vol.points[mine], vol.weights[mine], vol.bodies[mine]) if ranks.parallel else vol
        pieces = piece_centres(gam_pts, gam_w, [n] * (len(gam_w) // n))  # interface_rule's segments
        share = ranks.share(len(gam_w))  # and Γ's points
        gam_pts, gam_w, gam_n, pieces = gam_pts[share], gam_w[share], gam_n[share], pieces[share]
        evaluated = (lambda c: distributed.owned_multipliers(ranks, approx.ndofs, c)) if ranks.parallel else None
        error = None
        try:  # what a rank evaluates alone may fail on it alone: every rank raises the error alike
            K, body_vectors = approx.stiffness_and_forces(cells, origin, step, D, _body_forces(scene, cells))
            m = len(gam_w)
            sv = [mls.evaluate(gam_pts, np.full(m, b)) for b in (0, 1)]
            jump = (approx.displacement_operator(sv[1], np.ones(m, int))
                    - approx.displacement_operator(sv[0], np.zeros(m, int)))
            G = block_diagonal(np.stack([gam_n, tangent_of(gam_n)], axis=1)) @ jump
            cells = (origin, step, np.rint((hi.max(axis=0) - origin) / step).astype(int))
            S, gamma = (traction.traction(scene, approx, sv, vol, cells, gam_pts, gam_n, n) if is_exact(scene.law)
                        else (None, None))
            constraints = _constraints(scene, approx, ns.h, n, evaluated)
            loads = _load_vectors(scene, approx, body_vectors, ns.h, n, ranks)
        except ContactError as exc:
            error = exc
        ranks.raise_any(error)
        scale, what = max(m.E for m in scene.materials.values()), f"scene {scene.name} (efgm)"
        interface = InterfaceOperator(G.tocsr(), gam_w, gam_pts, S=S, stabilisation=gamma, pieces=pieces)
        if ranks.parallel:
            check_serial(options.name, options.flux, scene.law, ranks.comm.size)
            system = distributed.DistributedEFGMSystem(K, constraints, loads, interface, scale, ranks,
                                                       options.estimate_condition, what)
        else:
            system = EFGMSystem(K, constraints, loads, interface, scale,
                                np.vstack([approx.dof_points(), constraints.points]), 2 * mls.reach,
                                options.estimate_condition, what)
            if options.flux == "reaction" and is_exact(scene.law):  # Γ's multipliers, the reaction as flux
                system.interface = reaction_interface(scene, system, ns.h)
    # the fields of the whole solution, on every rank (gathered: output only)
    return Built(system, lambda x: EFGMFields(scene, approx, ranks.gather(x)[:approx.ndofs]), approx.ndofs, h=ns.h,
                 warnings=_dilation_warnings(degree, dmax, options.gauss is None, n) + _cell_warnings(ns, radii, n),
                 record={"h": ns.h, "nodes": len(ns.x), "enriched_nodes": approx.enr.count, "dmax": dmax,
                         "weight": options.weight, "support": options.support, "gauss": n, "basis_degree": degree,
                         "flux": options.flux})


def _cell_warnings(ns: NodeSet, radii: np.ndarray, n: int) -> list[str]:
    """Supports smaller than :data:`~contactcore.tolerances.SUPPORT_CELL_WARN`
    of the background cells (whose size is the median node spacing): the
    cells' Gauss rule under-integrates them."""
    smallest = float(np.min(radii))
    if smallest >= tol.SUPPORT_CELL_WARN * ns.h:
        return []
    return [f"the smallest supports (radius {smallest:.2g}) are {smallest / ns.h:.2g} of the background cells "
            f"(h = {ns.h:.2g}, the median node spacing): the {n}x{n} Gauss rule per cell under-integrates their "
            "shape functions, and more nodes there can mean a larger error; pass gauss with more points, or give "
            "nodes of more even spacing"]


def _dilation_warnings(degree: int, dmax: float, default_gauss: bool, n: int) -> list[str]:
    """What a dilation outside :data:`~contactcore.tolerances.DMAX_WARN_RANGE` of the default costs."""
    low, high = tol.DMAX_WARN_RANGE[degree]
    if dmax < low * DMAX[degree]:
        return [f"dmax = {dmax:g} is below {low:g} of the default {DMAX[degree]:g}: supports that barely cover "
                "their neighbours give near-singular moment matrices, and stresses at least ten times the "
                "default's error (a hundred times at 0.75 of it, linear basis)"]
    if dmax > high * DMAX[degree] and default_gauss:
        return [f"dmax = {dmax:g} is above {high:g} of the default {DMAX[degree]:g}: the default {n}x{n} Gauss "
                "rule under-integrates such wide supports (error up to ten times the default's); pass gauss with "
                "more points"]
    return []


def solve(scene: Scene, h: float | None = None, *, paper: bool = False, progress=None, reuse=None,
          **options) -> Result:
    """Solve ``scene`` with EFGM: the contract's
    :func:`contactcore.discretisation.solve` with :class:`efgm.options.EFGM`
    ``(**options)``."""
    return discretisation.solve(scene, make(EFGM, **options), h, paper=paper, progress=progress, reuse=reuse)
