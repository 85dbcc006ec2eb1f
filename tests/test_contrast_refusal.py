"""A solve that fails on moduli too far apart is refused naming them
(grader24's F3, 2026-11-28): a soft lower body on the support at
contrast 1e-10 was told to use another stabilisation (exact unilateral)
or that a rigid-body mode may be nearly free (bonded), at every β."""
import tomllib
from dataclasses import replace

import pytest

from contactcore import ContactError, load_scene
from contactcore.health import contrast_cause
from contactcore.scene_files import scene_from_dict
from contactcore.tolerances import CONTRAST_CAUSE
from verification import methods

SCENE = "tests/scenes/soft_support_contrast.toml"
#: Coarse enough to be quick; the failure is the contrast's at any h.
H = 0.1


def _with(law: str):
    data = tomllib.loads(open(SCENE).read())
    if law == "bonded":
        data["interface"]["law"] = {"type": "bonded"}
    return scene_from_dict(data)


@pytest.mark.parametrize("method", ["fe", "xfem", "efgm"])
@pytest.mark.parametrize("law", ["unilateral", "bonded"])
def test_a_failed_solve_at_contrast_1e_10_names_the_moduli(method, law):
    with pytest.raises(ContactError) as refused:
        methods.solver(method)(_with(law), H)
    text = str(refused.value)
    assert "materials.minus.E = 20 Pa is 1.0e-10 of materials.plus.E" in text, text
    assert "stabilisation" not in text and "rigid-body mode" not in text, text


def test_the_contrast_is_named_at_its_bound_and_not_above():
    scene = load_scene(SCENE)
    stiff = scene.materials["plus"].E

    def at(ratio):
        minus = replace(scene.materials["minus"], E=ratio * stiff)
        return replace(scene, materials={**scene.materials, "minus": minus})

    assert contrast_cause(at(CONTRAST_CAUSE)) and not contrast_cause(at(CONTRAST_CAUSE * 2))
    assert not contrast_cause(load_scene("A"))
