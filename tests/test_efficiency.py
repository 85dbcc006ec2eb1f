"""``efficiency --ref-h``'s effectivity: one quantity's estimate over the
same quantity's true error (grader21's F8: the worst estimate over the
worst true error mixed two quantities)."""
import csv
import math
from types import SimpleNamespace

import numpy as np
import pytest

from verification.__main__ import main
from verification.efficiency import effectivity_at


def test_the_effectivity_is_the_worst_true_errors_own():
    """effectivity_at: the estimate of the quantity whose true error is the
    worst, not the estimate's own worst (grader21's scene A fe P1 at h =
    0.05: A4:sxx's estimate 0.105 is the largest, A1:sxy's error 0.148
    the worst true), both RMS over the samples that estimate keeps (a
    sample within the coarse run's reach of a singular point, left out of
    the estimate, is left out of the true error too: 2026-11-29, the
    ratio had mixed two sets of samples); NaN where that quantity has no
    estimate or no error there."""
    got = {"A1": SimpleNamespace(columns={"sxy": np.array([1.0, 2.0, 3.0, 50.0])})}
    ref = {"A1": SimpleNamespace(columns={"sxy": np.array([1.5, 2.5, 3.5, 3.0])})}
    keep = np.array([True, True, True, False])
    estimates = {"A1:sxy": (np.array([0.25, 0.25, 0.25]), keep), "A4:sxx": (np.array([9.0]), keep[:1])}
    assert effectivity_at(estimates, "A1:sxy", got, ref) == pytest.approx(0.5)  # 0.25 / 0.5, not the 47 left out
    assert math.isnan(effectivity_at(estimates, "A2:ux", got, ref))
    assert math.isnan(effectivity_at(estimates, "A1:sxy", got, {"A1": got["A1"]}))


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
