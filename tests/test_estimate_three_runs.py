"""Three runs (``run --estimate 3``) keep the warnings whose cause a third
run does not remove, and name a last halving that slowed
(contactcore.estimate.caveats.observed_exact_tractions, slow_halving;
docs/error-estimates.md, "The warnings")."""
import numpy as np
import pytest

from contactcore import load_scene
from contactcore import estimate as est
from contactcore import tolerances as core_tol
from contactcore.discretisation import solve
from contactcore.estimate.runs import three_run_caveats
from verification import methods
from verification.agreement import default_exclusion
import tolerances as tol
from contactcore.estimate.energy import EnergyEstimate
from contactcore.profiles import ProfileData
from contactcore.result import MethodFacts
from contactcore.scaling import Sizes
from test_estimate_warning_lines import BLOCK, _pointed

#: The three runs' h of the synthetic quantities below, coarse to fine.
HS = (0.1, 0.05, 0.025)


def _named(warnings: list[str], key: str) -> list[str]:
    """The lines of ``warnings`` that name ``key`` (``PID:Q``)."""
    return [line for line in warnings if key in line.split(": ")[0].replace(" (", ", ").split(", ")]


def test_three_runs_name_the_exact_tractions_two_runs_name():
    """newuser32's block (exact Coulomb), fe P1 at h = 1, 0.5, 0.25 mm:
    the two finest runs' estimate names Γ's t_N and t_T (an exact law's
    traction at order 1); the three runs' estimate, whose order the third
    run observes (1.2 against 1) but whose runs' differences still
    over-state a multiplier's error varying from run to run, names them
    too (before 2026-11-29 it named them in no line)."""
    scene = load_scene(BLOCK)
    results = [solve(scene, methods.discretisation("fe")(degree=1), h) for h in est.levels_of(scene.h, 3)]
    two, three = (est.estimate_runs(scene, runs, default_exclusion(scene), energy=False)
                  for runs in (results[1:], results))
    for key in ("G:tN", "G:tT"):
        assert _named(two.warnings, key) and not two.profiles["G"][key[2:]].observed
        assert three.profiles["G"][key[2:]].observed
        assert _named(three.warnings, key) and key in three.unsettled


def _quantity(floor: float, theory: tuple[float, float] = (3.0, 3.0)) -> est.QuantityEstimate:
    """A three-run estimate of a quantity converging as ``h^3`` whose
    finest run carries a further error of ``floor`` times its own at
    alternate samples (a floor of the finest run, as EFGM P2's)."""
    x = np.linspace(0.0, 1.0, 11)
    values = [x * h ** 3 for h in HS]
    values[-1] = values[-1] + floor * HS[-1] ** 3 * (-1.0) ** np.arange(len(x))
    return est.richardson(values, theory=theory)


def test_a_last_halving_that_slowed_is_named_off_either_way():
    """slow_halving: a floor in the finest run that slows the last
    halving's difference by more than SLOW_HALVING against theory's 2^-p
    is named (the old code left such an entry unwarned: the observed order
    lies within ORDER_MISMATCH of theory's); the same runs without it are
    not, nor an order far below theory (order_warnings' own); the line
    claims no direction."""
    clean, stalled, far = _quantity(0.0), _quantity(4.0), _quantity(16.0)
    assert 2.0 ** (3.0 - stalled.measured) > core_tol.SLOW_HALVING and not est.order_mismatch(stalled)
    assert est.order_mismatch(far)
    found = est.slow_halving({"R": {"ux": stalled, "uy": clean, "sxx": far}})
    assert list(found) == ["R:ux"] and found["R:ux"] > core_tol.SLOW_HALVING
    line, = est.slow_halving_warning(found)
    assert line.startswith("R:ux (") and "either way" in line
    assert not est.slow_halving_warning({})


def test_two_runs_get_no_three_run_caveat():
    """three_run_caveats: an unobserved (two-run) estimate is named by
    neither three-run line, whatever its law."""
    scene = load_scene(BLOCK)
    two = est.richardson([np.linspace(0.0, 1.0, 5) * (1.0 + h) for h in HS[:2]], theory=(1.0, 1.0))
    assert three_run_caveats(scene, {"G": {"tN": two, "ux": two}}) == ([], set())


def test_three_runs_name_an_exact_traction_only_with_a_sample_near_a_status_change():
    """fix38: observed_exact_tractions names a three-run traction of a
    switching Γ (theory (1, 1)) only where a sample lies within
    STATUS_CHANGE_CELLS of a final status change (``smooth`` False there),
    as exact_tractions does from two runs; where every sample is beyond
    them (a Γ that switched only in its history) the far order applies
    everywhere and the line does not name it.  The old code named both."""
    scene = load_scene(BLOCK)
    x = np.linspace(0.0, 1.0, 11)
    levels = [np.cos(x) + (1.0 + x) * h for h in HS]
    far, mixed = np.ones(len(x), bool), x > x[2]
    steady, switching = (est.richardson(levels, theory=(1.0, 1.0), far=(m, est.balanced_order(1.0, 2.0)))
                         for m in (far, mixed))
    assert steady.observed and switching.observed
    assert est.observed_exact_tractions(scene, {"G": {"tN": steady}}, {"G": far}) == []
    assert est.observed_exact_tractions(scene, {"G": {"tN": switching}}, {"G": mixed}) == ["G:tN"]
    assert est.observed_exact_tractions(scene, {"G": {"tN": steady}}) == ["G:tN"]


def test_the_three_run_lines_are_short_and_point_to_their_rows():
    """Each three-run line with two quantities named (with their figures)
    is at most ESTIMATE_WARNING_CHARS and ends with its row of
    docs/error-estimates.md, "The warnings"."""
    names = ["G:gN", "G:gT"]
    lines = (est.observed_exact_traction_warning(names)
             + est.slow_halving_warning({k: 1.43 for k in names}))
    assert len(lines) == 2
    for line in lines:
        _pointed(line)
        assert len(line) <= tol.ESTIMATE_WARNING_CHARS, (len(line), line)


def test_the_recovery_floor_claims_no_direction():
    """recovery_floor: EFGM P2 on a disc whose Γ is open (h = 0.025) was
    named at 0.52 of η with an energy effectivity of 0.67, too small,
    where the line used to say "likely too large": it now says off either
    way."""
    line, = est.recovery_floor(EnergyEstimate(1.77e-2, 96.9, 1e-9, recovery=0.52 * 1.77e-2))
    assert "either way" in line and "likely too large" not in line


def test_an_order_observed_within_a_range_above_its_balanced_order_is_taken():
    """three_run_order's ``upper`` (est3_37): q_h = q + C h^2.8 with theory's
    range [1.52, 3] (a polluted degree-2 gap or penalty traction, scene C's
    C4): the observed order 2.8 lies within the range above its balanced
    order 2.20, so a mesh method's three-run estimate takes it and recovers
    the error (the old code kept 2.20: (2^2.8 − 1)/(2^2.20 − 1) = 1.65 times
    it; C4's degree-2 tractions read 2.21-2.33 so); EFGM's (``upper``
    False, profile_estimates' ``not facts.meshfree``) keeps the balanced
    order; an observed order above the range keeps it too."""
    s = np.linspace(0.0, 1.0, 11)
    lead, theory = 1.0 + s ** 2, (1.52, 3.0)
    levels = [np.cos(s) + lead * h ** 2.8 for h in HS]
    mesh, meshfree = est.richardson(levels, theory, upper=True), est.richardson(levels, theory)
    assert mesh.order == pytest.approx(2.8) and np.allclose(mesh.error, lead * HS[-1] ** 2.8)
    assert meshfree.order == pytest.approx(est.balanced_order(*theory))
    assert meshfree.rms / mesh.rms > tol.UNLIKE_OVER_READ
    fast = est.richardson([np.cos(s) + lead * h ** 3.5 for h in HS], theory, upper=True)
    assert fast.order == pytest.approx(est.balanced_order(*theory))


def test_profile_estimates_take_the_observed_order_for_mesh_methods_only():
    """profile_estimates passes ``upper`` for a mesh method and not for a
    meshfree one (its facts): a degree-1 stress (theory [1, 2], balanced
    1.45) observed at 1.8 is taken at 1.8 by fe, at 1.45 by EFGM; a
    displacement observed at 3 against its one order 2 is capped at 2."""
    s = np.linspace(0.0, 1.0, 11)
    cols = lambda h: {"s": s, "x": s, "y": 0.0 * s, "ux": np.cos(s) + (1 + s ** 2) * h ** 3}  # noqa: E731
    levels = [[ProfileData("L", "arclength", cols(h))] for h in HS]
    assert est.profile_estimates(levels, 1)["L"]["ux"].order == pytest.approx(2.0)
    ranged = [[ProfileData("L", "arclength", {**cols(h), "sxx": np.cos(s) + (1 + s ** 2) * h ** 1.8})] for h in HS]
    fe = est.profile_estimates(ranged, 1)["L"]["sxx"]
    efgm = est.profile_estimates(ranged, 1, MethodFacts(meshfree=True))["L"]["sxx"]
    assert fe.order == pytest.approx(1.8) and efgm.order == pytest.approx(est.balanced_order(1.0, 2.0))


def test_an_order_observed_above_theorys_range_is_named_off_either_way():
    """above_range (est3_39): q_h = q + C h^p with p above theory's range
    [2, 3] (ABOVE_RANGE_RATE) is estimated at the range's balanced order,
    ABOVE_RANGE_OVER_READ times or more the error, and named (the old code
    left such an entry unwarned: scene A's xfem P1 A1 σxy, 2.52; an exact
    law's fe P2 g_N on tilt_unil_exact, 3.84); not an order within the
    range, nor above a single order (its estimate takes that order), nor
    one further than ORDER_MISMATCH above (the order line's); the line
    claims no direction and three_run_caveats gives it."""
    s = np.linspace(0.0, 1.0, 11)
    lead, theory = 1.0 + s ** 2, (2.0, 3.0)
    runs = lambda p: [np.cos(s) + lead * h ** p for h in HS]  # noqa: E731
    above = est.richardson(runs(tol.ABOVE_RANGE_RATE), theory, upper=True)
    within = est.richardson(runs(2.8), theory, upper=True)
    single = est.richardson(runs(tol.ABOVE_RANGE_RATE), (3.0, 3.0), upper=True)
    beyond = est.richardson(runs(theory[1] + core_tol.ORDER_MISMATCH + 0.5), theory, upper=True)
    assert above.order == pytest.approx(est.balanced_order(*theory))
    assert above.rms / est.rms(lead * HS[-1] ** tol.ABOVE_RANGE_RATE) > tol.ABOVE_RANGE_OVER_READ
    assert est.order_mismatch(beyond) and not est.order_mismatch(above)
    found = est.above_range({"A1": {"sxy": above, "sxx": within, "syy": beyond}, "G": {"gN": single}})
    assert list(found) == ["A1:sxy"] and found["A1:sxy"] == pytest.approx(tol.ABOVE_RANGE_RATE)
    line, = est.above_range_warning(found)
    assert line.startswith("A1:sxy (3.30)") and "either way" in line
    assert not est.above_range_warning({})
    lines, named = three_run_caveats(load_scene(BLOCK), {"A1": {"sxy": above}})
    assert named == {"A1:sxy"} and lines == [line]


def test_the_above_range_line_is_short_and_points_to_its_row():
    """The above-range line with two quantities named is at most
    ESTIMATE_WARNING_CHARS and ends with its row of
    docs/error-estimates.md, "The warnings"."""
    line, = est.above_range_warning({"A1:sxy": 3.03, "G:gN": 2.51})
    _pointed(line)
    assert len(line) <= tol.ESTIMATE_WARNING_CHARS, (len(line), line)


def test_runs_that_differ_only_at_round_off_are_not_named_above_the_range():
    """review22: a quantity whose two finest runs differ only at round-off
    at every sample (:func:`contactcore.estimate.caveats.roundoff_runs`,
    which the stencil, exact tractions, steady tractions, enforced gaps
    and unlike differences lines skip) but show, over the kept samples
    against their own scale, an order above theory's range (its largest
    value at a singular point left out) is not named by ``above the
    range``: that order is round-off's.  The old code named it
    (``above_range`` and ``three_run_caveats`` took no ``roundoff``)."""
    scene = load_scene("tests/scenes/tilt_unil_exact.toml")
    size = Sizes.of(scene).stress
    s = np.linspace(0.0, 1.0, 41)
    levels = []
    for h in HS:
        sxx = size * (np.sin(3 * s) + tol.ABOVE_RANGE_ROUNDOFF_ERROR * (1 + s ** 2) * h ** tol.ABOVE_RANGE_RATE)
        sxx[0] = size * tol.UNLIKE_SINGULAR_PEAK
        levels.append([ProfileData("D", "arclength", {"s": s, "x": s, "y": np.zeros_like(s), "sxx": sxx})])
    e = est.richardson([run[0].columns["sxx"] for run in levels], theory=(2.0, 3.0), kept=s > 0, upper=True,
                       floor=est.roundoff_floor(Sizes.of(scene), "sxx"))
    roundoff = est.caveats.roundoff_runs(scene, levels)
    assert roundoff == {"D:sxx"} and e.measured == pytest.approx(tol.ABOVE_RANGE_RATE)
    profiles = {"D": {"sxx": e}}
    assert list(est.above_range(profiles)) == ["D:sxx"]
    assert est.above_range(profiles, roundoff=roundoff) == {}
    assert three_run_caveats(scene, profiles, roundoff=roundoff) == ([], set())
