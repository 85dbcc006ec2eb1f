"""The load contract (contactcore.scene.loads' module doc), with a
test-only load defined here: a load class declares where it acts, its
parameters' dimensions and its one formula; a load that declares too
little is refused at registration by name; every method, the scaling
and the health checks dispatch on the declared kind and refuse anything
else by its type; a new load registered in contactcore.scene.loads.LOADS
and nowhere else solves in all three methods (grader18's ``hydrostatic``,
a pressure linear in the plane, against its closed form); xdolfinx's UFL
traction and body force are the core's formula.

The solves are small (h = L/10 on a square) and in km away from the
origin, so that the declared dimensions (a stress, a gradient, a point)
are what the scaling reads."""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import pytest

from contactcore import (InterfaceProfile, LinearLaw, LineInterface, LineProfile, Material, Rectangle, Scene,
                         SceneError, Support, discretisation, load_scene, sample_profiles)
from contactcore.errors import ContactError
from contactcore.scaling import Scales, dimensionless_inputs
from contactcore.scene import BODY, EDGE, LOADS, BodyForce, Pressure, Torque, Traction, edge_traction, place_of
from contactcore.scene import loads as load_module
from contactcore.scene.loads import FORCE_DENSITY, POINT, STRESS, _Load, load_contract, load_registry
from contactcore.scene_files import _LOAD_TYPES

from tolerances import DIMENSIONLESS_ROUNDOFF, LINEAR_PRESSURE, SAME_SUMS


@dataclass(frozen=True)
class Hydrostatic(_Load):
    """A pressure linear in the plane: ``p = value + gradient · (x − datum)``
    (Pa, Pa/m, m), traction ``−p n``."""

    boundary: str
    value: float
    gradient: tuple[float, float]
    datum: tuple[float, float] = (0.0, 0.0)
    path: tuple[tuple[int, float], ...] = ()

    name = "hydrostatic"
    acts_on = EDGE
    parameters = ("value", "gradient", "datum")
    dimensions = {"value": STRESS, "gradient": FORCE_DENSITY, "datum": POINT}

    @staticmethod
    def field(c, x, y, n):
        p0, g, d = c
        p = p0 + g[0] * (x - d[0]) + g[1] * (y - d[1])
        return -p * n[0], -p * n[1]


@dataclass(frozen=True)
class Undeclared(Hydrostatic):
    """``datum`` left out of the parameters: it would reach the methods in
    the user's metres against a dimensionless scene."""

    name = "undeclared"
    parameters = ("value", "gradient")
    dimensions = {"value": STRESS, "gradient": FORCE_DENSITY}


@dataclass(frozen=True)
class Unregistered:
    """A load-like object no registry holds."""

    boundary: str
    value: float
    path: tuple = ()


@pytest.fixture
def hydrostatic(monkeypatch):
    """``Hydrostatic`` registered as if added to contactcore.scene.loads."""
    monkeypatch.setitem(LOADS, Hydrostatic.name, load_registry(Hydrostatic)[Hydrostatic.name])
    return Hydrostatic


def test_the_registered_loads_hold_to_the_contract_and_are_the_scene_files_types():
    """Every load a scene file can name is registered, under that name,
    and declares where it acts and a dimension for each parameter."""
    assert {cls: name for name, cls in LOADS.items()} == _LOAD_TYPES
    assert {name: cls.acts_on for name, cls in LOADS.items()} == {
        "traction": EDGE, "pressure": EDGE, "body_force": BODY, "torque": BODY}
    for cls in LOADS.values():
        assert set(load_contract(cls)) == set(cls.parameters)


def _lacking(**members):
    namespace = {k: v for k, v in vars(Hydrostatic).items() if k in ("name", "acts_on", "parameters", "dimensions",
                                                                     "field")}
    namespace.update(members)
    namespace = {k: v for k, v in namespace.items() if v is not None}
    namespace["__annotations__"] = dict(Hydrostatic.__annotations__)
    namespace.update({f.name: f.default for f in dataclasses.fields(Hydrostatic)
                      if f.default is not dataclasses.MISSING})
    return dataclass(frozen=True)(type("Lacking", (_Load,), namespace))


@pytest.mark.parametrize("members,message", [
    ({"acts_on": None}, r"'hydrostatic'\): declares no 'acts_on'"),
    ({"acts_on": "surface"}, r"declares no 'acts_on' \('edge' or 'body'; got 'surface'\)"),
    ({"name": None}, r"Lacking: declares no 'name'"),
    ({"dimensions": {"value": STRESS, "gradient": FORCE_DENSITY}}, r"no dimension for its parameter 'datum'"),
    ({"dimensions": {"value": STRESS, "gradient": "pressure", "datum": POINT}},
     r"no dimension for its parameter 'gradient' \(got 'pressure'"),
    ({"dimensions": {"value": POINT, "gradient": POINT, "datum": POINT}}, r"no parameter of a magnitude"),
    ({"field": None}, r"declares no formula 'field' \(the traction"),
    ({"acts_on": BODY}, r"acts on a body but has no field 'body'"),
], ids=["no-acts-on", "bad-acts-on", "no-name", "no-dimension", "bad-dimension", "no-magnitude", "no-formula",
        "no-body"])
def test_a_load_that_declares_too_little_is_refused_at_registration_by_name(members, message):
    """The base class declares nothing, so a new load cannot inherit a
    wrong declaration; each omission is named with the load's class."""
    with pytest.raises(ContactError, match=message):
        load_registry(_lacking(**members))


def test_a_field_that_is_no_declared_parameter_is_refused():
    """grader18's gap law in load form: a field the scaling does not know
    of would be solved in the user's units."""
    with pytest.raises(ContactError, match=r"Undeclared \('undeclared'\): its field 'datum' is not among its "
                                           r"declared parameters"):
        load_registry(Undeclared)
    with pytest.raises(ContactError, match="registered twice"):
        load_registry(Traction, dataclass(frozen=True)(type("Again", (Traction,), {})))


def _block(load, L=1000.0, x0=5000.0, y0=-3000.0, vertical=False):
    """A square of side L at (x0, y0), bottom fixed, ν = 0, plane stress,
    bonded springs across Γ (horizontal at mid-height, E⁻ ≠ E⁺; or
    vertical at 0.53 L, one material, so that the loaded top edge crosses
    Γ: xfem's band edge loads), the top under ``load``: σ_yy = −p(x),
    σ_xx = σ_xy = 0, and across a horizontal Γ t_N = −p(x)."""
    if vertical:
        gamma, E = LineInterface((x0 + 0.53 * L, y0), (1.0, 0.0)), (2e11, 2e11)
    else:
        gamma, E = LineInterface((x0, y0 + 0.5 * L), (0.0, 1.0)), (2e11, 7e10)
    return Scene(name="linear-pressure", title="a pressure linear in x on a block", plane="stress",
                 domain=Rectangle((x0, y0), (L, L)), interface=gamma,
                 materials={"minus": Material(E[0], 0.0), "plus": Material(E[1], 0.0)},
                 law=LinearLaw(1e11 / L, 1e11 / L), supports=(Support("bottom", "xy"),), loads=(load,),
                 profiles=(InterfaceProfile("gamma", ("tN",)),
                           LineProfile("near-top", (x0, y0 + 0.9 * L), (x0 + L, y0 + 0.9 * L), ("syy",))),
                 h=0.1 * L).validated()


#: p = 1 MPa at x0, 2 MPa at x0 + L; its datum away from the domain
P0, P1, DATUM = 1e6, 1e6, (4000.0, 250.0)


def _pressure(x, x0=5000.0, L=1000.0):
    return P0 + P1 * (np.asarray(x) - x0) / L


def _linear_load(x0=5000.0, L=1000.0):
    g = P1 / L
    return Hydrostatic("top", P0 + g * (DATUM[0] - x0), (g, 0.0), DATUM)


def _options(method):
    from efgm.options import EFGM
    from xdolfinx.options import FE, XFEM
    return {"fe": FE(degree=2), "xfem": XFEM(degree=2), "efgm": EFGM(basis="quadratic")}[method]


@pytest.mark.parametrize("vertical", [False, True], ids=["across-gamma", "crossing-gamma"])
@pytest.mark.parametrize("method", ["fe", "xfem", "efgm"])
def test_a_load_registered_only_in_loads_solves_in_every_method(hydrostatic, method, vertical):
    """The linear pressure, known to contactcore.scene.loads' registry and
    nowhere else, against its closed form: degree 2 reproduces it (fe,
    xfem to round-off; efgm's quadratic MLS to its quadrature)."""
    scene = _block(_linear_load(), vertical=vertical)
    result = discretisation.solve(scene, _options(method))
    gamma, top = sample_profiles(scene, result.fields, result.interface)
    tol = LINEAR_PRESSURE[method]
    assert np.max(np.abs(top.columns["syy"] + _pressure(top.columns["x"]))) <= tol * P0
    if not vertical:
        assert np.max(np.abs(gamma.columns["tN"] + _pressure(gamma.columns["x"]))) <= tol * P0


def test_the_scaling_reads_the_declared_dimensions(hydrostatic):
    """Value over Σ, gradient times L/Σ, datum moved and shrunk as every
    point: the dimensionless traction at the dimensionless points is the
    user's over Σ."""
    scene = _block(_linear_load())
    scales = Scales.of(scene)
    inner = scales.scene(scene)
    load, mine = inner.loads[0], scene.loads[0]
    assert load.value == mine.value / scales.stress
    assert load.gradient[0] == mine.gradient[0] / (scales.stress / scales.length)
    assert load.datum == tuple(scales.to_dimensionless(np.array(DATUM)))
    x = np.array([[5000.0, 0.0], [5300.0, 0.0], [6000.0, 0.0]]) + [0.0, -2000.0]
    n = np.tile([0.0, 1.0], (3, 1))
    user = edge_traction(scene, mine, x[:, 0], x[:, 1], n)
    xs = scales.to_dimensionless(x)
    ours = scales.stress * edge_traction(inner, load, xs[:, 0], xs[:, 1], n)
    assert np.allclose(ours, user, rtol=DIMENSIONLESS_ROUNDOFF, atol=0)
    assert np.allclose(user[:, 1], -_pressure(x[:, 0]), rtol=DIMENSIONLESS_ROUNDOFF, atol=0)


def test_the_health_checks_integrate_a_varying_load_by_its_formula(hydrostatic):
    """The resultant the equilibrium check reads is ∫ −p n over each
    body's part of the loaded edge (Γ vertical at 0.53 L cuts the top)."""
    from contactcore.health.equilibrium import _boundary_resultant

    scene = _block(_linear_load(), vertical=True)
    L, cut = 1000.0, 0.53
    for body, (a, b) in enumerate([(0.0, cut), (cut, 1.0)]):
        exact = -(P0 * (b - a) + P1 * (b * b - a * a) / 2) * L
        got = _boundary_resultant(scene, body, (1.0,))
        assert got[0] == 0.0
        assert abs(got[1] - exact) <= SAME_SUMS * abs(exact)


def test_an_unknown_load_is_refused_by_name_everywhere(tmp_path):
    """Not registered: the scene model, the scaling, each method's load
    assembly and the health checks name its type, rather than meeting a
    missing attribute in a method."""
    from contactcore.health.equilibrium import _boundary_resultant
    from efgm.method import _load_vectors
    from xdolfinx.xfem.kernels import band_loads

    scene = load_scene("A")
    stranger = Unregistered("top", 1.0)
    with pytest.raises(SceneError, match=r"^loads\[0\]: must be a Traction, Pressure, BodyForce or Torque"):
        scene.with_changes(loads=(stranger,))
    for load, match in [(stranger, "unknown load type Unregistered"),
                        (Hydrostatic("top", 1.0, (0.0, 0.0)), "unknown load type Hydrostatic")]:
        raw = dataclasses.replace(scene, loads=(load,))
        with pytest.raises(SceneError, match=rf"^loads\[0\]: .*{match}"):
            dimensionless_inputs(raw, _options("efgm"), 0.1)
        for call in (lambda: place_of(load), lambda: _load_vectors(raw, None, np.zeros((0, 0)), 0.1, 1),
                     lambda: next(band_loads(None, load)), lambda: _boundary_resultant(raw, 0, (1.0,))):
            with pytest.raises(ContactError, match=match):
                call()


def test_the_ufl_loads_are_the_core_formula(hydrostatic):
    """xdolfinx's traction (a FacetNormal given) and body force, their
    numbers as Constants, evaluate at points to the core's
    ``edge_traction`` / ``body_force``, which efgm, the xfem band and the
    health checks use: every registered load and the linear pressure."""
    ufl = pytest.importorskip("ufl")
    from dolfinx import mesh
    from mpi4py import MPI

    from contactcore.scene import body_force
    from xdolfinx import elasticity

    msh = mesh.create_unit_square(MPI.COMM_SELF, 1, 1)
    scene = load_scene("B")
    points = np.random.default_rng(1).uniform(-1.0, 1.0, (5, 2))
    normal = np.array([0.6, -0.8])
    loads = [Traction("top", (2.5e4, -1e5)), Pressure("right", 3e4), _linear_load(0.0, 1.0),
             BodyForce("plus", (1e3, -2e3)), Torque("minus", -9417.6)]
    assert {type(ld) for ld in loads} >= set(LOADS.values())
    for load in loads:
        if place_of(load) == EDGE:
            expr = elasticity.edge_traction(scene, load, msh)
            theirs = edge_traction(scene, load, points[:, 0], points[:, 1], np.tile(normal, (len(points), 1)))
        else:
            expr = elasticity.body_force(scene, load, msh)
            theirs = np.column_stack(body_force(scene, load, points[:, 0], points[:, 1]))
        values = {c: c.value.item() if c.value.shape == () else tuple(c.value)
                  for c in ufl.algorithms.extract_type(expr, ufl.Constant)}
        values[ufl.FacetNormal(msh)] = tuple(normal)
        ours = np.array([[expr[i]((x, y), values) for i in range(2)] for x, y in points])
        scale = np.abs(theirs).max()
        assert scale > 0
        assert np.abs(ours - theirs).max() <= SAME_SUMS * scale, type(load).__name__


def test_a_load_vanishes_and_scales_by_its_magnitudes_not_its_points():
    """Zero in every parameter of a magnitude, whatever its points, is no
    load; a factor of the load path multiplies those parameters only."""
    assert load_module.vanishes(Hydrostatic("top", 0.0, (0.0, -0.0), (3.0, 4.0)))
    assert not load_module.vanishes(Hydrostatic("top", 0.0, (0.0, 1.0), (3.0, 4.0)))
    assert load_module.scaled_load(Hydrostatic("top", 1.5, (2.0, -1.0), (3.0, 4.0)), -2.0) == \
        Hydrostatic("top", -3.0, (-4.0, 2.0), (3.0, 4.0))
    assert load_module.scaled_load(Torque("minus", 3.0), 0.5) == Torque("minus", 1.5)
