"""An outside code's answer against the project's (verification.agreement.compare_outside,
issue 34): newuser33's case in code (fe P2's own answer perturbed by 3 % of
max|t_N| in the middle third of Γ is blamed on the outside code there and
agrees elsewhere; the project's answer at a finer h agrees everywhere), a
warned estimate gives a verdict only beyond WARNED_MULTIPLE, the window
takes no q_err from samples left out, s given alone is said and a wide
`outside` hints at the conventions, samples near singular points are left
out, against's files name every unit, and every bad input is one line
naming its problem, before any solve."""
import json
from pathlib import Path

import numpy as np
import pytest
import tolerances as tol

from contactcore import ContactError, SceneError, load_scene
from contactcore import estimate as est
from verification import methods as known
from verification.agreement import compare_outside, default_exclusion, sampled
from verification.agreement.outside import judge
from verification.agreement.outside_files import read_outside
from verification.agreement.outside_input import MIN_SAMPLES, outside_profiles
from verification.agreement.outside_verdicts import BLAME_MULTIPLE, WARNED_EFFECTIVITY, WARNED_MIN_SHARE, WARNED_MULTIPLE

DOCS = Path(__file__).resolve().parent.parent / "docs"

SCENES = Path(__file__).resolve().parent / "scenes"
#: A disc pressed uniformly into a softer ring, exact unilateral law (Lamé:
#: t_N = −13.06 MPa all round Γ): fe P2's estimate there warns only of Γ's
#: gaps, held closed and stuck all round (since 2026-11-29, "enforced gaps":
#: contactcore.estimate.caveats.tractions.enforced_gaps), and of Γ's t_T,
#: zero by symmetry, whose two runs' values are each its own error (since
#: 2026-11-30, "unlike runs": contactcore.estimate.caveats.unlike_runs).
CYLINDER = SCENES / "cylinder.toml"


def _runs(scene, h):
    return [known.solver("fe")(scene, hk, degree=2) for hk in est.levels_of(h, 2)]


@pytest.fixture(scope="module")
def cylinder():
    """fe P2 on the cylinder at H and H/2, estimated."""
    scene = load_scene(CYLINDER)
    estimate = est.estimate_runs(scene, _runs(scene, tol.OUTSIDE_H), default_exclusion(scene))
    project = {p.id: p for p in estimate.sampled}
    return scene, estimate, project


@pytest.fixture(scope="module")
def finer(cylinder):
    """fe P2 on the cylinder at H/4, a finer answer (about 5 s: its test is
    in the slow stage, tests/conftest.py)."""
    scene = cylinder[0]
    return sampled(scene, known.solver("fe")(scene, tol.OUTSIDE_H / 4, degree=2))


def _middle_third(s, span):
    return (s >= span / 3) & (s <= 2 * span / 3)


def _perturbed(project):
    """newuser33's outside answer: the project's own t_N on Γ, plus 3 % of
    max|t_N| in the middle third of Γ (s from 2π/3 to 4π/3)."""
    g = project["G"].columns
    tn = g["tN"] + tol.OUTSIDE_PERTURBATION * np.max(np.abs(g["tN"])) * _middle_third(g["s"], 2 * np.pi)
    return {"G": {"s": g["s"], "tN": tn}}


def test_a_perturbed_middle_third_is_the_outside_codes_error(cylinder):
    scene, estimate, project = cylinder
    outside = _perturbed(project)
    table = judge(scene, outside_profiles(scene, outside), project, estimate, "fe P2")
    [row] = table.rows
    middle = _middle_third(row.columns["s"], 2 * np.pi)
    assert middle.sum() == 33 and not row.warnings
    assert list(row.columns["verdict"][middle]) == ["outside"] * 33
    assert list(row.columns["verdict"][~middle]) == ["agree"] * 68
    assert [r.verdict for r in row.regions] == ["agree", "outside", "agree"]
    assert row.regions[1].s_from == pytest.approx(row.columns["s"][middle][0])
    assert row.regions[1].s_to == pytest.approx(row.columns["s"][middle][-1])
    assert row.regions[1].ratio > BLAME_MULTIPLE
    # the agreement's worst sample: 3 % of the largest |t| (t_T zero by symmetry)
    assert abs(row.agreement.worst / tol.OUTSIDE_PERTURBATION - 1) <= tol.OUTSIDE_ZERO_TT


def test_the_same_through_compare_outside_from_a_csv_in_any_order(cylinder, tmp_path):
    """The public route (solves H and H/2 itself) from a CSV whose rows run
    backwards, giving x, y and no s: the same verdicts as above."""
    scene, estimate, project = cylinder
    g = project["G"].columns
    tn = _perturbed(project)["G"]["tN"]
    path = tmp_path / "G.csv"
    path.write_text("x,y,tN\n" + "".join(f"{x!r},{y!r},{t!r}\n" for x, y, t in zip(g["x"][::-1], g["y"][::-1],
                                                                                     tn[::-1])))
    table = compare_outside(CYLINDER, path, method="fe:2", h=tol.OUTSIDE_H)
    [row] = table.rows
    assert table.hs == (tol.OUTSIDE_H, tol.OUTSIDE_H / 2) and table.method == "fe P2"
    middle = _middle_third(row.columns["s"], 2 * np.pi)
    assert list(row.columns["verdict"][middle]) == ["outside"] * 33
    assert list(row.columns["verdict"][~middle]) == ["agree"] * 68
    text = table.markdown()
    assert "| G | tN | 3 % at s = " in text and "outside 2.136–4.147 rad (33, " in text


@pytest.mark.parametrize("step", [1, 2])
def test_a_finer_answer_agrees_everywhere(cylinder, finer, step):
    """The project's answer at H/4 (all 101 samples, or every other one) as
    the outside code's: within its estimate everywhere, on Γ and the ray;
    Γ's held gaps, whose estimate is warned (enforced gaps), and Γ's t_T,
    zero by symmetry so each run's value is its own error (unlike runs,
    since 2026-11-30), read ``warned`` there, the rest ``agree``."""
    scene, estimate, project = cylinder
    assert estimate.unsettled == {"G:gN", "G:gT", "G:tT"}
    assert any(line.startswith("G:gN, G:gT: ") and "enforced gaps" in line for line in estimate.warnings)
    assert any(line.startswith("G:tT ") and "unlike runs" in line for line in estimate.warnings)
    outside = {pid: {c: v[::step] for c, v in p.columns.items()} for pid, p in finer.items()}
    table = judge(scene, outside_profiles(scene, outside), project, estimate, "fe P2")
    assert len(table.rows) == 7
    for row in table.rows:
        held = f"{row.profile}:{row.quantity}" in estimate.unsettled
        assert set(row.columns["verdict"]) == ({"warned"} if held else {"agree"}), (row.profile, row.quantity)
        assert 0 < row.ratio <= BLAME_MULTIPLE
        assert len(row.columns["s"]) == len(range(0, 101, step))


@pytest.fixture(scope="module")
def scene_c():
    """fe P2 on scene C at H and H/2, estimated: C4's t_N estimate is warned (split share)."""
    scene = load_scene("C")
    estimate = est.estimate_runs(scene, _runs(scene, tol.OUTSIDE_H), default_exclusion(scene))
    return scene, estimate, {p.id: p for p in estimate.sampled}


def test_a_warned_estimate_gives_a_verdict_only_beyond_the_lowest_effectivity(scene_c):
    """Scene C at h = 0.1, C4 t_N warned: a difference within WARNED_MULTIPLE
    (BLAME_MULTIPLE / the lowest effectivity the docs record) of the
    estimate reads `warned`, though beyond BLAME_MULTIPLE; t_N of the
    wrong sign (newuser34: 7.05e4× the estimate) reads `outside (estimate
    warned)` on every sample, said so in outside.md, with a hint to check
    the sign conventions."""
    scene, estimate, project = scene_c
    c4 = project["C4"].columns
    assert "C4:tN" in estimate.unsettled
    [own] = judge(scene, outside_profiles(scene, {"C4": {"s": c4["s"], "tN": c4["tN"]}}), project, estimate,
                  "fe P2").rows
    budget = own.columns["estimate"]
    within = c4["tN"] + tol.OUTSIDE_WARNED_SHARE * WARNED_MULTIPLE * budget
    [row] = judge(scene, outside_profiles(scene, {"C4": {"s": c4["s"], "tN": within}}), project, estimate,
                  "fe P2").rows
    assert tol.OUTSIDE_WARNED_SHARE * WARNED_MULTIPLE > BLAME_MULTIPLE  # an unwarned estimate would blame these
    assert set(row.columns["verdict"]) == {"warned"} and [r.verdict for r in row.regions] == ["warned"]
    assert row.warnings and all("C4:tN" in w for w in row.warnings)
    table = judge(scene, outside_profiles(scene, {"C4": {"s": c4["s"], "tN": -c4["tN"]}}), project, estimate,
                  "fe P2")
    [row] = table.rows
    assert [(r.verdict, r.samples) for r in row.regions] == [("outside (estimate warned)", 101)]
    assert "outside (estimate warned) 0–6.283 rad (101, " in table.markdown()
    assert any("sign conventions" in h for h in row.hints)


def test_a_warned_verdict_needs_a_difference_above_a_share_of_the_size(scene_c, monkeypatch):
    """review18 #1: a correct finer answer was blamed at 22.9 × a warned
    estimate near zero beside a status change (2e-5 of t_N's size).  With
    the multiple made negligible, the size's share alone decides: a
    difference below WARNED_MIN_SHARE of t_N's size reads `warned`, one
    above it `outside (estimate warned)`."""
    from verification.agreement import outside_verdicts as module
    scene, estimate, project = scene_c
    c4 = project["C4"].columns
    monkeypatch.setattr(module, "WARNED_MULTIPLE", tol.OUTSIDE_NEGLIGIBLE_MULTIPLE)
    [own] = judge(scene, outside_profiles(scene, {"C4": {"s": c4["s"], "tN": c4["tN"]}}), project, estimate,
                  "fe P2").rows
    size = own.agreement.size
    for factor, verdict in ((1 / tol.OUTSIDE_SIZE_FACTOR, "warned"), (tol.OUTSIDE_SIZE_FACTOR,
                                                                      "outside (estimate warned)")):
        shifted = c4["tN"] + factor * WARNED_MIN_SHARE * size
        [row] = judge(scene, outside_profiles(scene, {"C4": {"s": c4["s"], "tN": shifted}}), project, estimate,
                      "fe P2").rows
        assert set(row.columns["verdict"]) - {"left out"} == {verdict}, (factor, set(row.columns["verdict"]))


def test_the_warned_multiple_is_the_lowest_effectivity_the_docs_record():
    """WARNED_EFFECTIVITY is the lowest effectivity docs/error-estimates.md's
    "Known limits" gives (an exact law's traction, 0.09 since 2026-11-29)."""
    text = (DOCS / "error-estimates.md").read_text()
    limits = text[text.index("## Known limits"):]
    assert f"the lowest effectivity of a warned estimate this page records: {WARNED_EFFECTIVITY:g}" in limits
    assert WARNED_MULTIPLE == pytest.approx(BLAME_MULTIPLE / WARNED_EFFECTIVITY)


def test_the_window_takes_no_error_from_samples_left_out():
    """newuser34: A3's σxx estimate was 22× its true error, the window
    reaching the q_err of samples near Γ's end, which the agreement leaves
    out. No kept sample's estimate exceeds the largest q_err of the kept
    samples, though the left-out ones' is larger."""
    scene = load_scene("A")
    exclude = default_exclusion(scene)
    estimate = est.estimate_runs(scene, _runs(scene, tol.OUTSIDE_H), exclude)
    project = {p.id: p for p in estimate.sampled}
    a3 = project["A3"].columns
    [row] = judge(scene, outside_profiles(scene, {"A3": {"s": a3["s"], "sxx": a3["sxx"]}}), project, estimate,
                  "fe P2").rows
    error = estimate.profiles["A3"]["sxx"].error
    kept = row.columns["verdict"] != "left out"
    assert (~kept).any() and error[~kept].max() > tol.OUTSIDE_LEFT_OUT_SWELL * error[kept].max()
    assert row.columns["estimate"][kept].max() <= error[kept].max()


def test_samples_near_singular_points_are_left_out():
    """Scene A's Γ (A5) ends on the domain's sides: samples within the
    exclusion of its ends are `left out`, the rest judged."""
    scene = load_scene("A")
    runs = _runs(scene, tol.OUTSIDE_H)
    exclude = default_exclusion(scene)
    estimate = est.estimate_runs(scene, runs, exclude)
    project = {p.id: p for p in estimate.sampled}
    a5 = project["A5"].columns
    [row] = judge(scene, outside_profiles(scene, {"A5": {"s": a5["s"], "gN": a5["gN"]}}), project, estimate,
                  "fe P2").rows
    near = (a5["s"] < exclude) | (a5["s"] > 1 - exclude)
    assert near.any() and not near.all()
    assert set(row.columns["verdict"][near]) == {"left out"}
    assert "left out" not in set(row.columns["verdict"][~near])
    assert row.regions[0].verdict == row.regions[-1].verdict == "left out"


def test_s_alone_is_said_and_a_wide_outside_region_hints_at_the_conventions(cylinder):
    """Given s alone, the verdict says what s was taken as (C4's or G's
    polar angle in rad); given x, y it need not.  t_N of the wrong sign
    reads `outside` all round Γ, with the hint to check s's unit and
    direction and the sign conventions; the perturbed middle third (a
    third of Γ) gets no such hint."""
    scene, estimate, project = cylinder
    g = project["G"].columns
    [row] = judge(scene, outside_profiles(scene, {"G": {"s": g["s"], "tN": -g["tN"]}}), project, estimate,
                  "fe P2").rows
    assert set(row.columns["verdict"]) == {"outside"}
    taken, wide = row.hints
    assert taken.startswith("s was taken as the polar angle in rad, from +x anticlockwise about Γ's centre")
    assert "check s's unit, origin and direction, and the sign conventions" in wide and "docs/scenes.md" in wide
    [row] = judge(scene, outside_profiles(scene, {"G": {"x": g["x"], "y": g["y"], "tN": -g["tN"]}}), project,
                  estimate, "fe P2").rows
    [wide] = row.hints
    assert "check the sign conventions" in wide
    [row] = judge(scene, outside_profiles(scene, _perturbed(project)), project, estimate, "fe P2").rows
    assert len(row.hints) == 1 and row.hints[0].startswith("s was taken as")
    r = project["R"].columns
    [row] = judge(scene, outside_profiles(scene, {"R": {"s": r["s"], "ux": r["ux"]}}), project, estimate,
                  "fe P2").rows
    assert row.hints[0].startswith("s was taken as the arc length in mm from the profile's start (")


# --- bad input: one line naming the problem, before any solve -------------------------------------------------

S = list(np.linspace(0.0, 6.0, 5))
T = [-13.0] * 5


@pytest.mark.parametrize("outside, words", [
    ({"g": {"s": S, "tN": T}}, ["scene cylinder has no profile 'g'", "did you mean 'G'?", "its profiles: G, R"]),
    ({"G": {"tN": T}}, ["outside['G']", "no position column", "s", "x and y"]),
    ({"G": {"x": S, "tN": T}}, ["no position column", "only x given"]),
    ({"G": {"s": S, "tn": T}}, ["unknown quantity 'tn'", "did you mean 'tN'?"]),
    ({"G": {"s": S, "sxy": T}}, ["unknown quantity 'sxy'", "profile G samples gN, gT, tN, tT"]),
    ({"G": {"s": S, "tN": T[:4] + [float("nan")]}}, ["outside['G'].tN", "sample 4 is nan", "not a finite number"]),
    ({"G": {"s": S[:1], "tN": T[:1]}}, [f"1 sample: give at least {MIN_SAMPLES}", "one sample is a point"]),
    ({"G": {"s": [], "tN": []}}, [f"0 samples: give at least {MIN_SAMPLES}"]),
    ({"G": {"s": S, "tN": T[:4]}}, ["columns of different lengths", "s 5", "tN 4"]),
    ({"G": {"s": S[:4] + [7.0], "tN": T}}, ["sample 4: s = 7 rad lies off profile G", "from 0 to 6.28319 rad",
                                            "docs/scenes.md"]),
    ({"G": {"x": [2.53, 1.7], "y": [-0.4, 0.9], "tN": T[:2]}}, ["sample 1 (x = 1.7, y = 0.9 mm) lies",
                                                                  "mm off profile G"]),
    ({"G": {"s": [0.0, np.pi / 2], "x": [2.53, 1.7], "y": [-0.4, -1.23], "tN": T[:2]}},
     ["sample 1: s = 1.5708 rad is the point (1.7, 0.43)", "s's origin or direction differs"]),
    ({"R": {"s": [0.0, 0.5], "ux": [0.0, 0.1]}}, []),  # a line profile's s in mm: accepted
    ("not a mapping", ["outside: no *.csv", "neither a CSV file nor a folder"]),
])
def test_bad_input_is_one_line_naming_the_problem(outside, words, monkeypatch):
    monkeypatch.setattr(known, "solver", lambda name: pytest.fail("solved before refusing the input"))
    if not words:
        assert list(outside_profiles(load_scene(CYLINDER), outside)) == ["R"]
        return
    with pytest.raises(ContactError) as info:
        compare_outside(CYLINDER, outside, method="fe:2", h=tol.OUTSIDE_H)
    message = str(info.value)
    assert "\n" not in message
    if isinstance(outside, dict):
        assert isinstance(info.value, SceneError)
    assert any(w in message for w in words) if outside == "not a mapping" else all(w in message for w in words), \
        message


def test_bad_csvs_name_the_file_line_and_column(tmp_path):
    (tmp_path / "G.csv").write_text("s,tN\n0.0,-13\n1.0,abc\n")
    with pytest.raises(ContactError, match=r"G.csv line 3, column tN: 'abc' is not a number"):
        read_outside(tmp_path / "G.csv")
    (tmp_path / "G.csv").write_text("s,tN\n")        # newuser33's header-only file: 0 samples, named
    with pytest.raises(SceneError, match=f"0 samples: give at least {MIN_SAMPLES}"):
        outside_profiles(load_scene(CYLINDER), tmp_path / "G.csv")
    (tmp_path / "G.csv").write_text("s,tN\n0.0,-13\n\n1.0,nan\n")   # newuser34: a file's line, not an index
    with pytest.raises(SceneError, match=r"sample on line 4 of .*G.csv is nan"):
        outside_profiles(load_scene(CYLINDER), tmp_path / "G.csv")
    (tmp_path / "G.csv").write_text("s [rad],tN\n0.0,-13\n1.0,-13\n")
    with pytest.raises(SceneError, match=r"unknown quantity 's \[rad\]'.*position columns: s, x, y; headers are "
                                         r"bare names"):
        outside_profiles(load_scene(CYLINDER), tmp_path / "G.csv")
    (tmp_path / "G.csv").write_text("s,tN,tN\n0.0,-13,-13\n")  # review17 #10: a column named twice, named
    with pytest.raises(ContactError, match=r"G.csv line 1: the header names tN more than once"):
        read_outside(tmp_path / "G.csv")
    (tmp_path / "G.csv").write_bytes("s,tN\n0.0,-13\n".encode("utf-8-sig"))  # a spreadsheet's byte-order mark
    assert list(read_outside(tmp_path / "G.csv")["G"]) == ["s", "tN"]
    (tmp_path / "empty").mkdir()
    with pytest.raises(ContactError, match="no \\*.csv file in folder"):
        read_outside(tmp_path / "empty")


# --- the command line ------------------------------------------------------------------------------------------


def test_the_against_command_writes_the_verdict(cylinder, tmp_path, capsys):
    """``against FOLDER SCENE``: outside.md and outside.csv in the result
    folder, the verdict of every sample; a bad file ends in one line,
    exit status 2, and no folder."""
    from verification import __main__ as verification_main
    from verification.against_outside import CSV_COLUMNS
    _, _, project = cylinder
    given = tmp_path / "given"
    given.mkdir()
    outside = _perturbed(project)["G"]
    (given / "G.csv").write_text("s,tN\n" + "".join(f"{s!r},{t!r}\n" for s, t in zip(outside["s"], outside["tN"])))
    out = tmp_path / "out"
    assert verification_main.main(["against", str(given), str(CYLINDER), "--h", str(tol.OUTSIDE_H),
                                   "--estimate", "2", "--out", str(out)]) == 0
    text = (out / "outside.md").read_text()
    assert "# An outside answer against fe P2 on scene cylinder" in text and "outside 2.136–4.147 rad (33, " in text
    assert "Γ's normal n points from the − body into the + body" in text and "t_N > 0 is tension" in text
    assert "s was taken as the polar angle in rad" in text
    lines = (out / "outside.csv").read_text().splitlines()
    assert lines[0] == ",".join(CSV_COLUMNS) and len(lines) == 102
    assert [line.rsplit(",", 1)[1] for line in lines[1:]].count("outside") == 33
    units = json.loads((out / "units.json").read_text())["outside.csv"]
    assert units == {"s": "rad", "x": "mm", "y": "mm", "outside": "MPa", "project": "MPa", "estimate": "MPa",
                     "difference": "MPa"}
    assert set(CSV_COLUMNS) - set(units) == {"profile", "quantity", "s_unit", "unit", "verdict"}
    run = json.loads((out / "run.json").read_text())
    assert (run["method"], run["degree"], run["h"], run["levels"]) == ("fe", 2, tol.OUTSIDE_H, 2)
    assert run["exclude"] == pytest.approx(default_exclusion(load_scene(CYLINDER)))
    (given / "g.csv").write_text("s,tN\n0,1\n1,2\n")
    capsys.readouterr()
    assert verification_main.main(["against", str(given), str(CYLINDER), "--out", str(tmp_path / "no")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["error: outside['g']: scene cylinder has no profile 'g' (did you mean 'G'?) (its profiles: G, R)"]
    assert not (tmp_path / "no").exists()
    # newuser34: the warning's "try --estimate 3" is against's option too; --levels is not
    capsys.readouterr()
    assert verification_main.main(["against", str(given), str(CYLINDER), "--estimate", "3", "--out",
                                   str(tmp_path / "no")]) == 2
    assert "scene cylinder has no profile 'g'" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        verification_main.main(["against", str(given), str(CYLINDER), "--levels", "3", "--out", str(tmp_path / "no")])
    assert "unrecognized arguments: --levels" in capsys.readouterr().err


def test_each_estimate_warning_is_listed_once_without_repeating_its_keys():
    """newuser35: outside.md read "G:tT: G:tN, G:tT: an exact law's
    traction …", once per quantity.  A warning naming its quantities is
    listed once as written; one that names none (the status) follows the
    quantities it is given for."""
    from types import SimpleNamespace
    from verification.agreement.outside_table import _warned_lines
    traction = "G:tN, G:tT: an exact law's traction on Γ at order 1"
    status = "the status along Γ differs from h = 0.1 m to 0.05 m"
    rows = [SimpleNamespace(profile="G", quantity=q, warnings=(traction, status)) for q in ("tN", "tT")]
    assert _warned_lines(rows) == [f"- {traction}", f"- G:tN, G:tT: {status}"]
