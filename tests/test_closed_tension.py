"""A point an exact law reports closed carries no tension beyond Newton's
band (grader7, fault 3): the closed/open band is in traction
(``Decision.in_traction``), and a run that holds a point closed in
tension past it says so (``health.closed_tension_warnings``)."""
from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import tolerances as tol
from contactcore import discretisation, health, load_scene
from contactcore import tolerances as ctol
from contactcore.collective import SERIAL
from contactcore.laws import OPEN, STICK, Decision, UnilateralLaw
from xdolfinx.options import XFEM

SCENE = Path(__file__).parent / "scenes" / "partial_unilateral.toml"


def _held(decision):
    """The unilateral law at γ = 240 on three points: a large open gap
    (the gap scale), a closed point under pressure, and a point whose
    y_N = 1.1e-5 (0.26 of the gap band) was closed at the last iterate."""
    gamma = np.full(3, 240.0)
    y = np.array([[4.4, 0.0], [-5e-3, 0.0], [1.136e-5, 0.0]])
    law = UnilateralLaw(gamma, gamma)
    d = Decision.reduced(law, y, None, np.array([OPEN, STICK, STICK]), SERIAL)
    if decision:
        d = d.in_traction(gamma, float(np.max(-gamma * y[:, 0])))
    return law.evaluate(y, None, d)


def test_the_gap_band_held_a_point_closed_in_tension_and_the_traction_band_opens_it():
    """The measured margin of the xfem P2 point (y_N 0.26 of the band
    relative to an open gap): held closed with t_N = γ y_N > 0 by the gap
    band, open by the band in traction (γ y_N is 2.4e-3 of p here)."""
    old, new = _held(False), _held(True)
    assert old.status[2] == STICK and old.traction[2, 0] > 0
    assert new.status[2] == OPEN and new.traction[2, 0] == 0.0
    assert new.status[1] == STICK and new.status[0] == OPEN


def test_the_band_in_traction_still_holds_a_margin_within_it():
    """A margin within DECISION_BAND of p in traction keeps its status
    (the band is narrowed, not removed)."""
    gamma = np.full(3, 240.0)
    p = 240.0 * 5e-3
    y = np.array([[4.4, 0.0], [-5e-3, 0.0], [0.5 * ctol.DECISION_BAND * p / 240.0, 0.0]])
    law = UnilateralLaw(gamma, gamma)
    d = Decision.reduced(law, y, None, np.array([OPEN, STICK, STICK]), SERIAL).in_traction(gamma, p)
    assert law.evaluate(y, None, d).status[2] == STICK


def test_no_point_of_the_partial_contact_is_closed_in_tension():
    """xfem P2, h = 0.05 on grader7's partial contact: every closed point
    has t_N <= CLOSED_TENSION_OF_P of Γ's largest pressure (it was +2.4e-3
    of p at x = 1.4465) and the run carries no tension warning."""
    result = discretisation.solve(load_scene(SCENE), XFEM(degree=2), 0.05)
    final = result.interface.final
    t = np.asarray(final.traction).reshape(-1, 2)
    closed = np.asarray(final.status) != OPEN
    p = float(np.max(-t[:, 0]))
    assert float(np.max(t[closed, 0])) <= tol.CLOSED_TENSION_OF_P * p
    assert not any("closed in tension" in w for w in result.solver.warnings)


@pytest.mark.parametrize("tension, warned", [(0.0, False), (2.4e-3, True)])
def test_a_path_with_a_closed_point_in_tension_warns(tension, warned):
    """A converged path whose closed point carries 2.4e-3 of p is warned
    of, naming the share; one with none is not."""
    scene = load_scene(SCENE)
    step = SimpleNamespace(step=1.0, traction=np.array([[-1e6, 0.0], [tension * 1e6, 5e5], [0.0, 0.0]]),
                           status=np.array([STICK, STICK, OPEN]))
    warnings = health.closed_tension_warnings(scene, SimpleNamespace(steps=[step]))
    assert bool(warnings) == warned
    if warned:
        assert "closed in tension" in warnings[0] and "0.0024" in warnings[0]


@pytest.mark.parametrize("enforcement", ["penalty", "exact"])
def test_a_gamma_in_pure_shear_is_not_warned_of_tension(enforcement):
    """review4: Γ carrying pure shear (σ_nn = 0, σ_nt = 1 MPa) has every
    t_N of round-off (about 1e-14 of the shear), some of it positive; the
    path's largest pressure is round-off too, and a threshold relative to
    it alone warned of "closed in tension up to 0.6-0.9 of the largest
    pressure" (xfem P1, h = 0.1; the count followed the BLAS kernel).
    Such a t_N is no tension: no warning."""
    from contactcore import Material, make_law
    from verification import methods
    from verification.closed_forms import interface_patch
    law = {"type": "unilateral", "kN": 1e12, "kT": 5e10} if enforcement == "penalty" else \
        {"type": "unilateral", "enforcement": "exact"}
    case = interface_patch(0.0, minus=Material(2e11, 0.3), plus=Material(2e11, 0.3), sigma_nn=0.0, sigma_nt=1e6)
    result = discretisation.solve(case.scene.with_changes(law=make_law(law)), methods.discretisation("xfem")(degree=1),
                                  0.1)
    t = np.asarray(result.interface.final.traction).reshape(-1, 2)
    assert float(np.max(np.abs(t[:, 0]))) <= ctol.TRACTION_ROUNDOFF * float(np.max(np.abs(t[:, 1])))  # round-off
    assert not any("closed in tension" in w for w in result.solver.warnings), result.solver.warnings


@pytest.mark.parametrize("stress_size, warned", [(1e6, False), (0.0, True)])
def test_a_gamma_no_load_reaches_is_not_warned_of_tension(stress_size, warned):
    """review4's case left open: a Γ that the loads leave unloaded along the
    whole path has every traction of round-off of the loads elsewhere
    (here 1e-9 Pa against a scene's stress size of 1 MPa); relative to the
    path's own largest traction (itself round-off) it read as tension up
    to 0.5 of the largest pressure.  With the scene's stress size
    (``scaling.softer_stress``) as the round-off's floor: no warning; without it
    (size 0, the rule before) the warning fires, so the floor is what
    silences it."""
    scene = load_scene(SCENE)
    step = SimpleNamespace(step=1.0, traction=np.array([[-2e-9, 1e-9], [1e-9, -1e-9], [0.0, 0.0]]),
                           status=np.array([STICK, STICK, OPEN]))
    assert bool(health.closed_tension_warnings(scene, SimpleNamespace(steps=[step]), stress_size)) == warned


@pytest.mark.parametrize("name, method, degree", [("hung_on_gamma", "fe", 2), ("hung_on_gamma_coulomb", "xfem", 2)])
def test_a_gamma_at_its_lift_off_load_is_not_warned(name, method, degree):
    """grader10 F2: a body hung on Γ exactly (t = 0, g_N = 0 in closed
    form, tests/scenes/hung_on_gamma*.toml) has every traction of
    round-off (7.6e-10 Pa against loads of 4e5 Pa); relative to the
    path's own largest pressure, itself round-off, fe P2 was warned of 23-25
    pairs closed in tension and xfem P2 of 92-104 sticking above μ|t_N|,
    the counts following the BLAS kernel.  The scene's stress size floors
    the round-off: the closed form holds and no warning is given."""
    from verification import methods
    scene = load_scene(Path(__file__).parent / "scenes" / f"{name}.toml")
    result = discretisation.solve(scene, methods.discretisation(method)(degree=degree), scene.h)
    t = np.asarray(result.interface.final.traction).reshape(-1, 2)
    assert float(np.max(np.abs(t))) <= ctol.TRACTION_ROUNDOFF * 4e5  # the closed form's t = 0, to round-off
    assert not result.solver.warnings, result.solver.warnings
