"""Unilateral contact and Coulomb friction (issue 6): the laws, load paths,
Newton with cut-back, and the three methods against a closed form and
against each other."""
import dataclasses
import re
from pathlib import Path

import numpy as np
import scipy.sparse as sp
import pytest

import tolerances as tol
from contactcore import tolerances as core_tol
from contactcore import Pin, SceneError, SolverError, load_scene, make_law, sample_profiles, scene_from_dict
from contactcore.laws import OPEN, SLIP, STICK, CoulombLaw, LinearLaw, UnilateralLaw
from contactcore.newton import solve_increments
from contactcore.system import ContactSystem, InterfaceOperator
from contactcore.result import SolverReport
from verification import methods
from verification.closed_forms import layered_slip

METHODS = ["fe", "xfem", "efgm"]


# ----- the laws ---------------------------------------------------------------

def _fd_tangent(law, g, state, eps=tol.FD_STEP):
    """∂t/∂g by central differences, one point at a time."""
    out = np.zeros((len(g), 2, 2))
    for j in range(2):
        d = np.zeros_like(g)
        d[:, j] = eps
        out[:, :, j] = (law.evaluate(g + d, state).traction - law.evaluate(g - d, state).traction) / (2 * eps)
    return out


def test_coulomb_return_map_and_consistent_tangent():
    law = CoulombLaw(kN=2.0, kT=1.0, mu=0.5)
    # open; stick; slip forwards; slip backwards (kN g_N = -2, μp = 1)
    g = np.array([[0.3, 0.7], [-1.0, 0.4], [-1.0, 3.0], [-1.0, -3.0]])
    s = np.array([0.1, 0.0, 0.5, -0.5])
    r = law.evaluate(g, s)
    assert list(r.status) == [OPEN, STICK, SLIP, SLIP]
    assert np.allclose(r.traction, [[0, 0], [-2, 0.4], [-2, 1.0], [-2, -1.0]])
    # open: s follows g_T; stick: s unchanged; slip: k_T (g_T - s) = t_T
    assert np.allclose(r.state, [0.7, 0.0, 2.0, -2.0])
    assert np.allclose(r.tangent, _fd_tangent(law, g, s), atol=tol.FD_TANGENT)
    assert r.tangent[2, 1, 0] != r.tangent[2, 0, 1]  # slipping: not symmetric


def test_coulomb_sticks_exactly_at_the_limit_despite_round_off():
    law = CoulombLaw(kN=1e10, kT=1e8, mu=0.3)
    gN = -1e-5
    limit = law.mu * law.kN * -gN
    gT = limit / law.kT * (1 + 1e-14)  # the limit, plus round-off
    assert law.evaluate(np.array([[gN, gT]]), np.zeros(1)).status[0] == STICK


def test_unilateral_opens_in_tension_and_matches_linear_when_closed():
    uni, lin = UnilateralLaw(3.0, 2.0), LinearLaw(3.0, 2.0)
    g = np.array([[-1.0, 0.5], [0.2, 0.5]])
    r = uni.evaluate(g)
    assert list(r.status) == [STICK, OPEN]
    assert np.allclose(r.traction[0], lin.evaluate(g[:1]).traction[0]) and np.all(r.traction[1] == 0)
    assert np.allclose(r.tangent, _fd_tangent(uni, g, None), atol=tol.FD_TANGENT)


@pytest.mark.parametrize("params,field", [
    ({"type": "coulomb", "kN": 1.0, "kT": 1.0}, "interface.law.mu"),
    ({"type": "coulomb", "kN": 1.0, "kT": 1.0, "mu": -0.1}, "interface.law.mu"),
    ({"type": "unilateral", "kN": 1.0, "kT": 0.0}, "interface.law.kT"),
    ({"type": "unilateral", "kN": 1.0, "kT": 1.0, "mu": 0.2}, "interface.law.mu"),
])
def test_bad_law_parameters_name_the_field(params, field):
    with pytest.raises(SceneError, match=field.replace(".", r"\.")):
        make_law(params, "interface.law")


# ----- load paths --------------------------------------------------------------

def test_load_path_factors():
    scene = load_scene("layered-slip")
    assert scene.factors(2) == ((0.5, 0.0, 0.0), (0.1, 0.0))  # no path on the bottom support: the ramp 2/20
    assert scene.factors(10)[1][1] == 1.5 and scene.factors(14)[0][1] == 0.0
    assert scene.factors(20) == ((1.0, -1.0, -1.0), (1.0, -1.0))


@pytest.mark.parametrize("path,problem", [
    ([[4, 1.0], [3, 0.0]], "increasing"),
    ([[25, 1.0]], "at most"),
    ([[4, "x"]], "finite number"),
    ([4, 1.0], "pair"),
    ([], "non-empty"),
])
def test_bad_load_paths_are_refused(scene_dict, path, problem):
    data = scene_dict("layered-slip")
    data["loads"][0]["path"] = path
    with pytest.raises(SceneError, match=r"loads\[0\]\.path") as exc:
        scene_from_dict(data)
    assert problem in str(exc.value)


# ----- Newton and cut-back on a system of one spring ------------------------------

class _OneSpring(ContactSystem):
    """One unknown u (the jump), a bulk spring of stiffness K to ground, a
    load F: R = K u + w t(u) − F.  Its solve refuses steps longer than
    ``max_step`` increments of the load (a stand-in for a failing Newton)."""

    def __init__(self, K, F, max_step):
        self.size, self.K, self.F, self.max_step = 1, K, F, max_step
        self.interface = InterfaceOperator(sp.csr_matrix([[1.0], [0.0]]),
                                           np.ones(1), np.zeros((1, 2)))
        self.fixed = np.zeros(0, int)
        self.last, self.J = 0.0, {}

    def fixed_values(self, f):
        return np.zeros(0)

    def external(self, loads, supports):
        self.load = loads[0]
        return np.array([loads[0] * self.F])

    def internal(self, u):
        return self.K * u

    def solve(self, Ki, rhs, force_scale=0.0, slot=0):
        if abs(self.load - self.last) > self.max_step + tol.LOAD_STEP_ROUNDOFF:
            raise SolverError("step too long")
        self.last = self.load
        if Ki is not None:  # else this slot's last matrix
            self.J[slot] = self.K + Ki.toarray()[0, 0]
        return rhs / self.J[slot], SolverReport("direct", residual=0.0, backward_error=0.0)


def _one_spring_scene(increments):
    scene = load_scene("A")
    # the + block pinned at two points: the rigid-mode check sees it held
    # (the one-unknown system stands for the jump alone)
    pins = (Pin((0.2, 0.8)), Pin((0.8, 0.8)))
    return dataclasses.replace(scene, law=UnilateralLaw(1.0, 1.0), increments=increments, pins=pins)


def test_newton_cuts_back_and_records_each_sub_step():
    # compression: g_N < 0 closed, K_total = 2, u = -F/2
    system = _OneSpring(K=1.0, F=-1.0, max_step=0.25 / 2)  # each increment (0.25) needs one halving
    u, path, report = solve_increments(_one_spring_scene(4), system)
    assert np.isclose(u[0], -0.5)
    assert [s.step for s in path.steps] == [0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4]


def test_newton_failure_names_the_increment_and_the_residuals():
    system = _OneSpring(K=1.0, F=-1.0, max_step=0.0)  # no step is ever short enough
    with pytest.raises(SolverError, match=r"increment 1 of 4 failed after \d+ cut-backs"):
        solve_increments(_one_spring_scene(4), system)


def test_shear_above_friction_has_no_equilibrium_and_says_so(scene_dict):
    data = scene_dict("A")
    data["interface"]["law"] = {"type": "coulomb", "kN": 1e10, "kT": 1e8, "mu": 0.2}  # 2.5e4 > 0.2 · 1e5
    with pytest.raises(SolverError, match=r"increment 1 of 20: on Γ the loads ask for shear/normal = 0\.25 .*above μ = 0\.2"):
        methods.solver("fe")(scene_from_dict(data), 0.1)


# ----- the three methods ------------------------------------------------------

@pytest.fixture(scope="module")
def layered():
    return layered_slip()


@pytest.mark.parametrize("method", METHODS)
def test_layered_closed_form_in_every_method(method, layered):
    """Stick, slip, stick after reversal and reversed slip, increment by
    increment: the mean t_T, g_T and every point's status match the closed
    form; the final fields match it to round-off (fe, xfem: linear fields
    are in their spaces) or to EFGM's quadrature error."""
    result = methods.solver(method)(layered.scene)
    exact = layered.history()
    w = result.interface.weights / result.interface.weights.sum()
    assert len(result.interface.steps) == len(exact)
    bound, bound_sigma = tol.FRICTION_CLOSED_FORM[method]
    for step, st in zip(result.interface.steps, exact):
        # where the exact shear sits on the limit (the last stick step before
        # a slip), the status is decided by the method's own error
        on_limit = abs(st.tau) >= (1 - bound) * layered.mu * st.p
        if not on_limit or st.status == "slip":
            assert np.all(step.status == (STICK if st.status == "stick" else SLIP)), step.step
        assert abs(w @ step.traction[:, 1] - st.tau) <= bound * layered.mu * st.p + tol.MEAN_TRACTION_FLOOR_PA, step.step
        gT = st.tau / layered.kT + st.slip
        assert abs(w @ step.jump[:, 1] - gT) <= bound * layered.mu * st.p / layered.kT, step.step
    pts = np.column_stack([np.full(41, 0.37), np.linspace(0.01, 0.99, 41)])
    bodies = layered.scene.body_of(pts)
    want = layered.fields(exact[-1])
    err_u = np.max(np.abs(result.fields.displacement(pts, bodies) - want.displacement(pts, bodies)))
    err_s = np.max(np.abs(result.fields.stress(pts, bodies) - want.stress(pts, bodies)))
    assert err_u <= bound * np.max(np.abs(want.displacement(pts, bodies)))
    assert err_s <= bound_sigma * exact[-1].p


def _assert_closed_form_path(result, case, bound: float, bound_g: float | None = None) -> None:
    """At every increment (cut-backs add others, skipped), the mean t_T
    within ``bound`` of μp and the mean g_T within ``bound_g`` (default
    ``bound``) of the path's largest |g_T| (its slip, which can dwarf μp/k_T)."""
    bound_g = bound if bound_g is None else bound_g
    exact = case.history()
    steps = [s for s in result.interface.steps if float(s.step).is_integer()]
    assert len(steps) == len(exact)
    w = result.interface.weights / result.interface.weights.sum()
    g_exact = np.array([st.tau / case.kT + st.slip for st in exact])
    for step, st, g in zip(steps, exact, g_exact):
        assert abs(w @ step.traction[:, 1] - st.tau) <= bound * case.mu * st.p + tol.MEAN_TRACTION_FLOOR_PA, step.step
        assert abs(w @ step.jump[:, 1] - g) <= bound_g * np.max(np.abs(g_exact)), step.step


@pytest.mark.parametrize("method", METHODS)
def test_a_soft_layer_under_a_stiff_one_answers_right_or_refuses(method, layered):
    """The layered closed form with the − layer SOFT_LAYER times as stiff
    (the top's δ rescaled, so τ's path and the side tractions hold).  The
    prescribed δ moves the stiff + layer, whose lift (the forces of δ alone,
    ~E₊δ/h) dwarfs the soft layer's forces; Newton judged an unsettled
    stick/slip split against it and accepted 2 sticking points of 30 where
    all slip: fe and xfem P1 exited 0 with t_T 0.25 μp off and g_T lost.
    fe and xfem must now match the closed form at every increment; EFGM
    refuses before any solve: its springs are 5e7 times the soft layer's
    E/h, where its tractions oscillate from point to point."""
    case = layered_slip(E=(tol.SOFT_LAYER * layered.E[0], layered.E[1]))
    if method == "efgm":
        refusal = r"interface\.law\.kN: 1e\+12 Pa/m is 5\.0e\+07 times the softer body's E/h"
        with pytest.raises(SolverError, match=refusal):
            methods.solver(method)(case.scene, estimate_condition=False)
        return
    result = methods.solver(method)(case.scene, estimate_condition=False)
    _assert_closed_form_path(result, case, max(tol.SOFT_LAYER_CLOSED_FORM, tol.FRICTION_CLOSED_FORM[method][0]))


@pytest.mark.parametrize("share", [0.5, 2.0])
def test_efgm_answers_coulomb_springs_below_its_limit_and_refuses_them_above(share, layered):
    """The layered closed form with its − layer softened until the springs
    are ``share`` times EFGM_FRICTION_SPRINGS times its E/h (α = k_N h/E₋
    at h = 0.1): below the limit efgm follows the closed form, t_T to its
    patch test's bound, g_T to EFGM_STIFF_SPRINGS_GT; above it refuses
    before any solve and names the largest spring it carries (k_N / share)."""
    h, kN = layered.scene.h, layered.scene.law.kN
    case = layered_slip(E=(kN * h / (share * core_tol.EFGM_FRICTION_SPRINGS["N"]), layered.E[1]))
    if share > 1:
        refusal = r"above the 1e\+03 efgm carries .* use k_N <= " + re.escape(f"{kN / share:.2e} Pa/m")
        with pytest.raises(SolverError, match=refusal):
            methods.solver("efgm")(case.scene, estimate_condition=False)
        return
    result = methods.solver("efgm")(case.scene, estimate_condition=False)
    _assert_closed_form_path(result, case, tol.FRICTION_CLOSED_FORM["efgm"][0], tol.EFGM_STIFF_SPRINGS_GT)


def test_efgm_refuses_a_tangential_spring_above_its_own_limit(layered):
    """k_T alone at twice EFGM_FRICTION_SPRINGS["T"] of the − layer's E/h
    (k_N unchanged, far below its own limit) is refused before any solve,
    naming k_T and the largest k_T carried: a stiff k_T alone made Newton
    fail at α_T = 1e3, below the k_N limit."""
    h, E = layered.scene.h, layered.scene.softer_modulus
    kT = 2 * core_tol.EFGM_FRICTION_SPRINGS["T"] * E / h
    refusal = r"interface\.law\.kT: .* use k_T <= " + re.escape(f"{kT / 2:.2e} Pa/m")
    with pytest.raises(SolverError, match=refusal):
        methods.solver("efgm")(layered_slip(kT=kT).scene, estimate_condition=False)


@pytest.mark.parametrize("method", METHODS)
def test_a_rigidly_shifted_block_has_the_unshifted_answer(method, layered):
    """The layered closed form with both edges moved by tol.RIGID_SHIFT
    more (x): t_T and g_T are the closed form's at every increment.  EFGM
    imposes supports by multiplier rows whose values, E·S, are data, not
    forces: judged among the forces, Newton's residual would accept
    stick/slip splits 0.30 of μp off."""
    from contactcore import Support

    top = layered.scene.supports[1]
    path = ((0, tol.RIGID_SHIFT),) + tuple((k, tol.RIGID_SHIFT + f * top.value[0]) for k, f in top.path)
    scene = layered.scene.with_changes(supports=(
        Support("bottom", "xy", (tol.RIGID_SHIFT, 0.0), ((0, 1.0),)), Support("top", "x", (1.0, 0.0), path)))
    result = methods.solver(method)(scene, estimate_condition=False)
    _assert_closed_form_path(result, layered, max(tol.SHIFTED_CLOSED_FORM, tol.FRICTION_CLOSED_FORM[method][0]))


def test_the_closed_form_matches_its_scene_inputs(layered):
    """The side tractions of the scene file are τ of the closed form at every
    increment (the file was written from it)."""
    for k, st in enumerate(layered.history(), 1):
        loads, _ = layered.scene.factors(k)
        assert np.isclose(loads[2] * layered.scene.loads[2].value[1], st.tau, rtol=tol.SCENE_FILE_RTOL,
                          atol=tol.SCENE_FILE_ATOL)


def _profiles(scene, method, h):
    res = methods.solver(method)(scene, h, estimate_condition=False)
    return res, {p.id: p for p in sample_profiles(scene, res.fields, res.interface)}


@pytest.mark.parametrize("method", METHODS)
def test_unilateral_in_full_compression_is_the_linear_answer(method):
    linear = load_scene("A")
    unilateral = linear.with_changes(law=UnilateralLaw(linear.law.kN, linear.law.kT))
    res, got = _profiles(unilateral, method, 0.1)
    assert np.all(res.interface.final.status == STICK)  # closed everywhere
    _, want = _profiles(linear, method, 0.1)
    for pid, prof in want.items():
        for q in prof.names[3:]:
            scale = np.max(np.abs(prof.columns[q]))
            assert np.max(np.abs(got[pid].columns[q] - prof.columns[q])) <= tol.PATCH_ROUNDOFF * scale, (pid, q)


@pytest.mark.parametrize("method", METHODS)
def test_coulomb_with_large_friction_is_the_unilateral_answer(method):
    """Compared where the law is evaluated, at Γ's quadrature points, and on
    the bulk profiles (between quadrature points a profile's t_T interpolates
    the history, which is approximate where open and closed points meet)."""
    scene = load_scene("C-coulomb")
    sticky = scene.with_changes(law=CoulombLaw(scene.law.kN, scene.law.kT, tol.NEVER_SLIPS_MU))
    unilateral = scene.with_changes(law=UnilateralLaw(scene.law.kN, scene.law.kT))
    res, got = _profiles(sticky, method, 0.1)
    assert not np.any(res.interface.final.status == SLIP)
    assert np.any(res.interface.final.status == OPEN)  # the comparison includes open points
    ref, want = _profiles(unilateral, method, 0.1)
    t_got, t_want = res.interface.final.traction, ref.interface.final.traction
    assert np.max(np.abs(t_got - t_want)) <= tol.PATCH_ROUNDOFF * np.max(np.abs(t_want))
    assert np.array_equal(res.interface.final.status, ref.interface.final.status)
    for pid, prof in want.items():
        for q in set(prof.names[3:]) - {"tN", "tT", "gN", "gT"}:
            scale = np.max(np.abs(prof.columns[q]))
            assert np.max(np.abs(got[pid].columns[q] - prof.columns[q])) <= tol.PATCH_ROUNDOFF * scale, (pid, q)


@pytest.mark.parametrize("method", METHODS)
def test_scene_c_coulomb_has_open_stick_and_slip(method):
    res = methods.solver(method)(load_scene("C-coulomb"), estimate_condition=False)  # the scene's h = 0.05
    counts = res.interface.final.counts()
    assert min(counts.values()) > 0, counts
    assert res.solver.solver.startswith("newton") and len(res.solver.iterations) == 20


@pytest.mark.parametrize("scale, expected", [(core_tol.DECISION_FLOOR, True), (1e3 * core_tol.DECISION_FLOOR, False)])
def test_a_point_is_at_rest_only_where_gamma_is(scale, expected):
    """The at-rest rule (a margin within REST_ROUNDOFF of a gap decides
    closed, sticking) holds only where Γ's own scale is at DECISION_FLOOR
    (a load back to zero).  Under load, a stiff spring's window (here
    k = 1e6, so REST_ROUNDOFF·k = 1e-3) would hold a point whose trial
    traction exceeds μp by a thousand bands: it slips."""
    from contactcore.laws import Decision
    stiffness = 1e6
    margin = -0.5 * core_tol.REST_ROUNDOFF * stiffness  # inside the rest window
    assert -margin > core_tol.DECISION_BAND * scale or expected  # beyond the band where Γ is loaded
    decided = Decision(np.array([STICK]), scale, scale).switch(np.array([margin]), scale, np.array([True]), stiffness)
    assert bool(decided[0]) is expected


def _unloaded_to(load: float):
    """tests/scenes/unloaded.toml (scene A's blocks on Coulomb springs,
    μ = 0.3, h = 0.1) loaded over one increment and unloaded to ``load``
    times the full load over the next."""
    scene = load_scene(Path(__file__).resolve().parent / "scenes" / "unloaded.toml")
    top = scene.loads[0]
    return scene.with_changes(increments=2, loads=(dataclasses.replace(top, path=((1, 1.0), (2, load))),))


@pytest.mark.parametrize("method", ["fe", "efgm"])
def test_a_block_unloaded_to_zero_stays_where_the_unloading_leaves_it(method):
    """Unloaded to exactly zero, every slip limit μp is zero and every
    position of the upper block (held by Γ alone) along Γ solves the step:
    Newton's singular solves placed it by round-off (fe: 1.8e-4 m along under
    Haswell, 6.3e-5 m under Nehalem, then refused the held zero load; xfem
    and efgm 3e-9 to 4e-7 m).  The answer is the limit of the unloading:
    the position of a step to a load just short of zero, where one point's
    stick window balances the block (docs/newton.md, "A load back to
    zero"): at zero that point is at rest and sticks, every other slips on
    its history with zero traction.  CI runs this under a second kernel."""
    at_zero = methods.solver(method)(_unloaded_to(0.0), None, estimate_condition=False)
    near = methods.solver(method)(_unloaded_to(tol.UNLOADED_LIMIT_LOAD), None, estimate_condition=False)
    step, limit = at_zero.interface.steps[-1], near.interface.steps[-1]
    assert np.count_nonzero(step.status == STICK) == 1 and not np.any(step.status == OPEN)
    assert np.array_equal(step.status, limit.status)
    loaded = np.max(np.abs(at_zero.interface.steps[0].traction))
    assert np.max(np.abs(step.traction)) <= tol.UNLOADED_PROFILES * loaded
    position = np.max(np.abs(limit.jump[:, 1]))
    assert np.max(np.abs(step.jump[:, 1] - limit.jump[:, 1])) <= tol.UNLOADED_LIMIT * position


def test_a_block_unloaded_to_zero_on_a_shifted_base_stays_where_the_unloading_leaves_it():
    """The same with the lower block's base displaced rigidly by 1e-4 m
    throughout: the loads go to zero, a prescribed displacement stays, and
    the upper block is still free along Γ at zero load.  Its jumps are
    those of the unshifted base (a rigid shift of the lower block moves no
    jump); Newton's singular solves gave 8.0e-5 or 3.3e-5 m (fe, Haswell or
    Nehalem) where the limit of the unloading is 1.43e-4 m."""
    from contactcore import Support
    plain = _unloaded_to(0.0)
    shifted = plain.with_changes(supports=(Support("bottom", "xy", (1e-4, 0.0)),))
    a, b = (methods.solver("fe")(s, None, estimate_condition=False).interface.steps[-1] for s in (plain, shifted))
    assert np.array_equal(a.status, b.status)
    assert np.max(np.abs(a.jump - b.jump)) <= tol.UNLOADED_PROFILES * np.max(np.abs(a.jump))
