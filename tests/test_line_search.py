"""Newton's line search (contactcore.newton._Newton._line_search,
docs/newton.md): a full step that settles its status map is not doubled,
so an increment whose predictor already has the right map (every one
after C-coulomb's first: one iteration each) evaluates the residual twice,
at the predictor and at the full step; a step that does not settle still
tries the doubled one."""
import pytest

from contactcore import load_scene, make_law, newton
from contactcore.newton import guess as newton_guess
from verification import methods

#: C-coulomb's own resolution, where the evaluations were counted (docs/newton.md).
H = 0.05


def _exact(scene):
    return scene.with_changes(law=make_law({"type": "coulomb", "mu": scene.law.mu, "enforcement": "exact"}))


@pytest.mark.parametrize("enforcement", ["penalty", "exact"])
def test_a_settled_step_is_not_doubled(enforcement, monkeypatch):
    evaluations, per_increment, trials = [0], [], []
    residual, commit, line_search = newton._Newton._residual, newton._Newton._commit, newton._Newton._line_search

    def counted(self, *args):
        evaluations[0] += 1
        return residual(self, *args)

    def committed(self, *args):
        per_increment.append(evaluations[0])
        evaluations[0] = 0
        return commit(self, *args)

    def searched(self, u, du, b, R, status, secant=False, tangent=None):
        before = evaluations[0]
        alpha, evaluated = line_search(self, u, du, b, R, status, secant, tangent)
        trials.append((alpha, evaluations[0] - before))
        return alpha, evaluated

    monkeypatch.setattr(newton._Newton, "_residual", counted)
    monkeypatch.setattr(newton._Newton, "_commit", committed)
    monkeypatch.setattr(newton._Newton, "_line_search", searched)
    monkeypatch.setattr(newton_guess, "COARSER", None)  # the first increment's search from every point sticking
    scene = load_scene("C-coulomb")
    result = methods.solver("fe")(_exact(scene) if enforcement == "exact" else scene, H, degree=1)
    assert result.solver.iterations[1:] == [1] * (scene.increments - 1)
    assert per_increment[1:] == [2] * (scene.increments - 1)
    first = result.solver.iterations[0]
    assert any(count > 1 for alpha, count in trials[:first - 1] if alpha == 1.0), \
        "the first increment's unsettled full steps try the doubled one"
