"""EFGM with Γ off the node rows (issue 22): the stress on Γ is the limit
from its side, and every profile agrees with fe P2 at h/2 over inclined
straight interfaces in scene A and off-centre rods in scene C."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import sample_profiles
from placements import circle_C, inclined_A, one_sided_gaps, worst_sample
from verification import methods

BASES = ["linear", "quadratic"]


def _placements(count: int, seed: int = 22):
    """``count`` seeded (angle in ±30°, height in 0.35–0.65) pairs."""
    rng = np.random.default_rng(seed)
    return [tuple(np.round(rng.uniform((-30.0, 0.35), (30.0, 0.65)), 4)) for _ in range(count)]


#: the issue's geometry first, then seeded draws, at the issue's h = 0.025
#: (fe P2 at 0.0125): the first DEFAULT_PLACEMENTS by default, all of them
#: with --runslow.  (At h = 0.05 the second one is 10.4 % off in σxy with
#: the quadratic basis, not yet understood; 3.9 % at 0.025.)
PLACEMENTS = [(20.0, 0.4)] + _placements(23)
DEFAULT_PLACEMENTS = 1
#: off-centre rods (centre, radius) of scene C, clear of tangency with the cell rows
CIRCLES = [((0.93, 1.43), 0.45), ((1.063, 1.581), 0.421)]


_REFERENCES = {}


def _reference(scene, h):
    """fe P2 profiles, once per scene (both bases compare against them)."""
    key = (scene.name, h)
    if key not in _REFERENCES:
        fe = methods.solver("fe")(scene, h, degree=2, estimate_condition=False)
        _REFERENCES[key] = {p.id: p for p in sample_profiles(scene, fe.fields)}
    return _REFERENCES[key]


def _worst(scene, h, basis):
    got = methods.solver("efgm")(scene, h, basis=basis, estimate_condition=False)
    return worst_sample(scene, {p.id: p for p in sample_profiles(scene, got.fields)}, _reference(scene, h / 2))


@pytest.mark.parametrize("basis", BASES)
def test_stress_on_gamma_is_its_one_sided_limit(basis):
    """The point x = 0.8325 on Γ turned 20° at h = 0.025, where a node's
    support crosses Γ by only h/32: σ on Γ equals σ 1e-6 off Γ on
    the + side, and the quadratic extrapolation to Γ of σ at h/8, h/4 and
    3h/8 off Γ (the thin lens that held the error lay within h/32)."""
    scene, h = inclined_A(20.0, 0.4), 0.025
    fields = methods.solver("efgm")(scene, h, basis=basis, estimate_condition=False).fields
    gaps = one_sided_gaps(fields, scene, 0.8325, 20.0, h)
    assert max(gaps) <= tol.EFGM_ONE_SIDED, gaps


def _placement_cases():
    return [pytest.param(a, y, marks=[pytest.mark.slow] if k >= DEFAULT_PLACEMENTS else [])
            for k, (a, y) in enumerate(PLACEMENTS)]


@pytest.mark.parametrize("basis", BASES)
@pytest.mark.parametrize("angle,height", _placement_cases())
def test_inclined_gamma_agrees_with_fe(angle, height, basis):
    """Every sample of every profile (A1–A5; away from corners and Γ's
    ends) within EFGM_INCLINED_AGREE of the profile's scale of fe P2 at h/2."""
    value, pid, q = _worst(inclined_A(angle, height), 0.025, basis)
    assert value <= tol.EFGM_INCLINED_AGREE, (pid, q, value)


@pytest.mark.slow
@pytest.mark.parametrize("basis", BASES)
@pytest.mark.parametrize("centre,radius", CIRCLES)
def test_off_centre_rod_agrees_with_fe(centre, radius, basis):
    """Scene C with its rod moved off the node rows, at the scene's h."""
    scene = circle_C(centre, radius)
    value, pid, q = _worst(scene, scene.h, basis)
    assert value <= tol.EFGM_INCLINED_AGREE, (pid, q, value)
