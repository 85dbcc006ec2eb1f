"""The UFL forms of fe and xfem depend on a scene's structure only: E, ν and
every load value enter as Constants (xdolfinx.elasticity), so two scenes
that differ only in values compile to the same C code (ffcx names a
module by the form's signature), and a parameter study over E or a load
compiles nothing new."""
import numpy as np
import pytest
import ufl
from ffcx.naming import compute_signature
from mpi4py import MPI

import tolerances as tol
from contactcore import LinearLaw, Material, load_scene
from contactcore import scene as scene_model
from contactcore.scene import BodyForce, Pressure, Support, Torque, Traction
from xdolfinx import conforming, elasticity, xfem
from xdolfinx.fitted_mesh import fitted_mesh
from xdolfinx.xfem.assembly import tags, ufl_forms

H = 0.5


def _loaded(scale: float, E=(2e11, 2e10), nu=(0.3, 0.2), plane="stress"):
    """Scene B (a rod under torsion) with a load of every kind, their values
    times ``scale``, and the given materials."""
    base = load_scene("B")
    loads = (Torque("minus", -9417.6 * scale), Traction("top", (2.5e4 * scale, -1e5 * scale)),
             Pressure("right", 3e4 * scale), BodyForce("plus", (1e3 * scale, -2e3 * scale)))
    return base.with_changes(materials={"minus": Material(E[0], nu[0]), "plus": Material(E[1], nu[1])},
                             loads=loads, supports=(Support("left"), Support("bottom")), plane=plane)


SCENES = (_loaded(1.0), _loaded(-2.7, E=(7e10, 3e9), nu=(0.25, 0.45), plane="strain"))


def _signature(form):
    """What ffcx names a form's compiled module by (with its options)."""
    return None if form is None else compute_signature([form], "")


def test_fe_forms_of_scenes_differing_in_values_compile_to_the_same_code():
    fm = fitted_mesh(SCENES[0], H, order=1, comm=MPI.COMM_SELF)
    el = ufl.VectorElement("Lagrange", fm.mesh.ufl_cell(), 1)
    from dolfinx import fem
    V = fem.FunctionSpace(fm.mesh, ufl.MixedElement([el, el]))
    signatures = [[_signature(conforming.bilinear_form(s, fm, V, exact))
                   for exact in (False, True)] + [_signature(L) for L in conforming.linear_forms(s, fm, V)]
                  for s in SCENES]
    assert None not in signatures[0]
    assert signatures[0] == signatures[1]


def test_xfem_forms_of_scenes_differing_in_values_compile_to_the_same_code():
    signatures = []
    for s in SCENES:
        space = xfem.enriched_space(xfem.background_mesh(s, H, "quad", comm=MPI.COMM_SELF), 1, s,
                                    xfem.GAUSS_POINTS[1])
        a, linear = ufl_forms(space, *tags(space))
        signatures.append([_signature(a)] + [_signature(L) for L in linear])
    assert None not in signatures[0]
    assert signatures[0] == signatures[1]


@pytest.mark.parametrize("load", [Traction("top", (0.0, 0.0)), Traction("top", (-0.0, 0.0)), Pressure("right", 0.0),
                                  BodyForce("plus", (0.0, 0.0)), Torque("minus", 0.0)])
def test_a_zero_load_has_no_form_and_a_nonzero_one_has(load):
    """Decided from the load's numbers (a Constant is never UFL's zero):
    a zero load gets no form, one non-zero component is enough for one."""
    base = load_scene("B").with_changes(supports=(Support("left"), Support("bottom")))
    fm = fitted_mesh(base, H, order=1, comm=MPI.COMM_SELF)
    from dolfinx import fem
    el = ufl.VectorElement("Lagrange", fm.mesh.ufl_cell(), 1)
    V = fem.FunctionSpace(fm.mesh, ufl.MixedElement([el, el]))
    nonzero = {Traction: lambda l: Traction(l.boundary, (0.0, 1.0)), Pressure: lambda l: Pressure(l.boundary, 1.0),
               BodyForce: lambda l: BodyForce(l.body, (1.0, 0.0)), Torque: lambda l: Torque(l.body, 1.0)}
    forms = conforming.linear_forms(base.with_changes(loads=(load, nonzero[type(load)](load))), fm, V)
    assert forms[0] is None
    assert forms[1] is not None


def test_the_ufl_body_force_is_the_shared_formula():
    """xdolfinx's body force (its numbers as Constants) evaluates to
    contactcore.scene.body_force, which efgm and the xfem band use."""
    from dolfinx import mesh
    msh = mesh.create_unit_square(MPI.COMM_SELF, 1, 1)
    scene = SCENES[1].with_changes(interface=scene_model.CircleInterface((0.1, -0.2), 0.3))
    points = np.random.default_rng(0).uniform(-1.0, 1.0, (7, 2))
    for load in scene.loads[::3]:  # the torque and the body force
        b = elasticity.body_force(scene, load, msh)
        values = {c: c.value.item() if c.value.shape == () else tuple(c.value)
                  for c in ufl.algorithms.extract_type(b, ufl.Constant)}
        ours = np.array([[b[i]((x, y), values) for i in range(2)] for x, y in points])
        theirs = np.column_stack(scene_model.body_force(scene, load, points[:, 0], points[:, 1]))
        scale = np.abs(theirs).max()
        assert scale > 0
        assert np.abs(ours - theirs).max() <= tol.SAME_SUMS * scale


def test_a_second_scene_of_other_values_compiles_no_new_form(tmp_path):
    """Scene A solved by fe with its forms compiled into an empty cache,
    then with other moduli, Poisson's ratios, springs and traction (not in
    proportion: every method solves the scene made dimensionless, where
    proportional values are the same numbers): no new module in the cache,
    and another answer."""
    scene = load_scene("A")
    other = scene.with_changes(materials={"minus": Material(7e10, 0.2), "plus": Material(2e11, 0.35)},
                               loads=(Traction("top", (-1e5, 4e4)),), law=LinearLaw(3e9, 7e8))
    points = np.array([[0.3, 0.25], [0.6, 0.75], [0.45, 0.9]])
    bodies = scene.body_of(points)
    compiled, answers = [], []
    for s in (scene, other):
        res = conforming.solve(s, H, jit_params={"cache_dir": str(tmp_path)})
        compiled.append(sorted(p.name for p in tmp_path.glob("*.so")))
        answers.append(res.fields.displacement(points, bodies))
    assert compiled[0]
    assert compiled[1] == compiled[0]
    assert np.abs(answers[1] - answers[0]).max() > tol.SOLVER_AGREEMENT * np.abs(answers[0]).max()


def test_xfem_forms_compiled_in_turn_for_two_scenes_compile_once(tmp_path):
    """The xfem forms of two scenes of other values, each scene's compiled
    as xfem compiles them (the stiffness first): the second scene adds no
    module.  ffcx gives a mesh's coordinate element its equispaced variant
    when it first compiles on it, which renumbered the domains of the load
    form built before: it compiled anew (xdolfinx.xfem.assembly)."""
    from dolfinx import fem
    compiled = []
    for s in (load_scene("A"), load_scene("A").with_changes(materials={"minus": Material(7e10, 0.2),
                                                                       "plus": Material(2e11, 0.35)})):
        space = xfem.enriched_space(xfem.background_mesh(s, H, "quad", comm=MPI.COMM_SELF), 1, s,
                                    xfem.GAUSS_POINTS[1])
        a, linear = ufl_forms(space, *tags(space))
        for form in (a, *linear):
            fem.form(form, jit_params={"cache_dir": str(tmp_path)})
        compiled.append(sorted(p.name for p in tmp_path.glob("*.so")))
    assert len(compiled[0]) == 2
    assert compiled[1] == compiled[0]
