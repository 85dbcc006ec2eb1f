"""Error estimates without a reference (contactcore.estimate): Richardson
per profile quantity and Zienkiewicz–Zhu in energy, their effectivity on
the closed forms, and ``run --estimate``'s outputs."""
import json
import logging

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore import estimate as est
from contactcore.labels import run_label
from contactcore import tolerances as core_tol
from contactcore.scaling import Sizes
from verification import files, methods
from verification.effectivity import CASES, VARIANTS, effectivity
from verification.run import run
from verification.run_summary import NOT_ESTIMATED, NOT_ESTIMATED_MARK


def _facts(name: str, degree: int):
    """Method ``name``'s facts at ``degree``, as its options declare them."""
    return methods.discretisation(name)(degree=degree).facts()

#: The paper scenes' effectivity setting (the issue's): runs h = 0.05 ->
#: 0.025 against fe P2 at h = 0.00625.
SCENE_H, SCENE_REF_H = 0.05, 0.00625


def test_richardson_is_exact_for_an_error_that_is_a_power_of_h():
    """q_h = q + C h^p: with the right order the finer run's error is
    recovered exactly, and three levels observe the order."""
    s = np.linspace(0.0, 1.0, 11)
    exact, lead = np.sin(s), 1.0 + s ** 2
    levels = [exact + lead * h ** 2 for h in (0.1, 0.05, 0.025)]
    two = est.richardson(levels[:2], theory=(2, 2))
    assert np.allclose(two.error, lead * 0.05 ** 2) and not two.observed
    three = est.richardson(levels, theory=(2, 2))
    assert three.observed and three.order == pytest.approx(2.0) and three.measured == pytest.approx(2.0)
    assert np.allclose(three.error, lead * 0.025 ** 2)
    # an observed order below a range's balanced one is balanced with it
    # (three_run_order, grader8's fault 2): within the bound of the two
    ranged = est.richardson(levels, theory=(2, 3))
    bal = est.balanced_order(2, 3)
    assert ranged.measured == pytest.approx(2.0) and ranged.order == pytest.approx(est.balanced_order(2.0, bal))
    assert ranged.rms / est.rms(lead * 0.025 ** 2) == pytest.approx(((2 ** 2 - 1) / (2 ** bal - 1)) ** 0.5)
    assert np.allclose(est.richardson(levels[:2], theory=(2, 2), coarse=True).error, lead * 0.1 ** 2)


def test_the_order_is_observed_away_from_singular_samples():
    """A sample converging at a singularity's rate h^0.5 would set the
    observed order; with it left out (``kept``) the smooth samples' order
    2 is seen, and the error is still estimated at every sample."""
    s = np.linspace(0.0, 1.0, 11)
    kept = s < 0.95
    levels = [np.sin(s) + h ** 2 + np.where(kept, 0.0, h ** 0.5) for h in (0.1, 0.05, 0.025)]
    assert est.richardson(levels, theory=(2, 2)).order < 1.0
    e = est.richardson(levels, theory=(2, 2), kept=kept)
    assert e.order == pytest.approx(2.0) and len(e.error) == len(s)
    assert np.allclose(e.error[kept], 0.025 ** 2)


@pytest.mark.parametrize("p", [1, 2])
def test_a_degree_one_stress_is_estimated_within_root_three_of_either_order_it_may_take(p):
    """A degree-1 stress converges at its order p or, where it
    superconverges, at p + 1: with two runs the estimate is off by the
    same factor either way, ((2^(p+1) − 1)/(2^p − 1))^½ (√3 for p = 1),
    and by no more; the other quantities keep their one order."""
    low, high = est.order_range("sxx", 1, _facts("xfem" if p == 2 else "fe", 1))
    assert (low, high) == (p, p + 1) and est.order_range("ux", 1) == (2, 2) and est.order_range("sxx", 2) == (2, 2)
    bound = np.sqrt((2.0 ** high - 1) / (2.0 ** low - 1))
    s = np.linspace(0.0, 1.0, 11)
    lead = 1.0 + s ** 2
    effectivity = {}
    for rate in (low, high):
        e = est.richardson([lead * h ** rate for h in (0.1, 0.05)], theory=(low, high))
        effectivity[rate] = e.rms / est.rms(lead * 0.05 ** rate)
    assert effectivity[low] == pytest.approx(1 / bound) and effectivity[high] == pytest.approx(bound)
    assert est.balanced_order(2, 2) == pytest.approx(2.0)


def test_an_observed_order_above_theory_is_not_used():
    """q_h = q + h² − 150 h⁴: the h⁴ term turns the coarse run's error
    over (−0.005 at h = 0.1, then 1.6e-3 and 5.7e-4), and the RMS
    differences give an order of 2.72 against theory's 2, within
    ORDER_MISMATCH, so no warning.  Used as it is, that order makes the
    finest run's estimate 0.31 of its error (1/(2^2.72 − 1) instead of
    1/3): grader6's unwarned underestimates.  The estimate takes the
    least of the observed and the theoretical order (Roache's GCI, ASME
    V&V 20: p no more than the formal order): 0.59 of the error.
    summary.json keeps the observed order (``observed_order``)."""
    s = np.linspace(0.0, 1.0, 11)
    lead = 1.0 + s ** 2
    error = lambda h: lead * (h ** 2 - 150 * h ** 4)  # noqa: E731
    levels = [np.cos(s) + error(h) for h in (0.1, 0.05, 0.025)]
    e = est.richardson(levels, theory=(2, 2))
    d1, d2 = (0.05 ** 2 - 150 * 0.05 ** 4) - (0.1 ** 2 - 150 * 0.1 ** 4), (0.025 ** 2 - 150 * 0.025 ** 4) - (
        0.05 ** 2 - 150 * 0.05 ** 4)
    assert e.measured == pytest.approx(np.log2(abs(d1 / d2))) and round(e.measured, 2) == 2.72
    assert e.order == 2 and e.record()["observed_order"] == e.measured and e.record()["order"] == 2
    assert e.rms / est.rms(error(0.025)) == pytest.approx(abs(d2) / 3 / (0.025 ** 2 - 150 * 0.025 ** 4))
    assert tol.EFFECTIVITY[0] <= e.rms / est.rms(error(0.025)) <= tol.EFFECTIVITY[1]
    assert not est.order_warnings({"P": {"ux": e}}) and not est.order_mismatch(e)
    # below theory, the balanced order of the observed and the theoretical
    # one (three_run_order): within 3^½ of the error whichever holds
    slow = est.richardson([np.cos(s) + lead * h for h in (0.1, 0.05, 0.025)], theory=(2, 2))
    assert slow.order == pytest.approx(est.balanced_order(1.0, 2.0))
    assert slow.rms / est.rms(lead * 0.025) == pytest.approx(3 ** -0.5)


@pytest.mark.parametrize("measured", [0.76, 0.84])
def test_an_observed_order_below_theory_is_balanced_with_it(measured):
    """grader8's fault 2: with three runs an observed order below theory
    (within ORDER_MISMATCH, so unwarned) was used as it was, and where the
    coarse run was still pre-asymptotic while the finer pair converged at
    theory (fe P1 σxy on the twisted rod: 0.84 against 1-2; efgm P1 σxy on
    the Lamé disc: 0.76) the estimate came to 2.49-4.35 times the error,
    against 1.13-1.74 from two runs.  Now the order is the balanced one of
    the observed and the two-run order: q_h = q + C h^a at h, h/2, then at
    h/4 converging at theory's balanced order b (a coarse run off its
    asymptote), and the reverse case (a true rate a): both within
    [0.5, 2]."""
    s = np.linspace(0.0, 1.0, 11)
    lead, b = 1.0 + s ** 2, est.balanced_order(1, 2)
    mid = 0.05 ** b                                   # the h/2 run's error
    for rate in (b, measured):                         # the finest pair's true rate
        fine = mid / 2 ** rate
        coarse = mid + (mid - fine) * 2 ** measured     # the differences shrink at `measured`
        e = est.richardson([np.cos(s) + lead * c for c in (coarse, mid, fine)], theory=(1, 2))
        assert e.measured == pytest.approx(measured)
        assert e.order == pytest.approx(est.balanced_order(measured, b))
        assert tol.EFFECTIVITY[0] <= e.rms / est.rms(lead * fine) <= tol.EFFECTIVITY[1]
    # taken as it was (the old rule), the first case overestimated beyond 2
    assert (mid - mid / 2 ** b) / (2 ** measured - 1) / (mid / 2 ** b) > tol.EFFECTIVITY[1]


@pytest.mark.slow
def test_three_runs_on_a_disc_estimate_a_stress_across_gamma_within_a_factor_two():
    """grader6's fault: a stiff rod held by springs in a softer ring under
    pressure (Lamé, verification.closed_forms.pressurised_rod), fe P2 at
    h = 0.1, 0.05, 0.025: σyy and σxy along a ray at 30° converge between
    the runs at observed orders 2.6 against theory's 2 (a stress that
    crosses a curved Γ); taken as they are, their estimates were 0.45 and
    0.47 of the true error, unwarned.  At the theoretical order they lie
    within EFFECTIVITY (0.75, 0.82 measured 2026-11-27)."""
    from contactcore import LineProfile, Material, sample_profiles
    from contactcore.discretisation import solve
    from verification import methods
    from verification.agreement import default_exclusion
    from verification.closed_forms import pressurised_rod
    case = pressurised_rod(a=0.5, b=1.0, p=1e7, kN=1e12, kT=1e11, rod=Material(2e11, 0.3),
                           matrix=Material(3e10, 0.2))
    ray = LineProfile("ray", (0.0, 0.0), (np.sqrt(3) / 2, 0.5), ("sxx", "syy", "sxy"))
    scene = case.scene.with_changes(profiles=(ray,))
    results = [solve(scene, methods.discretisation("fe")(degree=2), h) for h in est.levels_of(0.1, 3)]
    estimate = est.estimate_runs(scene, results, default_exclusion(scene), energy=False)
    exact = sample_profiles(scene, case)[0]
    for q in ("syy", "sxy"):
        e = estimate.profiles["ray"][q]
        effectivity = e.rms / est.rms(estimate.sampled[0].columns[q] - exact.columns[q])
        assert tol.EFFECTIVITY[0] <= effectivity <= tol.EFFECTIVITY[1], (q, effectivity)
        assert e.measured > e.theory[1] and e.order == e.theory[1]


def test_an_observed_order_far_from_theory_warns():
    s = np.linspace(0.0, 1.0, 11)
    levels = [1.0 + h ** 1 * np.ones_like(s) for h in (0.1, 0.05, 0.025)]
    e = est.richardson(levels, theory=(3, 3))
    assert e.order == pytest.approx(1.0)
    (warning,) = est.order_warnings({"P": {"ux": e}})
    assert "P:ux" in warning and "asymptotic" in warning


def test_a_clipped_order_warns_even_within_theorys_reach():
    """Differences that do not shrink (order clipped to ORDER_RANGE's 0.5)
    warn, though 0.5 lies within ORDER_MISMATCH of a degree-1 stress's
    range 1-2."""
    levels = [1.0 + 0.01 * np.ones(5), 1.0 + 0.02 * np.ones(5), 1.0 + 0.03 * np.ones(5)]
    e = est.richardson(levels, theory=(1, 2))
    assert e.order == core_tol.ORDER_RANGE[0] and e.theory[0] - core_tol.ORDER_MISMATCH <= e.order
    (warning,) = est.order_warnings({"P": {"sxx": e}})
    assert "(clipped)" in warning


def test_the_observed_order_is_clipped_and_round_off_shows_none():
    base = np.ones(5)
    assert est.observed_order(base + 1.0, base + 1e-3, base + 1e-12) == core_tol.ORDER_RANGE[1]
    assert est.observed_order(base, base * (1 + 1e-14), base) is None


def test_a_quantity_exactly_zero_shows_no_order_against_the_scenes_size():
    """grader8's fault 4: σxy on a column under its weight is exactly 0;
    its runs give round-off (1e-8 Pa against stresses of 1e6), whose
    differences' ratio was read as an order, clipped to 0.5, and warned
    "not to be trusted", against the docs' round-off rule.  A difference at
    most NEGLIGIBLE_SHARE of the scene's own size of the kind (Sizes) shows
    none: no order, the two-run order, no warning."""
    scene = load_scene("C")
    stress = Sizes.of(scene).stress
    noise = np.array([3e-9, -1e-8, 2e-8, 5e-9, -7e-9]) * stress * 1e-6   # 1e-8 Pa-like on 1e6 Pa
    levels = [noise * k for k in (1.0, -0.3, 2.0)]
    floor = est.roundoff_floor(Sizes.of(scene), "sxy")
    assert floor == core_tol.NEGLIGIBLE_SHARE * stress
    assert est.observed_order(*levels) is not None                       # the quantity's own scale sees an order
    e = est.richardson(levels, theory=(1, 2), floor=floor)
    assert e.measured is None and e.order == est.balanced_order(1, 2)
    assert not est.order_warnings({"vert": {"sxy": e}})
    assert est.roundoff_floor(Sizes.of(scene), "ux") == core_tol.NEGLIGIBLE_SHARE * Sizes.of(scene).displacement


@pytest.mark.parametrize("case,key", [("pressurised_rod", ("fe", 1)), ("pressurised_rod", ("xfem", 2)),
                                      ("twisted_rod", ("xfem", 1)), ("layered_slip", ("efgm", 1))],
                         ids=lambda v: str(v))
def test_the_estimates_are_within_a_factor_two_of_the_true_error(case, key, record_property):
    """One closed form per method (the layered slip: Coulomb, the final
    increment) and xfem P1, whose energy estimate takes its recovered
    stress as σ* (it read 0.40 on the twisted rod with a second recovery):
    every profile quantity with an error above round-off and the energy
    estimate within tol.EFFECTIVITY of the truth, but for the measured
    exceptions of tol.EFFECTIVITY_OUTSIDE (EFGM P1's energy on the
    layered slip: its quadrature's error, which ZZ does not see), each
    where it was measured and still outside."""
    rows = [r for r in effectivity(case, key) if r["kind"] == "error"]
    assert rows
    for r in rows:
        record_property(f"{r['profile']}:{r['quantity']}", r["effectivity"])
        _assert_effectivity(r, tol.EFFECTIVITY_OUTSIDE.get((case, *key, r["profile"], r["quantity"])))


def _assert_effectivity(row: dict, known: tuple | None) -> None:
    """``row``'s effectivity in tol.EFFECTIVITY, or, for a listed exception
    ``known`` (measured value, reason), within tol.EFFECTIVITY_OUTSIDE_DRIFT
    of its value and still outside the range."""
    inside = tol.EFFECTIVITY[0] <= row["effectivity"] <= tol.EFFECTIVITY[1]
    if known is None:
        assert inside, row
        return
    assert row["effectivity"] == pytest.approx(known[0], rel=tol.EFFECTIVITY_OUTSIDE_DRIFT), (row, known[1])
    assert not inside, (row, "now inside the range: unlist it")


@pytest.mark.slow
@pytest.mark.parametrize("case", list(CASES))
@pytest.mark.parametrize("key", list(VARIANTS), ids=lambda k: f"{k[0]}-P{k[1]}")
def test_the_full_effectivity_table(case, key):
    """Every closed form, method and degree: in tol.EFFECTIVITY, but for
    the measured exceptions of tol.EFFECTIVITY_OUTSIDE, each of which
    must stay where it was measured (tol.EFFECTIVITY_OUTSIDE_DRIFT) and
    outside the range; every profile quantity outside it named by one of
    the estimate's warnings (``warned``: since 2026-11-28 the twisted
    rod's EFGM P1 g_T, t_T at 2.02 too, est.fast_gamma)."""
    for r in effectivity(case, key):
        if r["kind"] != "error":
            continue
        _assert_effectivity(r, tol.EFFECTIVITY_OUTSIDE.get((case, *key, r["profile"], r["quantity"])))
        if r["profile"] != "energy":
            assert r["warned"] or tol.EFFECTIVITY[0] <= r["effectivity"] <= tol.EFFECTIVITY[1], r


@pytest.mark.slow
def test_the_effectivity_table_of_scene_a():
    """Scene A against fe P2 at h = 0.00625 (verification.effectivity,
    ``python -m verification effectivity --scene A``): every method and
    profile quantity in tol.EFFECTIVITY but for the measured exceptions of
    tol.SCENE_A_EFFECTIVITY_OUTSIDE, each where it was measured, and each
    of those named by the estimate's own warning that it is not
    asymptotic (est.unsettled), but for those listed in
    tol.SCENE_A_SILENT, which it does not name."""
    from contactcore import load_scene
    from verification.effectivity import SCENE_VARIANTS, scene_truth, scene_rows
    scene = load_scene("A")
    truth = scene_truth(scene, SCENE_REF_H)
    for key in SCENE_VARIANTS:
        for r in scene_rows(scene, key, SCENE_H, truth):
            entry = (*key, r["profile"], r["quantity"])
            _assert_effectivity(r, tol.SCENE_A_EFFECTIVITY_OUTSIDE.get(entry))
            if entry in tol.SCENE_A_SILENT:
                assert not r["warned"], (r, "now warned of: unlist it from SCENE_A_SILENT")
                continue
            assert r["warned"] or tol.EFFECTIVITY[0] <= r["effectivity"] <= tol.EFFECTIVITY[1], r


def test_run_estimate_writes_the_errors(tmp_path, caplog):
    """``run --estimate``: every profile CSV has ``q_err`` beside each
    ``q``, summary.json an ``estimate`` per profile and quantity and the
    energy, summary.md the estimated error and the agreement table; the
    answer is the run at h/2; the estimate's warnings are logged as the
    solver's are (newuser33 #4: none reached the terminal)."""
    out = tmp_path / "run"
    logger = logging.getLogger("verification")  # a CLI test before may have stopped it propagating to caplog's root
    logger.addHandler(caplog.handler)
    try:
        with caplog.at_level("WARNING", logger="verification"):
            text = run("A", ["xfem", "efgm"], out, h=0.2, estimate=2, draw=False)
    finally:
        logger.removeHandler(caplog.handler)
    logged = [r.getMessage() for r in caplog.records]
    assert "estimated error" in text and "Agreement within the estimated errors" in text
    assert "The reference is solved at the same h" not in text  # the estimates say whose error it is
    assert "Estimated from runs at h = 0.2, 0.1: every figure here is the run at 0.1." in text
    for name in ("xfem", "efgm"):
        summary = json.loads((out / name / "summary.json").read_text())
        assert summary["discretisation"]["h"] == pytest.approx(0.1)
        estimate = summary["estimate"]
        assert estimate["h"] == pytest.approx([0.2, 0.1]) and estimate["energy"]["eta"] > 0
        assert estimate["warnings"] and all(f"{run_label(name, 1)}: {w}" in logged for w in estimate["warnings"])
        from contactcore.scene import RESERVED_PROFILE_IDS  # no profile id may take a key beside the profiles
        assert set(estimate) - {p.id for p in load_scene("A").profiles} == set(RESERVED_PROFILE_IDS)
        columns = files.read_profile_csv(out / name / "profiles" / "A1.csv")
        names = list(columns)
        for q in names[3:]:
            if not q.endswith("_err"):
                assert names[names.index(q) + 1] == f"{q}_err"
                record = estimate["A1"][q]
                assert record["max"] == pytest.approx(max(columns[f"{q}_err"]))
                orders = est.order_range(q, 1, _facts(name, 1), load_scene("A").law, pollution=est.pollution_order(load_scene("A")))
                assert record["orders"] == pytest.approx(list(orders))
                assert record["order"] == pytest.approx(est.balanced_order(*orders))
                # summary.md's figure: over the samples at least 0.1 L from Γ's ends (A1 lies on Γ) and
                # beyond the coarse run's reach of them (est.beyond_reach): two patches of 0.6 or supports of
                # 0.4 at h = 0.2, capped at half the farthest sample's 0.5
                x, err = np.asarray(columns["x"]), np.asarray(columns[f"{q}_err"])
                keep = np.minimum(x, 1.0 - x) >= core_tol.EXCLUDE_KEEP_SHARE * 0.5
                assert record["kept_rms"] == pytest.approx(np.sqrt(np.mean(err[keep] ** 2)), rel=tol.SAME_SUMS)
        for q, record in estimate["A5"].items():  # Γ's gaps and tractions: the orders the scene allows them
            orders = est.order_range(q, 1, _facts(name, 1), load_scene("A").law, pollution=est.pollution_order(load_scene("A")))
            assert record["orders"] == pytest.approx(list(orders)) and record["order"] >= orders[0]
    assert json.loads((out / "run.json").read_text())["estimate"] == 2
    units = json.loads(files.write_units(out).read_text())
    assert units["xfem/profiles/A1.csv"]["sxy_err"] == units["xfem/profiles/A1.csv"]["sxy"] == "Pa"
    alone = tmp_path / "reference_alone"
    run("A", ["fe"], alone, h=0.1, degree=2, draw=False)
    ref = json.loads((alone / "fe" / "summary.json").read_text())
    dofs, h_ref = ref["dofs"], ref["discretisation"]["h"]
    assert f"| reference: fe P2 | 2 | {h_ref:.6g} | {dofs} |" in text  # the reference is solved at the answer's h/2
    reference_row = next(line for line in text.splitlines() if line.startswith("| reference: fe P2 |"))
    assert reference_row.count(f"—{NOT_ESTIMATED_MARK}") == 2 and NOT_ESTIMATED in text  # why it has no estimate


def test_run_and_efficiency_name_the_same_worst_estimate_on_scene_b(tmp_path):
    """summary.json's and summary.md's estimated error is the efficiency's:
    the same two runs of scene B (h, h/2, the coarse run estimated as
    ``efficiency`` does) give the same worst quantity and value, B6's t_N
    and g_N (zero: the rod neither opens nor presses) measured against
    |t| and |g| with B5's t_T and g_T, as those are, not against their own
    residue; and ``run --estimate`` writes its own worst into summary.md."""
    from contactcore import load_scene
    from verification import methods
    from verification.agreement import default_exclusion, sampled
    from verification.efficiency import _estimated
    from verification.run_files import estimate_record
    from verification.run_summary import _estimate_cells
    scene, h = load_scene("B"), 0.2
    exclude, solve = default_exclusion(scene), methods.solver("fe")
    coarse, fine = (solve(scene, hk, degree=1, estimate_condition=False) for hk in (h, h / 2))
    row = _estimated(scene, solve, coarse, h, 1, exclude)
    estimate = est.estimate_runs(scene, [coarse, fine], exclude, energy=False, coarse=True)
    record = estimate_record(scene, estimate, list(sampled(scene, coarse).values()))
    assert record["worst"] == {"relative": row["estimate"], "at": row["estimate_worst"]}
    # grader8's fault 8: est.summary() is summary.json's record less the
    # agreement's scales and worst (the same kept_rms, not a second copy)
    api = estimate.summary()
    for pid, qs in estimate.profiles.items():
        for q in qs:
            assert api[pid][q].items() <= record[pid][q].items(), (pid, q)
            assert set(record[pid][q]) - set(api[pid][q]) == {"scale", "kept_scale"}
    assert set(record) - set(api) == {"worst"}
    for (pid, q), (cpid, cq) in {("B6", "tN"): ("B5", "tT"), ("B6", "gN"): ("B5", "gT")}.items():
        assert record[pid][q]["kept_scale"] == record[cpid][cq]["kept_scale"] > 0
    out = tmp_path / "run"
    text = run(scene, ["fe"], out, h=h, estimate=2, draw=False)
    summary = json.loads((out / "fe" / "summary.json").read_text())["estimate"]
    ratios = {f"{pid}:{q}": e["kept_rms"] / e["kept_scale"] for pid, qs in summary.items()
              if pid.startswith("B") for q, e in qs.items()}
    worst = max(ratios, key=ratios.get)
    assert summary["worst"] == {"relative": ratios[worst], "at": worst} and not worst.startswith("B6")
    assert _estimate_cells({"estimate": summary}) in text


def test_a_users_profile_named_b6_is_measured_by_kind_not_by_name(tmp_path):
    """A scene of the user's whose Γ profile is named B6 is no scene B: its
    t_N and g_N are not labelled zero, and are measured against |t| and |g|
    of its own profile (as every Γ component is), in the agreement and the
    estimate alike, not against B5's (it has none) or their own values."""
    from contactcore import load_scene, scene_text
    from verification import methods
    from verification.agreement import agreements, default_exclusion, estimated_shares, measured_against
    from verification.agreement import sampled
    path = tmp_path / "wedge-b6.toml"
    path.write_text(scene_text("examples/wedge.toml").replace('id = "gamma"', 'id = "B6"'))
    scene = load_scene(path)
    exclude, solve = default_exclusion(scene), methods.solver("fe")
    runs = [solve(scene, h) for h in (0.2, 0.1)]
    profiles = sampled(scene, runs[-1])
    assert not any(kind == "zero" for *_, kind, _ in agreements(scene, profiles, profiles, exclude))
    estimate = est.estimate_runs(scene, runs, exclude)
    shares = estimated_shares(scene, profiles, estimate)
    for q, other in (("tN", "tT"), ("gN", "gT")):
        keep = estimate.kept["B6"][q]  # the samples the estimate keeps (est.beyond_reach)
        size = np.hypot(profiles["B6"].columns[q], profiles["B6"].columns[other])
        own = est.rms(measured_against(scene, q, size[keep]))
        assert own > 0 and shares["B6", q][1] == pytest.approx(own, rel=tol.FLOORED_SCALE)


def test_run_estimate_starts_from_the_scenes_own_h(tmp_path):
    """No --h: the estimate runs at the scene's h and h/2."""
    from contactcore import load_scene
    run(load_scene("A").with_changes(h=0.2), ["efgm"], tmp_path / "r", estimate=2, draw=False)
    summary = json.loads((tmp_path / "r" / "efgm" / "summary.json").read_text())
    assert summary["estimate"]["h"] == pytest.approx([0.2, 0.1])
    from contactcore import ContactError
    with pytest.raises(ContactError, match="no default h"):
        run(load_scene("A").with_changes(h=None), ["efgm"], tmp_path / "none", estimate=2, draw=False)


def test_run_estimate_refuses_the_paper_grids(tmp_path):
    from contactcore import ContactError
    with pytest.raises(ContactError, match="--estimate"):
        run("A", ["efgm"], tmp_path / "r", paper=True, estimate=2, draw=False)


def test_efficiency_without_a_reference_estimates_and_says_so(tmp_path):
    """No --ref-h: the error column is the estimate, with its error bar,
    and the text says that it is estimated."""
    from verification.efficiency import efficiency
    text = efficiency("A", [("efgm", 1)], {1: (0.2,)}, None, 0.1, tmp_path / "eff", workers=1)
    assert "ESTIMATED" in text and "estimated error" in text
    import csv
    with open(tmp_path / "eff" / "efficiency.csv", newline="") as fh:
        (row,) = list(csv.DictReader(fh))
    low, error, high = (float(row[k]) for k in ("error_low", "error", "error_high"))
    assert 0 < error and high / error == pytest.approx(error / low) == pytest.approx(core_tol.ESTIMATE_TRUST)
    # at h = 0.2 on A the estimate is not asymptotic: its warnings are counted and listed, as run --estimate gives them
    assert int(row["warned"]) > 0 and "Warnings of the estimates" in text
    assert text.count("- efgm P1 h = 0.2: ") == int(row["warned"])


def test_an_exact_law_caps_the_orders_on_gamma():
    """Under an exact law that switches (unilateral, Coulomb) Γ's gaps are
    estimated at order min(k + 1, 2) and its tractions at 1, in every
    degree (the solution's regularity where Γ's status changes); under
    ``bonded`` the traction is a stress (order k) and the gaps keep k + 1;
    a penalty law's traction follows its gaps (k + 1); the bulk is
    unchanged.  On exact C-coulomb (h = 0.05 -> 0.025 against fe P2 at
    0.00833, docs/error-estimates.md) the capped orders give C4
    effectivities 0.70-2.68 where k + 1 gave 0.14-0.89."""
    from contactcore import load_scene, make_law
    coulomb = make_law({"type": "coulomb", "mu": 0.2, "enforcement": "exact"})
    bonded = make_law({"type": "bonded"})
    penalty = load_scene("C-coulomb").law
    for k in (1, 2):
        assert [est.theoretical_order(q, k, _facts("fe", k), coulomb) for q in ("gN", "gT", "tN", "tT")] == [min(k + 1, 2)] * 2 + [1] * 2
        assert [est.theoretical_order(q, k, _facts("fe", k), bonded) for q in ("gN", "tN")] == [k + 1, k]
        assert [est.theoretical_order(q, k, _facts("fe", k), penalty) for q in ("gN", "tN")] == [k + 1, k + 1]
        assert est.theoretical_order("sxx", k, _facts("fe", k), coulomb) == est.theoretical_order("sxx", k, _facts("fe", k)) == k
        assert est.theoretical_order("ux", k, _facts("efgm", k), coulomb) == k + 1


def test_a_status_that_never_changes_along_gamma_lifts_the_cap():
    """Where Γ's status never changes along it, in any increment of any run
    (scene A under the exact unilateral law: closed and tied everywhere),
    no point limits the solution's smoothness, and the gaps are estimated
    at k + 1 as under ``bonded``.  Measured on A5 (h = 0.05 -> 0.025
    against fe P2 at h = 0.00625, 2026-11-26): the degree-2 gaps'
    effectivities were 2.4-3.8 with the cap (order 2) and are 1.0-1.6
    at order 3 (fe, xfem, efgm P2); degree 1 keeps order 2 either way."""
    from contactcore import load_scene, make_law
    from contactcore.interface_path import Increment, InterfacePath
    from verification import methods

    def path(*statuses, shear=1.0):
        steps = [Increment(1.0, (1.0,), 1, [0.0], np.zeros((len(s), 2)),
                           np.column_stack([-np.ones(len(s)), shear * np.ones(len(s))]), np.array(s, np.int8))
                 for s in statuses]
        m = len(statuses[0])
        return InterfacePath(np.zeros((m, 2)), np.ones(m), steps)
    assert not est.switches([path([1, 1, 1], [1, 1, 1]), path([1, 1])])
    assert est.switches([path([1, 1, 1], [1, 2, 1])])  # slipped once, then stuck: the slip kinks
    assert est.switches([path([1, 1]), path([0, 0])])  # open at h/2, closed at h
    assert not est.switches([path([2, 2]), path([2, 2, 2])])  # one slip direction
    assert est.switches([path([2, 2]), path([2, 2], shear=-1.0)])  # t_T jumps from +μp to −μp
    unilateral = make_law({"type": "unilateral", "enforcement": "exact"})
    assert [est.theoretical_order(q, 2, _facts("fe", 2), unilateral, switching=False) for q in ("gN", "tN")] == [3, 2]
    assert [est.theoretical_order(q, 2, _facts("fe", 2), unilateral, switching=True) for q in ("gN", "tN")] == [2, 1]

    scene = load_scene("A").with_changes(law=unilateral)
    runs = [methods.solver("fe")(scene, h, degree=2) for h in (0.1, 0.05)]
    estimate = est.estimate_runs(scene, runs, energy=False)
    assert not est.switches([r.interface for r in runs])
    polluted = est.pollution_order(scene)  # A's clamped-free corners (its exact Γ's ends are not taken)
    assert {q: estimate.profiles["A5"][q].theory for q in ("gN", "gT")} == {"gN": (polluted, 3), "gT": (polluted, 3)}
    assert estimate.profiles["A5"]["gN"].order == pytest.approx(est.balanced_order(polluted, 3))


def test_effectivity_takes_a_scene_file_and_refuses_an_unknown_scene(tmp_path, capsys, monkeypatch):
    """`effectivity --scene` takes built-in names or TOML files (docs/
    error-estimates.md: scene A under the exact unilateral law), read
    before any solve; a name that is neither is refused in one line, with
    no result folder.  (The solves are stubbed: the table's rows are
    tested above.)"""
    from contactcore import load_scene
    from contactcore.scene_files import scene_text
    from verification import effectivity as eff
    from verification.__main__ import main
    solved = []
    monkeypatch.setattr(eff, "scene_truth", lambda scene, ref_h: solved.append(scene.name) or {})
    monkeypatch.setattr(eff, "scene_rows", lambda scene, key, h, truth, levels: [])
    toml = tmp_path / "A-copy.toml"
    toml.write_text(scene_text("A").replace('name = "A"', 'name = "A-copy"'))
    assert load_scene(toml).name == "A-copy"
    assert main(["effectivity", "--scene", str(toml), "--out", str(tmp_path / "good"), "-q"]) == 0
    assert solved == ["A-copy"] and (tmp_path / "good" / "effectivity.md").exists()
    out = tmp_path / "bad"
    assert main(["effectivity", "--scene", "A", "nosuch", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "'nosuch' is neither a built-in scene" in err and len(err.strip().splitlines()) == 1
    assert solved == ["A-copy"] and not out.exists()  # A was not solved before nosuch was refused


def test_two_run_estimates_at_order_three_warn_of_corner_pollution():
    """Degree-2 displacements and gaps estimated from two runs at order 3
    on a rectangle whose corners the pollution order does not take
    (scene B: every edge clamped) are named in a warning; a disc with a
    circular Γ (no singular point), a lower order or an observed one is
    not.  On A the rule takes the corners: its degree-2 gaps are not
    estimated at 3 at all."""
    from verification.closed_forms import pressurised_rod

    def quantity(order, measured=None):
        return est.QuantityEstimate(np.zeros(3), float(order), (order, order), measured=measured)

    profiles = {"A5": {"gN": quantity(3), "gT": quantity(3)}, "A1": {"sxy": quantity(2)}}
    (warning,) = est.pollution_warning(load_scene("B"), profiles)
    assert warning.startswith("A5:gN, A5:gT: estimated at order 3") and "--estimate 3" in warning
    assert est.order_range("gN", 2, _facts("fe", 2), pollution=est.pollution_order(load_scene("A")))[0] < 2
    assert est.order_range("gN", 2, _facts("fe", 2), pollution=est.pollution_order(load_scene("B"))) == (3, 3)
    assert est.pollution_warning(pressurised_rod().scene, profiles) == []
    assert est.pollution_warning(load_scene("A"), {"A5": {"gN": quantity(2), "gT": quantity(3, measured=3.0)}}) == []


def test_a_changed_status_names_the_runs_it_compares():
    """With three runs the status is compared between the two finest: the
    warning names their h, not "h and h/2"."""
    change = {"coarse": {"open": 0.5, "stick": 0.5}, "fine": {"open": 0.4, "stick": 0.6}, "differ": 3,
              "samples": 101, "h": [0.05, 0.025]}
    (warning,) = est.status_warning(change)
    assert warning.startswith("the status along Γ differs from h = 0.05 m to 0.025 m at 3 of 101 samples")
    assert "(open 50→40%, stick 50→60%)" in warning  # the shares that moved
    assert est.status_warning({**change, "differ": 0}) == []


def _kolosov_determinant(lam: float, alpha: float, kappa: float) -> float:
    """The 4×4 determinant of a clamped (θ = 0) – free (θ = α) wedge in
    Kolosov–Muskhelishvili potentials ``φ = A z^λ``, ``ψ = B z^λ`` (real
    λ): clamped ``κφ − z conj(φ') − conj(ψ) = 0``, free ``φ + z conj(φ')
    + conj(ψ) = 0`` (Muskhelishvili 1953, §§ 32-41), in the real and
    imaginary parts of A and B.  Independent of the eigen-equation the
    estimate solves."""
    rows = []
    for theta, k, s in ((0.0, kappa, -1.0), (alpha, 1.0, 1.0)):
        e1, e2, e3 = np.exp(1j * lam * theta), np.exp(1j * (2 - lam) * theta), np.exp(-1j * lam * theta)
        cols = [k * e1 + s * lam * e2, 1j * k * e1 - 1j * s * lam * e2, s * e3, -1j * s * e3]
        rows += [[c.real for c in cols], [c.imag for c in cols]]
    return float(np.linalg.det(np.array(rows)))


@pytest.mark.parametrize("alpha, nu, plane", [(np.pi / 2, 0.3, "strain"), (np.pi / 2, 0.3, "stress"),
                                              (np.pi / 2, 0.45, "strain"), (0.75 * np.pi, 0.3, "strain")])
def test_the_clamped_free_exponent_is_a_root_of_the_wedge_determinant(alpha, nu, plane):
    """Williams' clamped-free exponent: the wedge's determinant changes
    sign across it, none lower does (0.711 for a right angle in plane
    strain at ν = 0.3, Williams 1952), and the half-plane's is ½."""
    kappa = est.kolosov(nu, plane)
    lam = est.clamped_free_exponent(alpha, kappa)
    step = 1e-6
    assert _kolosov_determinant(lam - step, alpha, kappa) * _kolosov_determinant(lam + step, alpha, kappa) < 0
    below = [_kolosov_determinant(x, alpha, kappa) for x in np.linspace(0.05, lam - step, 400)]
    assert np.all(np.sign(below) == np.sign(below[0]))
    if (alpha, nu, plane) == (np.pi / 2, 0.3, "strain"):
        assert lam == pytest.approx(0.7112, abs=tol.QUOTED_EXPONENT)
    assert est.clamped_free_exponent(np.pi, kappa) == pytest.approx(0.5)


def test_the_pollution_order_comes_from_the_scenes_singular_points():
    """2λ_min: A's clamped-free corners (0.758 in plane stress) and its
    penalty Γ's ends on free sides (λ = 1); C's corners alone; none on B
    (every edge clamped), on a disc, at a corner with a roller, or at the
    end of an exactly enforced Γ; an end on a clamped edge is a
    clamped-free wedge of Γ's angle."""
    from contactcore import Support, make_law
    from verification.closed_forms import pressurised_rod
    a = load_scene("A")
    right = est.clamped_free_exponent(np.pi / 2, est.kolosov(0.3, "stress"))
    assert est.corner_exponents(a) == pytest.approx([right, right]) and est.interface_end_exponents(a) == [1.0, 1.0]
    assert est.pollution_order(a) == pytest.approx(2 * right) == est.pollution_order(load_scene("C"))
    assert est.pollution_order(load_scene("B")) == np.inf == est.pollution_order(pressurised_rod().scene)
    roller = a.with_changes(supports=(Support("bottom"), Support("left", fix="x")))
    assert len(est.corner_exponents(roller)) == 1  # (1, 0): clamped meets free; (0, 0): clamped meets a roller
    assert est.interface_end_exponents(a.with_changes(law=make_law({"type": "bonded", "enforcement": "exact"}))) == []
    side = est.interface_end_exponents(a.with_changes(supports=(Support("left"),)))
    assert side == pytest.approx([right, 1.0])  # (0, 0.5) on the clamped left side, (1, 0.5) on the free right
    assert est.order_range("ux", 1, _facts("fe", 1), pollution=2 * right) == (2 * right, 2)
    assert est.order_range("tN", 2, _facts("fe", 2), pollution=2 * right) == (2 * right, 3)
    assert est.order_range("tN", 2, _facts("fe", 2), make_law({"type": "bonded", "enforcement": "exact"}), pollution=1.5) == (2, 2)
    assert est.order_range("sxx", 2, _facts("fe", 2), pollution=1.5) == (2, 2)
    assert est.order_range("sxx", 1, _facts("xfem", 1), pollution=1.5) == (2, 3)


def test_an_edge_held_by_two_supports_is_clamped():
    """A bottom held in x by one support and in y by another is clamped:
    its corners with the free sides are clamped–free, as for fix = "xy"."""
    from contactcore import Support
    a = load_scene("A")
    split = a.with_changes(supports=(Support("bottom", fix="x"), Support("bottom", fix="y")))
    assert est.corner_exponents(split) == est.corner_exponents(a) != []
    assert est.pollution_order(split) == est.pollution_order(a)


def test_a_corner_on_gamma_takes_both_bodies_whatever_the_sign_of_round_off():
    """Γ through the clamped–free corner (0, 0) of A, given through points
    whose φ at the corner is +round-off, −round-off or 0: the corner takes
    the least exponent of both bodies (here the softer ν = 0.45 one's)."""
    from contactcore.geometry import LineInterface
    from contactcore.scene import Material
    a = load_scene("A")
    a = a.with_changes(profiles=tuple(p for p in a.profiles if p.id != "A5"),
                       materials={"minus": Material(2e11, 0.3), "plus": Material(2e11, 0.45)})
    soft = est.clamped_free_exponent(np.pi / 2, est.kolosov(0.45, "stress"))
    signs = set()
    for angle in (0.37, 0.74, 1.11):  # φ(0, 0) = -1.4e-17, +2.8e-17, 0 for these lines through the corner
        n, t = (-np.sin(angle), np.cos(angle)), (np.cos(angle), np.sin(angle))
        scene = a.with_changes(interface=LineInterface((0.3 * t[0], 0.3 * t[1]), n))
        signs.add(float(np.sign(scene.interface.phi([(0.0, 0.0)])[0])))
        assert min(est.corner_exponents(scene)) == pytest.approx(soft), angle
    assert signs == {-1.0, 0.0, 1.0}


def test_an_end_of_gamma_at_a_corner_splits_the_right_angle():
    """Γ through A's corner (0, 0) at β = 0.3 rad to the bottom: its end
    there makes wedges of β with the bottom and π/2 − β with the left
    side (no wedge of π − β exists at a corner); the clamped edge's
    wedge is clamped–free, a free edge's takes λ = 1.  The other end, on
    the free right side, λ = 1."""
    from contactcore import Support
    from contactcore.geometry import LineInterface
    a = load_scene("A")
    beta = 0.3
    a = a.with_changes(profiles=tuple(p for p in a.profiles if p.id != "A5"),
                       interface=LineInterface((0.5, 0.5 * np.tan(beta)), (-np.sin(beta), np.cos(beta))))
    wedge = lambda angle: est.clamped_free_exponent(angle, est.kolosov(0.3, "stress"))  # noqa: E731
    for supports, at_corner in (((Support("bottom"), Support("left")), min(wedge(beta), wedge(np.pi / 2 - beta))),
                                ((Support("left"),), min(wedge(np.pi / 2 - beta), 1.0)),
                                ((Support("bottom"),), min(wedge(beta), 1.0))):
        ends = est.interface_end_exponents(a.with_changes(supports=supports))
        assert sorted(ends) == pytest.approx(sorted([at_corner, 1.0])), supports
    assert wedge(np.pi / 2 - beta) < 1.0 < wedge(beta) and wedge(np.pi - beta) < wedge(np.pi / 2 - beta)


def test_a_polynomial_root_of_the_wedge_is_not_its_exponent():
    """At ν = 0 (κ = 3) λ = 1 solves a right angle's eigen-equation, but
    its field u = (0, c y) is linear, smooth: the exponent is the next
    root, where the wedge's determinant changes sign (1.352; below it the
    determinant changes sign at λ = 1 alone)."""
    kappa, step = est.kolosov(0.0, "strain"), 1e-6
    lam = est.clamped_free_exponent(np.pi / 2, kappa)
    assert _kolosov_determinant(lam - step, np.pi / 2, kappa) * _kolosov_determinant(lam + step, np.pi / 2, kappa) < 0
    xs = np.linspace(0.05, lam - step, 401)
    signs = np.sign([_kolosov_determinant(x, np.pi / 2, kappa) for x in xs])
    changes = xs[:-1][signs[:-1] != signs[1:]]
    assert len(changes) == 1 and changes[0] < 1.0 < changes[0] + (xs[1] - xs[0])
    assert est.clamped_free_exponent(np.pi / 2, kappa) == est.clamped_free_exponent(np.pi / 2, est.kolosov(0.0, "stress"))


def test_efgm_p2s_supports_carry_no_defect_of_their_own():
    """EFGM P2 takes fe P2's orders (no rule of its own since its supports
    are held by boundary multipliers, efgm.method): once it collocated
    them at the nodes of a basis that does not interpolate, and its trace
    missed a roller's value by O(h) at the regular ends, a defect that
    slowed its bulk displacements to order 2 (2λ beside a clamped–free
    corner).  Now, on scene A with its bottom and left side on rollers
    (corners regular), EFGM P2's largest miss of each support at h = 0.05
    is within tol.EFGM_P2_SUPPORT_MISS_OVER_P1 of EFGM P1's (measured 0.20,
    2.1; collocation 111 on the bottom), and the estimate's orders of
    EFGM P2 on A and B are fe P2's."""
    from contactcore import Support
    from contactcore.discretisation import solve
    from efgm.options import EFGM
    a = load_scene("A")
    rollers = a.with_changes(supports=(Support("bottom", "y"), Support("left", "x")), pins=())
    t = np.linspace(0.0, 1.0, 1001)
    edges = {"bottom": (np.column_stack([t, np.zeros_like(t)]), 1), "left": (np.column_stack([np.zeros_like(t), t]), 0)}
    miss = {}
    for degree in (1, 2):
        fields = solve(rollers, EFGM(degree=degree), 0.05).fields
        for edge, (pts, comp) in edges.items():
            bodies = (rollers.interface.signed_distance(pts) > 0).astype(int)
            miss[degree, edge] = np.max(np.abs(fields.displacement(pts, bodies)[:, comp]))
    for edge in edges:
        assert 0 < miss[2, edge] <= tol.EFGM_P2_SUPPORT_MISS_OVER_P1 * miss[1, edge], (edge, miss)
    assert not hasattr(est, "COLLOCATED")
    for scene in (a, load_scene("B")):
        pollution = est.pollution_order(scene)
        for q in ("ux", "uy", "sxx", "syy", "sxy", "gN", "gT", "tN", "tT"):
            assert est.order_range(q, 2, _facts("efgm", 2), scene.law, pollution=pollution) == \
                est.order_range(q, 2, _facts("fe", 2), scene.law, pollution=pollution), (scene.name, q)
    assert est.order_range("ux", 2, _facts("efgm", 2), a.law, pollution=est.pollution_order(a)) == (est.pollution_order(a), 3)


def test_a_runs_stencil_is_its_cells_supports_or_recovery_patch():
    """est.stencil_radius: EFGM's support dmax·h (to a rectangular
    support's corner √2 times that), xfem P1's recovered stress its patch
    of RECOVERY_RINGS vertex rings around the cell, every other quantity
    one cell."""
    efgm = {"h": 0.05, "dmax": 2.0, "support": "circular"}
    assert est.stencil_radius(efgm, _facts("efgm", 1), "sxx") == pytest.approx(0.1)
    assert est.stencil_radius({**efgm, "support": "rectangular"}, _facts("efgm", 1), "gN") == pytest.approx(0.1 * np.sqrt(2))
    assert est.stencil_radius({"h": 0.05}, _facts("xfem", 1), "sxy") == pytest.approx((core_tol.RECOVERY_RINGS + 1) * 0.05)
    assert est.stencil_radius({"h": 0.05}, _facts("xfem", 1), "gN") == pytest.approx(0.05)
    assert est.stencil_radius({"h": 0.05}, _facts("fe", 2), "sxy") == pytest.approx(0.05)


def test_the_smallest_feature_is_the_domains_or_a_circular_gammas():
    """est.feature_size: A's unit square; B's circle of radius 0.25 in a
    2 × 2 square; C's circle of radius 0.45 in a 2 × 3 rectangle."""
    assert est.feature_size(load_scene("A")) == pytest.approx(1.0)
    assert est.feature_size(load_scene("B")) == pytest.approx(0.5)
    assert est.feature_size(load_scene("C")) == pytest.approx(0.9)


def _line_along_gamma(start: float) -> list:
    """Scene A's Γ (y = 0.5) sampled from x = ``start`` to 1 − ``start``:
    its nearest singular points are Γ's ends, ``start`` away."""
    from contactcore import ProfileData
    x = np.linspace(start, 1.0 - start, 21)
    return [ProfileData("L", "arclength", {"s": x - start, "x": x, "y": np.full_like(x, 0.5), "sxx": np.zeros_like(x)})]


@pytest.mark.parametrize("method, h, dmax, causes", [
    ("fe", 0.05, None, set()),                  # reach 0.1 < 0.15; 1/8 of 1 > 0.05
    ("fe", 0.1, None, {"reach"}),               # reach 0.2 > 0.15
    ("efgm", 0.05, 2.0, {"reach"}),             # supports 0.1: reach 0.2 > 0.15, 0.1 < 1/8
    ("efgm", 0.1, 2.0, {"reach", "coarse"}),    # supports 0.2 > 1/8 of A
    ("efgm", 0.025, 2.0, set()),                # reach 0.1 < 0.15
    ("efgm", 0.1, 3.0, {"reach", "coarse", "thin"}),  # supports 0.3: 2 of them exceed A's bodies, 0.5 thick
])
def test_a_coarse_run_whose_stencil_reaches_a_singular_point_or_spans_a_feature_is_not_asymptotic(
        method, h, dmax, causes):
    """est.unsettled: a sample kept 0.15 from Γ's ends on scene A is
    within the coarse run's reach (REACH_STENCILS stencils) or not, and
    the stencil exceeds 1/FEATURE_STENCILS of A's unit side or not; the
    warning names the quantity."""
    scene = load_scene("A")
    record = {"h": h} if dmax is None else {"h": h, "dmax": dmax, "support": "circular"}
    found = est.unsettled(scene, [_line_along_gamma(0.15)], record, _facts(method, 1), exclude=0.1)
    assert {cause for cause, names in found.items() if names} == causes
    lines = est.unsettled_warnings(found, h, est.feature_size(scene), thin=est.thinnest_body(scene))
    assert len(lines) == len(causes) and all(line.startswith("L:sxx: ") for line in lines)
    assert ("over the thinner body across Γ (0.5 m)" in " ".join(lines)) == ("thin" in causes)
    for cause in causes:  # the h from which the cause is gone: just below it, it is
        (_, h_ok), = found[cause].values()
        below = est.unsettled(scene, [_line_along_gamma(0.15)], {**record, "h": h_ok * (1 - tol.ACROSS_A_THRESHOLD)}, _facts(method, 1),
                              exclude=0.1)
        assert not below[cause] and f"start below h = {h_ok:.3g} m" in " ".join(lines)


def _layer(tmp_path, y: float):
    """Scene A with Γ at height ``y``: its upper body a layer 1 − y thick."""
    from contactcore.scene_files import scene_text
    toml = tmp_path / "layer.toml"
    toml.write_text(scene_text("A").replace("0.5]", f"{y!r}]"))  # Γ and the profiles along it
    return load_scene(toml)


@pytest.mark.parametrize("method, h, dmax, thin", [
    ("fe", 0.1, None, True),          # 2 cells of 0.1 exceed the layer's 0.15 (grader25b's xfem P1 u_y, 0.127)
    ("fe", 0.05, None, False),        # 2 cells of 0.05 do not
    ("efgm", 0.05, 2.0, True),        # 2 supports of 0.1 do
])
def test_a_body_thinner_than_two_stencils_across_gamma_is_not_asymptotic(tmp_path, method, h, dmax, thin):
    """est.unsettled's ``thin`` cause: a layer 0.15 thick (Γ at y = 0.85
    on A's unit square; est.thinnest_body) spans fewer than
    THIN_BODY_STENCILS of the coarse run's stencils or not; below the h
    the warning gives, it is gone.  A curved Γ (B, C) has no such body."""
    scene = _layer(tmp_path, 0.85)
    assert est.thinnest_body(scene) == pytest.approx(0.15)
    assert est.thinnest_body(load_scene("B")) == est.thinnest_body(load_scene("C")) == np.inf
    record = {"h": h} if dmax is None else {"h": h, "dmax": dmax, "support": "circular"}
    found = est.unsettled(scene, [_line_along_gamma(0.45)], record, _facts(method, 1), exclude=0.1)
    assert bool(found["thin"]) == thin
    if thin:
        (_, h_ok), = found["thin"].values()
        assert h_ok == pytest.approx(h * 0.15 / (core_tol.THIN_BODY_STENCILS * (h if dmax is None else dmax * h)))
        below = est.unsettled(scene, [_line_along_gamma(0.45)], {**record, "h": h_ok * (1 - tol.ACROSS_A_THRESHOLD)},
                              _facts(method, 1), exclude=0.1)
        assert not below["thin"]


def test_a_stencil_exactly_at_a_threshold_is_no_cause_whatever_the_round_off():
    """est.unsettled: supports of 2.5 × 0.05 on scene A (feature 1) are
    1/FEATURE_STENCILS of it but for round-off, and a sample 0.25 from Γ's
    ends is at their reach: neither fires, nor does either a relative
    GEOMETRY/10 to the other side."""
    scene = load_scene("A")
    for nudge in (1 - core_tol.GEOMETRY / 10, 1.0, 1 + core_tol.GEOMETRY / 10):
        record = {"h": 0.05 * nudge, "dmax": 2.5, "support": "circular"}
        found = est.unsettled(scene, [_line_along_gamma(0.25)], record, _facts("efgm", 1), exclude=0.1)
        assert not found["coarse"] and not found["reach"], nudge


@pytest.mark.parametrize("method, degree, record, reach", [
    ("fe", 1, {"h": 0.05}, 0.0),                                          # 2 cells, 0.1: inside the scene's 0.141
    ("efgm", 1, {"h": 0.05, "dmax": 2.0, "support": "circular"}, 0.2),    # 2 supports of 0.1
    ("efgm", 2, {"h": 0.05, "dmax": 3.0, "support": "circular"}, 0.25),   # 2 of 0.15, capped at half of 0.5
    ("xfem", 1, {"h": 0.05}, 0.25),                                       # 2 recovery patches of 0.15, capped
])
def test_the_estimate_keeps_no_sample_within_the_coarse_runs_reach_of_a_singular_point(method, degree, record, reach):
    """est.beyond_reach: along A's Γ, whose ends are singular points, the
    samples an estimate is summarised over lie at least the scene's
    exclusion and REACH_STENCILS of the coarse run's stencils from the
    ends, the latter at most EXCLUDE_KEEP_SHARE of the farthest sample's
    0.5; an exclusion of 0 keeps every sample."""
    scene = load_scene("A")
    x = np.linspace(0.0, 1.0, 101)
    xy, exclude = np.column_stack([x, np.full_like(x, 0.5)]), 0.1 * np.sqrt(2.0)
    kept = est.beyond_reach(scene, xy, record, _facts(method, degree), "sxx", exclude)
    assert np.array_equal(kept, np.minimum(x, 1.0 - x) >= max(exclude, reach) * (1 - core_tol.GEOMETRY))
    assert est.beyond_reach(scene, xy, record, _facts(method, degree), "sxx", 0.0).all()


def test_an_estimates_kept_rms_leaves_out_each_quantitys_reach():
    """xfem P1 on A at h = 0.1 -> 0.05: the estimate's ``kept_rms`` of a
    recovered stress along Γ leaves out the samples within 0.25 of Γ's
    ends (two patches of 0.3, capped), of the gap within 0.2 (two cells):
    each quantity its own coarse stencil's reach."""
    scene = load_scene("A")
    disc = methods.discretisation("xfem")(degree=1)
    from contactcore.discretisation import solve
    estimate = est.estimate_runs(scene, [solve(scene, disc, h) for h in (0.1, 0.05)], 0.1 * np.sqrt(2.0),
                                 energy=False)
    summary, sampled = estimate.summary(), {p.id: p for p in estimate.sampled}
    for pid, q, reach in (("A2", "syy", 0.25), ("A5", "gN", 0.2)):
        x = sampled[pid].columns["x"]
        keep = np.minimum(x, 1.0 - x) >= reach * (1 - core_tol.GEOMETRY)
        assert np.array_equal(estimate.kept[pid][q], keep)
        assert summary[pid][q]["kept_rms"] == pytest.approx(est.rms(estimate.profiles[pid][q].error[keep]),
                                                            rel=tol.SAME_SUMS)


def test_the_cell_scale_part_of_a_difference_is_what_a_local_line_does_not_follow():
    """contactcore.estimate.cell_scale_part: a line (one per group of
    samples) has none; a wave of the coarse run's cell is taken almost
    whole; samples in no group (−1) have none."""
    s, h = np.linspace(0.0, 1.0, 101), 0.05
    one = np.zeros(len(s), int)
    assert np.max(np.abs(est.cell_scale_part(1.0 + 2.0 * s, s, one, h))) <= tol.CELL_SCALE_LINE
    two = np.where(s < 0.5, 0, 1)
    two[45:55] = -1
    part = est.cell_scale_part(np.where(s < 0.5, 1.0 + s, 5.0 - 3.0 * s) + np.where(two < 0, 1.0, 0.0), s, two, h)
    assert np.max(np.abs(part)) <= tol.CELL_SCALE_LINE
    for phase in (0.0, 0.3, 1.0):
        wave = np.sin(2 * np.pi * s / h + phase)
        assert est.rms(est.cell_scale_part(wave, s, one, h) - wave) <= tol.CELL_SCALE_WAVE_LEFT * est.rms(wave)


def test_a_polluted_range_takes_the_cell_scale_part_at_its_upper_order():
    """Two runs of a displacement-like quantity whose orders pollution
    widened to [1.52, 3]: the part of their difference at the coarse run's
    cells (the runs' local error) is estimated at 3, the smooth rest at
    the balanced order; a difference that is only the cells' wave is
    estimated near its error, and one that is only smooth as before."""
    s, h = np.linspace(0.0, 1.0, 101), 0.05
    groups = np.zeros(len(s), int)
    cells = lambda v: est.cell_scale_part(v, s, groups, h)  # noqa: E731
    theory = (1.52, 3.0)
    wave = [5.0 * hk ** 3 * np.sin(2 * np.pi * s / hk + 0.3) for hk in (h, h / 2)]
    split, whole = est.richardson(wave, theory, cells=cells), est.richardson(wave, theory)
    low, high = tol.CELL_SCALE_RECOVERED
    assert low <= split.rms / est.rms(wave[1]) <= high < whole.rms / est.rms(wave[1])
    assert split.order == whole.order == pytest.approx(est.balanced_order(*theory)) and split.cell_scale > 1 - tol.CELL_SCALE_WAVE_LEFT
    smooth = [(1.0 + 2.0 * s) * hk ** 1.52 for hk in (h, h / 2)]
    assert np.allclose(est.richardson(smooth, theory, cells=cells).error, est.richardson(smooth, theory).error,
                       rtol=tol.CELL_SCALE_LINE, atol=0)
    three = est.richardson([*smooth, (1.0 + 2.0 * s) * (h / 4) ** 1.52], theory, cells=cells)
    assert three.observed and three.cell_scale is None


def test_only_a_mesh_methods_polluted_quantities_are_split():
    """est.polluted: a displacement, gap or penalty traction whose order
    exceeds the scene's pollution order, in fe or xfem; not a stress, not
    EFGM (whose error at its nodes' scale holds its quadrature's, which
    does not converge), not where nothing pollutes, not an exact law's
    traction."""
    from contactcore import make_law
    assert est.polluted("gN", 2, _facts("fe", 2), pollution=1.52) and est.polluted("ux", 1, _facts("xfem", 1), pollution=1.52)
    assert not est.polluted("sxx", 2, _facts("fe", 2), pollution=1.52)
    assert not est.polluted("gN", 2, _facts("efgm", 2), pollution=1.52) and not est.polluted("ux", 2, _facts("efgm", 2), pollution=1.52)
    assert not est.polluted("gN", 2, _facts("fe", 2))
    exact = make_law({"type": "unilateral", "enforcement": "exact"})
    assert not est.polluted("tN", 2, _facts("fe", 2), exact, switching=False, pollution=1.52)


def test_a_line_across_gamma_is_split_there_and_at_left_out_samples():
    """est.sample_groups: runs of kept samples in one body; Γ's own
    samples (all on Γ) one group."""
    scene = load_scene("A")
    xy = np.column_stack([np.full(10, 0.5), np.linspace(0.05, 0.95, 10)])
    kept = np.ones(10, bool)
    kept[1] = False
    labels, below = est.sample_groups(scene, xy, kept), np.arange(10) < 5  # Γ: y = 0.5
    assert labels[1] == -1 and len(set(labels[below]) - {-1}) == 2
    assert set(labels[~below]) == {labels[-1]} and labels[-1] not in labels[below]
    on_gamma = np.column_stack([np.linspace(0.2, 0.8, 7), np.full(7, 0.5)])
    assert set(est.sample_groups(scene, on_gamma, np.ones(7, bool))) == {0}


def _runs_along_gamma(values_of_h, h: float, quantity: str = "sxx") -> list:
    """Scene A's Γ (y = 0.5) from x = 0.15 to 0.85, finely sampled, with
    ``values_of_h(s, h)`` at the coarse run's h and at h/2: one profile
    per run, coarse first."""
    from contactcore import ProfileData
    x = np.linspace(0.15, 0.85, 281)
    return [[ProfileData("L", "arclength", {"s": x - 0.15, "x": x, "y": np.full_like(x, 0.5),
                                            quantity: values_of_h(x - 0.15, hk)})] for hk in (h, h / 2)]


@pytest.mark.parametrize("rate, warns", [
    (1.0, False),   # the cells' error at the lower order theory allows a degree-1 stress
    (2.0, False),   # at the upper one
    (3.0, True),    # a whole order above: the coarse run's error is not asymptotic
])
def test_a_coarse_run_rough_at_its_cells_beyond_theory_is_not_asymptotic(rate, warns):
    """est.cell_scale_orders: a smooth value plus a wave of each run's
    cell (amplitude ∝ h^rate, above the smooth value's own part at that
    scale): the runs' parts at the coarse cells' scale
    shrink at about ``rate``; beyond the orders a degree-1 stress is
    allowed, [1, 2], by more than CELL_SCALE_EXCESS, the quantity is
    named as not asymptotic, in the estimate's warnings too."""
    scene, h = load_scene("A"), 0.05
    stress = Sizes.of(scene).stress  # A's load
    levels = _runs_along_gamma(lambda s, hk: stress * (1.0 + s + 0.1 * s ** 2
                                                       + 100.0 * hk ** rate * np.sin(2 * np.pi * s / hk + 0.3)), h)
    theory = est.order_range("sxx", 1, _facts("fe", 1))
    estimates = {"L": {"sxx": est.QuantityEstimate(np.zeros(281), est.balanced_order(*theory), theory)}}
    found = est.cell_scale_orders(scene, levels, estimates, 0.1, h)
    assert bool(found) == warns, found
    lines = est.cell_scale_warnings(found, (h, h / 2))
    assert len(lines) == int(warns) and all(line.startswith("L:sxx (") for line in lines)
    if warns:
        order, high = found["L:sxx"]
        assert high == theory[1] and order > high + core_tol.CELL_SCALE_EXCESS


def test_a_smooth_value_round_off_at_the_cells_or_an_observed_order_shows_no_cell_scale_order():
    """est.cell_scale_orders: runs that differ by a smooth amount only
    (each run's part at the cells' scale the exact value's own, ratio 1),
    runs whose values are lines (that part at round-off, whatever its
    ratio), runs whose values are all round-off of the scene's stresses
    (rough as they may be), and an estimate whose order three runs
    observed (left to the order's own warning): none is named."""
    scene, h = load_scene("A"), 0.05
    theory = est.order_range("sxx", 1, _facts("fe", 1))
    two = {"L": {"sxx": est.QuantityEstimate(np.zeros(281), 1.45, theory)}}
    smooth = _runs_along_gamma(lambda s, hk: np.sin(3 * s) + hk * s, h)
    assert est.cell_scale_orders(scene, smooth, two, 0.1, h) == {}
    lines = _runs_along_gamma(lambda s, hk: 1.0 + 2.0 * s + 1e-14 * np.sin(2 * np.pi * s / hk) / hk ** 4, h)
    assert est.cell_scale_orders(scene, lines, two, 0.1, h) == {}
    stress = Sizes.of(scene).stress  # A's load
    rough = _runs_along_gamma(lambda s, hk: stress * (1.0 + 4.0 * hk ** 4 * np.sin(2 * np.pi * s / hk)), h)
    assert est.cell_scale_orders(scene, rough, two, 0.1, h)
    noise = _runs_along_gamma(lambda s, hk: 1e-14 * stress * (1.0 + 4.0 * hk ** 4 * np.sin(2 * np.pi * s / hk)), h)
    assert est.cell_scale_orders(scene, noise, two, 0.1, h) == {}  # round-off of A's stresses, however rough
    three = {"L": {"sxx": est.QuantityEstimate(np.zeros(281), 4.0, theory, measured=4.0)}}
    assert est.cell_scale_orders(scene, rough, three, 0.1, h) == {}


@pytest.mark.parametrize("far_rate, near_rate, named_whole, named_split", [
    (1.0, 3.0, False, True),   # rough only near the changes: the whole profile dilutes it (tilt-unil-exact)
    (2.4, 1.0, True, False),   # far samples at the far range's order (2), not above it by CELL_SCALE_EXCESS
    (1.0, 1.0, False, False),
])
def test_a_switching_exact_tractions_cells_are_judged_by_the_order_each_sample_takes(far_rate, near_rate,
                                                                                      named_whole, named_split):
    """est.cell_scale_orders with ``far`` (an exact traction on a Γ that
    switches, runs.far_tractions): the part at the cells' scale of the
    samples far from the status changes is compared with the far range's
    highest order (2), of the rest with 1, each over its own samples;
    without ``far`` (the code before), over the whole profile with 1.  A
    wave of each run's cell shrinking at ``far_rate`` for x ≤ 0.6 and at
    ``near_rate`` beyond."""
    scene, h = load_scene("A"), 0.05
    stress = Sizes.of(scene).stress  # A's load
    x = np.linspace(0.15, 0.85, 281)
    far = x <= 0.6
    wave = lambda s, hk: np.where(s + 0.15 <= 0.6, (hk / h) ** far_rate, (hk / h) ** near_rate)  # noqa: E731
    levels = _runs_along_gamma(lambda s, hk: stress * (1.0 + s + 0.01 * wave(s, hk)
                                                       * np.sin(2 * np.pi * s / hk + 0.3)), h, "tN")
    estimates = {"L": {"tN": est.QuantityEstimate(np.zeros(281), 1.0, (1.0, 1.0), far_order=2.0)}}
    assert bool(est.cell_scale_orders(scene, levels, estimates, 0.1, h)) == named_whole
    found = est.cell_scale_orders(scene, levels, estimates, 0.1, h, {"L": {"tN": (far, 2.0)}})
    assert bool(found) == named_split, found
    if named_split:
        order, high = found["L:tN"]
        assert high == 1.0 and order > high + core_tol.CELL_SCALE_EXCESS


def _two_profiles(share, other="sxy", h=0.05):
    """Runs at h and h/2 along A's Γ with profiles ``L`` (σxx, a smooth
    value whose runs differ by A's stress scale times h²) and ``M``
    (``other``: the same, its difference ``share`` of L's), and two-run
    estimates of both."""
    from contactcore import ProfileData
    scene = load_scene("A")
    stress = Sizes.of(scene).stress  # A's load
    x = np.linspace(0.15, 0.85, 281)
    base = {"s": x - 0.15, "x": x, "y": np.full_like(x, 0.5)}
    value = lambda k, hk: stress * (1.0 + x + k * hk ** 2 * np.sin(5 * x))  # noqa: E731
    levels = [[ProfileData("L", "arclength", {**base, "sxx": value(1.0, hk)}),
               ProfileData("M", "arclength", {**base, other: value(share, hk)})] for hk in (h, h / 2)]
    theory = est.order_range("sxx", 2, _facts("xfem", 2))
    estimates = {pid: {q: est.QuantityEstimate(np.zeros(281), 2.0, theory)}
                 for pid, q in (("L", "sxx"), ("M", other))}
    return scene, levels, estimates


@pytest.mark.parametrize("share, named", [(tol.RESIDUE_BELOW, True), (tol.RESIDUE_ABOVE, False)])
def test_a_quantity_whose_runs_differ_a_thousand_times_less_than_its_kinds_is_not_to_be_trusted(share, named):
    """est.residues: of two stresses of the same runs, the one whose runs
    differ by less than RESIDUE_SHARE of the other's is named, with its
    share and the quantity it is measured against, and in a warning
    line; the largest never is."""
    scene, levels, estimates = _two_profiles(share)
    found = est.residues(scene, levels, estimates, 0.1)
    assert ("M:sxy" in found) == named and "L:sxx" not in found, found
    if named:
        got, other = found["M:sxy"]
        assert got == pytest.approx(share) and other == "L:sxx"
        (line,) = est.residue_warnings(found)
        assert line.startswith("M:sxy (") and "L:sxx" in line
    else:
        assert est.residue_warnings(found) == []


def test_a_small_difference_of_another_kind_at_round_off_or_observed_is_no_residue():
    """est.residues compares a quantity with its own kind only (a
    displacement's difference, however small against a stress's, is
    not named), leaves out differences at round-off of the scene's
    sizes (they show nothing), and quantities whose order three runs
    observed (left to the order's own warning)."""
    scene, levels, estimates = _two_profiles(tol.RESIDUE_BELOW, other="ux")
    assert est.residues(scene, levels, estimates, 0.1) == {}
    scene, levels, estimates = _two_profiles(tol.RESIDUE_BELOW)
    assert "M:sxy" in est.residues(scene, levels, estimates, 0.1)
    estimates["M"]["sxy"] = est.QuantityEstimate(np.zeros(281), 1.3, estimates["M"]["sxy"].theory, measured=1.3)
    assert est.residues(scene, levels, estimates, 0.1) == {}
    scene, levels, estimates = _two_profiles(tol.RESIDUE_BELOW * core_tol.NEGLIGIBLE_SHARE)
    assert est.residues(scene, levels, estimates, 0.1) == {}  # M's runs differ at round-off of A's stresses


@pytest.mark.slow
def test_xfem_p2s_stress_on_bs_clamped_edge_is_named_and_converges_slower_than_theory():
    """The case est.residues was chosen on (docs/error-estimates.md,
    "Which estimates to warn of"): scene B, h = 0.05 -> 0.025.  xfem
    P2's two-run estimate names B2's σxx (its runs differ by 5e-4 of
    B1's σxy) and nothing else; fe P2's, on the same samples, names
    nothing (its B2 differs by 7e-3 of B1).  The premise, by a third run
    at h = 0.0125: that σxx's observed order lies at least
    RESIDUE_ORDER_GAP below the 2 theory gives it, while B1's σxy of
    the same runs lies within it of 2."""
    from contactcore import sample_profiles
    from contactcore.discretisation import solve
    from verification import methods
    from verification.agreement import default_exclusion
    scene = load_scene("B")
    exclude = default_exclusion(scene)
    xfem = [solve(scene, methods.discretisation("xfem")(degree=2), hk) for hk in est.levels_of(SCENE_H, 3)]
    two = est.estimate_runs(scene, xfem[:2], exclude, energy=False)
    assert "B2:sxx" in two.unsettled and any(w.startswith("B2:sxx (") for w in two.warnings)
    assert est.residues(scene, [sample_profiles(scene, r.fields, r.interface) for r in xfem[:2]],
                        two.profiles, exclude).keys() == {"B2:sxx"}
    fe = [solve(scene, methods.discretisation("fe")(degree=2), hk) for hk in est.levels_of(SCENE_H, 2)]
    fe_two = est.estimate_runs(scene, fe, exclude, energy=False)
    assert est.residues(scene, [sample_profiles(scene, r.fields, r.interface) for r in fe],
                        fe_two.profiles, exclude) == {}
    three = est.estimate_runs(scene, xfem, exclude, energy=False)
    b2, b1 = three.profiles["B2"]["sxx"], three.profiles["B1"]["sxy"]
    assert b2.observed and b1.observed
    assert b2.measured < b2.theory[0] - tol.RESIDUE_ORDER_GAP, b2  # the observed order, not the one used
    assert abs(b1.measured - b1.theory[0]) < tol.RESIDUE_ORDER_GAP, b1


def test_three_runs_name_their_order_warnings_among_the_unsettled_entries():
    """effectivity's ``warned`` column (Estimate.unsettled) names every
    entry that ``run --estimate 3``'s observed-order warnings name: on
    scene C, fe P1 at h = 0.25, 0.125, 0.0625, C1's σxy converges at a
    clipped order (0.5) and is warned of by its order alone."""
    from contactcore.discretisation import solve
    from verification import methods
    from verification.agreement import default_exclusion
    scene = load_scene("C")
    results = [solve(scene, methods.discretisation("fe")(degree=1), h) for h in est.levels_of(0.25, 3)]
    estimate = est.estimate_runs(scene, results, default_exclusion(scene), energy=False)
    named = {w.split(": ")[0] for w in est.order_warnings(estimate.profiles)}
    assert "C1:sxy" in named and named <= estimate.unsettled
    assert all(est.order_mismatch(estimate.profiles[k.split(":")[0]][k.split(":")[1]]) for k in named)


def test_efficiency_on_a_disc_says_no_sample_was_left_out():
    """A disc with a circular Γ has no corner and no end of Γ
    (estimate.singular_regions): efficiency's sentence says nothing was
    left out instead of naming them; a rectangle's names its corners."""
    from verification import efficiency
    from verification.closed_forms import pressurised_rod
    disc = est.singular_regions(pressurised_rod().scene)
    assert not disc
    text = efficiency._error_sentence(None, None, 0.2, "m", tuple(name for name, _ in disc))
    assert "no sample was left out" in text and "corners" not in text and "ends of Γ" not in text
    names = tuple(name for name, _ in est.singular_regions(load_scene("A")))
    assert "of corners and of the ends of Γ left out" in efficiency._error_sentence(None, None, 0.1, "m", names)


def test_a_two_run_estimate_among_three_runs_is_compared_with_every_quantity_of_its_kind():
    """est.residues (review1): its docstring compares a quantity with the
    most its kind differs "on every profile of the same runs".  With three
    runs, a quantity whose order is not observed (its coarse and middle
    runs agree, so observed_order is None) keeps a two-run estimate; its
    two finest runs differ by RESIDUE_BELOW of σxx's in the same runs, as
    in the two-run case that is named, but σxx (order observed) is left
    out of the kind's largest, so nothing is named."""
    from contactcore import ProfileData
    scene, h = load_scene("A"), 0.05
    stress = Sizes.of(scene).stress
    x = np.linspace(0.15, 0.85, 281)
    base = {"s": x - 0.15, "x": x, "y": np.full_like(x, 0.5)}
    value = lambda hk: stress * (1.0 + x + hk ** 2 * np.sin(5 * x))  # noqa: E731
    hs = est.levels_of(h, 3)
    flat = {hk: stress * (1.0 + x) for hk in hs}
    flat[hs[-1]] = flat[hs[-1]] + tol.RESIDUE_BELOW * (value(hs[-1]) - value(hs[-2]))
    levels = [[ProfileData("L", "arclength", {**base, "sxx": value(hk)}),
               ProfileData("M", "arclength", {**base, "sxy": flat[hk]})] for hk in hs]
    three = est.profile_estimates(levels, 2, _facts("xfem", 2), scene=scene, exclude=0.1)
    assert three["L"]["sxx"].observed and not three["M"]["sxy"].observed
    two = est.profile_estimates(levels[1:], 2, _facts("xfem", 2), scene=scene, exclude=0.1)
    assert "M:sxy" in est.residues(scene, levels[1:], two, 0.1)
    assert "M:sxy" in est.residues(scene, levels, three, 0.1)


@pytest.mark.parametrize("method", ["fe", pytest.param("xfem", marks=pytest.mark.slow)])
def test_p2_stresses_next_to_a_curved_gamma_keep_their_order_and_rays_centre_on_the_estimate(method):
    """grader6's fault 3: on one ray across a curved Γ the two-run
    estimate of a P2 stress came out at 2.3-2.9 of its error, most of it
    within 0.1 of Γ.  The stress there converges at the method's order
    (the median over 48 rays of the RMS error within 0.1 of Γ, h = 0.1
    against 0.05, at least NEAR_CURVED_GAMMA_STRESS_ORDER: 1.89 measured
    for fe and xfem), and the per-ray effectivities centre inside
    EFFECTIVITY (median 1.25 measured; 8 (fe) and 5 (xfem) of 144 lie
    above 2: one ray reads the pointwise errors of the one or two cells
    next to Γ, which the two meshes set independently;
    docs/error-estimates.md, "Stresses next to a curved Γ")."""
    from contactcore import LineProfile, Material, sample_profiles
    from contactcore.discretisation import solve
    from verification import methods
    from verification.closed_forms import pressurised_rod
    case = pressurised_rod(a=0.5, b=1.0, p=1e7, kN=1e12, kT=1e11, rod=Material(2e11, 0.3),
                           matrix=Material(3e10, 0.2))      # grader6's disc_coulomb_stiff
    angles = 2 * np.pi * (np.arange(48) + 0.5) / 48
    rays = tuple(LineProfile(f"r{k}", (0.0, 0.0), (np.cos(a), np.sin(a)), ("sxx", "syy", "sxy"))
                 for k, a in enumerate(angles))
    scene = case.scene.with_changes(profiles=rays)
    h, radius = 0.1, 0.5
    results = [solve(scene, methods.discretisation(method)(degree=2), hk) for hk in est.levels_of(h, 2)]
    estimate = est.estimate_runs(scene, results, 0.0, energy=False)
    coarse = sample_profiles(scene, results[0].fields, results[0].interface)
    ratios, effectivities = [], []
    for c, f, x in zip(coarse, estimate.sampled, sample_profiles(scene, case)):
        near = np.abs(np.hypot(x.columns["x"], x.columns["y"]) - radius) < h     # within a coarse cell of Γ
        for q in ("sxx", "syy", "sxy"):
            ratios.append(est.rms((c.columns[q] - x.columns[q])[near]) / est.rms((f.columns[q] - x.columns[q])[near]))
            effectivities.append(estimate.profiles[f.id][q].rms / est.rms(f.columns[q] - x.columns[q]))
    assert np.log2(np.median(ratios)) >= tol.NEAR_CURVED_GAMMA_STRESS_ORDER, np.log2(np.median(ratios))
    assert tol.EFFECTIVITY[0] <= np.median(effectivities) <= tol.EFFECTIVITY[1], np.median(effectivities)


def test_a_sample_at_the_exclusion_distance_is_kept_at_every_corner_alike():
    """grader28 F6: A's diagonal sampled at 101 points, the exclusion
    distance 0.1·√2: samples 10 and 90 lie at that distance from the
    corners (0, 0) and (1, 1), one 5.6e-17 short of it by round-off.  Both
    are kept (a GEOMETRY tolerance), so the kept samples are symmetric."""
    t = np.linspace(0.0, 1.0, 101)
    kept = est.far_from_singular(load_scene("A"), np.column_stack([t, t]), 0.1 * np.sqrt(2.0))
    assert np.array_equal(np.flatnonzero(kept), np.arange(10, 91))
