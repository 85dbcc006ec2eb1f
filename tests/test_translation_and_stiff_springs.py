"""review5's fault 4, measured (memfix):

- a rigid translation the supports prescribe strains nothing, yet
  ``scaling.softer_stress`` counted it as the stress ``E₋|ū|/L``, whose
  TRACTION_ROUNDOFF share (1e-9) is the friction-excess warning's
  round-off allowance: moving scene layered-slip's stack 0.1 m
  (tests/scenes/layered_moved.toml) silenced the warning of EFGM's
  decision-band excess (2.8 Pa at stick above μ|t_N|, 9.3e-6 of μp, the
  same answer to the digit as unmoved).  The translation now counts with
  the round-off it leaves, TRANSLATION_ROUNDOFF of ``E₋|ū|/h``;
- Coulomb springs stiff enough that their traction round-off
  (SPRING_TRACTION_ROUNDOFF·α of p) exceeds the decision band's whole
  excess (DECISION_BAND·μ of p) silence that warning too: a line now says
  the excess cannot be told from round-off there."""
from __future__ import annotations

from pathlib import Path

import pytest

from contactcore import load_scene
from contactcore import tolerances as tol
from contactcore.health import friction_excess_warnings
from contactcore.scaling import rigid_translation, softer_stress
from verification import methods
from verification.closed_forms import layered_slip
from verification.sweeps import H

MOVED = Path(__file__).parent / "scenes" / "layered_moved.toml"
EXCESS = "stick with |t_T| above"
BLIND = "cannot be told from round-off"


def test_the_decision_bands_excess_is_warned_of_with_the_stack_moved():
    result = methods.solver("efgm")(load_scene(MOVED), H)
    assert [w for w in result.solver.warnings if EXCESS in w], result.solver.warnings


@pytest.mark.parametrize("method", ["fe", "xfem"])
def test_the_moved_stacks_roundoff_is_not_warned_of(method):
    """fe and xfem answer the closed form to round-off, translation or not."""
    result = methods.solver(method)(load_scene(MOVED), H)
    assert not [w for w in result.solver.warnings if EXCESS in w], result.solver.warnings


def test_a_translation_is_told_from_a_prescription_that_strains():
    moved, unmoved = load_scene(MOVED), load_scene("layered-slip")
    assert rigid_translation(moved) == (False, True)  # the top fixes x only: y moves as a whole
    assert rigid_translation(unmoved) == (False, False)  # bottom held, top pushed: a shear
    # without h, or with nothing but the translation: counted as before (E₋|ū|/L)
    assert softer_stress(moved) == moved.softer_modulus * 0.1
    assert softer_stress(moved, H) < softer_stress(moved)
    assert softer_stress(unmoved, H) == softer_stress(unmoved)


def _layered(alpha: float):
    return layered_slip(kT=alpha * layered_slip().scene.softer_modulus / H).scene


def test_springs_stiffer_than_the_band_can_tell_say_so():
    """At μ = 0.3 the band's whole excess is 3e-6 of p: α = 1e8 (1e-6 of
    p of round-off) is below it, 1e9 above; decided on the inputs alone
    (an empty path: nothing sticks, the line is there all the same)."""
    from types import SimpleNamespace
    empty = SimpleNamespace(steps=[])
    assert not friction_excess_warnings(_layered(1e8), empty, 0.0, H)
    said = friction_excess_warnings(_layered(1e9), empty, 0.0, H)
    assert len(said) == 1 and BLIND in said[0], said
    edge = tol.DECISION_BAND * 0.3 / tol.SPRING_TRACTION_ROUNDOFF
    assert f"α at most {edge:.2g}" in said[0]
