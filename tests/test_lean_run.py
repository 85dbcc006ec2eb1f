"""Only what a run needs (issue 24): a law without history is solved at
the final load, not along the path, unless the scene asks for the path
(``follow_path``); a law with history always follows it."""
import tomllib

import numpy as np
import pytest

import tolerances as tol
from contactcore import SceneError, linear_solver, load_scene, make_law, sample_profiles, scene_from_dict, scene_text
from verification import methods


def _unilateral_A():
    scene = load_scene("A")
    return scene.with_changes(law=make_law({"type": "unilateral", "kN": scene.law.kN, "kT": scene.law.kT}))


@pytest.fixture
def factorisations(monkeypatch):
    """Counts the matrices factorised: every method's factorisations go
    through contactcore.linear_solver.Factorisation.factorise."""
    count = [0]
    factorise = linear_solver.Factorisation.factorise

    def counted(self, A):
        count[0] += 1
        return factorise(self, A)

    monkeypatch.setattr(linear_solver.Factorisation, "factorise", counted)
    return count


def _run(method, scene, h=0.2):
    return methods.solver(method)(scene, h, estimate_condition=False)


@pytest.mark.parametrize("method", ["fe", "xfem", "efgm"])
def test_a_law_without_history_is_solved_once(method, factorisations):
    """Scene A, unilateral law, proportional load over 20 increments: at most
    3 linear solves (Newton from the unloaded state at the final load, not
    one per increment; factorisations would not tell, since a path with an
    unchanged tangent reuses its factorisation), the factorisations counted
    at the solver as reported."""
    scene = _unilateral_A()
    result = _run(method, scene)
    assert 1 <= result.solver.solves <= 3  # the path would take one solve per increment at least
    assert 1 <= factorisations[0] == result.solver.factorisations <= result.solver.solves
    assert result.solver.increments == 1
    assert len(result.interface.steps) == 1 and result.interface.final.step == scene.increments


@pytest.mark.parametrize("method", ["fe", "xfem", "efgm"])
def test_the_path_asked_for_is_followed_and_ends_where_one_solve_does(method, factorisations):
    """``follow_path`` gives every increment of the unilateral law; its last
    state is the one-solve answer to round-off (the law has no history, so
    the final state does not depend on the path)."""
    scene = _unilateral_A()
    once = _run(method, scene)
    solved_once = factorisations[0]
    path = _run(method, scene.with_changes(follow_path=True))
    assert path.solver.increments == scene.increments == len(path.interface.steps)
    assert [s.step for s in path.interface.steps] == list(range(1, scene.increments + 1))
    assert factorisations[0] - solved_once == path.solver.factorisations
    assert path.solver.solves >= scene.increments
    a, b = once.interface.final, path.interface.final
    assert np.array_equal(a.status, b.status)
    for x, y in ((a.jump, b.jump), (a.traction, b.traction)):
        assert np.max(np.abs(x - y)) <= tol.PATCH_ROUNDOFF * np.max(np.abs(x))


def test_a_law_with_history_follows_its_path_whatever_follow_path_says(factorisations):
    """C-coulomb (stick-slip, history in s) follows all its increments, one
    solve per Newton iteration, and ``follow_path`` changes none of its
    iteration counts (the dispatch is in the core: one method checks it)."""
    scene = load_scene("C-coulomb")
    runs = [_run("xfem", scene.with_changes(follow_path=f)) for f in (False, True)]
    for r in runs:
        assert r.solver.increments == scene.increments == len(r.interface.steps)
        assert r.solver.solves == sum(r.solver.iterations)
    assert runs[0].solver.iterations == runs[1].solver.iterations
    assert factorisations[0] == sum(r.solver.factorisations for r in runs)


def test_run_writes_the_path_of_a_linear_law_that_follows_it(tmp_path):
    """``follow_path`` with the linear law: ``run`` writes the response at
    every increment (``increments.csv``, ``interface.csv``), as for a law
    with history; without it, no path files (one solve)."""
    import csv

    from contactcore.scene_files import scene_toml
    from verification.__main__ import main
    for follow in (True, False):
        path = tmp_path / f"A{follow}.toml"
        path.write_text(scene_toml(load_scene("A").with_changes(follow_path=follow)))
        out = tmp_path / f"out{follow}"
        assert main(["run", str(path), "--method", "fe", "--h", "0.2", "--no-plots", "--out", str(out), "--quiet"]) == 0
        assert (out / "fe" / "increments.csv").exists() == follow
    with open(tmp_path / "outTrue" / "fe" / "increments.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert [float(r["step"]) for r in rows] == list(range(1, 21))
    assert float(rows[-1]["mean_tT"]) == pytest.approx(2 * float(rows[9]["mean_tT"]), rel=tol.LINEAR_IN_LOAD)


def test_follow_path_must_be_a_boolean():
    data = tomllib.loads(scene_text("A"))
    data["follow_path"] = "yes"
    with pytest.raises(SceneError, match=r"^follow_path: must be true or false \(got 'yes'\)$"):
        scene_from_dict(data)
    data["follow_path"] = True
    assert scene_from_dict(data).follow_path


@pytest.mark.parametrize("method", ["fe", "xfem", "efgm"])
def test_a_study_of_the_law_builds_once_and_answers_as_separate_runs(method, monkeypatch):
    """Reuse keeps the built system while only the law's parameters change
    (issue 24): one build for three k_N, the profiles identical to separate
    runs'; a change of h builds afresh."""
    from contactcore.discretisation import Reuse
    cls = methods.discretisation(method)
    builds = []
    build = cls.build
    monkeypatch.setattr(cls, "build", lambda self, *a: builds.append(a) or build(self, *a))
    base, reuse = load_scene("C"), Reuse()
    try:
        for kN in (1e11, 1e12, 1e13):
            scene = base.with_changes(law=make_law({"type": "linear", "kN": kN, "kT": base.law.kT}))
            kept = methods.solver(method)(scene, 0.2, reuse=reuse)
            alone = methods.solver(method)(scene, 0.2)
            assert kept.discretisation.get("reused", False) == (kN != 1e11)
            for a, b in zip(sample_profiles(scene, kept.fields), sample_profiles(scene, alone.fields)):
                assert all(np.array_equal(a.columns[q], b.columns[q]) for q in a.columns)
        assert len(builds) == 1 + 3  # the kept system once, and each separate run
        methods.solver(method)(scene, 0.1, reuse=reuse)
        assert len(builds) == 5
    finally:
        reuse.close()


def test_efficiency_spawns_a_process_per_run_only_when_they_would_not_fit(monkeypatch):
    """Its runs stay in one process while their memory estimates, summed,
    fit the machine; the log says which and why (issue 24)."""
    import logging
    from verification.efficiency import spawn_each
    said = []

    class Keep(logging.Handler):  # the drivers' logger does not propagate: catch it at the source
        def emit(self, record):
            said.append(record.getMessage())

    logger = logging.getLogger("verification")
    monkeypatch.setattr(logger, "handlers", [Keep()])
    monkeypatch.setattr(logger, "level", logging.INFO)
    scene = load_scene("C")
    assert not spawn_each(scene, [("fe", 1, 0.2, 0.2), ("efgm", 1, 0.1, 0.2)], 0.1)
    assert spawn_each(scene, [("fe", 2, 2e-4, 2e-4)], 0.1)
    assert "in this process" in said[0] and "fresh process" in said[1], said
