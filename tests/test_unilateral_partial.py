"""The unilateral law where no open/closed map is consistent: a point of
Γ in a partial state (contactcore.newton.partial; docs/contact-enforcement.md,
"The unilateral law under shear").  grader16's `uni` at fe P1, h = 0.05
was refused (one Gauss point, s = 0.325, contradicting both its
statuses); it now has one partial point there and the opening of the
fine references."""
import pathlib
import re

import numpy as np
import pytest

from contactcore import discretisation, load_scene
from contactcore.errors import SolverError
from contactcore.laws import OPEN
from contactcore.newton import partial

from test_partial_status import check_partial_reported
from test_xfem_opening import UNI
import tolerances as tol
from tolerances import (PARTIAL_MAP_RESIDUAL, TILT_OPENING_REFERENCE, TILT_PARTIAL_FROM_OPENING, UNI_OPENING,
                        UNI_OPENING_REFERENCE)

SHEAR_UNILATERAL = (pathlib.Path(__file__).parent / "scenes" / "shear_unilateral.toml").read_text()


def _partial_points(report):
    """The partial points the run's warning names: [(x, y, θ)]."""
    lines = [w for w in report.warnings if "hold y_N = 0 with a share θ" in w]
    assert len(lines) <= 1, lines
    if not lines:
        return []
    return [tuple(map(float, m)) for m in re.findall(r"\(([-\d.e+]+), ([-\d.e+]+)\) θ = ([-\d.e+]+)", lines[0])]


@pytest.fixture(scope="module")
def uni_p1(tmp_path_factory):
    """`uni` at fe P1, h = 0.05, solved once for the tests that read it
    (it takes about 9 s): the scene and its result."""
    from xdolfinx.options import FE
    path = tmp_path_factory.mktemp("uni") / "uni.toml"
    path.write_text(UNI)
    scene = load_scene(path)
    return scene, discretisation.solve(scene, FE(degree=1), 0.05)


def test_uni_fe_p1_has_one_partial_point_and_the_references_opening(tmp_path, uni_p1):
    """fe P1 at h = 0.05, refused before: one partial point, the middle
    Gauss point of [0.3, 0.35], carrying (0, τ) with θ strictly
    inside (0, 1); Γ changes from open to closed once, within UNI_OPENING
    of the reference opening (measured 0.3153 against 0.3156; fe P1 at
    h = 0.025, which Newton solves, 0.325)."""
    scene, result = uni_p1
    points = _partial_points(result.solver)
    assert len(points) == 1, result.solver.warnings
    check_partial_reported(tmp_path, scene, result)  # reported `partial`, with its θ (test_partial_status)
    (x, y, theta), = points
    assert x == pytest.approx(0.325) and y == pytest.approx(0.5) and 0.0 < theta < 1.0
    interface = result.interface
    at = np.argmin(np.abs(interface.points[:, 0] - x))
    traction = interface.final.traction
    assert traction[at, 0] == 0.0 and 0.0 < abs(traction[at, 1])  # (0, τ) as committed
    order = np.argsort(interface.points[:, 0], kind="stable")
    xs, status = interface.points[order, 0], interface.final.status[order]
    change = np.flatnonzero((status[:-1] == OPEN) != (status[1:] == OPEN))
    assert len(change) == 1
    where = 0.5 * (xs[change[0]] + xs[change[0] + 1])
    assert abs(where - UNI_OPENING_REFERENCE) <= UNI_OPENING, where


def test_a_grazing_shear_with_no_partial_answer_is_still_refused(tmp_path):
    """grader17's `shear-unilateral` (penalty, no normal load: the closed
    form has g_N = 0 and t_N = 0 on all of Γ), fe P1 at h = 0.1: the
    discrete all-closed answer puts g_N at up to 2e-4 of |g_T| in
    tension (discretisation, not round-off), both walks of the partial
    search end past PARTIAL_SEARCH_POINTS (15 partial after the 2nd map,
    review11, 2026-11-29), and the refusal names the unilateral law as
    before."""
    from xdolfinx.options import FE
    path = tmp_path / "shear.toml"
    path.write_text(SHEAR_UNILATERAL)
    with pytest.raises(SolverError, match="no open/closed map of the unilateral law"):
        discretisation.solve(load_scene(path), FE(degree=1), 0.1)


def test_the_partial_search_is_for_the_unilateral_law_alone():
    """Coulomb (history) and linear keep their refusals; a parallel run
    searches as the serial one does (tests/test_mpi.py)."""
    from contactcore.enforcement import make_law
    from contactcore.collective import Collective

    class _System:
        def __init__(self, comm=None):
            self.collective = Collective(comm)

    class _Comm:
        size, rank = 2, 0

    scene = load_scene("A")
    for law, applies in (({"type": "unilateral", "kN": 1e12, "kT": 1e12}, True),
                         ({"type": "unilateral", "enforcement": "exact"}, True),
                         ({"type": "coulomb", "kN": 1e12, "kT": 1e12, "mu": 0.3}, False),
                         ({"type": "linear", "kN": 1e12, "kT": 1e12}, False)):
        s = scene.with_changes(law=make_law(law))
        assert partial.applies(s, _System()) is applies, law
    s = scene.with_changes(law=make_law({"type": "unilateral", "enforcement": "exact"}))
    assert partial.applies(s, _System(_Comm())) is True


@pytest.mark.slow
@pytest.mark.parametrize("method, degree, h", [("efgm", 1, 0.05), ("xfem", 2, 0.025)])
def test_tilt_unil_exact_has_a_partial_answer(method, degree, h):
    """grader17's `tilt-unil-exact` (tests/scenes/tilt_unil_exact.toml),
    refused before in efgm P1 at h = 0.05 and xfem P2 at 0.025: one and
    two partial points at the edge of the contact zone (x = 0.081; 0.067
    and 0.073; the fe P2 reference at h = 0.0125 opens at 0.081-0.088),
    each at θ strictly inside (0, 1)."""
    from efgm.options import EFGM
    from xdolfinx.options import XFEM
    options = {"efgm": EFGM, "xfem": XFEM}[method](degree=degree)
    scene = load_scene(pathlib.Path(__file__).parent / "scenes" / "tilt_unil_exact.toml")
    result = discretisation.solve(scene, options, h)
    points = _partial_points(result.solver)
    assert 1 <= len(points) <= 2 and all(0.0 < p[2] < 1.0 and abs(p[0] - TILT_OPENING_REFERENCE) <= TILT_PARTIAL_FROM_OPENING
                                       for p in points), points


def test_a_maps_problem_holds_where_a_prescribed_displacement_opens_gamma_at_rest(tmp_path, monkeypatch):
    """review8: with the left edge pulled 1e-6 (u_x prescribed), the
    unloaded state already has y_N = -8e-3 at three points of Γ.  Each map's
    linear problem takes its residual at rest under the map's own
    tractions (partial._Search.rest), so its answer solves the map's own
    equations to round-off, all closed and with those points open (the law's
    response at rest left 0.128 of the scale in the second)."""
    from contactcore.laws import LawResponse
    from contactcore.newton.increments import _Newton
    from xdolfinx.options import FE
    path = tmp_path / "pulled.toml"
    path.write_text(UNI.replace('fix = "xy"', 'fix = "y"\n[[supports]]\nboundary = "left"\nfix = "x"\nvalue = [1e-6, 0.0]'))
    seen = []

    def probe(scene, system, progress=None, guess=None):
        newton = _Newton(scene, system)
        search = partial._Search(newton, float(scene.increments))
        opened = np.abs(search.y0).max(axis=1) > 0
        assert opened.any()
        for s in (np.full(search.m, partial._CLOSED, np.int8), np.where(opened, partial._OPEN, partial._CLOSED)):
            u, y, tau, P = search.solve(s.astype(np.int8))
            R, _, _ = newton._residual(u, search.b, search.response(s, y, tau, P))
            seen.append(np.abs(R[newton.free]).max() / search.scale)
        raise SystemExit

    monkeypatch.setattr(discretisation, "solve_increments", probe)
    with pytest.raises(SystemExit):
        discretisation.solve(load_scene(path), FE(degree=1), 0.05)
    assert len(seen) == 2 and max(seen) <= PARTIAL_MAP_RESIDUAL, seen


def test_a_consistent_map_the_search_finds_is_handed_to_newton(tmp_path, monkeypatch):
    """Where Newton answers (`uni`, fe P1 at h = 0.025: no point partial),
    the search run in its place finds that consistent open/closed map with
    no partial point, hands it to Newton (partial._answer), and the
    committed answer is Newton's own: the same statuses, the tractions
    within Newton's tolerance (SEARCH_AS_NEWTON) of Newton's, no partial
    point reported."""
    from contactcore.newton.increments import _Newton
    from xdolfinx.options import FE
    path = tmp_path / "uni.toml"
    path.write_text(UNI)
    scene = load_scene(path)
    newtons = discretisation.solve(scene, FE(degree=1), 0.025)
    handed = []

    def searched(scene, system, progress=None, guess=None):
        newton = _Newton(scene, system)
        answer = partial._answer
        monkeypatch.setattr(partial, "_answer", lambda *a: handed.append(len(a[6])) or answer(*a))
        assert partial.partial_answer(newton, float(scene.increments))
        newton.report.increments = len(newton.path.steps)
        newton.path.state = newton.state
        return newton.u, newton.path, newton.report

    monkeypatch.setattr(discretisation, "solve_increments", searched)
    result = discretisation.solve(scene, FE(degree=1), 0.025)
    assert handed == [0]  # a consistent map with no partial point, handed over
    mine, theirs = result.interface.final, newtons.interface.final
    assert np.array_equal(mine.status, theirs.status) and mine.counts().get("partial", 0) == 0
    scale = np.max(np.abs(theirs.traction))
    assert np.max(np.abs(mine.traction - theirs.traction)) <= tol.SEARCH_AS_NEWTON * scale


def test_a_walk_with_more_partial_points_than_the_bound_ends(monkeypatch, uni_p1):
    """review10 #2: PARTIAL_SEARCH_POINTS ends a walk.  `uni` fe P1 at
    h = 0.05 answers with one partial point; with the bound below that
    (0) neither walk may hold it and the refusal stands."""
    from contactcore import tolerances as ctol
    from xdolfinx.options import FE
    scene, result = uni_p1
    assert len(_partial_points(result.solver)) == 1
    monkeypatch.setattr(ctol, "PARTIAL_SEARCH_POINTS", 0)
    with pytest.raises(SolverError, match="Newton found no open/closed map"):
        discretisation.solve(scene, FE(degree=1), 0.05)


def test_partial_equations_singular_to_working_precision_are_refused_on_every_kernel():
    """partial.singular (review11 #1): M of condition 1.3e16 is singular
    to working precision, though LAPACK factors it without a zero pivot
    (the tilted block's xfem P1 map at h = 0.025 was refused under one
    kernel and solved under another); a condition of 94, the most an
    answer's M has had, is not; nor is a 1×1 M of any nonzero size."""
    from contactcore.tolerances import PARTIAL_M_RCOND
    near = np.array([[1.0, 1.0], [1.0, 1.0 + 4e-16]])
    np.linalg.solve(near, np.ones(2))  # no LinAlgError: a pivot test would pass it
    assert partial.singular(near)
    assert partial.singular(np.zeros((1, 1))) and partial.singular(np.full((2, 2), np.nan))
    assert not partial.singular(np.diag([1.0, 1.0 / 94.0]))
    assert not partial.singular(np.array([[3e-300]]))
    assert partial.singular(np.diag([1.0, 0.5 * PARTIAL_M_RCOND]))
    assert not partial.singular(np.diag([1.0, 2.0 * PARTIAL_M_RCOND]))


def test_a_partial_point_asks_to_close_or_open_only_beyond_the_band_and_a_tie_within_it_has_no_side():
    """partial.partial_asks (review11 #5, review12 #3): τ within [0, k_T y_T]
    stays partial; beyond the tie by more than the band closes, beyond 0
    opens; a tie within the band (no side but round-off's) opens at any τ
    beyond the band, either way (the old rule, side = sign(tie), closed
    the first of these)."""
    band, O, C, P = 1.0, partial._OPEN, partial._CLOSED, partial._PARTIAL
    within = 0.5 * band
    asks = partial.partial_asks(np.array([2.0, -2.0, 0.5]) * band, np.full(3, within), band)
    assert asks.tolist() == [O, O, P]
    for sign in (1.0, -1.0):  # a tie beyond the band, either way
        tau = sign * np.array([12.0, 10.5, 5.0, 0.0, -0.5, -2.0]) * band
        assert partial.partial_asks(tau, np.full(6, sign * 10.0 * band), band).tolist() == [C, P, P, P, P, O]


def test_the_tilted_block_in_fe_p2_answers_with_one_partial_point_where_gamma_opens(tmp_path):
    """The docs' tilted block (tests/test_unilateral_shear.TILTED, exact),
    fe P2 at h = 0.1, which Newton refuses: the search answers (its first
    walk, cycling) with one partial point at (0.567, 0.5), θ = 0.502
    (measured 2026-11-29, docs/contact-enforcement.md, "The tilted
    block"), where Γ changes from open (left) to closed (right), carrying
    (0, τ) with θ inside (0, 1).  A default test whose partial point moves
    during the walk (review11 #3: the `uni` answer's appears only in its
    last map, and 13 of 18 mutations of partial.py passed the default
    suite; this one fails on dropping the second walk, on a partial point
    that never moves, on one that stays partial, and on the open side's
    test)."""
    from test_unilateral_shear import TILTED
    from xdolfinx.options import FE
    path = tmp_path / "tilted.toml"
    path.write_text(TILTED)
    scene = load_scene(path)
    result = discretisation.solve(scene, FE(degree=2), 0.1)
    (x, y, theta), = _partial_points(result.solver)
    # named in the scene's metres (it named the dimensionless (0.2835, 0.25) before 2026-11-29)
    assert (x, y) == pytest.approx((0.567, 0.5), abs=tol.PARTIAL_PRINTED)
    assert theta == pytest.approx(0.502, abs=tol.PARTIAL_PRINTED)
    check_partial_reported(tmp_path, scene, result)
    interface = result.interface
    at = np.argmin(np.hypot(*(interface.points - [x, y]).T))
    assert interface.final.traction[at, 0] == 0.0 and 0.0 < abs(interface.final.traction[at, 1])
    xs, opened = interface.points[:, 0], interface.final.status == OPEN
    h = 0.1  # Γ open on the left, closed on the right, beyond a cell of the partial point
    assert np.all(opened[xs < x - h]) and not np.any(opened[xs > x + h])
