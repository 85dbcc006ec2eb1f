"""GetFEM's own contact bricks: an independent peer of our exact contact.

Our exact laws (``enforcement = "exact"``) are enforced by Nitsche's method
(docs/contact-enforcement.md).  This module solves the same scene with a
different formulation in a different code, GetFEM 5.4 (Debian's
``python3-getfem``): Lagrange multipliers on Γ with Alart and Curnier's
augmented Lagrangian (Alart & Curnier, CMAME 92, 1991; Renard, CMAME 256,
2013, for the integral form GetFEM implements).  Only the studies import it;
a missing GetFEM is a clear error.

The model, in GetFEM's own terms:

* the − and the + body are two GetFEM meshes, from the same gmsh model as
  our fe method (:func:`meshes.build.build_model`): triangles of size h,
  geometry of the elements' degree (curved on a circle at degree 2), the
  two meshes conforming along Γ but separate objects, so each body has its
  own displacement ``u1`` (−) and ``u2`` (+), ``FEM_PK(2, k)``;
* ``add_integral_contact_between_nonmatching_meshes_brick``, option 1 (the
  non-symmetric Alart–Curnier method): the multiplier λ, the traction on
  the − body, is a ``FEM_PK(2, 1)`` field on the − body's side of Γ; the
  + body's trace is projected onto it.  GetFEM's normal is the − body's
  outward normal, our n; its contact holds where ``λ_N − r (u1 − u2)·n < 0``;
* friction (``coulomb``): GetFEM's quasi-static law acts on the slip
  increment ``(u1 − w1) − (u2 − w2)`` with ``w`` the previous increment's
  displacements (``alpha`` = 1): a point sticks when its jump does not
  move, ``|λ_T| ≤ μ|λ_N|``, and slips against its increment otherwise.
  With multipliers a stick is exact, so the slip accumulated so far is the
  jump itself; this is the slip state our Nitsche law converges to
  (docs/contact-enforcement.md, "The slip state");
* ``unilateral`` (closed points tied, open points free): the same brick
  without a previous displacement and with μ = :data:`TIE_FRICTION`: a
  closed point's total tangential jump is held at zero.  A point that
  slips all the same is refused by name (the tie did not hold);
* edges held by multipliers of degree k (both components, or one at a
  prescribed displacement, as the layered-slip closed form's top), edge
  tractions and pressures as source terms, each increment's factors of
  the loads and supports (:meth:`Scene.factors`), GetFEM's Newton with
  MUMPS.

Sign conventions (docs/scenes.md): λ is the traction on the − body, so
``t_N = λ·n`` (< 0 in compression) and ``t_T = λ·t``, ``t = (n_y, −n_x)``;
``g = (u2 − u1)·(n, t)``.  The interface record (:class:`InterfacePath`)
holds Gauss points of each Γ facet, so profiles report λ's mean over each
facet, as for our exact laws.  Each point's status at an increment is
GetFEM's own test: open where ``λ_N + r g_N ≥ 0``, else stick where
``|λ_T + r Δg_T| ≤ μ (−λ_N − r g_N)``, else slip.
"""
from __future__ import annotations

import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from contactcore import ContactError, DiscretisationError, Result, Scene, Timings
from contactcore.elasticity import lame
from contactcore.enforcement import make_law
from contactcore.exact import is_exact
from contactcore.geometry import CircleInterface, LineInterface, tangent_of
from contactcore.interface_path import Increment, InterfacePath, piece_centres
from contactcore.laws import OPEN, SLIP, STICK
from contactcore.result import SolverReport
from contactcore.budget import check_budget
from contactcore.scene import InterfaceProfile, Pressure, Traction, check_resolution
from meshes.build import build_model, gmsh_session
from meshes.tags import BODY, INTERFACE
from verification.peer_getfem import EDGE_NORMALS, NUDGE, GetFEMFields, geometry_problems, getfem_module

METHOD = "getfem-contact"

#: Degree of the multiplier on Γ: P1 against P1 or P2 displacements (a
#: stable mortar pair on the − body's trace; GetFEM's contact demos' choice).
MULTIPLIER_DEGREE = 1

#: Alart–Curnier's augmentation r, a multiple of the larger Young's modulus
#: (GetFEM's documentation: "close to the Young modulus").  It moves the
#: discrete answer little (10 E: C-coulomb's C4 t_T by 0.69 % RMS at
#: h = 0.05) and decides whether Newton finds the status map: at E/3 and
#: E/10 it did not on C-coulomb's first increment (docs/peer-contact.md).
AUGMENTATION = 1.0

#: μ standing for "no limit" in the tied law (``unilateral``): a closed
#: point would have to carry a shear 1e6 times its pressure to slip.
TIE_FRICTION = 1e6

#: Gauss–Legendre points per Γ facet for the interface record: exact for a
#: degree-7 polynomial in the facet's parameter, where λ is linear and a
#: degree-2 facet's speed on a circle varies by O(θ²) over its angle θ.
FACET_POINTS = 4

#: Newton's test: the residual in force units against the loads
#: (:func:`_residual`), and the iterations it may take.
NEWTON_RESIDUAL = 1e-10
NEWTON_ITERATIONS = 100

#: Relative tolerance of a face's position on a named edge or on Γ.
FACE_MATCH = 1e-6

LINEAR_SOLVER = "mumps"

#: gmsh's element types: 3- and 6-node triangles, 2- and 3-node lines.
_GMSH_TRIANGLE = {1: 2, 2: 9}
_GMSH_LINE = {1: 1, 2: 8}

#: GetFEM's node order of a ``GT_PK(2, 2)`` triangle from gmsh's (vertices,
#: then the midpoints of edges 01, 12, 20).
_GMSH_TO_GETFEM = {1: [0, 1, 2], 2: [0, 3, 1, 5, 4, 2]}

#: GetFEM region numbers: Γ, then one per named edge.
_GAMMA = 1
_EDGES = {"left": 11, "right": 12, "bottom": 13, "top": 14}


def _check(scene: Scene, degree: int, paper: bool) -> None:
    """The peer covers exact unilateral or Coulomb contact on a rectangle
    with a straight or circular Γ, edges held in x, y or both (at zero or a
    prescribed displacement) and edge tractions or pressures."""
    if degree not in (1, 2):
        raise DiscretisationError(f"{METHOD}: degree must be 1 or 2 (got {degree})")
    if paper:
        raise DiscretisationError(f"{METHOD}: the paper's grids are structured; this peer meshes Γ: give h")
    problems = geometry_problems(scene)
    if not is_exact(scene.law) or scene.law.name not in ("unilateral", "coulomb"):
        problems.append(f"the interface law must be unilateral or coulomb with enforcement = \"exact\" (got "
                        f"{scene.law.enforcement} '{scene.law.name}')")
    if scene.pins:
        problems.append("supports must hold whole edges (no pins)")
    if any(not isinstance(ld, (Traction, Pressure)) for ld in scene.loads):
        problems.append("loads must be edge tractions or pressures")
    if problems:
        raise DiscretisationError(f"{METHOD}: scene {scene.name} is outside the peer's reach: "
                                  + "; ".join(problems))


# ----- meshes ---------------------------------------------------------------

def _gmsh_meshes(scene: Scene, h: float, degree: int) -> tuple[dict, np.ndarray]:
    """Each body's triangles as node coordinates (2, nodes per cell, cells)
    in GetFEM's order, and Γ's facets (facets, nodes, 2) in gmsh's order
    (end points, then the midpoint at degree 2)."""
    import gmsh
    with gmsh_session():
        build_model(scene, h, order=degree)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        xy = np.zeros((int(tags.max()) + 1, 2))
        xy[tags.astype(int)] = coords.reshape(-1, 3)[:, :2]
        cells = {}
        for body, tag in BODY.items():
            nodes = [gmsh.model.mesh.getElementsByType(_GMSH_TRIANGLE[degree], s)[1]
                     for s in gmsh.model.getEntitiesForPhysicalGroup(2, tag)]
            conn = np.concatenate(nodes).astype(int).reshape(-1, len(_GMSH_TO_GETFEM[degree]))
            cells[body] = xy[conn[:, _GMSH_TO_GETFEM[degree]]].transpose(2, 1, 0)
        lines = [gmsh.model.mesh.getElementsByType(_GMSH_LINE[degree], c)[1]
                 for c in gmsh.model.getEntitiesForPhysicalGroup(1, INTERFACE)]
        facets = xy[np.concatenate(lines).astype(int).reshape(-1, degree + 1)]
    return cells, facets


def _getfem_mesh(gf, cells: np.ndarray, degree: int):
    m = gf.Mesh("empty", 2)
    m.add_convex(gf.GeoTrans(f"GT_PK(2,{degree})"), np.asfortranarray(cells))
    return m


def _gamma_faces(scene: Scene, m, body: str) -> np.ndarray:
    """The outer faces of a body's mesh on Γ: inside the circle's ball, or
    along the line's normal (outward: n for −, −n for +)."""
    itf, L = scene.interface, scene.length_scale
    if isinstance(itf, CircleInterface):
        return m.outer_faces_in_ball(np.asarray(itf.centre, float), itf.radius + FACE_MATCH * L)
    n = np.asarray(itf.normal, float) * (1 if body == "minus" else -1)
    return m.outer_faces_with_direction(n, FACE_MATCH)


def _edge_faces(scene: Scene, m) -> dict[str, np.ndarray]:
    """The outer faces of a body's mesh on each named edge of the rectangle."""
    (x0, y0), (a, b) = scene.domain.corner, scene.domain.size
    e = FACE_MATCH * scene.length_scale
    boxes = {"left": ([x0 - e, y0 - e], [x0 + e, y0 + b + e]), "right": ([x0 + a - e, y0 - e], [x0 + a + e, y0 + b + e]),
             "bottom": ([x0 - e, y0 - e], [x0 + a + e, y0 + e]), "top": ([x0 - e, y0 + b - e], [x0 + a + e, y0 + b + e])}
    return {name: m.outer_faces_in_box(*map(np.array, box)) for name, box in boxes.items()}


# ----- the model --------------------------------------------------------------

class _Bodies:
    """GetFEM's meshes, spaces and integration methods of the two bodies."""

    VARS = {"minus": "u1", "plus": "u2"}

    def __init__(self, gf, scene: Scene, h: float, degree: int):
        cells, self.facets = _gmsh_meshes(scene, h, degree)
        self.mesh, self.mfu, self.mim, self.edges = {}, {}, {}, {}
        for body in BODY:
            m = _getfem_mesh(gf, cells[body], degree)
            m.set_region(_GAMMA, _gamma_faces(scene, m, body))
            self.edges[body] = {}
            for name, faces in _edge_faces(scene, m).items():
                if faces.size:
                    m.set_region(_EDGES[name], faces)
                    self.edges[body][name] = _EDGES[name]
            mfu = gf.MeshFem(m, 2)
            mfu.set_fem(gf.Fem(f"FEM_PK(2,{degree})"))
            self.mesh[body], self.mfu[body] = m, mfu
            self.mim[body] = gf.MeshIm(m, gf.Integ(f"IM_TRIANGLE({4 * degree})"))
        m1 = self.mesh["minus"]
        base = gf.MeshFem(m1, 2)
        base.set_fem(gf.Fem(f"FEM_PK(2,{MULTIPLIER_DEGREE})"))
        self.mflambda = gf.MeshFem("partial", base, base.basic_dof_on_region(_GAMMA))
        self.keep = [base]  # GetFEM frees an object with its last Python reference

    def dofs(self) -> int:
        return int(sum(mf.nbdof() for mf in self.mfu.values()) + self.mflambda.nbdof())


def _bricks(gf, md, scene: Scene, bodies: _Bodies, degree: int) -> None:
    """Elasticity per body, the contact brick, clamped edges, tractions at
    factor 0 (set per increment by :func:`_set_loads`)."""
    for body, var in _Bodies.VARS.items():
        md.add_fem_variable(var, bodies.mfu[body])
        mat = scene.materials[body]
        lam, mu = lame(mat.E, mat.nu, scene.plane)
        md.add_initialized_data(f"lambda_{var}", [lam])
        md.add_initialized_data(f"mu_{var}", [mu])
        md.add_isotropic_linearized_elasticity_brick(bodies.mim[body], var, f"lambda_{var}", f"mu_{var}")
        for i, support in enumerate(scene.supports):
            if support.boundary in bodies.edges[body]:
                _support(gf, md, bodies, body, i, support, degree)
        for i, load in enumerate(scene.loads):
            if load.boundary in bodies.edges[body]:
                md.add_initialized_data(f"T{i}_{var}", [0.0, 0.0])
                md.add_source_term_brick(bodies.mim[body], var, f"T{i}_{var}", bodies.edges[body][load.boundary])
    md.add_fem_variable("lambda", bodies.mflambda)
    md.add_initialized_data("r", [AUGMENTATION * max(m.E for m in scene.materials.values())])
    if scene.law.name == "coulomb":
        md.add_initialized_data("friction", [scene.law.mu])
        md.add_initialized_data("alpha", [1.0])
        for var in _Bodies.VARS.values():
            md.add_initialized_fem_data(f"w_{var}", md.mesh_fem_of_variable(var), np.zeros(md.variable(var).size))
        md.add_integral_contact_between_nonmatching_meshes_brick(
            bodies.mim["minus"], "u1", "u2", "lambda", "r", "friction", _GAMMA, _GAMMA, 1, "alpha", "w_u1", "w_u2")
    else:
        md.add_initialized_data("friction", [TIE_FRICTION])
        md.add_integral_contact_between_nonmatching_meshes_brick(
            bodies.mim["minus"], "u1", "u2", "lambda", "r", "friction", _GAMMA, _GAMMA, 1)


def _support(gf, md, bodies: _Bodies, body: str, i: int, support, degree: int) -> None:
    """Support i on one body's part of its edge, by multipliers of degree k:
    both components held (GetFEM's Dirichlet brick), or one, ``u_c = d``
    weakly, ``∫ m v_c + ∫ q (u_c − d) = 0`` for every multiplier q of a
    scalar field on the edge; its value ``D{i}_{var}`` set per increment
    (:func:`_set_loads`)."""
    var, region, mim = _Bodies.VARS[body], bodies.edges[body][support.boundary], bodies.mim[body]
    data = f"D{i}_{var}"
    if support.fix == "xy":
        md.add_initialized_data(data, [0.0, 0.0])
        md.add_Dirichlet_condition_with_multipliers(mim, var, degree, region, data)
        return
    c, mult = "xy".index(support.fix) + 1, f"m{i}_{var}"
    mf = gf.MeshFem(bodies.mesh[body], 1)
    mf.set_fem(gf.Fem(f"FEM_PK(2,{degree})"))
    bodies.keep.append(mf)
    md.add_filtered_fem_variable(mult, mf, region)
    md.add_initialized_data(data, [0.0])
    md.add_linear_term(mim, f"{mult}*Test_{var}({c}) + Test_{mult}*{var}({c})", region)
    md.add_source_term(mim, f"{data}*Test_{mult}", region)


def _edge_traction(load) -> np.ndarray:
    """A load's traction on its edge: a pressure p is ``−p n_out``."""
    if isinstance(load, Pressure):
        return -load.value * np.asarray(EDGE_NORMALS[load.boundary], float)
    return np.asarray(load.value, float)


def _set_loads(md, scene: Scene, bodies: _Bodies, k: int) -> None:
    """Each edge traction and each support's displacement at increment k's
    factor."""
    factors, held = scene.factors(k)
    for body, var in _Bodies.VARS.items():
        for i, (load, f) in enumerate(zip(scene.loads, factors)):
            if load.boundary in bodies.edges[body]:
                md.set_variable(f"T{i}_{var}", f * _edge_traction(load))
        for i, (support, f) in enumerate(zip(scene.supports, held)):
            if support.boundary in bodies.edges[body]:
                md.set_variable(f"D{i}_{var}", [f * support.value["xy".index(c)] for c in support.fix])


# ----- Γ's points ----------------------------------------------------------------

def _facet_points(facets: np.ndarray, degree: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Gauss points (m, 2), weights (m,) and piece sizes of Γ's facets: the
    facet x(ξ), ξ ∈ [−1, 1], through its end points (and its midpoint at
    degree 2), weight w |x'(ξ)|."""
    xi, w = np.polynomial.legendre.leggauss(FACET_POINTS)
    a, b = facets[:, 0], facets[:, 1]
    mid = facets[:, 2] if degree == 2 else (a + b) / 2
    # quadratic Lagrange through ξ = −1, 1, 0
    pts = (a[:, None] * (xi * (xi - 1) / 2)[None, :, None] + b[:, None] * (xi * (xi + 1) / 2)[None, :, None]
           + mid[:, None] * (1 - xi ** 2)[None, :, None])
    speed = (a[:, None] * (xi - 0.5)[None, :, None] + b[:, None] * (xi + 0.5)[None, :, None]
             + mid[:, None] * (-2 * xi)[None, :, None])
    weights = w[None, :] * np.linalg.norm(speed, axis=2)
    return pts.reshape(-1, 2), weights.ravel(), np.full(len(facets), FACET_POINTS)


class GetFEMContactFields(GetFEMFields):
    """Displacement and stress of each body from its own GetFEM mesh (the
    XFEM peer's fields, :class:`~verification.peer_getfem.GetFEMFields`,
    with one mesh and one variable per body instead of one side each)."""

    #: The parent's expressions in a body's own variable ``{u}``.
    _OWN = {"u": "{u}", "Grad_u": "Grad_{u}"}

    def __init__(self, md, bodies: _Bodies, scene: Scene):
        super().__init__(md, None, scene, (bodies,))
        self.bodies = bodies

    def _eval(self, expr: str, points, bodies, width: int) -> np.ndarray:
        """``expr`` of each point's body, a point on Γ moved by NUDGE into
        it; a point just outside its body's curved mesh (an O(h⁴) sliver of
        the circle) takes the nearest cell's extension."""
        itf, L, bodies = self.scene.interface, self.scene.length_scale, np.asarray(bodies)
        points = np.asarray(points, float)[:, :2].copy()
        on = np.abs(itf.phi(points)) <= NUDGE * L
        points[on] += (NUDGE * L * (2 * bodies[on] - 1))[:, None] * itf.normals(points[on])
        out = np.zeros((len(points), width))
        for b, body in enumerate(BODY):
            sel = np.flatnonzero(bodies == b)
            if len(sel):
                own = self._OWN.get(expr, expr).format(u=_Bodies.VARS[body])
                vals = self.md.interpolation(own, points[sel].T.copy(), self.bodies.mesh[body], -1, 2)
                out[sel] = np.asarray(vals).reshape(len(sel), width)
        return out

    def multiplier(self, points) -> np.ndarray:
        """λ (m, 2), the traction on the − body, at points of Γ."""
        return self._eval("lambda", points, np.zeros(len(points), int), 2)


class _Gamma:
    """Γ's Gauss points and their frame; the jump, traction and status of
    GetFEM's solution there."""

    def __init__(self, scene: Scene, bodies: _Bodies, degree: int):
        self.points, self.weights, sizes = _facet_points(bodies.facets, degree)
        self.pieces = piece_centres(self.points, self.weights, sizes)
        n = scene.interface.normals(self.points)
        self.frame = np.stack([n, tangent_of(n)], axis=1)  # (m, 2 [N, T], 2 [x, y])
        self.zeros, self.ones = np.zeros(len(self.points), int), np.ones(len(self.points), int)

    def jump(self, fields: GetFEMContactFields) -> np.ndarray:
        """g = (g_N, g_T) of u2 − u1."""
        d = fields.displacement(self.points, self.ones) - fields.displacement(self.points, self.zeros)
        return np.einsum("pij,pj->pi", self.frame, d)

    def traction(self, fields: GetFEMContactFields) -> np.ndarray:
        """(t_N, t_T) = (λ·n, λ·t), λ read on the − side."""
        return np.einsum("pij,pj->pi", self.frame, fields.multiplier(self.points))

    @staticmethod
    def status(t: np.ndarray, g: np.ndarray, dg: np.ndarray, r: float, mu: float) -> np.ndarray:
        """GetFEM's Alart–Curnier test (module doc) at each point."""
        pressure = -(t[:, 0] + r * g[:, 0])
        trial = np.abs(t[:, 1] + r * dg[:, 1])
        return np.where(pressure <= 0, OPEN, np.where(trial <= mu * pressure, STICK, SLIP)).astype(np.int8)


def _external_norm(md) -> float:
    """‖F‖, the external forces of the current loads: the right-hand side
    at u = 0, λ = 0 (where the contact rows vanish)."""
    x = md.from_variables()
    md.to_variables(np.zeros_like(x))
    md.assembly(option="build_rhs")
    scale = float(np.linalg.norm(md.rhs()))
    md.to_variables(x)
    return scale


def _residual(md, r: float, scale: float) -> float:
    """The residual of every equation in force units, against ‖F‖.

    GetFEM's contact rows are Alart–Curnier's ``∫ (λ − P(λ − r g)) μ / r``,
    a length: its own Newton test (‖R‖ against the loads) would pass a
    status map with λ_N > 0 in tension, whose contact rows are 1e-11 of the
    forces (measured: C-coulomb at h = 0.05 in one increment, Newton
    stopped after one iteration with max t_N = +1.4e5 Pa).  Multiplied by r
    they are forces, ``∫ (λ − P(…)) μ``."""
    md.assembly(option="build_rhs")
    res = np.array(md.rhs())
    first, size = md.interval_of_variable("lambda")
    res[first:first + size] *= r
    return float(np.linalg.norm(res) / scale)


def solve(scene: Scene, h: float | None = None, *, degree: int = 2, paper: bool = False,
          estimate_condition: bool | None = None) -> Result:
    """Solve ``scene`` (an exact unilateral or Coulomb law) with GetFEM's
    Alart–Curnier contact between the two bodies' meshes of size h, over
    the scene's increments (``estimate_condition`` is accepted for the
    common entry point; GetFEM gives no estimate)."""
    _check(scene, degree, paper)
    h = check_resolution(scene, scene.h if h is None else h, "h")
    gf = getfem_module()
    start, timings = time.perf_counter(), Timings()
    with timings.measure("mesh"):
        bodies = _Bodies(gf, scene, h, degree)
    with timings.measure("assembly"):
        md = gf.Model("real")
        _bricks(gf, md, scene, bodies, degree)
    fields, gamma = GetFEMContactFields(md, bodies, scene), _Gamma(scene, bodies, degree)
    path = InterfacePath(gamma.points, gamma.weights, pieces=gamma.pieces)
    report = SolverReport(solver="getfem Alart–Curnier (MUMPS)", increments=scene.increments)
    r, mu = md.variable("r")[0], md.variable("friction")[0]
    g_before = np.zeros((len(gamma.points), 2))
    with timings.measure("solve"):
        for k in range(1, scene.increments + 1):
            _set_loads(md, scene, bodies, k)
            iterations, history = _newton(md, scene, k, r)
            g, t = gamma.jump(fields), gamma.traction(fields)
            status = gamma.status(t, g, g - g_before if scene.law.name == "coulomb" else g, r, mu)
            path.steps.append(Increment(k, scene.factors(k), iterations, history, g, t, status))
            report.iterations.append(iterations)
            report.residual = history[-1]
            if scene.law.name == "coulomb":
                for var in _Bodies.VARS.values():
                    md.set_variable(f"w_{var}", md.variable(var))
            elif np.any(status == SLIP):
                raise DiscretisationError(f"{METHOD}: scene {scene.name}, increment {k}: a closed point slipped at "
                                          f"μ = {TIE_FRICTION:g}; the unilateral law's tie did not hold")
            g_before = g
    timings.total = time.perf_counter() - start
    return Result(method=METHOD, scene=scene, degree=degree, dofs=bodies.dofs(), timings=timings, solver=report,
                  fields=fields, interface=path,
                  discretisation={"h": h, "degree": degree, "multiplier_degree": MULTIPLIER_DEGREE,
                                  "augmentation": float(r), "facet_points": FACET_POINTS})


def _newton(md, scene: Scene, k: int, r: float) -> tuple[int, list[float]]:
    """GetFEM's Newton for increment k, one iteration per call so that the
    test is :func:`_residual` (GetFEM's own test is blind to the contact
    rows); its iterations and residuals, or a clear error."""
    scale, history = _external_norm(md), []
    for it in range(1, NEWTON_ITERATIONS + 1):
        md.solve("max_res", 0.0, "max_iter", 1, "lsolver", LINEAR_SOLVER)
        history.append(_residual(md, r, scale))
        if not all(np.isfinite(md.variable(v)).all() for v in ("u1", "u2", "lambda")):
            break
        if history[-1] <= NEWTON_RESIDUAL:
            return it, history
    raise DiscretisationError(f"{METHOD}: GetFEM's Newton did not converge on scene {scene.name} at increment "
                              f"{k} in {NEWTON_ITERATIONS} iterations (relative residual {history[-1]:.1e})")


# ----- the comparison with our exact answer ----------------------------------------

#: The README's wedge (a block pressed onto a plane inclined at 11.3°).
WEDGE = Path(__file__).resolve().parent.parent / "examples" / "wedge.toml"

#: Scene A's Γ turned this many degrees through (0.5, this height): the tied
#: unilateral law opens it over part of its length (tests/test_exact.py's
#: placement, rounded).
INCLINED_A = (17.8, 0.52)

#: The wedge's slipping variant: μ and the top's traction (Pa).  Its mean
#: shear on Γ is 0.094 of the pressure, below μ, so the block holds; Γ
#: slips from x ≈ 0.04 to 0.75 and sticks at its right end (fe P2, h =
#: 0.0125: 73 % of Γ slipping).
WEDGE_SLIP = (0.15, (3e5, -1e6))

#: Γ sampled on the scenes whose own profiles do not follow it.
_GAMMA_PROFILE = InterfaceProfile("gamma", ("gN", "gT", "tN", "tT"), parameter="arclength")


def _shipped(name: str, law: dict):
    def build() -> Scene:
        from contactcore import load_scene
        return load_scene(name).with_changes(law=make_law(law))
    return build


def _layered_slip() -> Scene:
    """The layered-slip closed form with its law exact (stick, slip, stick,
    reversed slip; :func:`verification.closed_forms.layered_slip`)."""
    from verification.closed_forms import layered_slip
    return layered_slip(exact=True).scene


def _inclined_A() -> Scene:
    """Scene A, tied unilateral, Γ turned :data:`INCLINED_A`: profiles along
    Γ (t, g) and A4 (σxx along y = 1, as shipped)."""
    from contactcore import load_scene
    angle, height = np.radians(INCLINED_A[0]), INCLINED_A[1]
    base = load_scene("A")
    itf = LineInterface((0.5, height), (-float(np.sin(angle)), float(np.cos(angle))))
    profiles = (_GAMMA_PROFILE, *(p for p in base.profiles if p.id == "A4"))
    return base.with_changes(name=f"A-inclined{INCLINED_A[0]:g}", interface=itf, profiles=profiles,
                             law=make_law({"type": "unilateral", "enforcement": "exact"}))


def _wedge(slipping: bool) -> Scene:
    """The README's wedge with its Coulomb law exact; ``slipping``: with μ and
    the top's traction of :data:`WEDGE_SLIP`."""
    from contactcore import load_scene
    wedge = load_scene(WEDGE)
    if not slipping:
        return wedge.with_changes(law=make_law({"type": "coulomb", "mu": wedge.law.mu, "enforcement": "exact"}))
    mu, top = WEDGE_SLIP
    return wedge.with_changes(name="wedge-slip", law=make_law({"type": "coulomb", "mu": mu, "enforcement": "exact"}),
                              loads=(Traction("top", top),))


#: The study's scenes, each with an exact law: scene A and its inclined Γ
#: tied where closed (``unilateral``), C-coulomb with its own μ = 0.2, the
#: layered-slip closed form, the README's wedge (μ = 0.5, sticking) and its
#: slipping variant.  Scene B is not among them: under its torque alone Γ
#: carries no pressure, so Coulomb's friction holds nothing and the rod has
#: no equilibrium (docs/peer-contact.md).
STUDIES = {"A": _shipped("A", {"type": "unilateral", "enforcement": "exact"}),
           "C-coulomb": _shipped("C-coulomb", {"type": "coulomb", "mu": 0.2, "enforcement": "exact"}),
           "layered-slip": _layered_slip,
           "A-inclined": _inclined_A,
           "wedge": lambda: _wedge(False),
           "wedge-slip": lambda: _wedge(True)}


def exact_scene(name: str) -> Scene:
    """A scene of the study (:data:`STUDIES`), its law exact."""
    if name not in STUDIES:
        raise DiscretisationError(f"{METHOD}: no study scene {name!r} (known: {', '.join(STUDIES)})")
    return STUDIES[name]()


@dataclass(frozen=True)
class Difference:
    """One profile quantity of the peer against ours, over the samples away
    from singular points: the largest and the RMS difference, each as a
    share of ours' largest |value| (a gap floored, as the agreement floors
    it), and where the largest lies (the profile's ``s``)."""

    profile: str
    quantity: str
    worst: float
    rms: float
    at: float
    scale: float


def differences(scene: Scene, got: dict, ref: dict, exclude: float | None = None) -> list[Difference]:
    """Every profile quantity of ``got`` (id -> ProfileData) against ``ref``."""
    from verification.agreement import default_exclusion, kept_samples, measured_against
    exclude = default_exclusion(scene) if exclude is None else exclude
    rows = []
    for pid, prof in ref.items():
        keep = kept_samples(scene, prof, exclude)
        for q in prof.names[3:]:
            d = got[pid].columns[q][keep] - prof.columns[q][keep]
            scale = float(np.max(np.abs(measured_against(scene, q, prof.columns[q][keep]))))
            i = int(np.argmax(np.abs(d)))
            rows.append(Difference(pid, q, float(abs(d[i]) / scale), float(np.sqrt(np.mean(d ** 2)) / scale),
                                   float(prof.columns["s"][keep][i]), scale))
    return rows


def status_split(result: Result) -> dict[str, float]:
    """Γ at the last increment: the open, stick and slip shares of its
    length (quadrature weights) and the largest |t_N| at a point."""
    path = result.interface
    w, status = path.weights, path.final.status
    split = {name: float(w[status == i].sum() / w.sum()) for i, name in enumerate(("open", "stick", "slip"))}
    return {**split, "max_tN": float(np.max(np.abs(path.final.traction[:, 0])))}


def path_means(result: Result) -> np.ndarray:
    """Γ's means per increment (n, 4): t_N, t_T, g_N and g_T, each weighted
    by the quadrature (the layered-slip closed form's uniform state)."""
    path = result.interface
    w = path.weights / path.weights.sum()
    return np.array([np.concatenate([w @ step.traction, w @ step.jump]) for step in path.steps])


def study(name: str, hs, degree: int = 2, methods=("fe",), allow_large: bool = False) -> tuple[dict, dict, dict]:
    """Scene ``name`` of :data:`STUDIES`, each of our ``methods`` and GetFEM
    at each h: the :func:`differences` from GetFEM (``(method, h) ->
    rows``); each run's :func:`status_split` with its time in seconds
    (``(h, method | "peer") -> split``); and each code's own move from one
    h to the next, its answer at the coarser h against the finer
    (``(method | "peer", finer h) -> rows``), the measure of its own
    discretisation error that a difference from GetFEM is judged by.
    Every h is checked first (:func:`check_sizes`; its memory unless
    ``allow_large``)."""
    from contactcore import sample_profiles
    from verification import methods as ours
    scene = exact_scene(name)
    check_sizes(scene, hs, degree, methods, allow_large)
    rows, splits, moves, profiles = {}, {}, {}, {}
    for h in hs:
        for label, solver in (*((m, ours.solver(m)) for m in methods), ("peer", solve)):
            result = solver(scene, h, degree=degree)
            profiles[label, h] = {p.id: p for p in sample_profiles(scene, result.fields, result.interface)}
            splits[h, label] = {**status_split(result), "seconds": result.timings.total}
        for m in methods:
            rows[m, h] = differences(scene, profiles["peer", h], profiles[m, h])
    for coarse, fine in zip(hs, hs[1:]):
        for label in (*methods, "peer"):
            moves[label, fine] = differences(scene, profiles[label, coarse], profiles[label, fine])
    return rows, splits, moves


def check_sizes(scene: Scene, hs, degree: int, methods, allow_large: bool = False) -> None:
    """Every h a resolution of ``scene`` (:func:`contactcore.scene.check_resolution`)
    whose runs fit this machine (:func:`contactcore.budget.check_budget`,
    GetFEM's two bodies' meshes one field over the domain; not checked if
    ``allow_large``), before any mesh: a ContactError naming the first
    that is not."""
    for h in hs:
        check_resolution(scene, h)
        for method in () if allow_large else (*methods, METHOD):
            check_budget(scene, h, degree, method)


def _share(s: dict) -> str:
    return (f"{100 * s['open']:.1f} % / {100 * s['stick']:.2f} % / {100 * s['slip']:.1f} %, "
            f"{s['max_tN']:.4g} Pa ({s['seconds']:.3g} s)")


def _table(columns: dict) -> list[str]:
    """One row per profile quantity, one column per entry of ``columns``
    (heading -> :func:`differences` rows): worst (RMS) in %."""
    first = next(iter(columns.values()))
    lines = ["| profile, quantity | " + " | ".join(columns) + " |", "|---|" + "---|" * len(columns)]
    for i, row in enumerate(first):
        lines.append(f"| {row.profile} {row.quantity} | "
                     + " | ".join(f"{100 * c[i].worst:.3g} ({100 * c[i].rms:.3g})" for c in columns.values()) + " |")
    return lines


def markdown(rows: dict, splits: dict, moves: dict) -> str:
    """The study's tables, per method of ours: per profile quantity the
    worst sample and (in brackets) the RMS difference from GetFEM, in % of
    ours' largest value, one column per h; Γ's open/stick/slip shares,
    largest |t_N| and time of each run; and the method's and GetFEM's own
    moves from each h to the next (in % of the finer answer's largest)."""
    out = []
    for method in dict.fromkeys(m for m, _ in rows):
        hs = [h for m, h in rows if m == method]
        lines = [f"{method} against GetFEM", "", *_table({f"h = {h:g}": rows[method, h] for h in hs}), "",
                 f"| h | {method}: open / stick / slip, max abs t_N | GetFEM: open / stick / slip, max abs t_N |",
                 "|---|---|---|"]
        lines += [f"| {h:g} | {_share(splits[h, method])} | {_share(splits[h, 'peer'])} |" for h in hs]
        steps = list(zip(hs, hs[1:]))
        if steps:
            lines += ["", f"{method}'s and GetFEM's own moves", "",
                      *_table({f"{who} h = {a:g} → {b:g}": moves[label, b]
                               for label, who in ((method, method), ("peer", "GetFEM")) for a, b in steps})]
        out.append("\n".join(lines) + "\n")
    return "\n".join(out)


def main(argv=None) -> int:
    """``python -m verification.peer_getfem_contact SCENE [--h H ...]
    [--methods M ...]``: print the study's tables (docs/peer-contact.md)."""
    import argparse
    parser = argparse.ArgumentParser(prog="python -m verification.peer_getfem_contact",
                                     description="GetFEM's Alart–Curnier contact against our exact answers")
    parser.add_argument("scene", choices=sorted(STUDIES), help="the scene, with its study law")
    parser.add_argument("--h", type=float, nargs="+", default=[0.05, 0.025], help="mesh sizes")
    parser.add_argument("--degree", type=int, default=2, choices=(1, 2), help="degree of every method")
    parser.add_argument("--methods", nargs="+", default=["fe"], choices=("fe", "xfem", "efgm"),
                        help="our methods compared with GetFEM")
    parser.add_argument("--allow-large", action="store_true",
                        help="run even when the estimated memory exceeds what this machine has")
    args = parser.parse_args(argv)
    try:
        tables = study(args.scene, args.h, args.degree, tuple(args.methods), args.allow_large)
    except ContactError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(markdown(*tables), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
