"""The conforming finite element reference ("fe").

Plane elasticity in each body on a mesh that follows Γ, the displacement
discontinuous across Γ, the interface law integrated along Γ.  Every other
method is checked against it.

Discretisation.  One vector Lagrange field per body on the whole mesh (a
``MixedElement`` of two ``VectorElement`` of degree ``k``); the degrees of
freedom of field ``b`` outside the closure of body ``b`` are held at zero,
so field ``b`` lives on body ``b`` and its trace on Γ.  The weak form is

    Σ_b ∫_{Ω_b} σ_b(u_b) : ε(v_b) dx + ∫_Γ g(v) · D g(u) dΓ
        = Σ_b ∫_{∂Ω_b ∩ Γ_t} t̄ · v_b ds + Σ_b ∫_{Ω_b} f · v_b dx,

with ``g(w) = ([[w]]·n, [[w]]·t)``, ``[[w]] = w_+ − w_−`` and ``D`` the
law's tangent ``∂(t_N, t_T)/∂(g_N, g_T)`` (the paper's Eq. 6 for ``linear``;
SCENES.md for signs).  Both fields are continuous across every facet, so
their traces on Γ need no side: the interior-facet orientation trap of
dolfinx 0.5.2 does not arise.  ``n`` is the exact normal of the level set at
the quadrature point, not the normal of the mesh's chord: on scene B's
curved Γ a chord normal creates a false normal traction of order
``(k_N/k_T)(h/2R)|t_T|`` (SCENES.md).  Boundary loads on an outer facet are
weighted by the DG0 indicator of the body that owns the facet's cell.

A linear law is one linear solve (load increments only scale it).
"""
from __future__ import annotations

import functools
import time

import numpy as np
import ufl
from dolfinx import fem
from dolfinx.fem import petsc as fem_petsc
from mpi4py import MPI
from petsc4py import PETSc

import meshes
from contactcore import BODIES, DiscretisationError, Result, Scene, Timings
from contactcore import tolerances as tol
from contactcore.elasticity import lame
from contactcore.geometry import LevelSetInterface, LineInterface, Rectangle
from contactcore.scene import Pressure, Traction, body_force

from . import linear_solver
from .evaluation import BodyCellLocator, BodyFields
from .fitted_mesh import FittedMesh, fitted_mesh

METHOD = "fe"


def resolution(scene: Scene, h: float | None, paper: bool) -> float:
    """The element size: ``h``, the paper's XFEM cell size, or the scene's default."""
    if paper:
        cells = scene.paper.get("xfem_cells")
        if cells is None or not isinstance(scene.domain, Rectangle):
            raise DiscretisationError(f"scene {scene.name} gives no paper discretisation")
        return min(s / n for s, n in zip(scene.domain.size, cells))
    h = scene.h if h is None else h
    if h is None or not h > 0:
        raise DiscretisationError(f"the resolution h must be > 0 (got {h}); the scene gives no default")
    return float(h)


def sigma(w, E: float, nu: float, plane: str):
    lam, mu = lame(E, nu, plane)
    eps = ufl.sym(ufl.grad(w))
    return 2.0 * mu * eps + lam * ufl.tr(eps) * ufl.Identity(2)


def _interface_frame(scene: Scene, x):
    """Exact unit normal (− into +) and tangent ``t = (n_y, −n_x)`` at ``x``."""
    itf = scene.interface
    if isinstance(itf, LineInterface):
        n = ufl.as_vector([float(itf.normal[0]), float(itf.normal[1])])
    else:
        d = x - ufl.as_vector([float(itf.centre[0]), float(itf.centre[1])])
        n = d / ufl.sqrt(ufl.dot(d, d))
    return n, ufl.as_vector([n[1], -n[0]])


def _body_indicator(fm: FittedMesh):
    """DG0 function equal to 1 on the − body, 0 on the + body."""
    chi = fem.Function(fem.FunctionSpace(fm.mesh, ("DG", 0)))
    chi.x.array[:] = 0.0
    chi.x.array[fm.cells_of("minus")] = 1.0
    chi.x.scatter_forward()
    return chi


def bilinear_form(scene: Scene, fm: FittedMesh, V):
    """Bulk elasticity of each body plus the interface springs on Γ."""
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    us, vs = ufl.split(u), ufl.split(v)
    dx = ufl.Measure("dx", domain=fm.mesh, subdomain_data=fm.cell_tags)
    dS = ufl.Measure("dS", domain=fm.mesh, subdomain_data=fm.facet_tags)
    a = sum(ufl.inner(sigma(us[b], scene.materials[name].E, scene.materials[name].nu, scene.plane),
                      ufl.sym(ufl.grad(vs[b]))) * dx(meshes.BODY[name]) for b, name in enumerate(BODIES))
    n, t = _interface_frame(scene, ufl.SpatialCoordinate(fm.mesh)("+"))

    def gap(w):
        jump = w[1]("+") - w[0]("+")  # both fields are continuous across Γ's facets
        return ufl.as_vector([ufl.dot(jump, n), ufl.dot(jump, t)])

    D = ufl.as_matrix(scene.law.constant_tangent().tolist())
    return a + ufl.inner(D * gap(us), gap(vs)) * dS(meshes.INTERFACE)


def linear_form(scene: Scene, fm: FittedMesh, V):
    """Boundary tractions, pressures, body forces and torques at full load."""
    v = ufl.TestFunction(V)
    vs = ufl.split(v)
    dx = ufl.Measure("dx", domain=fm.mesh, subdomain_data=fm.cell_tags)
    ds = ufl.Measure("ds", domain=fm.mesh, subdomain_data=fm.facet_tags)
    x = ufl.SpatialCoordinate(fm.mesh)
    chi = _body_indicator(fm)
    v_owner = chi * vs[0] + (1.0 - chi) * vs[1]  # trace of the body that owns the boundary facet
    L = ufl.inner(ufl.as_vector([0.0, 0.0]), vs[0]) * dx
    for load in scene.loads:
        if isinstance(load, Traction):
            L += ufl.dot(ufl.as_vector(list(load.value)), v_owner) * ds(meshes.BOUNDARY[load.boundary])
        elif isinstance(load, Pressure):
            L += -load.value * ufl.dot(ufl.FacetNormal(fm.mesh), v_owner) * ds(meshes.BOUNDARY[load.boundary])
        else:
            b = ufl.as_vector(body_force(scene, load, x[0], x[1]))
            L += ufl.dot(b, vs[BODIES.index(load.body)]) * dx(meshes.BODY[load.body])
    return L


class _Constraints:
    """Dirichlet data: fields held at zero off their body, supports and pins."""

    def __init__(self, scene: Scene, fm: FittedMesh, V):
        self.scene, self.fm, self.V = scene, fm, V
        tdim = fm.mesh.topology.dim
        ncells = fm.mesh.topology.index_map(tdim).size_local + fm.mesh.topology.index_map(tdim).num_ghosts
        every = np.arange(ncells, dtype=np.int32)
        self.active, self.bcs = [], []
        for b, name in enumerate(BODIES):
            Vb, _ = V.sub(b).collapse()
            allb = fem.locate_dofs_topological((V.sub(b), Vb), tdim, every)
            mine = fem.locate_dofs_topological((V.sub(b), Vb), tdim, fm.cells_of(name))
            off = ~np.isin(allb[0], mine[0])
            self.active.append(mine[0])
            zero = fem.Function(Vb)
            self.bcs.append(fem.dirichletbc(zero, [allb[0][off], allb[1][off]], V.sub(b)))
        for sup in scene.supports:
            facets = fm.facets_tagged(meshes.BOUNDARY[sup.boundary])
            for b in range(2):
                for j in _components(sup.fix):
                    self._fix(b, j, fem.locate_dofs_topological, (tdim - 1, facets), sup.value[j])
        for i, pin in enumerate(scene.pins):
            b = int(scene.body_of([pin.point])[0])
            p = np.asarray(pin.point)
            near = tol.NODE_MATCH * scene.length_scale
            for j in _components(pin.fix):
                found = self._fix(b, j, fem.locate_dofs_geometrical,
                                  (lambda x, p=p: np.hypot(x[0] - p[0], x[1] - p[1]) <= near,), 0.0)
                if found == 0:
                    raise DiscretisationError(f"pins[{i}]: no mesh node at {list(pin.point)}")

    @functools.cache
    def _component_space(self, b: int, j: int):
        """Component ``j`` of body ``b``'s field, collapsed once."""
        return self.V.sub(b).sub(j).collapse()[0]

    def _fix(self, b: int, j: int, locate, args, value: float) -> int:
        Vbj = self._component_space(b, j)
        dofs = locate((self.V.sub(b).sub(j), Vbj), *args)
        keep = np.isin(dofs[0], self.active[b])
        if keep.any():
            g = fem.Function(Vbj)
            g.x.array[:] = value
            self.bcs.append(fem.dirichletbc(g, [dofs[0][keep], dofs[1][keep]], self.V.sub(b).sub(j)))
        return int(keep.sum())

    @property
    def num_active(self) -> int:
        return sum(len(a) for a in self.active)

    def owned_active_rows(self) -> np.ndarray:
        """Global indices of the owned unknowns that are not held at zero."""
        imap = self.V.dofmap.index_map
        bs = self.V.dofmap.index_map_bs
        local = np.unique(np.concatenate(self.active))
        local = local[local < imap.size_local * bs]
        return local + imap.local_range[0] * bs


def _components(fix: str) -> list[int]:
    return [{"x": 0, "y": 1}[c] for c in fix]


def _stress_functions(scene: Scene, fm: FittedMesh, uh, degree: int):
    """Each body's stress ``(σxx, σyy, σxy)`` interpolated in DG of degree k−1
    (exact on straight cells) and its displacement, both on the whole mesh."""
    S = fem.FunctionSpace(fm.mesh, ufl.VectorElement("DG", fm.mesh.ufl_cell(), degree - 1, dim=3))
    disps, stresses = [], []
    for b, name in enumerate(BODIES):
        ub = uh.sub(b).collapse()
        mat = scene.materials[name]
        s = sigma(ub, mat.E, mat.nu, scene.plane)
        sf = fem.Function(S)
        sf.interpolate(fem.Expression(ufl.as_vector([s[0, 0], s[1, 1], s[0, 1]]), S.element.interpolation_points()))
        disps.append(ub)
        stresses.append(sf)
    return disps, stresses


def solve(scene: Scene, h: float | None = None, *, degree: int = 1, paper: bool = False,
          geometry_order: int | None = None, grading: meshes.Grading | None = None,
          petsc_options: dict | None = None, estimate_condition: bool | None = None,
          jit_params: dict | None = None, comm=MPI.COMM_WORLD) -> Result:
    """Solve ``scene`` with the conforming reference.

    ``degree`` 1 or 2 (P1/P2 triangles); ``geometry_order`` defaults to the
    degree (P2 on curved, second-order cells); ``petsc_options`` override the
    MUMPS LU defaults; the condition estimate is on below
    :data:`~contactcore.tolerances.CONDITION_ESTIMATE_MAX_DOFS` unknowns.
    """
    if degree not in (1, 2):
        raise DiscretisationError(f"fe: degree must be 1 or 2 (got {degree})")
    if isinstance(scene.interface, LevelSetInterface):
        raise DiscretisationError("fe: a general level set Γ is supported by xfem only (its mesh ignores Γ)")
    start = time.perf_counter()
    timings = Timings()
    h = resolution(scene, h, paper)
    with timings.measure("mesh"):
        fm = fitted_mesh(scene, h, order=geometry_order or degree, grading=grading, comm=comm)
    with timings.measure("assembly"):
        el = ufl.VectorElement("Lagrange", fm.mesh.ufl_cell(), degree)
        V = fem.FunctionSpace(fm.mesh, ufl.MixedElement([el, el]))
        cons = _Constraints(scene, fm, V)
        a = fem.form(bilinear_form(scene, fm, V), jit_params=jit_params or {})
        L = fem.form(linear_form(scene, fm, V), jit_params=jit_params or {})
        # Support rows get a diagonal of the order of the stiffness, not 1, so
        # that they do not spoil the condition estimate; rows held at zero off
        # their body are left out of the solve altogether.
        diag = max(m.E for m in scene.materials.values())
        A = fem_petsc.assemble_matrix(a, bcs=cons.bcs, diagonal=diag)
        A.assemble()
        rhs = fem_petsc.assemble_vector(L)
        fem_petsc.apply_lifting(rhs, [a], bcs=[cons.bcs])
        rhs.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        fem_petsc.set_bc(rhs, cons.bcs, scale=diag)
    uh = fem.Function(V)
    if estimate_condition is None:
        estimate_condition = cons.num_active <= tol.CONDITION_ESTIMATE_MAX_DOFS
    with timings.measure("solve"):
        report = linear_solver.solve(A, rhs, uh.vector, rows=cons.owned_active_rows(), petsc_options=petsc_options,
                                     estimate_condition=estimate_condition, what=f"scene {scene.name} (fe)")
    uh.x.scatter_forward()
    report.increments = scene.increments
    report.warnings += scene.interface_warnings(h, fitted=True)
    disps, stresses = _stress_functions(scene, fm, uh, degree)
    locator = BodyCellLocator(fm.mesh, [fm.cells_of(b) for b in BODIES])
    A.destroy()
    rhs.destroy()
    timings.total = time.perf_counter() - start
    return Result(method=METHOD, scene=scene, degree=degree, dofs=cons.num_active, timings=timings,
                  solver=report, fields=BodyFields(locator, disps, stresses),
                  discretisation={"h": h, "degree": degree, "geometry_order": geometry_order or degree,
                                  "cells": fm.num_cells, "grading": None if grading is None else vars(grading)})
