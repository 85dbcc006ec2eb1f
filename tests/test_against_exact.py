"""``run --against-exact`` (verification.against_exact): how far a penalty
answer at the scene's springs is from the same law enforced exactly, and
the one-line refusal of a scene with nothing to compare."""
import json

import numpy as np
import pytest

import tolerances as tol
from contactcore import estimate as est
from contactcore import load_scene, make_law, sample_profiles, scene_text
from contactcore.laws import STATUS_NAMES
from contactcore.tolerances import EXCLUDE_FRACTION
from verification import files, methods
from verification import run as run_driver
from verification.__main__ import main
from verification.agreement import default_exclusion, gap_floor, percent
from verification.closed_forms import layered_slip
from verification.run_summary import NOT_ESTIMATED_MARK

#: C-coulomb's resolution here: every method's exact solve converges at 0.1
#: from the committed state (at 0.2, fe P1's first increment needs Newton's
#: restart from 10β, docs/newton.md).
H = 0.1
#: Scene C's rectangle [0, 2] x [0, 3] (contactcore/scenes/C-coulomb.toml):
#: its corners are the singular points, Γ (a circle) meets no edge.
C_CORNERS = np.array([(0.0, 0.0), (2.0, 0.0), (2.0, 3.0), (0.0, 3.0)])
C_EXCLUDE = EXCLUDE_FRACTION * np.hypot(2.0, 3.0)  # docs/verification.md: a share of the diameter


@pytest.fixture(scope="module")
def coulomb_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("against_exact") / "out"
    assert main(["run", "C-coulomb", "--method", "fe", "--h", str(H), "--against-exact", "--no-plots",
                 "--out", str(out)]) == 0
    return out


def _record(out, method="fe") -> dict:
    return json.loads((out / method / "summary.json").read_text())["against_exact"]


def _columns(folder, pid) -> dict:
    return {k: np.array(v) for k, v in files.read_profile_csv(folder / "profiles" / f"{pid}.csv").items()}


def test_the_section_lists_every_profile_quantity_and_both_status_splits(coulomb_run):
    text = (coulomb_run / "summary.md").read_text()
    record = _record(coulomb_run)
    scene = load_scene("C-coulomb")
    assert "## Penalty against exact" in text and "| fe (exact) | 1 |" in text  # the exact run's row too
    assert {pid: list(qs) for pid, qs in record["profiles"].items()} == {p.id: list(p.quantities)
                                                                         for p in scene.profiles}
    for pid, quantities in record["profiles"].items():
        for q in quantities:
            assert f"| fe P1 | {pid} | {q} |" in text
    for enforcement in ("penalty", "exact"):
        assert f"| fe P1 | {enforcement} |" in text
    assert json.loads((coulomb_run / "run.json").read_text())["against_exact"] is True
    assert (coulomb_run / "fe" / "exact" / "increments.csv").exists()
    assert json.loads((coulomb_run / "fe" / "exact" / "summary.json").read_text())["ranks"] == 1  # as its twin's


def test_the_shares_are_the_difference_of_the_written_profiles(coulomb_run):
    """Recomputed from the two runs' profile CSVs: Δ = penalty − exact over
    the samples at least 0.1 L from a corner, max |Δ| over the largest
    scale and RMS(Δ) over RMS(scale), the scale |g| (floored,
    verification.agreement.gap_floor) or |t| on Γ."""
    record = _record(coulomb_run)
    floor = {"g": gap_floor(load_scene("C-coulomb")), "t": 0.0}
    for pid, quantities in record["profiles"].items():
        pen, ex = _columns(coulomb_run / "fe", pid), _columns(coulomb_run / "fe" / "exact", pid)
        xy = np.column_stack([ex["x"], ex["y"]])
        keep = np.linalg.norm(xy[:, None] - C_CORNERS[None], axis=-1).min(axis=1) >= C_EXCLUDE
        for q, got in quantities.items():
            diff = (pen[q] - ex[q])[keep]
            pair = {"g": ("gN", "gT"), "t": ("tN", "tT")}.get(q[0]) if pid == "C4" else None
            scale = np.hypot(np.hypot(ex[pair[0]], ex[pair[1]]), floor[q[0]])[keep] if pair else np.abs(ex[q][keep])
            assert got["kept"] == keep.sum() and got["samples"] == len(keep)
            assert got["worst"] == pytest.approx(np.abs(diff).max() / scale.max(), rel=tol.SAME_SUMS)
            assert got["rms"] == pytest.approx(np.sqrt(np.mean(diff ** 2) / np.mean(scale ** 2)), rel=tol.SAME_SUMS)
            assert got["largest_difference"] == pytest.approx(np.abs(diff).max(), rel=tol.SAME_SUMS)
            # the scales are floored by round-off too (1e-8 of the kind's largest: within SAME_SUMS here)
            assert got["scale"] == pytest.approx(scale.max(), rel=tol.SAME_SUMS)
            assert got["largest_exact"] == np.abs(ex[q][keep]).max()
            own = np.hypot(ex[q], floor[q[0]] if pair else 0.0)[keep]  # its own size, a gap floored
            assert got["own_size"] == pytest.approx(own.max(), rel=tol.SAME_SUMS)
            assert got["worst_own"] == pytest.approx(np.abs(diff).max() / own.max(), rel=tol.SAME_SUMS)


def test_the_share_of_its_own_size_shows_the_penalty_missing_t_t(coulomb_run):
    """C-coulomb's penalty t_T, at k_T = 1e8 Pa/m, is a few hundred Pa where
    the exact t_T reaches 6.7e4 Pa, a fifth of |t|: as a share of |t| the
    miss reads a fifth, as a share of t_T's own size at least
    1 − max|t_T penalty| / max|t_T exact| (the triangle inequality at the
    exact's largest sample), and summary.md shows both."""
    record = _record(coulomb_run)["profiles"]["C4"]["tT"]
    pen, ex = _columns(coulomb_run / "fe", "C4"), _columns(coulomb_run / "fe" / "exact", "C4")
    xy = np.column_stack([ex["x"], ex["y"]])
    keep = np.linalg.norm(xy[:, None] - C_CORNERS[None], axis=-1).min(axis=1) >= C_EXCLUDE
    bound = 1.0 - np.abs(pen["tT"][keep]).max() / np.abs(ex["tT"][keep]).max()
    assert record["worst_own"] >= bound > record["worst"]
    text = (coulomb_run / "summary.md").read_text()
    assert "| of its own size |" in text
    assert f"| fe P1 | C4 | tT | {percent(record['worst'])} | {percent(record['worst_own'])} |" in text


def test_the_exact_answer_is_the_scene_solved_with_its_law_enforced_exactly(coulomb_run):
    """The run's exact profiles and both status splits are those of direct
    solves of C-coulomb, as it is and with its law built exactly by hand."""
    scene = load_scene("C-coulomb")
    twin = scene.with_changes(law=make_law({"type": "coulomb", "mu": scene.law.mu, "enforcement": "exact"}))
    record = _record(coulomb_run)
    for folder, s, enforcement in ((coulomb_run / "fe", scene, "penalty"),
                                   (coulomb_run / "fe" / "exact", twin, "exact")):
        result = methods.solver("fe")(s, H)
        for prof in sample_profiles(s, result.fields, result.interface):
            written = _columns(folder, prof.id)
            for q in prof.names[3:]:
                scale = np.abs(prof.columns[q]).max()
                assert np.abs(written[q] - prof.columns[q]).max() <= tol.REPEATED_SOLVE * scale
        final, w = result.interface.final, result.interface.weights
        split = record["status"][enforcement]
        for code, name in enumerate(STATUS_NAMES):
            assert split[name] == np.sum(final.status == code)
            assert split[f"{name}_share"] == pytest.approx(w[final.status == code].sum() / w.sum(), rel=tol.SAME_SUMS)


@pytest.mark.parametrize("method", ["fe", "efgm"])
def test_on_the_layered_closed_form_the_difference_is_the_springs_interpenetration(tmp_path, method):
    """layered-slip, pressed by p and slipping all along Γ: both answers
    carry t_N = −p and t_T = μp, so the whole difference is the penalty's
    g_N = −p/k_N (the exact g_N is 0), and both slip everywhere."""
    assert main(["run", "layered-slip", "--method", method, "--against-exact", "--no-plots",
                 "--out", str(tmp_path / "out")]) == 0
    record = _record(tmp_path / "out", method)
    case = layered_slip()
    u_tol, sigma_tol = tol.FRICTION_CLOSED_FORM[method]
    gap = record["profiles"]["L1"]
    assert gap["gN"]["largest_difference"] == pytest.approx(case.history()[-1].p / case.kN, rel=u_tol)
    assert gap["tN"]["worst"] <= sigma_tol and gap["tT"]["worst"] <= sigma_tol
    for enforcement in ("penalty", "exact"):
        split = record["status"][enforcement]
        assert split["open"] == split["stick"] == 0 and split["slip"] > 0


def test_a_run_without_the_flag_solves_no_exact_answer(tmp_path, monkeypatch):
    def refuse(*args, **kwargs):
        raise AssertionError("an exact solve that was not asked for")
    monkeypatch.setattr(run_driver, "_against_exact", refuse)
    assert main(["run", "layered-slip", "--method", "fe", "--no-plots", "--out", str(tmp_path / "out")]) == 0
    assert "against_exact" not in json.loads((tmp_path / "out" / "fe" / "summary.json").read_text())
    assert "Penalty against exact" not in (tmp_path / "out" / "summary.md").read_text()
    assert not (tmp_path / "out" / "fe" / "exact").exists()


@pytest.mark.parametrize("scene, problem", [
    ("C", "'linear' law is enforced by its springs only"),
    ("exact", "'coulomb' law is already enforced exactly"),
    ("bonded", "'bonded' law is already enforced exactly, so there is no penalty answer to compare with it "
               "(type = \"linear\", with kN and kT, is its penalty counterpart)"),
])
def test_a_scene_with_nothing_to_compare_is_refused_in_one_line(tmp_path, capsys, scene, problem):
    if scene == "exact":
        scene = tmp_path / "C-coulomb-exact.toml"
        scene.write_text(scene_text("C-coulomb").replace('type = "coulomb"', 'type = "coulomb"\nenforcement = "exact"'))
    if scene == "bonded":
        scene = tmp_path / "C-bonded.toml"
        scene.write_text(scene_text("C").replace('type = "linear"', 'type = "bonded"').replace("kN = 1e10\n", "")
                         .replace("kT = 1e8\n", ""))
    out = tmp_path / "out"
    assert main(["run", str(scene), "--method", "fe", "--h", str(H), "--against-exact", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: --against-exact: ") and problem in err[0]
    assert not out.exists()


def test_with_an_estimate_the_exact_run_is_estimated_as_the_penalty_run(tmp_path):
    """``--estimate --against-exact``: the exact run is solved at h and h/2
    too, its estimate (summary.json, q_err columns, summary.md's row) that
    of direct exact solves at those h, and the penalty run at h/2 is
    compared with the exact run at h/2."""
    out = tmp_path / "out"
    assert main(["run", "C-coulomb", "--method", "fe", "--h", str(H), "--estimate", "2", "--against-exact",
                 "--no-plots", "--out", str(out)]) == 0
    scene = load_scene("C-coulomb")
    twin = scene.with_changes(law=make_law({"type": "coulomb", "mu": scene.law.mu, "enforcement": "exact"}))
    summary = json.loads((out / "fe" / "exact" / "summary.json").read_text())
    assert summary["estimate"]["h"] == pytest.approx([H, H / 2])
    assert summary["discretisation"]["h"] == pytest.approx(H / 2)
    assert json.loads((out / "fe" / "summary.json").read_text())["discretisation"]["h"] == pytest.approx(H / 2)
    runs = [methods.solver("fe")(twin, h) for h in (H, H / 2)]
    direct = est.estimate_runs(twin, runs, default_exclusion(twin))
    written = _columns(out / "fe" / "exact", "C4")
    for q, e in direct.profiles["C4"].items():
        assert np.abs(written[f"{q}_err"] - e.error).max() <= tol.REPEATED_SOLVE * np.abs(written[q]).max()
    worst = summary["estimate"]["worst"]
    row = next(line for line in (out / "summary.md").read_text().splitlines() if line.startswith("| fe (exact) |"))
    assert f"| {worst['relative']:.2e} ({worst['at']}) |" in row and NOT_ESTIMATED_MARK not in row


def test_a_gamma_component_without_its_partner_is_measured_against_its_own_size():
    """A line profile along Γ holding g_N and t_T but not g_T, t_N: each is
    measured against its own |value|, the gap floored as on an interface
    profile (it was measured against its unfloored self: 1e6 %)."""
    from contactcore.profiles import ProfileData
    from verification.against_exact import scales

    scene = load_scene("C-coulomb")
    gN, tT = np.array([0.0, 1e-9, -2e-9]), np.array([1.0, -2.0, 3.0])
    prof = ProfileData("L", "arclength", {"s": np.arange(3.0), "x": np.zeros(3), "y": np.zeros(3), "gN": gN,
                                          "tT": tT})
    got = scales(scene, {"L": prof})
    assert np.allclose(got["L", "gN"], np.hypot(gN, gap_floor(scene))) and np.allclose(got["L", "tT"], np.abs(tT))


def test_round_off_is_no_difference_and_a_users_floor_reaches_the_table():
    """A quantity zero in the exact answer (σxy of a uniform pressure):
    penalty and exact differ by round-off (1e-14 against σxx = 1e5), which
    read as 150–880 % of its own round-off; it is now measured against
    round-off of its kind (NEGLIGIBLE_SHARE of σxx's size), and a user's
    floor takes its place where larger."""
    from contactcore import ProfileData
    from verification.against_exact import differences
    from verification.agreement import NEGLIGIBLE_SHARE

    scene = load_scene("A")
    scene = scene.with_changes(profiles=tuple(p for p in scene.profiles if p.id == "A1"))
    s = np.linspace(0.0, 1.0, 101)

    def run(sxy):
        return {"A1": ProfileData("A1", "arclength", {"s": s, "x": s, "y": np.full_like(s, 0.5),
                                                      "sxx": np.full_like(s, 1e5), "sxy": sxy})}

    wobble = 1e-14 * np.sin(37 * s)
    [_, sxy] = differences(scene, "fe", run(wobble), run(-wobble))
    assert sxy.quantity == "sxy" and sxy.worst <= 2 * np.max(np.abs(wobble)) / (NEGLIGIBLE_SHARE * 1e5)
    [_, floored] = differences(scene, "fe", run(np.ones_like(s)), run(np.zeros_like(s)), floors={"sxy": 1e3})
    assert floored.worst == pytest.approx(1.0 / 1e3, rel=tol.SAME_SUMS)
