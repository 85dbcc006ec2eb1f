"""The law contract (contactcore.laws' module doc), with toy laws defined
here: every parameter is scaled by the dimension its class declares, in
every method's units path; a law that declares too little is refused by
name; Newton relies on positive homogeneity only where a law declares it;
the health checks read a law's capabilities, not its name; docs/scenes.md
names every law and load type the scene model accepts.

No solve: the units path is followed up to the method's build, which is
stopped there."""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from contactcore import SceneError, load_scene
from contactcore.collective import SERIAL
from contactcore.discretisation import Discretisation, solve
from contactcore.errors import ContactError
from contactcore.exact import EXACT_LAWS
from contactcore.health import NOT_CONVERGED, beyond_cone, friction_demand, tie_cause
from contactcore.laws import (DIMENSIONLESS, DISPLACEMENT, LAWS, OPEN, STICK, STIFFNESS, CoulombLaw, LawResponse,
                              _Law, law_contract, registry)
from contactcore.newton.increments import _Newton
from contactcore.newton.refusals import _unsettled
from contactcore.scaling import Scales, dimensionless_inputs
from contactcore.scene import Traction
from contactcore.scene_files import _LOAD_TYPES
from efgm.options import EFGM
from xdolfinx.options import FE, XFEM

from tolerances import DIMENSIONLESS_ROUNDOFF

DOCS = Path(__file__).resolve().parents[1] / "docs"


@dataclass(frozen=True)
class ToyGap(_Law):
    """Unilateral springs engaging after a gap ``g0`` (m): not homogeneous."""

    kN: float
    kT: float
    g0: float

    name = "toy-gap"
    parameters = ("kN", "kT", "g0")
    dimensions = {"kN": STIFFNESS, "kT": STIFFNESS, "g0": DISPLACEMENT}
    is_linear = False
    homogeneous = False
    unilateral = True
    frictional = False

    @classmethod
    def from_params(cls, params: dict, path: str):
        return cls(**{k: float(params[k]) for k in cls.parameters})

    def evaluate(self, g, state=None, decision=None) -> LawResponse:
        g = np.asarray(g, float).reshape(-1, 2)
        _, closed, tN = self._springs(g + np.array([self.g0, 0.0]), decision)
        tT = np.where(closed, self.kT * g[:, 1], 0.0)
        tangent = np.zeros((len(g), 2, 2))
        tangent[:, 0, 0], tangent[:, 1, 1] = np.where(closed, self.kN, 0.0), np.where(closed, self.kT, 0.0)
        return LawResponse(np.column_stack([tN, tT]), tangent, None, np.where(closed, STICK, OPEN).astype(np.int8))


@dataclass(frozen=True)
class Undeclared(ToyGap):
    """``g0`` added to the parameters, the base's dimensions inherited: the
    mistake that gave grader18 the ``g0 = 0`` answer in every method."""

    name = "undeclared"
    dimensions = {"kN": STIFFNESS, "kT": STIFFNESS}


@dataclass(frozen=True)
class ToyCoulomb(CoulombLaw):
    """Coulomb's law under another name."""

    name = "toy-coulomb"


class _Built(Exception):
    """Raised by the stopped build, with the scene the method was handed."""


@pytest.fixture
def stopped_build(monkeypatch):
    """Every method's build stopped at its start: the scene, options and h
    it would see are raised in :class:`_Built`."""
    def build(self, scene, resolution, timings):
        raise _Built(scene, self, resolution)
    monkeypatch.setattr(Discretisation, "build", build)


def _toy_scene(law=None):
    scene = load_scene("A")
    return scene.with_changes(law=law or ToyGap(kN=scene.law.kN, kT=scene.law.kT, g0=2e-6))


@pytest.mark.parametrize("method", [FE, XFEM, EFGM])
def test_every_parameter_is_scaled_by_its_declared_dimension_in_every_method(stopped_build, method):
    """The law a method's build receives (through the one decorated solve)
    has ``g0/U`` and ``k L/S``; and the scaled law at the scaled jumps is
    the law at the jumps over Σ, closed and open points alike."""
    scene = _toy_scene()
    scales = Scales.of(scene)
    with pytest.raises(_Built) as built:
        solve(scene, method(), 0.1)
    law = built.value.args[0].law
    assert type(law) is ToyGap
    assert law.g0 == scene.law.g0 / scales.displacement
    assert law.kN == scene.law.kN / (scales.modulus / scales.length)
    g = np.array([[-3e-6, 1e-6], [-1.5e-6, -2e-6], [1e-6, 4e-7]])  # closed, open (within g0), open
    user = scene.law.evaluate(g).traction
    assert np.any(user[:, 0] < 0) and np.any(user[:, 0] == 0)
    scaled = scales.stress * law.evaluate(g / scales.displacement).traction
    assert np.allclose(scaled, user, rtol=DIMENSIONLESS_ROUNDOFF, atol=0)


def test_a_parameter_without_a_dimension_is_refused_at_registration_and_at_solve(stopped_build):
    """``Undeclared`` is refused by :func:`registry` (at import, for a law
    in LAWS) and, built in code, before any method sees it, naming g0."""
    with pytest.raises(ContactError, match=r"'undeclared' law .*no dimension for its parameter 'g0'"):
        registry(Undeclared)
    scene = _toy_scene(Undeclared(kN=1e10, kT=1e8, g0=2e-6))
    with pytest.raises(SceneError, match=r"^interface\.law: .*parameter 'g0'") as refused:
        dimensionless_inputs(scene, EFGM(), 0.1)
    assert not isinstance(refused.value, _Built)


@pytest.mark.parametrize("capability", ["homogeneous", "unilateral", "frictional"])
def test_a_law_that_does_not_declare_a_capability_is_refused(capability):
    """The base class gives none, so a new law cannot inherit a wrong one."""
    members = {k: getattr(ToyGap, k) for k in ("homogeneous", "unilateral", "frictional") if k != capability}
    lacking = type("Lacking", (_Law,), {"name": "lacking", **members})
    with pytest.raises(ContactError, match=f"declares no '{capability}'"):
        law_contract(lacking)


def test_the_registered_laws_hold_to_the_contract():
    """Every law a scene file can name declares a dimension per parameter;
    linear, unilateral and coulomb, penalty or exact, are homogeneous."""
    for kind in (*LAWS.values(), *EXACT_LAWS.values()):
        assert set(law_contract(kind)) == set(kind.parameters)
    assert all(table[name].homogeneous for table in (LAWS, EXACT_LAWS) for name in ("unilateral", "coulomb"))
    assert LAWS["linear"].homogeneous and EXACT_LAWS["bonded"].homogeneous
    assert law_contract(CoulombLaw)["mu"] == DIMENSIONLESS


def _newton(law, scene):
    return SimpleNamespace(law=law, scene=scene, state=None, u=np.zeros(3), ranks=SERIAL)


def test_from_rest_holds_only_for_a_law_that_declares_itself_homogeneous():
    """A smaller step from rest is the same problem scaled only for a
    homogeneous law: the refusal says more increments do not help only
    there, and offers them to the toy gap law."""
    scene = load_scene("A")
    assert _Newton._from_rest(_newton(scene.law, scene), 0.0, 1.0)
    toy = _toy_scene()
    assert not _Newton._from_rest(_newton(toy.law, toy), 0.0, 1.0)
    assert "do not help" not in _unsettled(toy.law, False) and "more increments" in _unsettled(toy.law, False)


#: grader18's gap_pulled scene (its law unilateral): a block above a
#: horizontal Γ, held by Γ alone and pulled off it by a negative pressure.
PULLED = """
name = "pulled"
increments = 4
h = 0.1
[domain]
type = "rectangle"
size = [1.0, 1.0]
[interface]
type = "line"
point = [0.0, 0.5]
normal = [0.0, 1.0]
[interface.law]
type = "unilateral"
kN = 1e13
kT = 1e12
[materials.minus]
E = 2e11
nu = 0.0
[materials.plus]
E = 7e10
nu = 0.0
[[supports]]
boundary = "bottom"
fix = "xy"
[[loads]]
type = "pressure"
boundary = "top"
value = -1e6
"""


def _pulled(tmp_path, law):
    path = tmp_path / "pulled.toml"
    path.write_text(PULLED)
    return load_scene(path).with_changes(law=law)


def test_the_health_checks_read_capabilities_not_names(tmp_path):
    """A law that can open is refused in one line when the loads pull its
    body off Γ, under any name; springs that carry tension are not; a
    frictional law under another name gets Coulomb's cone check and the
    unilateral tie's diagnosis goes to a frictionless law that opens."""
    gap = _pulled(tmp_path, ToyGap(kN=1e13, kT=1e12, g0=1e-6))
    assert "held by Γ alone and the loads pull it off Γ" in friction_demand(gap, 1.0)
    assert friction_demand(gap.with_changes(law=LAWS["linear"](kN=1e13, kT=1e12)), 1.0) == ""
    sheared = gap.with_changes(law=ToyCoulomb(kN=1e13, kT=1e12, mu=0.5),
                               loads=(Traction(boundary="top", value=(1e6, -1e6)),))
    assert "slides off" in beyond_cone(sheared, 1.0) and "slides off" in friction_demand(sheared, 1.0)
    tie = tie_cause(gap.with_changes(loads=sheared.loads), 1.0, NOT_CONVERGED, from_rest=False)
    assert "of the toy-gap law" in tie and "do not help" not in tie
    assert tie_cause(sheared, 1.0, NOT_CONVERGED) == ""


def _section(text: str, title: str) -> str:
    return text.split(f"\n## {title}\n", 1)[1].split("\n## ", 1)[0]


def test_scenes_md_names_every_law_and_load_type_the_scene_model_accepts():
    """Each penalty law has a row of the law table, each exact law (and
    ``bonded``) is named in that section, each load type has a row of the
    loads table: a new one without its documentation fails here."""
    text = (DOCS / "scenes.md").read_text()
    laws = _section(text, "Interface laws")
    rows = set(re.findall(r"^\| `([a-z_-]+)` \|", laws, re.M))
    assert set(LAWS) <= rows, set(LAWS) - rows
    assert all(f"`{name}`" in laws or f'type = "{name}"' in laws for name in EXACT_LAWS)
    loads = re.findall(r"^\| `([a-z_-]+)` \|", text, re.M)
    assert set(_LOAD_TYPES.values()) <= set(loads), set(_LOAD_TYPES.values()) - set(loads)


@pytest.mark.parametrize("capability", ["homogeneous", "unilateral", "frictional"])
def test_an_exact_law_that_does_not_declare_a_capability_is_refused(capability):
    """The exact laws' base gives none either (review7 #3: it gave
    ``homogeneous``, so an exact law that forgot it was taken as
    homogeneous and told its user that more increments do not help)."""
    from contactcore.exact import ExactUnilateral, _ExactLaw

    members = {k: getattr(ExactUnilateral, k) for k in ("homogeneous", "unilateral", "frictional") if k != capability}
    lacking = type("LackingExact", (_ExactLaw,), {"name": "lacking_exact", **members})
    with pytest.raises(ContactError, match=f"declares no '{capability}'"):
        registry(lacking)
