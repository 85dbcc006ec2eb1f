"""sweeps.md's "range handled" (grader2 item 9): refused values on both
sides of the accurate ones were written "refused: 1e-12 … 1e+12 (3
values)", a range claiming the whole span refused."""
import json

from verification import files
from verification.sweeps import handled_range


def _rows(**outcomes) -> list[dict]:
    rows = [{"value": v, "outcome": o} for o, vals in outcomes.items() for v in vals]
    return sorted(rows, key=lambda r: r["value"])


def test_a_range_never_spans_another_outcomes_values():
    refused, accurate = (1e-12, 1e10, 1e12), (1e-9, 1e-6, 1e-3, 1.0, 1e3, 1e8)
    text = handled_range(_rows(refused=refused, accurate=accurate))
    assert f"{files.cell(1e-12)} … {files.cell(1e12)}" not in text, text
    assert f"refused: {', '.join(files.cell(v) for v in refused)}" in text, text
    assert f"accurate: {files.cell(1e-9)} … {files.cell(1e8)} (6 values)" in text, text


def test_an_outcome_split_by_another_is_two_ranges():
    low, high, between = (1e-12, 1e-11, 1e-10), (1e10, 1e11, 1e12), (1e-3, 1.0)
    text = handled_range(_rows(refused=low + high, warned=between))
    assert (f"refused: {files.cell(1e-12)} … {files.cell(1e-10)} (3 values), "
            f"{files.cell(1e10)} … {files.cell(1e12)} (3 values)") in text, text
    assert f"warned: {files.cell(1e-3)}, {files.cell(1.0)}" in text, text


def test_names_keep_the_sweeps_order():
    rows = [{"value": "b", "outcome": "accurate"}, {"value": "a", "outcome": "refused"},
            {"value": "c", "outcome": "accurate"}]
    assert handled_range(rows) == "accurate: b, c; refused: a"


def test_a_wrong_case_ends_the_sweeps_with_status_1_and_refusals_do_not(tmp_path, capsys, monkeypatch):
    """A sweep's *refused* and *warned* cases are data (exit 0: kN_patch
    refuses efgm at 1e-12 and 1e10); a *wrong* one is a bug: the sweeps are
    written whole, then one line and exit status 1, as a study with a failed
    point (grader11's fault 2)."""
    from verification import sweeps
    from verification.__main__ import main
    argv = ["sweeps", "--sweep", "kN_patch", "--method", "efgm"]
    assert main([*argv, "--out", str(tmp_path / "ok")]) == 0
    text = (tmp_path / "ok" / "sweeps.md").read_text()
    assert "refused" in text and "measured by 1 worker at once" in text  # grader11 #3
    assert json.loads((tmp_path / "ok" / "run.json").read_text())["workers"] == "1 worker"
    monkeypatch.setattr(sweeps, "classify", lambda *_: "wrong")
    capsys.readouterr()
    assert main([*argv, "--out", str(tmp_path / "bad")]) == 1
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith("sweeps: 17 of 17 cases are wrong")
    assert "wrong" in (tmp_path / "bad" / "sweeps.md").read_text()
