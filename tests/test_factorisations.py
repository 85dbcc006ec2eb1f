"""What Newton pays in factorisations (contactcore.factorisations, docs/newton.md):
a tangent a few point-rows away from a kept factorisation is solved by a
low-rank correction of it, a status map dominated by one whose tangent
proved singular is regularised without a factorisation, and the secant
steps of one increment share their matrix.  Counts are deterministic and
asserted; times are not."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import factorisations, load_scene, make_law, linear_solver
from contactcore import tolerances as core_tol
from contactcore.errors import SolverError
from contactcore.newton import guess as newton_guess
from verification import methods

#: C-coulomb's own resolution, where its exact run was measured
#: (docs/newton.md): after the first increment, points enter stick one at a time.
H = 0.05


def _exact(scene):
    return scene.with_changes(law=make_law({"type": "coulomb", "mu": scene.law.mu, "enforcement": "exact"}))


SCENES = {"penalty": lambda: load_scene("C-coulomb"), "exact": lambda: _exact(load_scene("C-coulomb"))}


@pytest.fixture
def counted(monkeypatch):
    """Factorisations begun (MUMPS set-ups, failed ones included),
    Newton's factorised solves that failed (a singular tangent), and those
    of a regularised detour."""
    counts = {"factorisations": 0, "singular": 0, "detours": 0}
    factorise, newton_factorise = linear_solver.Factorisation.factorise, factorisations.KeptFactorisations._factorise

    def begun(self, A):
        counts["factorisations"] += 1
        return factorise(self, A)

    def failing(self, *args):
        counts["detours"] += bool(args[-1])  # (tangent, rhs, scale, detour)
        try:
            return newton_factorise(self, *args)
        except SolverError:
            counts["singular"] += 1
            raise

    monkeypatch.setattr(linear_solver.Factorisation, "factorise", begun)
    monkeypatch.setattr(factorisations.KeptFactorisations, "_factorise", failing)
    return counts


def _run(method, law, counts=None, degree=1):
    """The run and the factorisations begun by the end of each increment."""
    after = []
    progress = None if counts is None else (lambda n, total, step: after.append(counts["factorisations"]))
    return methods.solver(method)(SCENES[law](), H, degree=degree, progress=progress), after


@pytest.mark.parametrize("method, law", [("fe", "penalty"), ("fe", "exact"), ("xfem", "exact"), ("efgm", "exact")])
def test_only_the_first_increment_factorises(method, law, counted):
    """Along C-coulomb's path each increment starts from the secant
    predictor and a point at a time enters stick: 1-3 rows of the points'
    tangents change, which a correction of a kept factorisation solves
    (before the corrections: one factorisation per change, fe P1 exact 6
    after the first increment).  EFGM's block of columns is as large as its
    costlier factorisation is worth (before that: 64 columns, one more
    factorisation in its third increment)."""
    result, after = _run(method, law, counted)
    assert len(after) == 20 and after[-1] == after[0]
    assert result.solver.factorisations <= after[-1]


@pytest.mark.parametrize("method", ["fe", "xfem"])
def test_a_map_free_to_turn_is_not_factorised(method, counted, monkeypatch):
    """Exact C-coulomb's first increment reaches maps where every closed
    point slips, the rod free to turn: the map and Γ's geometry say so
    (``health.slips_free``), so no factorisation of such a tangent is
    tried and fails (whether MUMPS's pivots call it singular is
    round-off's choice: one did, fe P1 and xfem P1), and the secant steps
    share one matrix: fewer factorisations than iterations."""
    monkeypatch.setattr(newton_guess, "COARSER", None)  # the search from every point sticking
    result, after = _run(method, "exact", counted)
    assert counted["singular"] == 0
    assert after[0] < result.solver.iterations[0]


@pytest.mark.parametrize("law", ["penalty", "exact"])
def test_corrections_give_the_factorised_answer(law, monkeypatch):
    """The same run with every tangent factorised (no correction allowed):
    the same iterations and interface history to round-off, with fewer
    factorisations."""
    corrected, _ = _run("fe", law)
    monkeypatch.setattr(core_tol, "LOW_RANK_COLUMNS", 0)  # the budget's floor and cap: none
    monkeypatch.setattr(core_tol, "LOW_RANK_COLUMNS_MAX", 0)
    factorised, _ = _run("fe", law)
    assert corrected.solver.iterations == factorised.solver.iterations
    assert corrected.solver.factorisations < factorised.solver.factorisations
    for a, b in zip(corrected.interface.steps, factorised.interface.steps):
        assert np.array_equal(a.status, b.status)
        for x, y in ((a.traction, b.traction), (a.jump, b.jump)):
            assert np.max(np.abs(x - y)) <= tol.LOW_RANK_AGREEMENT * np.max(np.abs(y))


@pytest.mark.parametrize("degree", [2])
def test_a_map_ahead_is_factorised(degree, counted, monkeypatch):
    """Exact C-coulomb's first increment moves its map a few points per
    iteration, each map a few rows past a correction of the last one
    factorised.  Where a factorisation is due, the map a few steps ahead
    (AHEAD_STEPS) is factorised instead and the tangent solved as its
    correction: xfem P2 at h = 0.05 factorises once less (measured
    2026-11-27: 4 -> 3 begun), with the same iterations, status maps and
    interface history to a correction's round-off.  (P1 gained 5 -> 4 while
    two cells where the circle touches a vertex 3e-10 h off kept caps of
    1.4e-14 h²; with Γ snapped to that vertex, contactcore.tolerances.XFEM_SNAP,
    both strategies factorise 4 times.)"""
    monkeypatch.setattr(newton_guess, "COARSER", None)  # the search from every point sticking
    ahead, _ = _run("xfem", "exact", counted, degree=degree)
    begun = counted["factorisations"]
    monkeypatch.setattr(core_tol, "AHEAD_STEPS", ())
    counted["factorisations"] = 0
    standing, _ = _run("xfem", "exact", counted, degree=degree)
    assert begun < counted["factorisations"]
    assert ahead.solver.factorisations < standing.solver.factorisations
    assert ahead.solver.iterations == standing.solver.iterations
    for a, b in zip(ahead.interface.steps, standing.interface.steps, strict=True):
        assert np.array_equal(a.status, b.status)
        for x, y in ((a.traction, b.traction), (a.jump, b.jump)):
            assert np.max(np.abs(x - y)) <= tol.LOW_RANK_AGREEMENT * np.max(np.abs(y))


@pytest.mark.parametrize("method", ["fe", "xfem"])
def test_a_costly_correction_looks_ahead_first(method, monkeypatch):
    """Exact C-coulomb's first increment in P1 at h = 0.05: the third
    iterate's map is 52 (fe) or 59 (xfem) rows from the second's
    factorisation, a correction of most of its budget of 64, and the next
    map is past it.  A correction of more than AHEAD_FIRST_SHARE of the
    budget's new columns first factorises a map ahead (AHEAD_STEPS), so
    those columns are not solved for a slot refilled one iterate later:
    fewer columns (measured 2026-11-29: 110 -> 80 fe, 119 -> 80 xfem), no
    more factorisations, the same iterations and status maps, the
    interface history to a correction's round-off.  With the share at
    infinity (no correction looks ahead first) the columns are as before."""
    monkeypatch.setattr(newton_guess, "COARSER", None)  # the search from every point sticking
    columns = []
    solve_columns = linear_solver.Tangent.solve_columns

    def counted_columns(self, rhs, slot=0):
        columns.append(rhs.shape[1])
        return solve_columns(self, rhs, slot)
    monkeypatch.setattr(linear_solver.Tangent, "solve_columns", counted_columns)
    first, _ = _run(method, "exact")
    ahead_first = sum(columns)
    monkeypatch.setattr(core_tol, "AHEAD_FIRST_SHARE", np.inf)
    columns.clear()
    standing, _ = _run(method, "exact")
    assert ahead_first < sum(columns)
    assert first.solver.factorisations <= standing.solver.factorisations
    assert first.solver.iterations == standing.solver.iterations
    for a, b in zip(first.interface.steps, standing.interface.steps, strict=True):
        assert np.array_equal(a.status, b.status)
        for x, y in ((a.traction, b.traction), (a.jump, b.jump)):
            assert np.max(np.abs(x - y)) <= tol.LOW_RANK_AGREEMENT * np.max(np.abs(y))


def test_corrections_on_another_factorisation_package():
    """SuperLU (no MUMPS block solve: the columns are solved one by one)
    gives MUMPS's run: the same iterations and status maps, and tractions
    within two direct solvers' agreement."""
    superlu = methods.solver("fe")(SCENES["exact"](), H, degree=1, petsc_options={"pc_factor_mat_solver_type": "superlu"})
    mumps, _ = _run("fe", "exact")
    assert "superlu" in superlu.solver.solver
    assert superlu.solver.iterations == mumps.solver.iterations
    a, b = superlu.interface.final, mumps.interface.final
    assert np.array_equal(a.status, b.status)
    assert np.max(np.abs(a.traction - b.traction)) <= tol.SOLVER_AGREEMENT * np.max(np.abs(b.traction))


@pytest.mark.parametrize("method, wide", [("fe", False), ("efgm", True)])
def test_a_factorisation_keeps_the_columns_it_is_worth(method, wide, monkeypatch):
    """Each MUMPS factorisation's correction budget is read from its own
    counts: the columns its flops would solve, in at most a quarter of its
    factors' memory, never below LOW_RANK_COLUMNS.  fe's factors (90-140
    entries per unknown) hold it at 64; EFGM's wide supports (600-1200)
    give more, which spares it the factorisation a full block of 64 cost
    (test_only_the_first_increment_factorises)."""
    seen = []
    budget = linear_solver.Tangent.column_budget

    def spy(self, slot):
        seen.append((budget(self, slot), self._slots[slot][1].columns_worth()))
        return seen[-1][0]
    monkeypatch.setattr(linear_solver.Tangent, "column_budget", spy)
    _run(method, "exact")
    assert seen
    for got, (cost, memory) in seen:
        worth = min(cost, core_tol.LOW_RANK_MEMORY * memory)
        assert got == int(min(max(worth, core_tol.LOW_RANK_COLUMNS), core_tol.LOW_RANK_COLUMNS_MAX))
    assert any(got > core_tol.LOW_RANK_COLUMNS for got, _ in seen) == wide


@pytest.mark.parametrize("method, degree", [("fe", 1), ("fe", 2), ("xfem", 1), ("efgm", 1)])
def test_a_map_left_behind_is_refilled_not_analysed_again(method, degree, counted, monkeypatch):
    """Exact C-coulomb's first increment leaves each factorised map for one
    past a correction's reach of it (from every point sticking: 187-1500
    rows): the next factorisation refills that map's slot, and MUMPS's
    analysis is made once per run, twice where a regularised detour (a map
    free to turn, or a singular tangent that failed) was factorised in the
    other slot (before: a second slot analysed anew, 2-3 analyses)."""
    analyses = []
    made = linear_solver.Factorisation.__init__

    def analysed(self, *args, **kwargs):
        analyses.append(1)
        made(self, *args, **kwargs)
    monkeypatch.setattr(linear_solver.Factorisation, "__init__", analysed)
    monkeypatch.setattr(newton_guess, "COARSER", None)  # the search from every point sticking
    _run(method, "exact", counted, degree=degree)
    assert counted["factorisations"] > 2
    assert len(analyses) == 1 + (counted["detours"] > 0)


def test_a_full_set_of_columns_keeps_those_the_tangent_needs(monkeypatch):
    """EFGM's exact first increment with a budget of 96 columns: its
    corrections fill it (93 columns) with rows of which the next tangent
    needs fewer: it keeps those and corrects instead of factorising (before:
    a factorisation), with the factorised answer."""
    dropped = []
    drop = factorisations.KeptFactorisations._drop_columns

    def spy(self, slot, changed):
        dropped.append(len(self.columns[slot]))
        drop(self, slot, changed)
    monkeypatch.setattr(factorisations.KeptFactorisations, "_drop_columns", spy)
    monkeypatch.setattr(core_tol, "LOW_RANK_COLUMNS_MAX", 96)
    monkeypatch.setattr(newton_guess, "COARSER", None)  # the search from every point sticking
    corrected, _ = _run("efgm", "exact")
    assert dropped
    monkeypatch.setattr(core_tol, "LOW_RANK_COLUMNS", 0)
    monkeypatch.setattr(core_tol, "LOW_RANK_COLUMNS_MAX", 0)
    factorised, _ = _run("efgm", "exact")
    assert corrected.solver.iterations == factorised.solver.iterations
    for a, b in zip(corrected.interface.steps, factorised.interface.steps):
        assert np.array_equal(a.status, b.status)
        for x, y in ((a.traction, b.traction), (a.jump, b.jump)):
            assert np.max(np.abs(x - y)) <= tol.LOW_RANK_AGREEMENT * np.max(np.abs(y))
