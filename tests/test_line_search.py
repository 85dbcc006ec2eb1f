"""Newton's line search (contactcore.newton._Newton._line_search,
docs/newton.md): a full step that settles its status map is not doubled,
so an increment whose predictor already has the right map (every one
after C-coulomb's first: one iteration each) evaluates the residual twice,
at the predictor and at the full step; a step that does not settle still
tries the doubled one.  A full step that only moves points on from stick
to slip, each for the first time in the step, is taken whole whatever its
merit (docs/newton.md, "A tie")."""
import pytest

from contactcore import load_scene, make_law, newton
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

    def searched(self, u, du, b, R, status, secant=False, tangent=None, held=None):
        before = evaluations[0]
        alpha, evaluated = line_search(self, u, du, b, R, status, secant, tangent, held)
        trials.append((alpha, evaluations[0] - before))
        return alpha, evaluated

    monkeypatch.setattr(newton._Newton, "_residual", counted)
    monkeypatch.setattr(newton._Newton, "_commit", committed)
    monkeypatch.setattr(newton._Newton, "_line_search", searched)
    scene = load_scene("C-coulomb")
    result = methods.solver("fe")(_exact(scene) if enforcement == "exact" else scene, H, degree=1)
    assert result.solver.iterations[1:] == [1] * (scene.increments - 1)
    assert per_increment[1:] == [2] * (scene.increments - 1)
    first = result.solver.iterations[0]
    assert any(count > 1 for alpha, count in trials[:first - 1] if alpha == 1.0), \
        "the first increment's unsettled full steps try the doubled one"


def test_only_a_first_move_from_stick_to_slip_escapes_armijo():
    """_Newton._onward: a full step whose law map differs from the map it
    was solved with only by points that stuck and now slip, each for the
    first time in the step, is taken whole (docs/newton.md, "A tie"); any
    other change (slip to stick, a point opening or closing, a point that
    slipped earlier in the step and stuck again) is left to Armijo's rule,
    and so is a step that moves no point.  A point can move on once per
    step, so at most m steps escape the rule and no cycle survives."""
    from types import SimpleNamespace

    import numpy as np

    from contactcore.collective import SERIAL
    from contactcore.laws import OPEN, SLIP, STICK

    newton_like = SimpleNamespace(ranks=SERIAL)
    status = np.array([STICK, STICK, SLIP, OPEN], np.int8)
    held = np.left_shift(1, status.astype(np.int64))

    def onward(after, held=held):
        return newton._Newton._onward(newton_like, held, status, SimpleNamespace(status=np.array(after, np.int8)))

    assert onward([SLIP, STICK, SLIP, OPEN])
    assert onward([SLIP, SLIP, SLIP, OPEN])
    assert not onward(list(status)), "no point moved"
    assert not onward([SLIP, STICK, STICK, OPEN]), "a point back from slip to stick"
    assert not onward([SLIP, STICK, SLIP, STICK]), "a point closing"
    assert not onward([OPEN, STICK, SLIP, OPEN]), "a point opening"
    again = held.copy()
    again[0] |= 1 << SLIP
    assert not onward([SLIP, STICK, SLIP, OPEN], again), "a point that slipped before in the step"
    assert not onward([SLIP, STICK, SLIP, OPEN], None), "no statuses held (a step's first iterate)"


def test_a_tie_is_solved_alike_with_fewer_iterations_when_points_move_on_whole(monkeypatch):
    """tests/roundoff.py's tie-exact (shearslide driven to exactly μp,
    efgm P1, h = 0.05): Newton moves points from stick to slip a few per
    iteration.  Armijo's rule alone damped the full step after each map
    change (its merit rises) and crept by steps that moved no point towards
    the same map's solution; taking the full steps that only move points
    on gives the same status at every point and increment, tractions and
    jumps within round-off, in fewer iterations."""
    import numpy as np

    import roundoff
    import tolerances as tol

    iterations, commit = [], newton._Newton._commit

    def committed(self, k, factors, u, response, its, history):
        iterations.append(its)
        return commit(self, k, factors, u, response, its, history)

    monkeypatch.setattr(newton._Newton, "_commit", committed)
    whole = roundoff.fingerprint("tie-exact", "efgm")
    with_rule = iterations[:]
    iterations.clear()
    monkeypatch.setattr(newton._Newton, "_onward", lambda self, held, status, response: False)
    armijo = roundoff.fingerprint("tie-exact", "efgm")
    assert "refused" not in whole and "refused" not in armijo
    problems = roundoff.differences(armijo, whole, tol.ROUNDOFF_PROFILES["tie-exact"])
    assert not problems, "; ".join(problems)
    assert np.any(whole["status"][-1] == newton.STICK) and np.any(whole["status"][-1] == newton.SLIP)
    assert with_rule[:-1] == iterations[:-1]
    assert with_rule[-1] < iterations[-1], (with_rule, iterations)
