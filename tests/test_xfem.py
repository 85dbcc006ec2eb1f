"""XFEM: assembly against dolfinx, enrichment, patch tests (including Γ on
nodes, along edges and leaving slivers), convergence (agreement:
test_agreement.py)."""
import dataclasses

import numpy as np
import pytest
import ufl
from dolfinx import fem
from dolfinx.fem import petsc as fem_petsc
from petsc4py import PETSc

import tolerances as tol
from contactcore import CircleInterface, DiscretisationError, LevelSetInterface, LineInterface, load_scene
from contactcore import sample_profiles
from contactcore.bodies import Body
from contactcore.profiles import interface_response
from contactcore.tolerances import ACCURATE_FLOOR, XFEM_SNAP
from contactcore.elasticity import voigt_matrix
from verification.closed_forms import interface_patch, pressurised_rod, quadratic_layers
from verification.norms import max_errors
from verification.sweeps import horizontal_patch
from xdolfinx import conforming, xfem
from xdolfinx.elasticity import sigma

PINS = {30.0: ((0.1, 0.1), (0.5, 0.1)), -65.0: ((0.1, 0.1), (0.1, 0.5)), 0.0: ((0.1, 0.1), (0.5, 0.1))}


@pytest.mark.parametrize("cell", ["quad", "triangle"])
@pytest.mark.parametrize("degree", [1, 2])
def test_cell_kernels_equal_dolfinx_without_enrichment(cell, degree):
    """Our kernels on every cell (cut ones split in sub-cells), no node
    enriched: the matrix equals dolfinx's assembly of the same form."""
    # one material, and a straight Γ: its sub-cells are polygons, integrated
    # exactly (an arc's curved sub-cells are exact only to ~1e-6 with 3 points)
    n = np.array([0.3, 1.0]) / np.hypot(0.3, 1.0)
    scene = load_scene("A").with_changes(interface=LineInterface((0.0, 0.43), tuple(n)), profiles=())
    cells = xfem.CellBasis(xfem.background_mesh(scene, 0.25, cell), degree, scene)
    cut = xfem.CutIntegration(cells, scene, xfem.GAUSS_POINTS[degree])
    assert cut.regions  # some cells are cut, so the split quadrature is exercised
    space = xfem.EnrichedFunctionSpace(cells, cut, enriched=np.zeros(len(cells.node_side), bool),
                                       band=np.arange(cells.num_cells))
    D = np.array([voigt_matrix(m.E, m.nu, scene.plane) for m in scene.materials.values()])
    ours = space.create_matrix()
    for dofs, K in xfem.band_kernels(space, D):
        ours.setValuesBlockedLocal(dofs.astype(PETSc.IntType), dofs.astype(PETSc.IntType), np.ascontiguousarray(K),
                                   addv=PETSc.InsertMode.ADD_VALUES)
    ours.assemble()
    u, v = ufl.TrialFunction(space.V), ufl.TestFunction(space.V)
    us, vs = ufl.as_vector([u[0], u[1]]), ufl.as_vector([v[0], v[1]])
    mat = scene.materials["minus"]
    theirs = fem_petsc.assemble_matrix(fem.form(ufl.inner(sigma(us, mat.E, mat.nu, scene.plane),
                                                          ufl.sym(ufl.grad(vs))) * ufl.dx))
    theirs.assemble()
    ours.axpy(-1.0, theirs, structure=PETSc.Mat.Structure.SUBSET_NONZERO_PATTERN)
    assert ours.norm() <= tol.KERNELS_VS_DOLFINX * theirs.norm()


def _tiny(interface):
    base = load_scene("A")
    return dataclasses.replace(base, interface=interface, profiles=())


@pytest.mark.parametrize("interface,enriched,cut", [
    (LineInterface((0.0, 0.55), (0.0, 1.0)), 10, 4),       # the row of cells 0.5 < y < 0.75
    (CircleInterface((0.5, 0.5), 0.3), 21, 12),            # 25 nodes but the 4 corners; 4 + 8 cells
])
def test_enriched_dof_counts(interface, enriched, cut):
    scene = _tiny(interface)
    space = xfem.enriched_space(xfem.background_mesh(scene, 0.25, "quad"), 1, scene, 3)
    assert (space.num_enriched, len(space.cut.regions)) == (enriched, cut)


@pytest.mark.parametrize("cell", ["quad", "triangle"])
def test_cut_share_is_the_area_of_a_body_in_cut_cells(cell):
    """Γ at y = 0.55 on a 0.1 grid: the cells 0.5 < y < 0.6 are cut; the −
    body holds 0.05 of them out of its 0.55, the + body 0.05 out of 0.45."""
    scene = _tiny(LineInterface((0.0, 0.55), (0.0, 1.0)))
    cut = xfem.enriched_space(xfem.background_mesh(scene, 0.1, cell), 1, scene, 3).cut
    assert np.isclose(cut.cut_share(Body.MINUS), 0.05 / 0.55, rtol=tol.MESH_SUMS)
    assert np.isclose(cut.cut_share(Body.PLUS), 0.05 / 0.45, rtol=tol.MESH_SUMS)
    assert cut.thin_body_warnings() == []


def test_a_body_mostly_in_cut_cells_is_warned_about():
    """A − wedge at 2.9° against the clamped bottom (Γ from (0, 0.03) to
    (0.6, 0)) lies wholly in cut cells at h = 0.05: xfem's mean t_N on Γ
    is 42 % below fe's there (tol.THIN_BODY_CUT_SHARE); the run says so.
    Scene C's rod at the same h is not warned about."""
    normal = tuple(np.array([0.05, 1.0]) / np.hypot(0.05, 1.0))
    wedge = _tiny(LineInterface((0.0, 0.03), normal))
    result = xfem.solve(wedge, 0.05, degree=1, estimate_condition=False)
    assert any("100% of body minus's area lies in cells that Γ cuts" in w for w in result.solver.warnings)
    rod = xfem.solve(load_scene("C"), 0.05, degree=1, estimate_condition=False)
    assert not any("lies in cells that Γ cuts" in w for w in rod.solver.warnings)


def test_gamma_missing_the_mesh_is_named():
    scene = _tiny(CircleInterface((5.0, 5.0), 0.3))  # built without validation, on purpose
    with pytest.raises(DiscretisationError, match="Γ crosses no cell"):
        xfem.enriched_space(xfem.background_mesh(scene, 0.25, "quad"), 1, scene, 3)


def _patch_error(patch, **kw):
    r = xfem.solve(patch.scene, 0.1, **kw)
    return (*max_errors(patch.scene, r.fields, patch), r)


@pytest.mark.parametrize("cell", ["quad", "triangle"])
@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("angle", [30.0, -65.0])
def test_interface_patch_is_exact(angle, degree, cell):
    eu, es, _ = _patch_error(interface_patch(angle, pins=PINS[angle]), degree=degree, cell=cell)
    assert eu <= tol.XFEM_PATCH and es <= tol.XFEM_PATCH_STRESS, (eu, es)


@pytest.mark.parametrize("cell", ["quad", "triangle"])
def test_gamma_through_nodes_and_along_edges(cell):
    eu, _, r = _patch_error(horizontal_patch(0.5), cell=cell)
    assert r.discretisation["cut_cells"] == 0 and r.discretisation["enriched_nodes"] == 11
    assert eu <= tol.XFEM_PATCH


@pytest.mark.parametrize("cell", ["quad", "triangle"])
def test_slivers_keep_the_answer_and_the_conditioning(cell, record_property):
    """Cut fractions 1e-2 … 1e-10 of a cell: the answer stays at the patch
    level but for the sliver itself, and the condition estimate stays within
    a factor 3 of the uncut mesh's, whatever the fraction.  Where a node
    is left unenriched and the error passes ACCURATE_FLOOR, the run says so."""
    _, _, plain = _patch_error(horizontal_patch(0.55), cell=cell, estimate_condition=True)
    conditions = []
    for fraction in (1e-2, 1e-4, 1e-6, 1e-8, 1e-10):
        eu, _, r = _patch_error(horizontal_patch(0.5 + fraction * 0.1), cell=cell, estimate_condition=True)
        assert eu <= max(tol.XFEM_PATCH, tol.SLIVER_ERROR_PER_FRACTION * fraction), (fraction, eu)
        assert eu <= ACCURATE_FLOOR or any("slivers" in w for w in r.solver.warnings), (fraction, eu)
        conditions.append(r.solver.condition)
    record_property("sliver_conditions", conditions)
    assert max(conditions) <= tol.SLIVER_CONDITION_GROWTH * plain.solver.condition, conditions


#: Scene A with Γ at y = 1 − STRIP: the + body a strip along the top.
STRIP = 0.005


@pytest.mark.parametrize("degree", [1, 2])
def test_a_body_no_cell_resolves_is_refused_then_resolved_when_refined(degree):
    """A + body thinner than tol.SLIVER_EVAL_DEPTH of every cell it lies in
    (a strip of 0.1 h at h = 0.05) has no cell to evaluate its fields in:
    refused by name, not answered with fields that read zero. At h = 0.025
    the strip is 0.14 of a cell's diameter: solved, and its displacement
    agrees with fe's."""
    scene = load_scene("A").with_changes(interface=LineInterface((0.0, 1.0 - STRIP), (0.0, 1.0)), profiles=())
    with pytest.raises(DiscretisationError, match=r"no cell resolves body \+: "):
        xfem.solve(scene, 0.05, degree=degree)
    points = np.column_stack([np.linspace(0.1, 0.9, 9), np.full(9, 1.0 - STRIP / 2)])
    bodies = np.ones(9, int)
    got = xfem.solve(scene, 0.025, degree=degree).fields.displacement(points, bodies)
    want = conforming.solve(scene, 0.025, degree=2).fields.displacement(points, bodies)
    assert np.max(np.abs(got - want)) <= tol.STRIP_AGREEMENT * np.max(np.abs(want)), (got, want)


@pytest.mark.parametrize("kind", ["shear", "stretch"])
@pytest.mark.parametrize("solver", ["fe", "xfem quad", "xfem triangle"])
def test_quadratic_field_is_reproduced_by_degree_two(solver, kind):
    """u quadratic in each layer (body forces, a spring on Γ, Γ meeting the
    supported sides): exact in every degree-2 space that holds it.  fe P2
    (fitted) checks the closed form itself."""
    case = quadratic_layers(kind)
    if solver == "fe":
        res = conforming.solve(case.scene, 0.1, degree=2)
    else:
        res = xfem.solve(case.scene, 0.1, degree=2, cell=solver.split()[1])
    eu, es = max_errors(case.scene, res.fields, case)
    assert eu <= tol.PATCH_ROUNDOFF and es <= tol.PATCH_ROUNDOFF, (eu, es)


def test_support_holds_both_sides_where_gamma_meets_it():
    """Γ crosses the rollers: the enriched unknowns of the supported nodes
    are held too, so each side's displacement takes the support's value."""
    case = quadratic_layers("shear")
    res = xfem.solve(case.scene, 0.1, degree=1)
    y = np.linspace(0.0, 1.0, 41)
    for x in (0.0, 1.0):
        pts = np.column_stack([np.full_like(y, x), y])
        for body in (0, 1):
            u = res.fields.extended.displacement(pts, np.full(len(y), body))  # the other side too
            assert np.max(np.abs(u[:, 1])) <= tol.PATCH_ROUNDOFF * np.max(np.abs(u[:, 0])), (x, body)


@pytest.mark.parametrize("degree", [1, 2])
def test_a_support_holds_only_the_body_that_reaches_it(degree):
    """Γ in the cells next to a support but not meeting it: the other
    body's enriched unknowns stay free. Scene A with Γ at y = 0.02 (h =
    0.05, below the first node row): the jumps on Γ are fe's (they were
    4.9e-8 against 2.5e-4, the upper block clamped to the bottom)."""
    scene = load_scene("A").with_changes(interface=LineInterface((0.0, 0.02), (0.0, 1.0)), profiles=())
    x = np.linspace(0.1, 0.9, 9)
    on_gamma = np.column_stack([x, np.full(len(x), 0.02)])
    want = interface_response(scene, conforming.solve(scene, 0.05, degree=2).fields, on_gamma)
    got = interface_response(scene, xfem.solve(scene, 0.05, degree=degree).fields, on_gamma)
    for q in ("gN", "gT"):
        assert np.max(np.abs(got[q] - want[q])) <= tol.NEAR_SUPPORT_JUMP * np.max(np.abs(want["gT"])), q


def test_a_rod_next_to_a_clamped_edge_carries_its_torque():
    """Scene B's rod moved to 0.01 from the clamped right edge: the mean
    t_T on Γ is the torque's −T/(2πR²), which equilibrium fixes whatever
    the discretisation (it was 0.26 of it: the rod's enriched unknowns
    at the edge were held)."""
    scene = load_scene("B").with_changes(interface=CircleInterface((0.7, 0.0), 0.29))
    res = xfem.solve(scene, 0.05, degree=2)
    theta = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)
    on_gamma = np.column_stack([0.7 + 0.29 * np.cos(theta), 0.29 * np.sin(theta)])
    tT = interface_response(scene, res.fields, on_gamma)["tT"]
    want = scene.loads[0].torque / (2 * np.pi * 0.29 ** 2)
    assert abs(np.mean(tT) / want - 1.0) <= tol.TORQUE_BALANCE[2], np.mean(tT) / want  # measured 9.7e-8


def test_gauss_rule_is_basix_gauss_legendre():
    """The cut-cell rules use numpy's Gauss–Legendre points: the same as
    basix's interval rule (no hand-typed tables)."""
    import basix

    from contactcore.cutcell import gauss01

    for n in (2, 3, 4, 6):
        pts, wts = basix.make_quadrature(basix.CellType.interval, 2 * n - 1)
        assert np.allclose(np.sort(pts.ravel()), gauss01(n)[0]) and np.allclose(wts[np.argsort(pts.ravel())],
                                                                                 gauss01(n)[1])


def _callable_line(patch):
    n, p0 = np.array(patch.scene.interface.normal), np.array(patch.scene.interface.point)
    return LevelSetInterface(lambda x: (x - p0) @ n, lambda x: np.tile(n, (len(x), 1)))


@pytest.mark.parametrize("cell", ["quad", "triangle"])
@pytest.mark.parametrize("degree", [1, 2])
def test_general_level_set_patch_is_exact(degree, cell):
    patch = interface_patch(30.0, pins=PINS[30.0])
    general = dataclasses.replace(patch, scene=dataclasses.replace(patch.scene,
                                                                   interface=_callable_line(patch)).validated())
    eu, es, _ = _patch_error(general, degree=degree, cell=cell)
    assert eu <= tol.XFEM_PATCH and es <= tol.XFEM_PATCH_STRESS, (eu, es)


def test_callable_circle_matches_the_builtin_one():
    scene = load_scene("C")
    c, R = np.array(scene.interface.centre), scene.interface.radius
    def grad(x):
        with np.errstate(invalid="ignore"):  # 0/0 at the centre: NaN, which the library reads as ∇φ = 0
            return (x - c) / np.hypot(*(x - c).T)[:, None]

    general = dataclasses.replace(scene, interface=LevelSetInterface(lambda x: np.hypot(*(x - c).T) - R, grad),
        profiles=tuple(p for p in scene.profiles if p.id != "C4")).validated()
    a, b = xfem.solve(scene, 0.1), xfem.solve(general, 0.1)
    pts = np.random.default_rng(1).uniform([0, 0], [2, 3], (500, 2))
    bodies = scene.body_of(pts)
    ua, ub = a.fields.displacement(pts, bodies), b.fields.displacement(pts, bodies)
    assert np.max(np.abs(ua - ub)) <= tol.GENERAL_VS_CIRCLE * np.max(np.abs(ua))


def test_a_level_set_scaled_by_any_factor_gives_the_same_profiles():
    """φ = s (r² − R²) is one circle for any s: the profiles read each
    point from the same body (with s = 1e-9 the whole rod was taken as on
    Γ and read from the + body: 12 times the profile's scale off)."""
    scene = load_scene("C")
    scene = scene.with_changes(profiles=tuple(p for p in scene.profiles if p.id == "C3"))
    c, R = np.array(scene.interface.centre), scene.interface.radius
    profiles = []
    for s in (1.0, 1e-9):
        general = scene.with_changes(interface=LevelSetInterface(lambda x, s=s: s * (np.sum((x - c) ** 2, axis=1) - R ** 2),
                                                                 lambda x, s=s: 2 * s * (x - c)))
        profiles.append(sample_profiles(general, xfem.solve(general, 0.1, degree=2).fields)[0].columns["syy"])
    assert np.max(np.abs(profiles[1] - profiles[0])) <= tol.GENERAL_VS_CIRCLE * np.max(np.abs(profiles[0]))


@pytest.mark.parametrize("centre, message", [
    ((0.525, 0.825), "changes sign inside a cell without crossing its edges"),
    ((0.52, 0.8), "could not be followed through the cell"),
])
def test_a_piece_of_gamma_inside_one_cell_is_refused(centre, message):
    """Γ = the line y = 0.5 and a disc of radius 0.01 within a cell or two
    of 0.05 (min of the two level sets, whose gradient is 0 at the disc's
    centre). Inside one cell, the cut cells found Γ through their edges
    only, so the disc was left out and its inside read as the block's
    stress, exit 0; across a node, projecting a chord onto φ = 0 divided by
    zero and NaN reached the solver (a LinAlgError traceback). Both are
    refused by name."""
    c, radius = np.array(centre), 0.01

    def phi(x):
        return np.minimum(x[:, 1] - 0.5, np.linalg.norm(x - c, axis=1) - radius)

    def grad(x):
        d = x - c
        r = np.linalg.norm(d, axis=1)
        disc = np.linalg.norm(d, axis=1) - radius < x[:, 1] - 0.5
        return np.where(disc[:, None], d / np.where(r > 0, r, 1.0)[:, None], np.array([0.0, 1.0]))

    scene = load_scene("A").with_changes(interface=LevelSetInterface(phi, grad), profiles=())
    with pytest.raises(DiscretisationError, match=message):
        xfem.solve(scene, 0.05, degree=2)


DISC_UNDER_PRESSURE = """
name = "disc-pressure"
increments = 1
[domain]
type = "disc"
centre = [0.0, 0.0]
radius = 1.0
[interface]
type = "line"
point = [0.0, 0.2]
normal = [0.3, 1.0]
[interface.law]
type = "linear"
kN = 1e10
kT = 1e8
[materials.minus]
E = 2e11
nu = 0.3
[materials.plus]
E = 2e11
nu = 0.3
[[pins]]
point = [0.0, -1.0]
fix = "xy"
[[pins]]
point = [0.0, 1.0]
fix = "x"
[[loads]]
type = "pressure"
boundary = "outer"
value = 1e5
"""


def test_a_pressure_on_a_disc_is_uniform_stress():
    """A disc under uniform pressure, Γ a line across it: σ = −p I in both
    bodies, exactly on the mesh's polygon (each rim edge loaded along its
    own normal, a disc's rim having no straight edges of its own)."""
    import tomllib

    from contactcore import scene_from_dict
    scene = scene_from_dict(tomllib.loads(DISC_UNDER_PRESSURE))
    res = xfem.solve(scene, 0.1, degree=1)
    pts = np.random.default_rng(3).uniform(-0.6, 0.6, (200, 2))
    sigma = res.fields.stress(pts, scene.body_of(pts))
    assert np.max(np.abs(sigma - [-1e5, -1e5, 0.0])) <= tol.XFEM_PATCH * 1e5


def test_ellipse_geometry_is_integrated():
    from contactcore.cutcell import cut_polygon, interface_rule_in

    a, b = 0.35, 0.2
    ellipse = LevelSetInterface(lambda x: (x[:, 0] / a) ** 2 + (x[:, 1] / b) ** 2 - 1,
                                lambda x: np.column_stack([2 * x[:, 0] / a ** 2, 2 * x[:, 1] / b ** 2]))
    area = length = 0.0
    for i in range(10):
        for j in range(10):
            lo = np.array([-0.5 + 0.1 * i, -0.5 + 0.1 * j])
            cell = np.array([lo, lo + [0.1, 0], lo + 0.1, lo + [0, 0.1]])
            area += sum(w.sum() for side, _, w in cut_polygon(ellipse, cell, 4) if side < 0)
            length += interface_rule_in(ellipse, cell, 4)[1].sum()
    k = ((a - b) / (a + b)) ** 2  # Ramanujan's perimeter, exact to ~1e-10 at this aspect ratio
    perimeter = np.pi * (a + b) * (1 + 3 * k / (10 + np.sqrt(4 - 3 * k)))
    assert abs(area - np.pi * a * b) <= tol.GENERAL_AREA * np.pi * a * b
    assert abs(length - perimeter) <= tol.GENERAL_LENGTH * perimeter


def test_a_circle_tangent_to_a_grid_line_is_integrated():
    """Γ a circle whose lowest point (0.42, 0.4) lies inside an edge of a
    0.1 grid: every split keeps that edge, so the finest pieces take Γ as
    its chord (contactcore.cutcell); the disc's area is still found, to
    tol.TANGENT_AREA."""
    from contactcore.cutcell import cut_polygon

    step, radius = 0.1, 0.2
    circle = CircleInterface((0.42, 0.6), radius)
    area = 0.0
    for i in range(10):
        for j in range(10):
            lo = step * np.array([i, j])
            cell = np.array([lo, lo + [step, 0], lo + step, lo + [0, step]])
            parts = cut_polygon(circle, cell, 4)
            assert sum(w.sum() for _, _, w in parts) == pytest.approx(step ** 2, rel=tol.MESH_SUMS)
            area += sum(w.sum() for side, _, w in parts if side < 0)
    assert abs(area - np.pi * radius ** 2) <= tol.TANGENT_AREA * np.pi * radius ** 2


def test_a_straight_gamma_in_a_disc_is_refused_for_every_h():
    """A straight Γ across a disc domain always meets its rim, whose cells
    are curved at degree 2, which xfem's cut cells cannot follow: the
    refusal says so, not "refine h"; xfem P1 and fe solve the same scene."""
    scene = dataclasses.replace(pressurised_rod().scene, interface=LineInterface((0.0, 0.1), (0.0, 1.0))).validated()
    for h in (0.2, 0.1):
        with pytest.raises(DiscretisationError, match="not supported at degree 2 at any h") as caught:
            xfem.solve(scene, h, degree=2)
        assert "refine" not in str(caught.value)
    for solved in (xfem.solve(scene, 0.2, degree=1), conforming.solve(scene, 0.2, degree=2)):
        assert solved.solver.residual < tol.CONVERGED_RUN_RESIDUAL


def test_a_straight_gamma_across_a_disc_is_integrated_and_solved_by_efgm():
    """Where a straight Γ leaves a disc, background cells are crossed by Γ
    and the rim: split until each piece is crossed by one (contactcore.
    quadrature.RIM_SPLITS), the disc's area and the − body's segment are
    found to tol.DISC_SPLIT_AREA at any h, and efgm, which reads its
    quadrature from there, solves the scene."""
    from contactcore.quadrature import volume_rule
    from efgm import method

    scene = dataclasses.replace(pressurised_rod().scene, interface=LineInterface((0.1, 0.1), tuple(np.array([0.3, 1.0]) / np.hypot(0.3, 1.0)))).validated()
    disc = scene.domain
    for h in (0.2, 0.1):
        rule = volume_rule(scene, h, 3)
        assert rule.weights.sum() == pytest.approx(np.pi * disc.radius ** 2, rel=tol.DISC_SPLIT_AREA)
        minus = rule.weights[rule.bodies == 0].sum()
        assert minus == pytest.approx(scene.interface.minus_area(disc), rel=tol.DISC_SPLIT_AREA)
    assert method.solve(scene, 0.2).solver.residual < tol.CONVERGED_RUN_RESIDUAL


def test_general_level_set_is_for_xfem_only():
    from contactcore import SceneError
    from efgm import method
    from xdolfinx import conforming

    patch = interface_patch(30.0, pins=PINS[30.0])
    scene = dataclasses.replace(patch.scene, interface=_callable_line(patch)).validated()
    for solve, name in ((conforming.solve, "fe"), (method.solve, "efgm")):
        with pytest.raises(DiscretisationError, match=f"{name}: a general level set Γ is supported by xfem only"):
            solve(scene, 0.2)
    outside = LevelSetInterface(lambda x: x[:, 0] + 5.0, lambda x: np.tile([1.0, 0.0], (len(x), 1)))
    with pytest.raises(SceneError, match="interface: the level set does not change sign in the domain"):
        dataclasses.replace(patch.scene, interface=outside).validated()


def test_a_node_within_round_off_of_gamma_lies_on_it():
    """dolfinx pushes each node through one of its cells, so a node on Γ may
    come out an ulp off it, on either side, depending on the cell (and the
    rank): it still lies on Γ (H = +1), as does every node within the snap
    distance (contactcore.tolerances.XFEM_SNAP of a cell), to which Γ is
    snapped.  A node beyond it keeps its side."""
    scene = _tiny(LineInterface((0.0, 0.5), (0.0, 1.0)))
    snap = XFEM_SNAP * 0.05
    y = np.array([0.5, np.nextafter(0.5, 0.0), np.nextafter(0.5, 1.0), 0.5 - 5e-14, 0.5 - 0.99 * snap,
                  0.5 - 1.01 * snap, 0.5 + 1.01 * snap])
    coords = np.column_stack([np.full(len(y), 0.3), y])
    assert list(xfem.node_sides(scene, coords, snap)) == [1, 1, 1, 1, 1, -1, 1]
