"""trac34 (2026-11-29): an exact law's traction on Γ estimated sample by
sample: far from Γ's status changes at a law's order that never switches
(degree 2: 2; degree 1: the range [1, 2], deg1_36), at 1 near them (contactcore.estimate.orders.smooth_range,
contactcore.estimate.status.far_from_changes,
contactcore.tolerances.STATUS_CHANGE_CELLS; docs/error-estimates.md,
"Known limits")."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import estimate as est
from contactcore import make_law, sample_profiles
from contactcore import tolerances as core_tol
from contactcore.discretisation import solve
from contactcore.estimate import runs as runs_module
from verification import methods
from verification.closed_forms import layered_slip
from verification.effectivity import exact_profiles, profile_rows


def test_an_exact_traction_takes_a_faster_order_far_from_status_changes():
    """Degree 2 its degree; degree 1 (deg1_36) the range [1, 2] of a
    degree-1 stress, whose balanced order is 1.45."""
    coulomb = make_law({"type": "coulomb", "mu": 0.3, "enforcement": "exact"})
    facts = methods.discretisation("fe")(degree=2).facts
    assert est.smooth_range("tN", 2, facts, coulomb, True) == est.smooth_range("tT", 2, facts, coulomb, True) == (2, 2)
    assert est.smooth_range("tN", 1, facts, coulomb, True) == (1, 2)
    assert est.smooth_range("gN", 2, facts, coulomb, True) is None
    assert est.smooth_range("tN", 2, facts, coulomb, False) is None  # no switch: order_range already gives it
    assert est.order_range("tN", 1, facts, coulomb, False) == (1, 2) and est.order_range("tN", 1, facts, coulomb,
                                                                                           True) == (1, 1)
    assert est.smooth_range("tN", 2, facts, make_law({"type": "coulomb", "mu": 0.3, "kN": 1e6, "kT": 1e6}),
                            True) is None


def test_samples_within_the_stated_cells_of_a_status_change_keep_order_one():
    """A change between samples 4 and 5 in one run, between 7 and 8 in the
    other: the samples within STATUS_CHANGE_CELLS coarse cells of either
    midpoint take factor 1/(2 - 1), the rest 1/(2^2 - 1)."""
    x = np.linspace(0.0, 1.0, 21)
    xy = np.column_stack([x, np.zeros_like(x)])
    a, b = (x > 0.21).astype(np.int8), (x > 0.36).astype(np.int8)
    points = est.change_points(xy, [a, b])
    assert np.allclose(points, [[0.225, 0.0], [0.375, 0.0]])
    h = 0.05
    far = np.min(np.abs(x[:, None] - points[None, :, 0]), axis=1) > core_tol.STATUS_CHANGE_CELLS * h
    values = [np.zeros_like(x), np.ones_like(x)]
    e = est.richardson(values, (1, 1), far=(far, 2.0))
    assert e.order == 1 and e.far_order == 2 and e.record()["far_order"] == 2
    assert np.allclose(e.error, np.where(far, 1 / 3, 1.0)) and 0 < far.sum() < len(x)


def _layered_exact_effectivities(key):
    case = layered_slip(exact=True)
    disc = methods.discretisation(key[0])(degree=key[1])
    results = [solve(case.scene, disc, h) for h in tol.LAYERED_EXACT_RUNS]
    estimate = est.estimate_runs(case.scene, results, energy=False)
    got = {p.id: p for p in sample_profiles(case.scene, results[-1].fields, results[-1].interface)}
    rows = profile_rows(estimate, got, exact_profiles(case))
    return {r["quantity"]: r["effectivity"] for r in rows if r["quantity"] in ("tN", "tT")}, estimate


def test_the_layered_exact_slips_tractions_move_into_the_range(monkeypatch):
    """The layered slip under exact Coulomb (verification.closed_forms.
    layered_slip(exact=True)): Γ slipped after sticking (the law switched),
    but its final status is one along Γ, so every sample is far from a
    change.  EFGM P2's t_N, t_T (fe's and xfem's are at round-off) read
    2.18 at order 1 and 0.73 at the degree's 2 (h = 0.1 -> 0.05)."""
    eff, estimate = _layered_exact_effectivities(("efgm", 2))
    for q in ("tN", "tT"):
        assert tol.EFFECTIVITY[0] <= eff[q] <= tol.EFFECTIVITY[1], (q, eff[q])
        assert estimate.profiles["L1"][q].far_order == 2
    monkeypatch.setattr(runs_module, "far_from_changes", lambda *args: {})
    before, _ = _layered_exact_effectivities(("efgm", 2))
    for q in ("tN", "tT"):
        assert before[q] > tol.EFFECTIVITY[1], (q, before[q])
        assert before[q] == pytest.approx(3 * eff[q])


def test_a_profile_that_starts_past_a_status_change_still_sees_it():
    """review19b: far_from_changes looked for status changes only between
    a profile's own samples, so a traction profile along part of Γ, from
    x = 0.08 on tests/scenes/tilt_unil_exact.toml (whose Γ opens at
    x = 0.075 in fe P2), took its first samples, within two coarse cells of
    that change, as smooth (order 2, the estimate a third).  Γ's changes
    are now taken along all of Γ too: the same samples as on the whole
    profile G are near."""
    from contactcore import LineProfile, load_scene
    scene = load_scene(TILT)
    part = LineProfile("Gsub", (PART_START, 0.47), (1.0, 0.47), ("gN", "tN", "tT"))
    scene = scene.with_changes(profiles=(*scene.profiles, part))
    h = PART_H
    results = [solve(scene, methods.discretisation("fe")(degree=2), hk) for hk in (h, h / 2)]
    profiles = sample_profiles(scene, results[-1].fields, results[-1].interface)
    far = est.far_from_changes(scene, results, profiles, h)
    x = {p.id: p.columns["x"] for p in profiles}
    near_whole = x["G"][~far["G"]]
    near_part = x["Gsub"][~far["Gsub"]]
    assert not far["Gsub"][0] and far["Gsub"][-1] and np.all(np.diff(far["Gsub"].astype(int)) >= 0)  # a leading run
    assert abs(near_part.max() - near_whole.max()) <= np.diff(x["G"]).max()  # as far along Γ as G's, to a sample


#: Where the part of Γ the partial profile reads starts: just past Γ's
#: status change at x = 0.075, at review19b's coarse h.
TILT = "tests/scenes/tilt_unil_exact.toml"
PART_START = 0.08
PART_H = 0.05


def test_a_degree_one_exact_traction_whose_status_never_changes_takes_the_balanced_order_of_one_and_two():
    """deg1_36: tests/scenes/wedge_held.toml under exact Coulomb slips whole
    (Γ's status never changes), fe P1 at h = 0.1 -> 0.05 against fe P2 at
    WEDGE_HELD_TRUTH_H.  Its t_N, t_T, Nitsche's multiplier as a mean per
    piece of Γ, took order 1 and read WEDGE_HELD_P1_AT_ORDER_ONE times their
    error; at 1.45, the balanced order of [1, 2] (a degree-1 stress's range:
    contactcore.estimate.orders.order_range), 1/√3 of that, in
    [0.5, 2].  Still warned (exact tractions)."""
    from contactcore import load_scene
    from verification.effectivity import scene_rows, scene_truth
    scene = load_scene(WEDGE_HELD)
    rows = scene_rows(scene, ("fe", 1), tol.LAYERED_EXACT_RUNS[0], scene_truth(scene, tol.WEDGE_HELD_TRUTH_H))
    got = {r["quantity"]: r for r in rows if r["quantity"] in ("tN", "tT")}
    for q, r in got.items():
        assert r["order"] == pytest.approx(est.balanced_order(1, 2)) and r["warned"], (q, r)
        assert tol.EFFECTIVITY[0] <= r["effectivity"] <= tol.EFFECTIVITY[1], (q, r["effectivity"])
        at_order_one = r["effectivity"] * (2 ** r["order"] - 1)  # the same differences over 2^1 - 1
        assert at_order_one == pytest.approx(tol.WEDGE_HELD_P1_AT_ORDER_ONE[q], rel=tol.WEDGE_HELD_P1_DRIFT)


def test_a_degree_one_exact_traction_takes_order_one_only_near_status_changes():
    """deg1_36: exact C-coulomb (docs/scenes/C-coulomb-exact.toml; Γ opens
    and closes, sticks and slips), fe P1 at h = 0.1 -> 0.05: C4's t_N, t_T
    take 1 within STATUS_CHANGE_CELLS coarse cells of a status change and
    1.45 (``far_order``) beyond, sample by sample."""
    from contactcore import load_scene
    scene = load_scene(C_EXACT)
    h = tol.LAYERED_EXACT_RUNS[0]
    results = [solve(scene, methods.discretisation("fe")(degree=1), hk) for hk in (h, h / 2)]
    estimate = est.estimate_runs(scene, results, energy=False)
    coarse = {p.id: p for p in sample_profiles(scene, results[0].fields, results[0].interface)}
    fine = {p.id: p for p in estimate.sampled}
    far = est.far_from_changes(scene, results, estimate.sampled, h)["C4"]
    assert 0 < far.sum() < len(far)
    bal = est.balanced_order(1, 2)
    for q in ("tN", "tT"):
        e = estimate.profiles["C4"][q]
        assert e.order == 1 and e.far_order == pytest.approx(bal)
        diff = np.abs(fine["C4"].columns[q] - coarse["C4"].columns[q])
        assert np.allclose(e.error, diff * np.where(far, 1 / (2 ** bal - 1), 1.0))


WEDGE_HELD = "tests/scenes/wedge_held.toml"
C_EXACT = "docs/scenes/C-coulomb-exact.toml"


def test_a_third_run_keeps_the_far_order_of_an_exact_traction():
    """review20 #3: with three runs an exact law's traction on a switching Γ
    (theory (1, 1)) took order 1 at every sample, the far samples' faster
    order dropped (fe P2's t_N across a stick/slip change read 2.72 of its
    error against two runs' 1.70).  Runs whose differences fall at order 2:
    the far samples take three_run_order(2, 2) = 2, the near ones 1, and
    the estimate records both."""
    from contactcore.estimate.extrapolation import richardson
    n = 6
    far = np.arange(n) >= n // 2
    coarse = np.linspace(1.0, 2.0, n)
    values = [coarse, coarse / 4, coarse / 16]  # differences shrink 4 times a halving: order 2
    got = richardson(values, (1, 1), far=(far, 2.0))
    step = np.abs(values[-1] - values[-2])
    assert got.far_order == 2.0 and got.measured == pytest.approx(2.0)
    assert np.allclose(got.error[far], step[far] / 3) and np.allclose(got.error[~far], step[~far])
