"""grader22 F2: a block held by Γ alone whose loads' line of action meets
Γ outside its extent overturns (no equilibrium, contact only pushes); it is
refused by name before Newton, not advised to soften its springs."""
from __future__ import annotations

from pathlib import Path

from contactcore import load_scene
from contactcore.health import beyond_cone
from contactcore.scene import Traction

SCENES = Path(__file__).resolve().parent / "scenes"
#: How far from the limit the two probes sit: far above DEMAND_ROUNDOFF (1e-12), the check's only slack.
PROBE = 1e-6


def test_overturning_block_is_refused_by_name():
    """1 × 0.55 block on a flat Γ, μ = 2, top traction (0.93, −1) MPa:
    eccentricity 0.55 · 0.93 = 0.5115 > half-length 0.5 (closed form)."""
    scene = load_scene(SCENES / "g22_tipping.toml")
    for k in range(1, scene.increments + 1):  # a straight path: every increment the same ratio
        message = beyond_cone(scene, float(k))
        assert "overturn" in message and "0.512 from" in message and "half-length 0.5 " in message


def test_eccentricity_within_half_length_is_not_refused():
    """The 0.88 variant: eccentricity 0.55 · 0.88 = 0.484 < 0.5, shear/normal 0.88 < μ = 2."""
    scene = load_scene(SCENES / "g22_tipping_088.toml")
    assert beyond_cone(scene, float(scene.increments)) == ""


def test_the_limit_is_the_half_length():
    """Shear/normal at half-width/height·(1 ∓ PROBE): answered below, refused above."""
    scene = load_scene(SCENES / "g22_tipping.toml")
    limit = 0.5 / 0.55
    below = scene.with_changes(loads=(Traction(boundary="top", value=(limit * (1 - PROBE) * 1e6, -1e6)),))
    above = scene.with_changes(loads=(Traction(boundary="top", value=(limit * (1 + PROBE) * 1e6, -1e6)),))
    assert beyond_cone(below, 1.0) == "" and "overturn" in beyond_cone(above, 1.0)
