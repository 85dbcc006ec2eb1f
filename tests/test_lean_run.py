"""Only what a run needs (issue 24): a law without history is solved at
the final load, not along the path."""
import pytest

from contactcore import load_scene, make_law
from verification import methods


def _unilateral_A():
    scene = load_scene("A")
    return scene.with_changes(law=make_law({"type": "unilateral", "kN": scene.law.kN, "kT": scene.law.kT}))


@pytest.mark.parametrize("method", ["fe", "xfem", "efgm"])
def test_a_law_without_history_is_solved_once(method):
    """Scene A, unilateral law, proportional load over 20 increments: at most
    3 factorisations (Newton from the unloaded state at the final load).
    That this is the answer at the end of the path is checked by
    tests/test_friction.py: Coulomb with a huge μ follows the path and
    equals the unilateral answer."""
    scene = _unilateral_A()
    result = methods.solver(method)(scene, 0.2)
    assert result.solver.solves <= 3 and result.solver.increments == 1
    assert len(result.interface.steps) == 1 and result.interface.final.step == scene.increments
