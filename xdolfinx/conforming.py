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

(shown for a linear law) with ``g(w) = ([[w]]·n, [[w]]·t)``, ``[[w]] = w_+ − w_−`` and ``D`` the
law's tangent ``∂(t_N, t_T)/∂(g_N, g_T)`` (the paper's Eq. 6 for ``linear``;
docs/scenes.md for signs).  Both fields are continuous across every facet, so
their traces on Γ need no side: the interior-facet orientation trap of
dolfinx 0.5.2 does not arise.  ``n`` is the exact normal of the level set at
the quadrature point, not the normal of the mesh's chord: on scene B's
curved Γ a chord normal creates a false normal traction of order
``(k_N/k_T)(h/2R)|t_T|`` (docs/scenes.md).  A law enforced exactly
(Nitsche) reads the traction ``σ(u) n_h`` with the mesh's own normal
``n_h`` (:func:`_mesh_normals`), the one the bulk's integration by parts
uses; its components, the law and the tractions reported stay in the
level set's frame (n, t).  Boundary loads on an outer facet are
weighted by the DG0 indicator of the body that owns the facet's cell.

Increments, Newton and the law are :mod:`contactcore.newton`'s, shared with
the other methods; the bulk matrix is dolfinx's, the interface term
``Gᵀ W D G`` comes from :func:`interface_operator` (a linear law: one solve).
The history of a ``coulomb`` law is kept at Γ's Gauss points.
"""
from __future__ import annotations

import numpy as np
import ufl
from dolfinx import fem
from dolfinx.fem import petsc as fem_petsc
from mpi4py import MPI
from petsc4py import PETSc

import meshes
from contactcore import BODIES, DiscretisationError, Result, Scene, Timings
from contactcore import discretisation
from contactcore.discretisation import Built, Resolution, make
from contactcore import tolerances as tol
from .elasticity import load_integrand, sigma, vanishes
from contactcore.assembly import Triplets
from contactcore.constraints import Constraints
from contactcore.cutcell import gauss01
from contactcore.exact import is_exact
from contactcore.geometry import polygon_area, tangent_of
from contactcore.interface_path import piece_centres
from contactcore.scaling import Scales
from contactcore.system import InterfaceOperator
from contactcore.scene import BODY, EDGE, place_of

from .contact_system import GhostExchange, PETScSystem
from .evaluation import BodyCellLocator, BodyFields
from .fitted_mesh import FittedMesh, file_mesh, fitted_mesh
from .nodal import nodal_interface
from .reference_cells import ReferenceCells
from .options import FE
from .quiet import quiet_jit

METHOD = FE.name

#: Gauss points on each Γ facet, by degree: the integrand N_i N_j of P_k on a
#: straight facet has degree 2k, exact with k + 1 points; one more covers
#: the curved (P2) facets and the exact normal of a circle.
INTERFACE_GAUSS = {1: 3, 2: 4}


def bilinear_form(scene: Scene, fm: FittedMesh, V, exact: bool = False):
    """Bulk elasticity of each body (the interface is :func:`interface_operator`'s).
    With ``exact``, a zero term on Γ's facets makes the matrix's pattern
    couple the two cells of each: Nitsche's ``G̃ᵀ W D G̃`` reads each
    body's stress in the cell on its own side."""
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    us, vs = ufl.split(u), ufl.split(v)
    dx = ufl.Measure("dx", domain=fm.mesh, subdomain_data=fm.cell_tags)
    a = sum(ufl.inner(sigma(us[b], scene.materials[name].E, scene.materials[name].nu, scene.plane),
                      ufl.sym(ufl.grad(vs[b]))) * dx(meshes.BODY[name]) for b, name in enumerate(BODIES))
    if exact:
        dS = ufl.Measure("dS", domain=fm.mesh, subdomain_data=fm.facet_tags)
        a += fem.Constant(fm.mesh, 0.0) * ufl.inner(ufl.jump(u), ufl.jump(v)) * dS(meshes.INTERFACE)
    return a


def _body_indicator(fm: FittedMesh):
    """DG0 function equal to 1 on the − body, 0 on the + body."""
    chi = fem.Function(fem.FunctionSpace(fm.mesh, ("DG", 0)))
    chi.x.array[:] = 0.0
    chi.x.array[fm.cells_of("minus")] = 1.0
    chi.x.scatter_forward()
    return chi


def linear_forms(scene: Scene, fm: FittedMesh, V) -> list:
    """One form per load (traction, pressure, body force or torque), at its
    full value, its numbers as Constants (:mod:`xdolfinx.elasticity`); None
    for a load of value zero (:func:`~xdolfinx.elasticity.vanishes`)."""
    v = ufl.TestFunction(V)
    vs = ufl.split(v)
    dx = ufl.Measure("dx", domain=fm.mesh, subdomain_data=fm.cell_tags)
    ds = ufl.Measure("ds", domain=fm.mesh, subdomain_data=fm.facet_tags)
    chi = _body_indicator(fm)
    v_owner = chi * vs[0] + (1.0 - chi) * vs[1]  # trace of the body that owns the boundary facet
    forms = []
    for load in scene.loads:
        if vanishes(scene, load):
            forms.append(None)
        elif place_of(load) == EDGE:
            forms.append(load_integrand(scene, load, fm.mesh, v_owner) * ds(meshes.BOUNDARY[load.boundary]))
        elif place_of(load) == BODY:
            forms.append(load_integrand(scene, load, fm.mesh, vs[BODIES.index(load.body)])
                         * dx(meshes.BODY[load.body]))
    return forms


def interface_operator(scene: Scene, fm: FittedMesh, V, degree: int, exchange: "GhostExchange",
                       exact: bool = False) -> InterfaceOperator:
    """Γ's quadrature on the mesh's Γ facets and ``G``: the jump
    ``[[u]] = u₊ − u₋`` in the frame (n, t) of the level set's exact normal
    at each point (not the chord's: docs/scenes.md, scene B); with ``exact``,
    also Nitsche's ``S`` and ``stabilisation`` (:func:`_nitsche_rows`),
    whose traction ``σ(u) n_h`` takes the mesh's own normal
    (:func:`_mesh_normals`).

    Both fields are continuous across Γ's facets, so their traces are taken
    from one cell of each facet, whichever side: the interior-facet
    orientation trap of dolfinx 0.5.2 does not arise.  Points and weights
    come from the cell's own (possibly curved) geometry map:
    ``x(X) = Σ ψ_g(X) x_g``, ``dΓ = |∂x/∂ξ| dξ`` on the reference facet, with
    ``INTERFACE_GAUSS[degree]`` Gauss points.
    """
    ref = ReferenceCells(fm, degree)
    xi, w_ref = gauss01(INTERFACE_GAUSS[degree])
    dofs = [[V.sub(b).sub(j).dofmap for j in range(2)] for b in range(2)]
    facets = fm.facets_tagged(meshes.INTERFACE)
    facets = facets[facets < fm.mesh.topology.index_map(1).size_local]  # each facet on the rank that owns it
    trip = Triplets((2 * len(facets) * len(xi), exchange.local_size))
    traction = Triplets((2 * len(facets) * len(xi), exchange.local_size)) if exact else None
    points, weights, nitsche = [], [], []
    for i, f in enumerate(facets):
        c = ref.f2c.links(f)[0]
        X, coords, tab, dx_dxi = ref.facet_map(c, f, xi)
        x = tab[0, :, :, 0] @ coords
        N = ref.element.tabulate(0, X)[0, :, :, 0]
        normals = scene.interface.normals(x)
        frame = np.stack([normals, tangent_of(normals)], axis=1)  # rows n, t
        rows = 2 * (i * len(xi) + np.arange(len(xi)))[:, None, None] + np.arange(2)[None, :, None]
        for side, sign in ((0, -1.0), (1, 1.0)):
            for j in range(2):
                trip.add(rows, dofs[side][j].cell_dofs(c)[None, None, :], sign * N[:, None, :] * frame[:, :, j:j + 1])
        points.append(x)
        weights.append(w_ref * np.linalg.norm(dx_dxi, axis=1))
        if exact:
            nitsche.append((f, x, frame, _mesh_normals(dx_dxi, normals), weights[-1].sum()))
    stabilisation = _nitsche_rows(scene, ref, dofs, xi, nitsche, traction) if exact else None
    S = traction.to_csr() if exact else None
    points, weights = _concatenate(points, 2), _concatenate(weights, 0)
    return InterfaceOperator(trip.to_csr(), weights, points, exchange if exchange.ranks.parallel else None, S=S,
                             stabilisation=stabilisation,
                             pieces=piece_centres(points, weights, [len(xi)] * len(facets)))


def _mesh_normals(dx_dxi: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """The mesh's own unit normal at a facet's points, where its tangent
    (unnormalised) is ``dx_dxi``: the chord's on straight P1 cells, the
    curved map's on P2 cells, turned to the side of the level set's
    ``normals`` there (from − into +).

    Nitsche's traction ``σ(u) n`` takes it: the bulk's ``∫ σ(u) : ε(v)``
    integrates by parts onto the mesh's facets, so only this normal keeps
    the two consistent.  With the exact circle's normal on P1 chords a
    constant stress was no longer the discrete answer (u off by 1.8e-4,
    σ by 4.2e-4 at h = 0.1: grader7, fault 1; docs/methods/fe.md).  The
    frame (n, t) in which ``S`` and ``G`` give components, the law acts
    and ``Result.interface`` reports stays the level set's."""
    t = dx_dxi / np.linalg.norm(dx_dxi, axis=1)[:, None]
    n = np.column_stack([t[:, 1], -t[:, 0]])
    return n * np.sign(np.sum(n * normals, axis=1))[:, None]


def _nitsche_rows(scene: Scene, ref: ReferenceCells, dofs, xi: np.ndarray, facets: list, S: Triplets) -> np.ndarray:
    """The rows of ``S`` of Γ's ``facets``, added to ``S``, and γ₀ at their
    points (parameters ``xi``; :class:`~contactcore.system.InterfaceOperator`);
    ``facets`` lists, in the rows' order, each facet's ``(f, x, frame, n,
    length)``: its points ``x``, the level set's frame there, the mesh's
    normal ``n`` (:func:`_mesh_normals`) and its length.  Each body's
    field is read in the cell on its own side of the facet (it is zero
    beyond its body), its stress by the body's Voigt matrix ``D``:
    ``τ = frame · σ(u) n``, weighted ``w_k = (|Ω_k|/E_k) / Σ_j |Ω_j|/E_j``
    over the two cells ``Ω_k`` (Annavarapu et al., CMAME 2012), and
    ``γ₀ = 2|Γ^e| / Σ_j |Ω_j|/E_j``.

    Every facet's numbers are made together, point by point by the same
    operations a facet at a time would take (the reference points of a
    cell's edge, run either way, tabulated once each), and each row's
    entries reach the COO sink in the facet-at-a-time order (the facet's
    two cells in dolfinx's order, each its x then its y dofs)."""
    D = scene.voigt_matrices()
    P = len(xi)
    if not facets:
        return np.zeros(0)
    cells, side = np.zeros((len(facets), 2), np.int64), np.zeros((len(facets), 2), np.int64)
    for i, (f, *_) in enumerate(facets):
        cells[i], side[i] = _facet_sides(scene, ref, f)
    total_cells = cells.ravel()
    coords = np.stack([ref.coords(c) for c in total_cells])  # (2F, nodes, 2)
    E = np.array([scene.materials[b].E for b in BODIES])
    compliance = (polygon_area(coords[:, :3]) / E[side.ravel()]).reshape(-1, 2)  # |Ω_k| / E_k, straight cells
    total = compliance[:, 0] + compliance[:, 1]
    share = compliance / total[:, None]
    x = np.stack([x for _, x, *_ in facets])  # (F, P, 2)
    frame = np.stack([fr for _, _, fr, *_ in facets])  # (F, P, 2, 2)
    n = np.stack([nm for *_, nm, _ in facets])  # (F, P, 2)
    # each cell's reference points on the facet: at x's parameters or at 1 - x's, whichever lands
    # on x (the facet's two cells may run along it in opposite directions)
    edge = np.array([int(np.flatnonzero(ref.c2f.links(c) == f)[0]) for c, f in
                     zip(total_cells, np.repeat([f for f, *_ in facets], 2))])
    runs = {}
    for e in np.unique(edge):
        a, b = ref.ref[ref.edges[e]]
        for flip, t in ((0, xi), (1, 1.0 - xi)):
            X = a + t[:, None] * (b - a)
            runs[e, flip] = X, ref.cmap.tabulate(0, X)[0, :, :, 0]
    xx = np.repeat(x, 2, axis=0)  # (2F, P, 2): each cell's facet points
    along = np.stack([runs[e, 0][1] for e in edge]) @ coords  # (2F, P, 2)
    back = np.stack([runs[e, 1][1] for e in edge]) @ coords
    flip = (np.abs(back - xx).max(axis=(1, 2)) < np.abs(along - xx).max(axis=(1, 2))).astype(int)
    grad = np.zeros((len(total_cells), P, ref.element.dim, 2))
    for e, k in {(e, k) for e, k in zip(edge.tolist(), flip.tolist())}:  # ref.gradients, cells of one X together
        at = np.flatnonzero((edge == e) & (flip == k))
        grad[at] = ref.gradients(runs[e, k][0], coords[at])
    Nx, Ny = grad[..., 0], grad[..., 1]
    Dc = D[side.ravel()]  # (2F, 3, 3)
    nn = np.repeat(n, 2, axis=0)
    nx, ny = nn[..., :1], nn[..., 1:]  # (2F, P, 1)
    vals = []
    for e_x, e_y, e_xy in ((Nx, 0.0 * Nx, Ny), (0.0 * Ny, Ny, Nx)):
        sigma = (Dc[:, :, 0, None, None] * e_x[:, None] + Dc[:, :, 1, None, None] * e_y[:, None]
                 + Dc[:, :, 2, None, None] * e_xy[:, None])  # (2F, 3, P, dofs): σxx, σyy, σxy
        sn = np.stack([sigma[:, 0] * nx + sigma[:, 2] * ny, sigma[:, 2] * nx + sigma[:, 1] * ny],
                      axis=2)  # (2F, P, 2, dofs)
        vals.append(share.ravel()[:, None, None, None]
                    * np.einsum("cpij,cpjd->cpid", np.repeat(frame, 2, axis=0), sn))
    nd = grad.shape[2]
    vals = np.stack(vals, axis=1).reshape(len(facets), 2, 2, P, 2, nd)  # (F, cell, j, P, row, dofs)
    cols = np.array([[[dofs[b][j].cell_dofs(c) for j in range(2)] for c, b in zip(cs, sd)]
                     for cs, sd in zip(cells, side)])  # (F, cell, j, dofs)
    rows = 2 * (np.arange(len(facets))[:, None] * P + np.arange(P))[:, :, None] + np.arange(2)  # (F, P, row)
    S.add(rows[:, :, :, None, None, None], cols[:, None, None], vals.transpose(0, 3, 4, 1, 2, 5))
    return np.repeat(2.0 * np.array([length for *_, length in facets]) / total, P)


def _facet_sides(scene: Scene, ref: ReferenceCells, f: int) -> tuple[np.ndarray, np.ndarray]:
    """Facet ``f``'s two cells and the body each lies in (by the mesher's
    tag, else its centroid); DiscretisationError where this rank does not
    hold both or they are not the two bodies."""
    cells = ref.f2c.links(f)
    if len(cells) != 2:
        raise DiscretisationError(f"fe: a facet of Γ has {len(cells)} cell(s) on this rank, not 2 (exact "
                                  "enforcement needs both sides: ghost mode shared_facet)")
    side = ref.body[cells]
    untagged = side < 0
    if np.any(untagged):  # by the centroid where the mesher's tag is missing
        side = np.where(untagged, scene.body_of(np.array([ref.coords(c)[:3].mean(axis=0) for c in cells])), side)
    if sorted(side) != [0, 1]:
        raise DiscretisationError("fe: a facet of Γ does not separate the two bodies")
    return cells, side


def _concatenate(parts: list, width: int) -> np.ndarray:
    """The parts joined (a rank may own no Γ facet)."""
    return np.concatenate(parts) if parts else np.zeros((0, width) if width else 0)


class _Constraints:
    """The prescribed unknowns: fields held at zero off their body, supports
    (value × the support's factor) and pins (zero), as this rank's owned
    unknowns.  Under mpirun a rank may not see every cell or facet around a
    dof it owns, so each finding is marked on the local dofs (owned and
    ghosts) and summed onto their owners (:class:`GhostExchange`) before
    it is read."""

    def __init__(self, scene: Scene, fm: FittedMesh, V, exchange: "GhostExchange"):
        self.scene, self.fm, self.V, self.exchange = scene, fm, V, exchange
        tdim = fm.mesh.topology.dim
        ncells = fm.mesh.topology.index_map(tdim).size_local + fm.mesh.topology.index_map(tdim).num_ghosts
        every = np.arange(ncells, dtype=np.int32)
        self.active, self.fixed, self.values, self.owner = [], [], [], []
        for b, name in enumerate(BODIES):
            Vb, _ = V.sub(b).collapse()
            allb = self._owned(fem.locate_dofs_topological((V.sub(b), Vb), tdim, every)[0])
            mine = self._owned(fem.locate_dofs_topological((V.sub(b), Vb), tdim, fm.cells_of(name))[0])
            self.active.append(mine)
            self._add(allb[~np.isin(allb, mine)], 0.0, -1)
        for i, sup in enumerate(scene.supports):
            facets = fm.facets_tagged(meshes.BOUNDARY[sup.boundary])
            for b, name in enumerate(BODIES):
                held = self._facets_of(facets, name)
                for j in _components(sup.fix):
                    self._fix(b, j, fem.locate_dofs_topological, (tdim - 1, held), sup.value[j], i)
        for i, pin in enumerate(scene.pins):
            b = int(scene.body_of([pin.point])[0])
            p = np.asarray(pin.point)
            near = tol.NODE_MATCH * scene.length_scale
            for j in _components(pin.fix):
                found = self._fix(b, j, fem.locate_dofs_geometrical,
                                  (lambda x, p=p: np.hypot(x[0] - p[0], x[1] - p[1]) <= near,), 0.0, -1)
                if exchange.ranks.sum(found) == 0:
                    raise DiscretisationError(f"pins[{i}]: no mesh node at {list(pin.point)}")

    def _facets_of(self, facets: np.ndarray, body: str) -> np.ndarray:
        """The boundary ``facets`` of the ``body``'s own cells: a support
        holds a body along the part of the edge it lies on, not at a
        vertex where Γ meets the edge and the body only touches it (a
        point constraint, which has no capacity in 2D elasticity: fe's
        answer pinned there drifts towards the unpinned one as log h).
        A rank holds every cell of its facets (owned or ghost)."""
        topology = self.fm.mesh.topology
        tdim = topology.dim
        topology.create_connectivity(tdim - 1, tdim)
        f2c = topology.connectivity(tdim - 1, tdim)
        ncells = topology.index_map(tdim).size_local + topology.index_map(tdim).num_ghosts
        mine = np.zeros(ncells, bool)
        mine[self.fm.cells_of(body)] = True
        return np.array([f for f in facets if mine[f2c.links(f)].any()], dtype=np.int32)

    def _owned(self, local_dofs) -> np.ndarray:
        """The owned dofs that some rank found among its local ``local_dofs``."""
        flags = np.zeros(self.exchange.local_size)
        flags[np.asarray(local_dofs, np.int64)] = 1.0
        return np.flatnonzero(self.exchange.reverse(flags) > 0)

    def _add(self, dofs, value: float, owner: int) -> None:
        self.fixed.append(np.asarray(dofs, np.int64))
        self.values.append(np.full(len(dofs), value))
        self.owner.append(np.full(len(dofs), owner))

    def _fix(self, b: int, j: int, locate, args, value: float, owner: int) -> int:
        Vbj = self.V.sub(b).sub(j).collapse()[0]
        dofs = self._owned(locate((self.V.sub(b).sub(j), Vbj), *args)[0])
        keep = dofs[np.isin(dofs, self.active[b])]
        self._add(keep, value, owner)
        return len(keep)

    @property
    def num_active(self) -> int:
        """The unknowns that take part, over every rank."""
        return self.exchange.ranks.sum(sum(len(a) for a in self.active))

    def constraints(self) -> Constraints:
        """The prescribed unknowns as the one constraint type."""
        return Constraints.on_dofs(self.fixed, self.values, self.owner, self.exchange.ranks)


def _components(fix: str) -> list[int]:
    return [{"x": 0, "y": 1}[c] for c in fix]


@quiet_jit
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


@quiet_jit
def build(scene: Scene, options: FE, resolution: Resolution, timings: Timings) -> Built:
    """The conforming system of ``scene`` (:class:`~contactcore.discretisation.Discretisation`'s
    ``build``; :class:`xdolfinx.options.FE` for the options)."""
    h, degree = resolution.h, options.degree
    comm = MPI.COMM_WORLD if options.comm is None else options.comm
    jit = options.jit_params or {}
    given = options.mesh_file()
    reaction = is_exact(scene.law) and options.flux == "reaction"  # Γ's nodes, the reaction as flux (xdolfinx.nodal)
    with timings.measure("mesh"):
        if given is None:
            fm = fitted_mesh(scene, h, order=options.geometry_order or degree, grading=options.grading, comm=comm,
                             gamma_on_one_rank=reaction)
        else:
            fm = file_mesh(given, Scales.of(scene.user).to_dimensionless, comm=comm, gamma_on_one_rank=reaction)
    with timings.measure("assembly"):
        el = ufl.VectorElement("Lagrange", fm.mesh.ufl_cell(), degree)
        V = fem.FunctionSpace(fm.mesh, ufl.MixedElement([el, el]))
        exchange = GhostExchange(V.dofmap.index_map, V.dofmap.index_map_bs, fm.mesh.comm)
        cons = _Constraints(scene, fm, V, exchange)
        exact = is_exact(scene.law)
        K = fem_petsc.assemble_matrix(fem.form(bilinear_form(scene, fm, V, exact), jit_params=jit))
        K.assemble()
        loads = []
        for L in linear_forms(scene, fm, V):
            if L is None:  # a load of value zero
                loads.append(np.zeros(V.dofmap.index_map.size_local * V.dofmap.index_map_bs))
                continue
            vec = fem_petsc.assemble_vector(fem.form(L, jit_params=jit))
            vec.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
            loads.append(vec.getArray().copy())
            vec.destroy()
        reader = (ReferenceCells(fm, degree), INTERFACE_GAUSS[degree], _facet_sides) if reaction else None
        interface, work = (nodal_interface(scene, fm, V, reader, exchange, K, cons.constraints().dofs) if reaction
                           else (interface_operator(scene, fm, V, degree, exchange, exact), None))
        system = PETScSystem(K, loads, cons.constraints(), interface, comm=fm.mesh.comm, work=work,
                             petsc_options=options.petsc_options, estimate_condition=options.estimate_condition,
                             what=f"scene {scene.name} (fe)")

    def fields(x):
        uh = fem.Function(V)
        uh.x.array[:len(x)] = x
        uh.x.scatter_forward()
        disps, stresses = _stress_functions(scene, fm, uh, degree)
        return BodyFields(BodyCellLocator(fm.mesh, [fm.cells_of(b) for b in BODIES]), disps, stresses)

    grading = options.grading
    on_gamma = h if grading is None else h * grading.factor  # the cells' size along Γ
    order = options.geometry_order or degree if given is None else given.order
    if given is None:
        warnings = meshes.polygon_warnings(scene, on_gamma) if order == 1 else []
    else:  # the file's, at its own Γ facets (meshes.read.check_mesh, in the user's units)
        warnings = options.mesh_warnings(scene)
    record = {"h": h, "degree": degree, "geometry_order": order, "cells": fm.num_cells,
              "grading": None if grading is None else vars(grading), "flux": options.flux}
    if given is not None:
        record["mesh"] = given.record()
    return Built(system, fields, cons.num_active, h=h, fitted=True, warnings=warnings, record=record)


def solve(scene: Scene, h: float | None = None, *, paper: bool = False, progress=None, reuse=None,
          **options) -> Result:
    """Solve ``scene`` with the conforming reference: the contract's
    :func:`contactcore.discretisation.solve` with :class:`xdolfinx.options.FE`
    ``(**options)``."""
    return discretisation.solve(scene, make(FE, **options), h, paper=paper, progress=progress, reuse=reuse)
