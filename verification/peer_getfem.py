"""GetFEM's level-set XFEM, the peer of the benchmark (not a method of ours).

GetFEM 5.4 (Debian's ``python3-getfem``) is what a user would otherwise pick
for level-set XFEM, so the benchmark (``python -m verification benchmark``)
runs it side by side with our methods, through the same entry point and
:class:`~contactcore.Result`.  Only the benchmark imports this module; the
project does not need GetFEM otherwise, and a missing GetFEM is a clear error.

The model, in GetFEM's own terms:

* the scene's rectangle in ``n_x × n_y`` quadrilaterals (``'cartesian'``),
  ``FEM_QK(2, k)`` Lagrange elements of degree k = 1 or 2;
* the scene's level set φ interpolated in a degree-2 ``LevelSet``; the space
  is ``MeshFem('levelset', …)``: every function whose support Γ cuts is
  doubled, one copy per side (the span of the shifted Heaviside enrichment);
* each body's elasticity integrated by a ``MeshIm('levelset', …, 'inside' |
  'outside')`` (cut cells on GetFEM's sub-triangles, ``IM_TRIANGLE(6)``;
  whole cells by ``IM_GAUSS_PARALLELEPIPED(2, 2k + 2)``); the springs on Γ
  (``'boundary'``) in its weak-form language, with the jump
  ``Xfem_plus(u) − Xfem_minus(u)`` and the level set's own normal;
* clamped edges by multipliers of degree k; edge tractions and the torque's
  body force as source terms; MUMPS, asked for by name: GetFEM's ``'auto'``
  choice switches to GMRES with an ILUT preconditioner above a size
  (measured: scene C at Q2, h = 0.0125, 3.1e5 unknowns, still iterating
  after 10 min), which no user after a reference answer would accept.

The stress at a point of body b is that body's side (``Xfem_plus`` or
``Xfem_minus`` of ``Grad_u``): the one-sided limit on Γ, as for our methods.
Timings: ``mesh`` (mesh, level set, cut, spaces and integration methods),
``assembly`` (the model's bricks), ``solve`` (GetFEM's assembly and solve).
"""
from __future__ import annotations

import time

import numpy as np

from contactcore import BODIES, DiscretisationError, Result, Scene, Timings
from contactcore.elasticity import lame
from contactcore.geometry import CircleInterface, LineInterface, Rectangle
from contactcore.result import SolverReport
from contactcore.scene import BodyForce, Torque, Traction
from contactcore.discretisation import resolution
from xdolfinx import xfem
from xdolfinx.options import XFEM

METHOD = "getfem"

#: Degree of GetFEM's level set: a circle's distance interpolated by Q2,
#: within O(h³) of Γ.
LEVEL_SET_DEGREE = 2

#: A point this close to Γ (relative to the scene's size) is evaluated this
#: far inside its own body: far below any discretisation error.
NUDGE = 1e-9

#: GetFEM's direct solver (see the module doc: not its size-dependent 'auto').
LINEAR_SOLVER = "mumps"

#: Outward normals of the rectangle's named edges (GetFEM tags faces by them).
EDGE_NORMALS = {"bottom": (0, -1), "top": (0, 1), "left": (-1, 0), "right": (1, 0)}


def getfem_module():
    """GetFEM, quiet; a clear error if it is not installed."""
    try:
        import getfem
    except ImportError as exc:
        raise DiscretisationError("getfem: GetFEM is not installed; the benchmark needs it: "
                                  "sudo apt-get install python3-getfem") from exc
    getfem.util("trace level", 0)
    getfem.util("warning level", 0)
    return getfem


def geometry_problems(scene: Scene) -> list[str]:
    """What of the scene's geometry a GetFEM peer cannot model: it meshes a
    rectangle with a straight or circular Γ."""
    problems = []
    if not isinstance(scene.domain, Rectangle):
        problems.append("the domain must be a rectangle")
    if not isinstance(scene.interface, (LineInterface, CircleInterface)):
        problems.append("Γ must be a line or a circle")
    return problems


def _check(scene: Scene, degree: int) -> None:
    """The peer covers the paper's scenes: a rectangle, a line or circle Γ,
    the linear law, clamped edges, edge tractions and torques."""
    if degree not in (1, 2):
        raise DiscretisationError(f"getfem: degree must be 1 or 2 (got {degree})")
    problems = geometry_problems(scene)
    if not scene.law.is_linear:
        problems.append("the interface law must be linear")
    if scene.pins or any(s.fix != "xy" or any(s.value) or s.path for s in scene.supports):
        problems.append("supports must clamp whole edges (no pins, no prescribed values)")
    if any(not isinstance(ld, (Traction, Torque, BodyForce)) or ld.path for ld in scene.loads):
        problems.append("loads must be constant tractions, torques or body forces")
    if problems:
        raise DiscretisationError(f"getfem: scene {scene.name} is outside the peer's reach: " + "; ".join(problems))


#: GetFEM region numbers: one per named edge, then the union of the clamped ones.
_EDGE_REGION = {name: k for k, name in enumerate(EDGE_NORMALS, start=1)}
_CLAMPED_REGION = len(EDGE_NORMALS) + 1


def _edge_faces(m) -> dict[str, np.ndarray]:
    """The outer faces (2, F) of each named edge of the rectangle."""
    faces = m.outer_faces()
    normals = m.normal_of_faces(faces)
    return {name: faces[:, np.all(np.abs(normals - np.array(n)[:, None]) < 1e-9, axis=0)]
            for name, n in EDGE_NORMALS.items()}


class GetFEMFields:
    """Displacement and stress of each body: its side of GetFEM's field."""

    SIDES = ("Xfem_minus", "Xfem_plus")

    def __init__(self, md, mesh, scene: Scene, keep: tuple):
        self.md, self.mesh, self.scene = md, mesh, scene
        self._keep = keep  # GetFEM frees an object with its last Python reference; the model needs these
        self.D = scene.voigt_matrices()

    def _eval(self, expr: str, points, bodies, width: int) -> np.ndarray:
        points = np.asarray(points, float)[:, :2]
        bodies = np.asarray(bodies)
        # a point on Γ is moved by NUDGE into its body: where Γ runs along
        # cell edges, GetFEM would otherwise pick the other side's cell,
        # whose Xfem_plus/minus there is not the limit (measured: 5.8e8 Pa
        # for 2.6e4 on scene A)
        itf = self.scene.interface
        on = np.abs(itf.phi(points)) <= NUDGE * self.scene.length_scale
        points = points.copy()
        points[on] += (NUDGE * self.scene.length_scale * (2 * bodies[on] - 1))[:, None] * itf.normals(points[on])
        out = np.zeros((len(points), width))
        for b in (0, 1):
            sel = np.flatnonzero(bodies == b)
            if len(sel):
                vals = self.md.interpolation(f"{self.SIDES[b]}({expr})", points[sel].T.copy(), self.mesh)
                out[sel] = np.asarray(vals).reshape(len(sel), width)
        return out

    def displacement(self, points, bodies) -> np.ndarray:
        return self._eval("u", points, bodies, 2)

    def stress(self, points, bodies) -> np.ndarray:
        """σ = D ε from ``Grad_u`` (column-major: ∂u_i/∂x_j at i + 2j)."""
        g = self._eval("Grad_u", points, bodies, 4)
        voigt = np.column_stack([g[:, 0], g[:, 3], g[:, 1] + g[:, 2]])
        return np.einsum("pij,pj->pi", self.D[np.asarray(bodies)], voigt)


def _plane_lame(scene: Scene, body: str) -> tuple[float, float]:
    mat = scene.materials[body]
    return lame(mat.E, mat.nu, scene.plane)


def _resolution(scene: Scene, h, paper: bool) -> tuple[int, int]:
    """The same quadrilaterals as our XFEM's: the paper's grid or cells ≈ h."""
    res = resolution(scene, h, paper, XFEM.paper_grid)
    return tuple(res.counts or xfem.cell_counts(scene, res.h))


def _model(gf, scene: Scene, degree: int, cells: tuple[int, int]):
    """Mesh, level set, cut, enriched space and integration methods."""
    (x0, y0), (a, b) = scene.domain.corner, scene.domain.size
    m = gf.Mesh("cartesian", np.linspace(x0, x0 + a, cells[0] + 1), np.linspace(y0, y0 + b, cells[1] + 1))
    ls = gf.LevelSet(m, LEVEL_SET_DEGREE)
    mf_ls = ls.mf()
    ls.set_values(scene.interface.phi(mf_ls.basic_dof_nodes().T))
    mls = gf.MeshLevelSet(m)
    mls.add(ls)
    mls.adapt()
    base = gf.MeshFem(m, 1)
    base.set_fem(gf.Fem(f"FEM_QK(2,{degree})"))
    mfu = gf.MeshFem("levelset", mls, base)
    mfu.set_qdim(2)
    cut = gf.Integ("IM_STRUCTURED_COMPOSITE(IM_TRIANGLE(6),1)")
    whole = gf.Integ(f"IM_GAUSS_PARALLELEPIPED(2,{2 * degree + 2})")
    mims = {}
    for where in ("inside", "outside", "all", "boundary"):
        mims[where] = gf.MeshIm("levelset", mls, where, cut)
        mims[where].set_integ(whole)
    return m, mf_ls, ls, mls, mfu, mims


def _bricks(md, scene: Scene, degree: int, m, mf_ls, ls, mfu, mims) -> None:
    """Elasticity per body, springs on Γ, supports and loads."""
    md.add_fem_variable("u", mfu)
    for body, where in zip(BODIES, ("inside", "outside")):
        lam, mu = _plane_lame(scene, body)
        md.add_initialized_data(f"lambda_{body}", [lam])
        md.add_initialized_data(f"mu_{body}", [mu])
        md.add_isotropic_linearized_elasticity_brick(mims[where], "u", f"lambda_{body}", f"mu_{body}")
    md.add_initialized_fem_data("ls", mf_ls, ls.values(0))
    md.add_initialized_data("kN", [scene.law.kN])
    md.add_initialized_data("kT", [scene.law.kT])
    jump, test = "(Xfem_plus(u)-Xfem_minus(u))", "(Xfem_plus(Test_u)-Xfem_minus(Test_u))"
    n = "Normalized(Grad_ls)"
    t = f"[{n}(2);-{n}(1)]"
    md.add_linear_term(mims["boundary"], f"kN*({jump}.{n})*({test}.{n}) + kT*({jump}.{t})*({test}.{t})")
    faces = _edge_faces(m)
    for name, region in _EDGE_REGION.items():
        m.set_region(region, faces[name])
    for i, load in enumerate(scene.loads):
        if isinstance(load, Traction):
            md.add_initialized_data(f"T{i}", list(load.value))
            md.add_source_term_brick(mims["all"], "u", f"T{i}", _EDGE_REGION[load.boundary])
        else:
            where = "inside" if load.body == "minus" else "outside"
            if isinstance(load, Torque):
                (xc, yc), R = scene.interface.centre, scene.interface.radius
                k = load.torque / (np.pi * R ** 4 / 2)
                force = f"[{-k}*(X(2)-({yc})); {k}*(X(1)-({xc}))]"
            else:
                force = f"[{load.value[0]}; {load.value[1]}]"
            md.add_source_term(mims[where], f"{force}.Test_u")
    clamped = sorted({s.boundary for s in scene.supports})
    if clamped:
        m.set_region(_CLAMPED_REGION, np.hstack([faces[name] for name in clamped]))
        md.add_Dirichlet_condition_with_multipliers(mims["all"], "u", degree, _CLAMPED_REGION)


def solve(scene: Scene, h: float | None = None, *, degree: int = 2, paper: bool = False,
          estimate_condition: bool | None = None) -> Result:
    """Solve ``scene`` with GetFEM's level-set XFEM of ``degree`` on
    quadrilaterals of size ≈ h (``estimate_condition`` is accepted for the
    common entry point; GetFEM gives no estimate)."""
    _check(scene, degree)
    gf = getfem_module()
    start, timings = time.perf_counter(), Timings()
    cells = _resolution(scene, h, paper)
    with timings.measure("mesh"):
        m, mf_ls, ls, mls, mfu, mims = _model(gf, scene, degree, cells)
    with timings.measure("assembly"):
        md = gf.Model("real")
        _bricks(md, scene, degree, m, mf_ls, ls, mfu, mims)
    with timings.measure("solve"):
        md.solve("lsolver", LINEAR_SOLVER)
    timings.total = time.perf_counter() - start
    report = SolverReport(solver="getfem (MUMPS)", residual=_residual(md))
    if not np.isfinite(md.variable("u")).all() or not report.residual < 1e-8:
        raise DiscretisationError(f"getfem: the solve failed on scene {scene.name} (relative residual "
                                  f"{report.residual:.1e}); a singular system?")
    return Result(method=METHOD, scene=scene, degree=degree, dofs=int(mfu.nbdof()), timings=timings, solver=report,
                  fields=GetFEMFields(md, m, scene, (mf_ls, ls, mls, mfu, mims)),
                  discretisation={"cells": list(cells), "degree": degree, "level_set_degree": LEVEL_SET_DEGREE})


def _residual(md) -> float:
    """‖F − K X‖ / ‖F‖ of the solved (linear) model, X every unknown,
    multipliers included."""
    md.assembly()
    F = md.rhs()
    r = np.linalg.norm(F - md.tangent_matrix().mult(md.from_variables()))
    return float(r / np.linalg.norm(F))
