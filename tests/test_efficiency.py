"""``efficiency --ref-h``'s effectivity: one quantity's estimate over the
same quantity's true error (grader21's F8: the worst estimate over the
worst true error mixed two quantities)."""
import csv
import math
from types import SimpleNamespace

import numpy as np
import pytest

import tolerances as tol

from verification.__main__ import main
from verification.efficiency import effectivity_at, ROUNDOFF


def test_the_effectivity_is_the_worst_true_errors_own():
    """effectivity_at: the estimate of the quantity whose true error is the
    worst, not the estimate's own worst (grader21's scene A fe P1 at h =
    0.05: A4:sxx's estimate 0.105 is the largest, A1:sxy's error 0.148
    the worst true), both RMS over the samples that estimate keeps (a
    sample within the coarse run's reach of a singular point, left out of
    the estimate, is left out of the true error too: 2026-11-29, the
    ratio had mixed two sets of samples); NaN where that quantity has no
    estimate there, round-off where its error is (test_round_off_has_no_effectivity)."""
    got = {"A1": SimpleNamespace(columns={"sxy": np.array([1.0, 2.0, 3.0, 50.0])})}
    ref = {"A1": SimpleNamespace(columns={"sxy": np.array([1.5, 2.5, 3.5, 3.0])})}
    keep = np.array([True, True, True, False])
    estimates = {"A1:sxy": (np.array([0.25, 0.25, 0.25]), keep), "A4:sxx": (np.array([9.0]), keep[:1])}
    assert effectivity_at(estimates, "A1:sxy", got, ref) == pytest.approx(0.5)  # 0.25 / 0.5, not the 47 left out
    assert math.isnan(effectivity_at(estimates, "A2:ux", got, ref))
    assert effectivity_at(estimates, "A1:sxy", got, {"A1": got["A1"]}) == ROUNDOFF


def test_the_table_names_the_effectivitys_quantity(tmp_path):
    """efficiency.md heads the column "effectivity at worst at" and says it
    is the same quantity's, over the samples its estimate keeps; every
    rung has one (its value: test_the_effectivity_is_the_worst_true_errors_own)."""
    assert main(["efficiency", "A", "--method", "fe", "--h", "0.2", "--ref-h", "0.1", "--out", str(tmp_path)]) == 0
    text = (tmp_path / "efficiency.md").read_text()
    assert "effectivity at worst at" in text and "the same quantity" in text and "samples its estimate keeps" in text
    with open(tmp_path / "efficiency.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert rows and all(float(r["effectivity"]) > 0 for r in rows)


def test_round_off_has_no_effectivity(tmp_path):
    """grader34 F4: a true error at round-off (at_roundoff, the rule by
    which the effectivity tool leaves such rows out) has no effectivity:
    fe P2 on a layered block whose answer is piecewise quadratic is exact,
    and ``efficiency --ref-h`` printed 0.439 (estimate 3.13e-14 over error
    7.13e-14) beside real effectivities; now the row reads round-off, in
    the table and the CSV.  A true error above round-off keeps its ratio."""
    values = np.array([1e6, 2e6])
    got, estimates = {"G": SimpleNamespace(columns={"tN": values})}, {"G:tN": (np.full(2, 1e-4), np.ones(2, bool))}
    noise, signal = ({"G": SimpleNamespace(columns={"tN": values * (1 + share)})}
                     for share in (tol.EFFICIENCY_NOISE, tol.EFFICIENCY_SIGNAL))
    assert effectivity_at(estimates, "G:tN", got, noise) == ROUNDOFF
    true = tol.EFFICIENCY_SIGNAL * float(np.sqrt(np.mean(np.square(values))))
    assert effectivity_at(estimates, "G:tN", got, signal) == pytest.approx(1e-4 / true)
    assert main(["efficiency", "tests/scenes/layered_press_exact.toml", "--method", "fe", "--degree", "2",
                 "--h", str(tol.LAYERED_EXACT_H), "--ref-h", str(tol.LAYERED_EXACT_H / 2), "--out", str(tmp_path),
                 "-q"]) == 0
    (row,) = [line for line in (tmp_path / "efficiency.md").read_text().splitlines() if line.startswith("| fe | 2 |")]
    assert row.endswith(f"| {ROUNDOFF} |"), row
    with open(tmp_path / "efficiency.csv") as fh:
        assert [r["effectivity"] for r in csv.DictReader(fh)] == [ROUNDOFF]
