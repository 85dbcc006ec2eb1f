"""The law contract proved by a law that is not shipped: a constant
friction threshold ``tau_c`` (Tresca's law; takeover31's, 2026-11-29),
registered from here as a user's plugin would register it
(:func:`contactcore.laws.register`, undone after this module), with no
edit of the core by name.  Frictional (its ``slip_bound`` is ``tau_c``
wherever a point is closed), so every place that needs a slip bound asks
the law: (i) with ``tau_c`` out of reach it gives the unilateral law's
answer on scene A, three methods, penalty and exact; (ii) the layered
block sheared past ``tau_c`` follows the layered closed form
(verification.closed_forms.LayeredSlip, the law's bound); (iii) a load
beyond ``tau_c |Γ|`` is refused before Newton, as Coulomb's beyond μ;
(iv) a profile sample labelled slip reads the bound."""
from __future__ import annotations

import dataclasses
import math
import pathlib
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pytest

import tolerances as tol
from contactcore import ContactError, SceneError, load_scene, make_law, sample_profiles, scene_from_dict
from contactcore import health
from contactcore.exact import EXACT_LAWS, _ExactLaw
from contactcore.laws import (DIMENSIONLESS, LAWS, OPEN, SLIP, STICK, STIFFNESS, STRESS, Decision, LawResponse, _Law,
                              law_contract, register, unregister)
from contactcore import tolerances as core_tol
from contactcore.tolerances import STICK_ROUNDOFF
from verification import methods
from verification.closed_forms import LayeredSlip, LayeredSlipFields

METHODS = ["fe", "xfem", "efgm"]
WEDGE = pathlib.Path(__file__).parents[1] / "examples" / "wedge.toml"
SLIDE = pathlib.Path(__file__).parent / "scenes" / "wedge_slide.toml"


def _threshold(params: dict, path: str) -> float:
    """``tau_c`` (a stress > 0), naming the field of a bad value."""
    if "tau_c" not in params:
        raise SceneError(f"{path}.tau_c", "missing (the friction threshold, a shear stress > 0)")
    value = params["tau_c"]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise SceneError(f"{path}.tau_c", f"must be a finite friction threshold > 0 (got {value!r})")
    return float(value)


@dataclass(frozen=True)
class ThresholdLaw(_Law):
    """Unilateral penalty contact with a constant friction threshold: the
    unilateral law's normal response; a closed point sticks while
    ``|t*| <= tau_c``, ``t* = k_T (g_T − s)``, else slips with
    ``t_T = tau_c sign t*``, ``s ← g_T − t_T/k_T``; open: ``t = 0``,
    ``s ← g_T``.  Decided as CoulombLaw decides."""

    kN: float
    kT: float
    tau_c: float

    name: ClassVar[str] = "threshold"
    parameters: ClassVar[tuple[str, ...]] = ("kN", "kT", "tau_c")
    dimensions: ClassVar[dict[str, str]] = {"kN": STIFFNESS, "kT": STIFFNESS, "tau_c": STRESS}
    is_linear: ClassVar[bool] = False
    has_history: ClassVar[bool] = True
    homogeneous: ClassVar[bool] = False  # a threshold
    unilateral: ClassVar[bool] = True
    frictional: ClassVar[bool] = True

    @classmethod
    def extra_parameters(cls, params: dict, path: str) -> dict:
        return {"tau_c": _threshold(params, path)}

    def initial_state(self, m: int) -> np.ndarray:
        return np.zeros(m)

    def slip_bound(self, tN: np.ndarray) -> np.ndarray:
        return np.full(np.shape(tN), self.tau_c)

    def evaluate(self, g: np.ndarray, state=None, decision: Decision | None = None) -> LawResponse:
        g, closed, tN = self._springs(g, decision)
        limit = np.where(closed, self.slip_bound(tN), 0.0)
        s = np.zeros(len(g)) if state is None else np.asarray(state, dtype=float)
        trial = self.kT * (g[:, 1] - s)
        if decision is None:
            stick = closed & (np.abs(trial) <= limit * (1.0 + STICK_ROUNDOFF))
        else:
            stick = closed & decision.switch(limit - np.abs(trial), decision.traction, decision.previous == STICK,
                                             self.kT, rest=decision.traction <= core_tol.DECISION_FLOOR
                                             and decision.pressure <= core_tol.DECISION_FLOOR)
        slip = closed & ~stick
        direction = np.sign(trial)
        tT = np.where(stick, trial, np.where(slip, limit * direction, 0.0))
        tangent = np.zeros((len(g), 2, 2))
        tangent[:, 0, 0] = np.where(closed, self.kN, 0.0)
        tangent[:, 1, 1] = np.where(stick, self.kT, 0.0)
        new_state = np.where(stick, s, g[:, 1] - tT / self.kT)
        status = np.where(stick, STICK, np.where(slip, SLIP, OPEN)).astype(np.int8)
        secant = np.divide(np.broadcast_to(self.kT * limit, limit.shape), np.abs(trial), out=np.zeros(len(g)),
                           where=slip)
        return LawResponse(np.column_stack([tN, tT]), tangent, new_state, status, secant)


@dataclass(frozen=True)
class ExactThreshold(_ExactLaw):
    """The threshold law enforced exactly: its springs at ``k = γ``."""

    tau_c: float = 0.0
    name: ClassVar[str] = "threshold"
    parameters: ClassVar[tuple[str, ...]] = ("tau_c", "stabilisation")
    dimensions: ClassVar[dict[str, str]] = {"tau_c": STRESS, "stabilisation": DIMENSIONLESS}
    has_history: ClassVar[bool] = True
    springs: ClassVar[type] = ThresholdLaw
    homogeneous: ClassVar[bool] = False
    unilateral: ClassVar[bool] = True
    frictional: ClassVar[bool] = True


@pytest.fixture(autouse=True, scope="module")
def registered():
    """The plugin's registration, undone after this module."""
    register(ThresholdLaw)
    register(ExactThreshold, EXACT_LAWS)
    yield
    unregister("threshold")
    unregister("threshold", EXACT_LAWS)


# ----- the registry and the contract ---------------------------------------

def test_a_registered_law_is_built_from_a_scene_table_penalty_and_exact():
    law = make_law({"type": "threshold", "kN": 1e12, "kT": 1e11, "tau_c": 2e5})
    assert law == ThresholdLaw(1e12, 1e11, 2e5)
    exact = make_law({"type": "threshold", "tau_c": 2e5, "enforcement": "exact"})
    assert isinstance(exact, ExactThreshold) and exact.tau_c == 2e5
    assert exact.initial_state(3).tolist() == [0.0, 0.0, 0.0]
    assert np.array_equal(exact.slip_bound(np.array([-1.0, 0.0])), [2e5, 2e5])
    for enforcement in ("penalty", "exact"):
        with pytest.raises(SceneError, match=r"^interface\.law\.tau_c: must be a finite friction threshold"):
            make_law({"type": "threshold", "kN": 1e12, "kT": 1e11, "tau_c": -1.0, "enforcement": enforcement})


def test_registering_twice_or_too_little_is_refused_by_name():
    with pytest.raises(ContactError, match="'threshold' is registered twice"):
        register(ThresholdLaw)

    @dataclass(frozen=True)
    class NoBound(_Law):
        kN: float
        kT: float
        name: ClassVar[str] = "nobound"
        homogeneous: ClassVar[bool] = True
        unilateral: ClassVar[bool] = True
        frictional: ClassVar[bool] = True

    with pytest.raises(ContactError, match="is frictional but has no method 'slip_bound"):
        register(NoBound)
    assert "nobound" not in LAWS
    # a frictional law needs no parameter named mu: the contract asks for the bound
    assert law_contract(ThresholdLaw)["tau_c"] == STRESS


def test_unregistered_the_name_is_unknown_again():
    unregister("threshold")
    try:
        with pytest.raises(SceneError, match=r"^interface\.law\.type: unknown interface law 'threshold'"):
            make_law({"type": "threshold", "kN": 1e12, "kT": 1e11, "tau_c": 2e5})
    finally:
        register(ThresholdLaw)


def test_the_decision_scale_is_the_bound_where_closed():
    law = ThresholdLaw(2.0, 1.0, 0.5)
    assert law.decision_scales(np.array([[-1.0, 0.3], [0.2, 0.0]])).tolist() == [1.0, 0.5, 2.0]
    assert law.decision_scales(np.array([[0.1, 0.3]])).tolist() == [0.1, 0.0, 0.0]  # nothing closed


# ----- (i) tau_c out of reach: the unilateral law's answer -------------------

@pytest.mark.parametrize("enforcement", ["penalty", "exact"])
@pytest.mark.parametrize("method", METHODS)
def test_a_huge_threshold_gives_the_unilateral_answer_on_scene_A(method, enforcement):
    base = load_scene("A")
    springs = {"kN": base.law.kN, "kT": base.law.kT, "enforcement": enforcement}
    runs = {}
    for name, extra in (("unilateral", {}), ("threshold", {"tau_c": tol.LAWCAPS_HUGE_TAU_C})):
        scene = base.with_changes(law=make_law({"type": name, **springs, **extra}))
        r = methods.solver(method)(scene, tol.LAWCAPS_H)
        runs[name] = (r, {p.id: p for p in sample_profiles(r.scene, r.fields, path=r.interface)})
    (ru, pu), (rt, pt) = runs["unilateral"], runs["threshold"]
    assert rt.solver.increments == base.increments and ru.solver.increments == 1
    fu, ft = ru.interface.final, rt.interface.final
    assert np.array_equal(fu.status, ft.status)
    for a, b in ((fu.traction, ft.traction), (fu.jump, ft.jump)):
        assert np.max(np.abs(a - b)) <= tol.LAWCAPS_AS_UNILATERAL * np.max(np.abs(a))
    for pid, p in pu.items():
        for q in p.names[3:]:
            a, b = p.columns[q], pt[pid].columns[q]
            assert np.max(np.abs(a - b)) <= tol.LAWCAPS_AS_UNILATERAL * np.max(np.abs(a)), (pid, q)


# ----- (ii) the layered block sheared past tau_c (closed form) ---------------

def layered_threshold(exact: bool) -> LayeredSlip:
    """``layered-slip`` with the threshold law at LAWCAPS_LAYERED_TAU_C
    (apart from the scene's μp = 3e5 Pa), the top's δ and the sides' shear
    rescaled to it, and the pressure dropped to 0.4 p while Γ slips (which
    would move a Coulomb limit μp, and does not move tau_c): the closed form
    is verification.closed_forms.LayeredSlip, which reads the law's bound."""
    base = load_scene("layered-slip")
    tau_c = tol.LAWCAPS_LAYERED_TAU_C
    law = make_law({"type": "threshold", "tau_c": tau_c, "enforcement": "exact"} if exact else
                   {"type": "threshold", "kN": base.law.kN, "kT": base.law.kT, "tau_c": tau_c})
    compliance = LayeredSlip(base.with_changes(law=law)).compliance
    press, top, left, right = base.loads[0], base.supports[1], base.loads[1], base.loads[2]
    supports = (base.supports[0], dataclasses.replace(top, value=(tau_c * compliance, 0.0)))
    loads = (dataclasses.replace(press, path=((4, 1.0), (10, 0.4), (12, 1.0))),
             dataclasses.replace(left, value=(0.0, -tau_c)), dataclasses.replace(right, value=(0.0, tau_c)))
    return LayeredSlip(base.with_changes(law=law, supports=supports, loads=loads))


def test_the_layered_closed_form_reads_the_laws_bound():
    case = layered_threshold(False)
    states = case.history()
    assert [st.status for st in states].count("slip") == 8  # both slips reached: 9-12, 17-20
    assert {abs(st.tau) for st in states if st.status == "slip"} == {tol.LAWCAPS_LAYERED_TAU_C}
    assert len({st.p for st in states if st.status == "slip"}) > 1  # the pressure moves, the bound does not


CASES = [(m, False) for m in METHODS] + [(m, True) for m in METHODS]


@pytest.mark.parametrize("method,exact", CASES)
def test_the_layered_block_slips_when_the_shear_reaches_tau_c(method, exact):
    """Every increment's mean t_T, t_N and g_T, each point's status away
    from the limit, the last increment's u and σ through both layers:
    linear fields, so fe and xfem P1 to round-off and efgm to its patch
    test (FRICTION_CLOSED_FORM, the bounds of the Coulomb closed form)."""
    case = layered_threshold(exact)
    result = methods.solver(method)(case.scene)
    exact_path = case.history()
    steps = [s for s in result.interface.steps if float(s.step).is_integer()]
    assert len(steps) == len(exact_path)
    w = result.interface.weights / result.interface.weights.sum()
    bound, bound_sigma = tol.FRICTION_CLOSED_FORM[method]
    tau_c = tol.LAWCAPS_LAYERED_TAU_C
    g_scale = tau_c / case.kT if not exact else max(abs(st.slip) for st in exact_path)
    for step, st in zip(steps, exact_path):
        on_limit = abs(st.tau) >= (1 - bound) * tau_c
        if not on_limit or st.status == "slip":
            assert np.all(step.status == (STICK if st.status == "stick" else SLIP)), step.step
        assert abs(w @ step.traction[:, 1] - st.tau) <= bound * tau_c + tol.MEAN_TRACTION_FLOOR_PA, step.step
        assert abs(w @ step.traction[:, 0] + st.p) <= bound_sigma * st.p + tol.MEAN_TRACTION_FLOOR_PA, step.step
        assert abs(w @ step.jump[:, 1] - (st.tau / case.kT + st.slip)) <= bound * g_scale, step.step
    pts = np.column_stack([np.full(41, 0.37), np.linspace(0.01, 0.99, 41)])
    bodies = case.scene.body_of(pts)
    want = LayeredSlipFields(case, exact_path[-1])
    err_u = np.max(np.abs(result.fields.displacement(pts, bodies) - want.displacement(pts, bodies)))
    err_s = np.max(np.abs(result.fields.stress(pts, bodies) - want.stress(pts, bodies)))
    assert err_u <= bound * np.max(np.abs(want.displacement(pts, bodies)))
    assert err_s <= bound_sigma * exact_path[-1].p


# ----- (iii) a load beyond tau_c |Γ| is refused before Newton ---------------

def _wedge(tau_c: float, enforcement: str = "penalty"):
    text = WEDGE.read_text()
    import tomllib
    data = tomllib.loads(text)
    law = {"type": "threshold", "tau_c": tau_c, "enforcement": enforcement}
    if enforcement == "penalty":
        law.update(kN=data["interface"]["law"]["kN"], kT=data["interface"]["law"]["kT"])
    data["interface"]["law"] = law
    return scene_from_dict(data)


def _wedge_mean_shear() -> float:
    """The wedge's loads' shear over Γ's length: the top's pressure p over
    a width 1 on Γ of normal (−0.2, 1), |Γ| = √1.04: shear p·0.2/√1.04 over
    √1.04, 0.2 p / 1.04."""
    data = load_scene(WEDGE)
    p = data.loads[0].value if not hasattr(data.loads[0].value, "__len__") else data.loads[0].value[0]
    return 0.2 * p / 1.04


@pytest.mark.parametrize("enforcement", ["penalty", "exact"])
def test_a_threshold_just_below_the_loads_shear_is_refused_and_just_above_is_not(enforcement):
    mean = _wedge_mean_shear()
    below = _wedge(mean * (1 - tol.LAWCAPS_BOUND_SHIFT), enforcement)
    above = _wedge(mean * (1 + tol.LAWCAPS_BOUND_SHIFT), enforcement)
    n = float(below.increments)
    message = health.beyond_cone(below, n)
    assert "slides off" in message and "'threshold' law's slip bound" in message and "body +" in message, message
    assert health.beyond_cone(above, n) == ""
    # the diagnosis after a failed increment says the same, not the unilateral tie's "use coulomb"
    assert health.friction_demand(below, n) == message
    assert health.tie_cause(below, n, "not converged") == ""


@pytest.mark.parametrize("method", METHODS)
def test_a_threshold_below_the_loads_shear_is_refused_before_newton(method):
    """takeover31 #1: τ_c = 1e5 on the wedge (mean shear 1.92e5) failed
    Newton at increment 6 after six cut-backs and said "use coulomb"; now
    refused before Newton, as coulomb μ = 0.1 is."""
    scene = _wedge(1e5)
    with pytest.raises(ContactError) as refused:
        methods.solver(method)(scene, tol.LAWCAPS_H)
    message = str(refused.value)
    assert "slides off" in message and "threshold" in message and "coulomb" not in message, message
    coulomb = scene.with_changes(law=make_law({"type": "coulomb", "kN": 1e12, "kT": 1e12, "mu": 0.1}))
    with pytest.raises(ContactError, match="shear/normal = 0.2 .*above μ = 0.1"):
        methods.solver(method)(coulomb, tol.LAWCAPS_H)


# ----- (iv) a profile's slipping samples read the bound ----------------------

@pytest.mark.parametrize("method", METHODS)
def test_a_profile_sample_labelled_slip_reads_the_bound(method):
    """The wedge at tau_c = LAWCAPS_WEDGE_TAU_C (part of Γ slips): every
    sample labelled slip reads |t_T| = tau_c (takeover31 #2: 0.990-0.994
    tau_c, the stick branch's, while only Coulomb was rewritten)."""
    from contactcore.profiles import interface_response, interface_status, sample_points
    from contactcore.scene import InterfaceProfile
    scene = _wedge(tol.LAWCAPS_WEDGE_TAU_C)
    r = methods.solver(method)(scene, tol.LAWCAPS_H)
    _, points, _ = sample_points(r.scene, InterfaceProfile("gamma", ("gN",)))
    status = interface_status(r.scene, r.fields, points, r.interface)
    t = interface_response(r.scene, r.fields, points, r.interface)
    slip = status == SLIP
    assert 0 < slip.sum() < len(slip), (int(slip.sum()), len(slip))  # the threshold is exercised
    assert np.array_equal(np.abs(t["tT"][slip]), np.full(int(slip.sum()), tol.LAWCAPS_WEDGE_TAU_C))
    assert np.all(np.abs(t["tT"][status == STICK]) <= tol.LAWCAPS_WEDGE_TAU_C * (1 + STICK_ROUNDOFF))


# ----- the rigid slide (contactcore/slide.py) reads the bound ----------------

@pytest.mark.parametrize("method", METHODS)
def test_a_block_slipping_all_along_gamma_but_one_point_slides_to_it_in_one_step(method):
    """tests/scenes/wedge_slide.toml (test_slide.py's steel block on an
    aluminium wedge) with the threshold law at tau_c |Γ| = the loads'
    shear / LAWCAPS_SLIDE_SHARE: every point slips but one.  The exact slide
    along the free rigid motion (its kinks at ± the law's bound) settles it
    in one step of 4 iterations in fe, xfem and efgm; skipped for this law
    (takeover31 #1: slide.py read mu), Newton crept through 3-6 cut-backs
    (fe 6 steps, xfem 4, efgm 5; measured 2026-11-29)."""
    import tomllib
    from contactcore.geometry import tangent_of
    data = tomllib.loads(SLIDE.read_text())
    n = np.asarray(data["interface"]["normal"], float)
    n /= np.linalg.norm(n)
    width = data["domain"]["size"][0]
    load = np.asarray(data["loads"][0]["value"], float) * width  # the top's traction × its length
    length = width * math.hypot(1.0, n[0] / n[1])  # Γ across the rectangle's width
    tau_c = abs(load @ tangent_of(n[None])[0]) / length / tol.LAWCAPS_SLIDE_SHARE
    law = data["interface"]["law"]
    data["interface"]["law"] = {"type": "threshold", "kN": law["kN"], "kT": law["kT"], "tau_c": tau_c}
    result = methods.solver(method)(scene_from_dict(data))
    assert len(result.solver.iterations) == 1, result.solver.iterations  # no cut-back
    step, weights = result.interface.final, result.interface.weights
    status, t_T = step.status, step.traction[:, 1]
    assert not np.any(status == OPEN) and np.any(status == STICK)
    slip = status == SLIP
    assert np.count_nonzero(slip) > np.count_nonzero(status == STICK)
    assert np.allclose(np.abs(t_T[slip]), tau_c, rtol=tol.SLIDE_BALANCE, atol=0)
    assert abs(weights @ t_T - load @ tangent_of(n[None])[0]) <= tol.SLIDE_BALANCE * np.linalg.norm(load)


def test_a_frictionless_gamma_is_asked_of_the_bound():
    """Newton reports a sticking point as slipping only where the law's
    slip bound is zero (contactcore.laws.frictionless): Coulomb's μ = 0,
    penalty or exact; never a threshold law, which has no μ, nor a law
    that is not frictional."""
    from contactcore.laws import frictionless
    coulomb = {"type": "coulomb", "kN": 1e10, "kT": 1e10}
    assert frictionless(make_law({**coulomb, "mu": 0.0}))
    assert frictionless(make_law({"type": "coulomb", "mu": 0.0, "enforcement": "exact"}))
    assert not frictionless(make_law({**coulomb, "mu": 0.2}))
    assert not frictionless(make_law({"type": "unilateral", "kN": 1e10, "kT": 1e10}))
    assert not frictionless(ThresholdLaw(kN=1e10, kT=1e10, tau_c=tol.LAWCAPS_LAYERED_TAU_C))
    assert not hasattr(ThresholdLaw(kN=1e10, kT=1e10, tau_c=tol.LAWCAPS_LAYERED_TAU_C), "mu")


def test_a_point_held_at_stick_beyond_the_bound_is_warned_of():
    """contactcore.health.friction_excess_warnings asks the law's bound:
    a point reported sticking with |t_T| 1 % above tau_c is named, one at
    1 % below is not (a Coulomb μ would have read None and named neither)."""
    from types import SimpleNamespace
    from contactcore.health import friction_excess_warnings
    scene = load_scene("layered-slip")
    scene = scene.with_changes(law=make_law({"type": "threshold", "kN": scene.law.kN, "kT": scene.law.kT,
                                             "tau_c": tol.LAWCAPS_LAYERED_TAU_C}))
    tau = tol.LAWCAPS_LAYERED_TAU_C

    def path(share):
        return SimpleNamespace(steps=[SimpleNamespace(step=1.0, traction=np.array([[-tau, share * tau]]),
                                                      status=np.array([STICK]))])
    said = friction_excess_warnings(scene, path(1 + tol.LAWCAPS_EXCESS_SHARE), 0.0, None)
    assert len(said) == 1 and "above the law's slip bound" in said[0] and "μ" not in said[0], said
    assert not friction_excess_warnings(scene, path(1 - tol.LAWCAPS_EXCESS_SHARE), 0.0, None)


# ----- the warnings that ask a frictional law's bound (lawwarn) --------------

def _layered_springs(alpha: float, law: str = "coulomb", tau_c: float = 0.0):
    """layered-slip with k_T at ``α E₋/H`` (its k_N's α is 1): Coulomb
    μ = 0.3 as the scene has it, or the threshold law at ``tau_c``."""
    from verification.sweeps import H
    base = load_scene("layered-slip")
    kT = alpha * base.softer_modulus / H
    if law == "coulomb":
        return base.with_changes(law=dataclasses.replace(base.law, kT=kT))
    return base.with_changes(law=ThresholdLaw(base.law.kN, kT, tau_c))


def test_the_spring_band_line_asks_the_laws_bound():
    """contactcore.health.spring_band_warnings compares the springs'
    round-off (SPRING_TRACTION_ROUNDOFF·α of p) with Newton's stick/slip
    band, DECISION_BAND of Γ's largest slip bound, asked of the law at the
    scene's stress scale P (a threshold's bound does not scale with p), on
    the inputs alone: a threshold law of τ_c = μP takes Coulomb μ's
    decision on both sides of its edge; one at LAWCAPS_LAYERED_TAU_C (below
    μP) is warned from α below half Coulomb's edge, where Coulomb is silent.
    The old code read ``mu`` and never warned a threshold law."""
    from types import SimpleNamespace
    from contactcore.health.caveats import spring_band_warnings
    from contactcore.scaling import softer_stress
    from verification.sweeps import H
    P = softer_stress(_layered_springs(1.0), H)
    mu = load_scene("layered-slip").law.mu
    for alpha in tol.LAWWARN_SPRING_ALPHAS:
        coulomb = bool(spring_band_warnings(_layered_springs(alpha), H))
        assert bool(spring_band_warnings(_layered_springs(alpha, "threshold", mu * P), H)) == coulomb, alpha
    assert {bool(spring_band_warnings(_layered_springs(a), H)) for a in tol.LAWWARN_SPRING_ALPHAS} == {True, False}
    between = tol.LAWWARN_BETWEEN_ALPHA
    assert not spring_band_warnings(_layered_springs(between), H)
    scene = _layered_springs(between, "threshold", tol.LAWCAPS_LAYERED_TAU_C)
    said = health.friction_excess_warnings(scene, SimpleNamespace(steps=[]), 0.0, H)  # an empty path: the inputs'
    assert len(said) == 1 and "cannot be told from round-off" in said[0], said
    assert "'threshold' law's slip bound" in said[0] and "μ" not in said[0].replace("α", ""), said[0]
    assert not spring_band_warnings(scene, None)  # no h, no spring scale: nothing to say


def test_the_threshold_laws_spring_band_edge_is_decided_alike_in_either_units():
    """The threshold law's band is τ_c over the scene's stress scale, both
    made dimensionless by the solve: at springs exactly on its edge the
    user's and the solve's numbers take the same decision for every h
    (LIMIT_ROUNDOFF, review6 #6's rule for Coulomb)."""
    from contactcore.health.caveats import spring_band_warnings
    from contactcore.scaling import dimensionless_inputs, softer_stress
    from xdolfinx.options import FE
    base = load_scene("layered-slip")
    tau_c = tol.LAWCAPS_LAYERED_TAU_C
    differ = []
    for i in range(200):
        h = 0.01 + 0.19 * i / 199
        edge = core_tol.DECISION_BAND * tau_c / softer_stress(base, h) / core_tol.SPRING_TRACTION_ROUNDOFF
        k = edge * base.softer_modulus / h
        scene = base.with_changes(law=ThresholdLaw(k, k, tau_c))
        _, scaled, _, scaled_h = dimensionless_inputs(scene, FE(), h)
        if bool(spring_band_warnings(scene, h)) != bool(spring_band_warnings(scaled, scaled_h)):
            differ.append(h)
    assert not differ, differ


@dataclass(frozen=True)
class CohesiveLaw(ThresholdLaw):
    """Test-only: a bound ``tau_c + slope·p`` (Coulomb with cohesion), whose
    growth in the pressure has no parameter named ``mu``."""

    slope: float = 0.0
    name: ClassVar[str] = "cohesive"
    parameters: ClassVar[tuple[str, ...]] = ("kN", "kT", "tau_c", "slope")
    dimensions: ClassVar[dict[str, str]] = {"kN": STIFFNESS, "kT": STIFFNESS, "tau_c": STRESS,
                                            "slope": DIMENSIONLESS}

    def slip_bound(self, tN: np.ndarray) -> np.ndarray:
        return self.tau_c + self.slope * np.maximum(-np.asarray(tN, dtype=float), 0.0)


def test_the_dundurs_warning_asks_how_the_bound_grows_with_the_pressure():
    """contactcore.health.dundurs_warnings takes the slope of the law's
    slip bound in the pressure (from slip_bound on the scene's inputs) for
    Coulomb's μ: the layered cycle (β = 0.499) with a threshold law, whose
    slip does not depend on the normal traction, is never warned, at any
    τ_c, penalty or exact; a cohesive law ``τ_c + f p`` takes Coulomb
    μ = f's decision (warned at f = 10, not at 0.3).  The old code read
    ``mu`` and warned the cohesive law at no slope."""
    from contactcore.health import caveats
    scene = load_scene(pathlib.Path(__file__).parent / "scenes" / "cycle_mu1e-06.toml")
    beta = health.dundurs_beta(scene)
    assert abs(beta) * max(tol.LAWWARN_SLOPES) > core_tol.MU_DUNDURS_WARN > abs(beta) * min(tol.LAWWARN_SLOPES)
    for f in tol.LAWWARN_SLOPES:
        coulomb = health.dundurs_warnings(scene.with_changes(law=dataclasses.replace(scene.law, mu=f)))
        said = health.dundurs_warnings(scene.with_changes(law=CohesiveLaw(1e12, 1e12, tol.LAWCAPS_LAYERED_TAU_C, f)))
        assert bool(said) == bool(coulomb), (f, said, coulomb)
        if said:
            assert len(said) == 1 and "'cohesive' law's slip bound" in said[0] and "Dundurs" in said[0], said
            assert f"slope·|β| = {f * abs(beta):.3g}" in said[0], said[0]
    for tau_c in (tol.LAWCAPS_LAYERED_TAU_C, tol.LAWCAPS_HUGE_TAU_C):
        for law in (ThresholdLaw(1e12, 1e12, tau_c), make_law({"type": "threshold", "tau_c": tau_c,
                                                                "enforcement": "exact"})):
            assert caveats.bound_slope(scene.with_changes(law=law)) == 0.0
            assert not health.material_warnings(scene.with_changes(law=law)), (tau_c, law)


@pytest.mark.parametrize("method", ["fe", "xfem"])
def test_a_run_with_stiff_threshold_springs_says_its_band_is_round_off(method):
    """The layered block with the threshold law at LAWWARN_RUN_ALPHA (k_T):
    the run's warnings carry the spring-band line in the law's words."""
    from verification.sweeps import H
    scene = layered_threshold(False).scene
    scene = scene.with_changes(law=dataclasses.replace(scene.law, kT=tol.LAWWARN_RUN_ALPHA * scene.softer_modulus / H))
    said = [w for w in methods.solver(method)(scene, H).solver.warnings if "cannot be told from round-off" in w]
    assert len(said) == 1 and "'threshold' law's slip bound" in said[0], said
