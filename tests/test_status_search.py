"""An exact law's first status map from a coarser solve
(contactcore.newton.guess, docs/newton.md "A first map from a coarser
solve"): the same scene at twice the spacing gives the fine Newton its
first map, which shortens the status search and decides nothing.  The
answer is the one Newton reaches from every point sticking (same statuses
at every increment, profiles to a correction's round-off); a penalty law
takes no coarser solve."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import discretisation, load_scene, make_law
from contactcore.laws import OPEN, SLIP, STICK
from contactcore.newton import guess as newton_guess
from contactcore.newton.iteration import FROM_COARSER, STICKING
from efgm.options import EFGM
from verification import methods
from xdolfinx.options import FE, XFEM

#: xfem P1's size rule, read before the fixture below sets it aside.
SIZE_RULE = XFEM(degree=1).coarse_map_min_unknowns

#: A size rule no system meets.
SIZE_FOR_NONE = 10 ** 12

#: C-coulomb's own resolution (its first increment: docs/newton.md).
H = 0.05


@pytest.fixture(autouse=True)
def _every_size_takes_a_coarser_map(monkeypatch):
    """The mechanism at C-coulomb's own h, whose systems (5 274 to 6 018
    unknowns at P1) are below fe's and xfem's coarse_map_min_unknowns: the
    size rule has its own test."""
    for options in (FE, XFEM, EFGM):
        monkeypatch.setattr(options, "coarse_map_from", {1: 0, 2: 0})


def _exact(scene):
    return scene.with_changes(law=make_law({"type": "coulomb", "mu": scene.law.mu, "enforcement": "exact"}))


def _first_increment(result):
    return result.solver.iterations[0]


@pytest.mark.parametrize("method, degree", [pytest.param("fe", 1, marks=pytest.mark.slow), ("xfem", 1),
                                            pytest.param("efgm", 1, marks=pytest.mark.slow)])  # 4.6, 6.7 s: slow stage
def test_a_coarser_map_shortens_the_search_and_keeps_the_answer(method, degree, monkeypatch):
    """Exact C-coulomb: with the map of the same scene at 2h the first
    increment takes fewer iterations than from every point sticking, and
    every increment's statuses, tractions and jumps are the same."""
    scene = _exact(load_scene("C-coulomb"))
    guessed = methods.solver(method)(scene, H, degree=degree)
    monkeypatch.setattr(newton_guess, "COARSER", None)
    searched = methods.solver(method)(scene, H, degree=degree)
    assert _first_increment(guessed) < _first_increment(searched)
    assert guessed.solver.first_map == FROM_COARSER
    assert searched.solver.first_map == STICKING + discretisation.NO_COARSER_MAP
    assert guessed.solver.iterations[1:] == searched.solver.iterations[1:]
    for a, b in zip(guessed.interface.steps, searched.interface.steps, strict=True):
        assert np.array_equal(a.status, b.status)
        for x, y in ((a.traction, b.traction), (a.jump, b.jump)):
            assert np.max(np.abs(x - y)) <= tol.LOW_RANK_AGREEMENT * np.max(np.abs(y))


def test_a_penalty_law_takes_no_coarser_solve(monkeypatch):
    """The penalty path is the one it was: no coarser system is built."""
    calls = []
    monkeypatch.setattr(discretisation, "coarse_guess", lambda *a: calls.append(a))
    assert methods.solver("xfem")(load_scene("C-coulomb"), H, degree=1).solver.first_map == ""
    assert calls == []
    methods.solver("xfem")(_exact(load_scene("C-coulomb")), H, degree=1)
    assert len(calls) == 1


def test_the_guess_is_the_nearest_coarse_point_times_gamma():
    """Each fine point takes the status and tangent over γ of the nearest
    coarse point, times its own γ."""
    shape = np.array([np.eye(2), np.zeros((2, 2)), [[1.0, 0.0], [-0.2, 0.0]]])
    guess = newton_guess.StatusGuess(np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]),
                                     np.array([STICK, OPEN, SLIP], np.int8), shape)
    tangent, status = guess.at(np.array([[1.9, 0.1], [0.2, 0.0], [1.1, -0.1]]), np.array([10.0, 20.0, 30.0]))
    assert status.tolist() == [SLIP, STICK, OPEN]
    assert np.array_equal(tangent, np.array([10.0 * shape[2], 20.0 * shape[0], 30.0 * shape[1]]))


def test_a_coarser_spacing_the_method_refuses_gives_no_guess(monkeypatch):
    """Where the coarser system cannot be built (here: every build refused)
    the fine run searches from every point sticking, as before."""
    from contactcore.errors import SceneError

    def refused(*a, **k):
        raise SceneError("h", "too coarse")
    scene = _exact(load_scene("C-coulomb"))
    monkeypatch.setattr(newton_guess, "COARSER", None)
    searched = methods.solver("xfem")(scene, H, degree=1)
    monkeypatch.setattr(newton_guess, "COARSER", 2.0)
    from xdolfinx.options import XFEM
    original, seen = XFEM.check_spacing, []

    def coarser_refused(self, sc, res):
        seen.append(res.h)  # the fine spacing first (dimensionless), the coarser one after
        return refused() if res.h > min(seen) else original(self, sc, res)
    monkeypatch.setattr(XFEM, "check_spacing", coarser_refused)
    alone = methods.solver("xfem")(scene, H, degree=1)
    assert alone.solver.iterations == searched.solver.iterations
    assert alone.solver.factorisations == searched.solver.factorisations
    assert max(seen) > min(seen)  # the coarser spacing was asked for, and refused


def test_a_short_coarse_search_leaves_the_fine_run_as_it_was(monkeypatch):
    """A coarse first step settled in SEARCH_WORTH_GUESSING iterations (the
    layered cycle pulled open at μ = 1e-6, xfem P1: the all-stick solve,
    then every point open) is not used: the fine run factorises and
    decides as without it, bit for bit (with it, the all-open map was
    factorised first and increment 3's stick was a correction of it, t_T
    1.1e-8 MPa off the closed form's 0 where the all-stick factorisation
    gives 2.6e-12; tests/test_mu_extremes.py)."""
    from pathlib import Path
    scene = load_scene(Path(__file__).parent / "scenes" / "cycle_mu1e-06.toml")
    seen = []
    coarse = discretisation.coarse_guess
    monkeypatch.setattr(discretisation, "coarse_guess", lambda *a: seen.append(coarse(*a)) or seen[-1])
    guessed = methods.solver("xfem")(scene, None, degree=1, estimate_condition=False)
    assert seen and seen[0] is not None and not seen[0].worth()
    monkeypatch.setattr(newton_guess, "COARSER", None)
    searched = methods.solver("xfem")(scene, None, degree=1, estimate_condition=False)
    assert guessed.solver.iterations == searched.solver.iterations
    assert guessed.solver.first_map.startswith(STICKING) and "settled" in guessed.solver.first_map
    for a, b in zip(guessed.interface.steps, searched.interface.steps, strict=True):
        assert np.array_equal(a.status, b.status)
        assert np.array_equal(a.traction, b.traction) and np.array_equal(a.jump, b.jump)


class _OtherRankFailed:
    """A communicator's reductions as seen from a rank whose coarse build
    succeeded while another rank's failed."""

    def all(self, flag):
        return False


def test_a_coarse_build_failing_on_another_rank_gives_no_guess_here():
    """Under mpirun a coarse build that fails on one rank means no guess
    on every rank: this rank's system is closed and it does not start the
    coarse Newton, whose reductions the failed rank would never join."""
    closed = []

    class _System:
        def close(self):
            closed.append(True)

    scene = _exact(load_scene("C-coulomb"))
    assert newton_guess.coarse_guess(scene, _System, _OtherRankFailed()) is None
    assert closed == [True]


def test_a_small_system_takes_no_coarser_map(monkeypatch):
    """Below xfem's coarse_map_min_unknowns (the library's, not the fixture's) no
    coarser system is built, the run says why, and the answer is the
    search from every point sticking, bit for bit."""
    calls = []
    scene = _exact(load_scene("C-coulomb"))
    monkeypatch.setattr(newton_guess, "COARSER", None)
    searched = methods.solver("xfem")(scene, H, degree=1)
    assert searched.dofs < SIZE_RULE
    monkeypatch.setattr(newton_guess, "COARSER", 2.0)
    monkeypatch.setattr(XFEM, "coarse_map_from", {1: SIZE_RULE, 2: SIZE_RULE})
    monkeypatch.setattr(discretisation, "coarse_guess", lambda *a: calls.append(a))
    small = methods.solver("xfem")(scene, H, degree=1)
    assert calls == []
    assert small.solver.first_map == STICKING + discretisation.SMALL_FOR_COARSER_MAP.format(SIZE_RULE)
    assert small.solver.iterations == searched.solver.iterations
    for a, b in zip(small.interface.steps, searched.interface.steps, strict=True):
        assert np.array_equal(a.status, b.status) and np.array_equal(a.traction, b.traction)


def test_a_given_grid_says_it_takes_no_coarser_map_whatever_its_size(monkeypatch):
    """The paper's grid has no h to coarsen: its reason is that, not the
    size rule's, even where the rule would also refuse it (review15 #3)."""
    monkeypatch.setattr(XFEM, "coarse_map_from", {1: SIZE_FOR_NONE, 2: SIZE_FOR_NONE})
    result = methods.solver("xfem")(_exact(load_scene("C-coulomb")), paper=True, degree=1)
    assert result.solver.first_map == STICKING + discretisation.NO_COARSER_MAP


def test_a_degree_without_its_own_size_rule_takes_the_new_methods(monkeypatch):
    """A method that gives its size rule for degree 1 alone answers degree
    2 with NEW_METHOD_COARSE_MAP_FROM, not a KeyError (review16 #3)."""
    monkeypatch.setattr(XFEM, "coarse_map_from", {1: SIZE_RULE})
    assert XFEM(degree=1).coarse_map_min_unknowns == SIZE_RULE
    assert XFEM(degree=2).coarse_map_min_unknowns == discretisation.NEW_METHOD_COARSE_MAP_FROM
