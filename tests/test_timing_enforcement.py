"""``timing`` names each row's enforcement (timing.md and timing.csv): a
scene's name alone does not say whether its law was enforced by its springs
or exactly, and the two cost differently (grader20's fault 5: only the solve
counts told an exact run from a penalty one)."""
import csv
import re

from contactcore import scene_text
from verification.__main__ import main


def _exact_copy_of_a(folder):
    """Scene A with its law made the exact unilateral law, under the name ``A-exact``."""
    text = re.sub(r'(?m)^name = ".*"', 'name = "A-exact"', scene_text("A"))
    text = re.sub(r'(?m)^type = "linear".*$', 'type = "unilateral"\nenforcement = "exact"', text, count=1)
    path = folder / "A-exact.toml"
    path.write_text(text)
    return path


def test_timing_names_each_rows_enforcement(tmp_path):
    out = tmp_path / "timing"
    assert main(["timing", "A", str(_exact_copy_of_a(tmp_path)), "--method", "efgm", "--degree", "1", "--h", "0.5",
                 "-q", "--out", str(out)]) == 0
    table = (out / "timing.md").read_text()
    assert "| scene | enforcement | method |" in table
    rows = [line for line in table.splitlines() if line.startswith("| A")]
    assert [line.split("|")[1:3] for line in rows] == [[" A ", " penalty "], [" A-exact ", " exact "]]
    with open(out / "timing.csv") as f:
        assert [(r["scene"], r["enforcement"]) for r in csv.DictReader(f)] == [("A", "penalty"), ("A-exact", "exact")]
