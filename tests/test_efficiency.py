"""``efficiency --ref-h``'s effectivity: one quantity's estimate over the
same quantity's true error (grader21's F8: the worst estimate over the
worst true error mixed two quantities)."""
import csv
import math

from verification.__main__ import main
from verification.efficiency import effectivity_at


def test_the_effectivity_is_the_worst_true_errors_own():
    """effectivity_at: the estimate of the quantity whose true error is the
    worst, not the estimate's own worst (grader21's scene A fe P1 at h =
    0.05: A4:sxx's estimate 0.105 is the largest, A1:sxy's error 0.148
    the worst true); NaN where that quantity has no estimate or no error."""
    estimates = {"A1:sxy": 0.0822, "A4:sxx": 0.105}
    assert effectivity_at(estimates, "A1:sxy", 0.148) == 0.0822 / 0.148
    assert math.isnan(effectivity_at(estimates, "A2:ux", 0.148))
    assert math.isnan(effectivity_at(estimates, "A1:sxy", 0.0))


def test_the_table_names_the_effectivitys_quantity(tmp_path):
    """efficiency.md heads the column "effectivity at worst at" and says it
    is the same quantity's; where the estimate's worst is the true error's
    quantity the effectivity is the two worsts' ratio."""
    assert main(["efficiency", "A", "--method", "fe", "--h", "0.2", "--ref-h", "0.1", "--out", str(tmp_path)]) == 0
    text = (tmp_path / "efficiency.md").read_text()
    assert "effectivity at worst at" in text and "the same quantity" in text
    with open(tmp_path / "efficiency.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert rows and all(float(r["effectivity"]) > 0 for r in rows)
    for r in rows:
        if r["estimate_worst"] == r["worst"]:
            assert float(r["effectivity"]) == float(r["estimate"]) / float(r["error"])
