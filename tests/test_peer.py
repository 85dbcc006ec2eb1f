"""The benchmark's peer (GetFEM) stays outside the project: never among the
methods, and a scene it cannot model is refused by name before GetFEM is
imported (so these checks need no GetFEM)."""
import pytest

from contactcore import DiscretisationError, load_scene
from verification import methods
from verification.closed_forms import pressurised_rod
from verification.peer_getfem import solve


def test_peer_is_not_one_of_the_methods():
    assert "getfem" not in methods.expand(["all"])
    assert methods.solver("getfem") is solve


@pytest.mark.parametrize("scene,problem", [
    (pressurised_rod().scene, "the domain must be a rectangle"),
    (load_scene("C-coulomb"), "the interface law must be linear"),
])
def test_peer_refuses_what_it_cannot_model(scene, problem):
    with pytest.raises(DiscretisationError, match=problem):
        solve(scene, 0.1)


def test_peer_refuses_a_bad_degree():
    with pytest.raises(DiscretisationError, match="degree must be 1 or 2"):
        solve(load_scene("A"), 0.1, degree=3)
