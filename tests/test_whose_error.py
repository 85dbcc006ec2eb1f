"""summary.md's "Agreement within the estimated errors" says whose error a
disagreement is (newuser35, 2026-11-29: the rule, a method's distance
from the reference against its own estimate, named the right method in
four of four cases but needed summary.json's figures): each row gives
whether either estimate is warned and each method's distance from the
reference over its own estimate, the figures
``verification.agreement.beyond_own_estimate`` gives on the profiles the
run wrote."""
import json

import numpy as np

from contactcore import load_scene
from contactcore.profile_data import ProfileData
from verification import files
from verification.agreement import beyond_own_estimate, default_exclusion
from verification.run import run

METHODS = {"xfem P1": "xfem", "efgm P1": "efgm"}


def _read(folder, pid: str) -> ProfileData:
    columns = {k: np.asarray(v) for k, v in files.read_profile_csv(folder / "profiles" / f"{pid}.csv").items()}
    return ProfileData(pid, "arclength", columns)


def _rows(text: str) -> list[list[str]]:
    table = text.split("## Agreement within the estimated errors", 1)[1].split("\n\n")[2]
    return [[c.strip() for c in line.strip("|").split("|")] for line in table.splitlines()[2:]]


def _written(folder, pids):
    """A run's profiles as written and their estimated errors (``q_err``)."""
    written = {pid: _read(folder, pid) for pid in pids}
    errors = {pid: {q: c for q, c in p.columns.items() if q.endswith("_err")} for pid, p in written.items()}
    return ({pid: ProfileData(pid, p.parameter, {q: c for q, c in p.columns.items() if not q.endswith("_err")})
             for pid, p in written.items()}, errors)


def test_an_estimated_reference_counts_its_own_error(tmp_path):
    """grader31: with fe P2 among the runs, its own estimate joins each
    method's in the last column (its underestimate had flagged xfem P2 and
    efgm P2, whose estimates held); the reference's own rows read
    ``reference``."""
    out = tmp_path / "run"
    text = run("A", ["fe", "xfem"], out, h=0.2, degree=2, estimate=2, draw=False)
    assert "| each from fe P2 ÷ its and the reference's estimates |" in text
    scene = load_scene("A")
    pids = [p.id for p in scene.profiles]
    ref, ref_err = _written(out / "fe", pids)
    got, errors = _written(out / "xfem", pids)
    own = beyond_own_estimate(scene, got, errors, ref, default_exclusion(scene), err_ref=ref_err)
    alone = beyond_own_estimate(scene, got, errors, ref, default_exclusion(scene))
    for pair, pid, q, ratio, _, _, each in _rows(text):
        assert pair == "fe P2 – xfem P2" and each == f"reference, {own[pid, q]:.2f}" == f"reference, {ratio}"
    assert all(own[k] < alone[k] for k in own if alone[k] > 0)


def test_each_row_says_which_estimate_is_warned_and_how_far_each_method_is_from_the_reference(tmp_path):
    out = tmp_path / "run"
    text = run("A", list(METHODS.values()), out, h=0.2, estimate=2, draw=False)
    assert "| estimate warned | each from fe P2 ÷ its estimate |" in text
    scene = load_scene("A")
    pids = [p.id for p in scene.profiles]
    ref = {pid: _read(out / "reference", pid) for pid in pids}
    own, warned = {}, {}
    for label, name in METHODS.items():
        got, errors = _written(out / name, pids)  # each q with its q_err beside it
        own[label] = beyond_own_estimate(scene, got, errors, ref, default_exclusion(scene))
        warnings = " ".join(json.loads((out / name / "summary.json").read_text())["estimate"]["warnings"])
        warned[label] = warnings
    rows = _rows(text)
    assert len(rows) == sum(len(p.quantities) for p in scene.profiles)
    figures = []
    for pair, pid, q, _, _, said, each in rows:
        a, b = pair.split(" – ")
        for label, figure in zip((a, b), each.split(", ")):
            assert float(figure) == round(own[label][pid, q], 2), (pair, pid, q)
            figures.append(own[label][pid, q])
        for label in (a, b):  # a method named as warned has a warning naming the quantity
            assert (label in said) <= (f"{pid}:{q}" in warned[label] or "status" in warned[label]), (pair, pid, q)
    assert any(f > 1 for f in figures) and any(f < 1 for f in figures)  # the column tells methods apart
