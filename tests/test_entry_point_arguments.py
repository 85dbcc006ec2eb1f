"""The one entry point, ``verification.methods.solver(name)(scene, h)``,
and ``sample_profiles`` refuse arguments of the wrong kind by name, with a
ContactError, in every method (grader14 #3: a scene's name gave
``AttributeError: 'str' object has no attribute 'domain'``, a string h a
bare TypeError, a missing interface history a plain ValueError)."""
import pytest

from contactcore import ContactError, load_scene, sample_profiles
from verification import methods

import registered

METHODS = registered.names()  # every registered method (tests/registered.py)
#: Scene C-coulomb's coarsest useful resolution: a second per method.
H_COARSE = 0.25


@pytest.mark.parametrize("name", METHODS)
@pytest.mark.parametrize("scene, named", [("A", "scene: must be a Scene"), (None, "scene: must be a Scene")])
def test_a_scene_that_is_no_scene_is_refused_by_name(name, scene, named):
    with pytest.raises(ContactError, match=named):
        methods.solver(name)(scene, H_COARSE)


@pytest.mark.parametrize("name", METHODS)
@pytest.mark.parametrize("h", ["0.1", True])
def test_an_h_that_is_no_number_is_refused_by_name(name, h):
    with pytest.raises(ContactError, match="h: must be a number"):
        methods.solver(name)(load_scene("A"), h)


def test_a_law_with_history_sampled_without_its_path_is_a_contact_error():
    scene = load_scene("C-coulomb")
    result = methods.solver("fe")(scene, H_COARSE)
    with pytest.raises(ContactError, match="path: the 'coulomb' law needs the interface history"):
        sample_profiles(scene, result.fields)
    assert sample_profiles(scene, result.fields, path=result.interface)
