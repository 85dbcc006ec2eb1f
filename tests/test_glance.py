"""Outputs a user reads at a glance: Ctrl-C, error messages, refusals, help
lines, units."""
from __future__ import annotations

import argparse
import csv
import json
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest
import tolerances as tol
from terminal import with_ctrl_c

from contactcore import SceneError, SolverError, health, load_scene, make_law, sample_profiles, scene_from_dict
from contactcore.laws import CoulombLaw
from verification import __main__ as verification_main
from verification.cli.parser import build_parser
from verification import files, methods, plots, study_parameters, study_plots, study_table

ROOT = Path(__file__).resolve().parents[1]
#: Long enough to be interrupted mid-solve: several seconds at h = 0.02, degree 2.
LONG_RUN = ["run", "A", "--method", "all", "--degree", "2", "--h", "0.02"]
#: A study on two local workers, interrupted while they solve.
POOLED_STUDY = ["study", "A", "--param", "kN", "--values", "1e9", "1e10", "1e11", "1e12", "--method", "fe",
                "--degree", "2", "--h", "0.02", "--workers", "2"]


def _interrupt(args: list[str], out: Path, sig: int = signal.SIGINT) -> subprocess.CompletedProcess:
    """Start ``python -m verification ARGS --out OUT`` in a process group of
    its own, wait for its first progress line, send ``sig`` to the whole
    group (as a terminal's Ctrl-C does SIGINT: pool workers too), collect its end."""
    proc = subprocess.Popen([sys.executable, "-m", "verification", *args, "--out", str(out)], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
                            preexec_fn=with_ctrl_c)
    seen = []
    for line in proc.stderr:
        seen.append(line)
        if line.startswith("INFO verification:"):
            break
    os.killpg(proc.pid, sig)
    stdout, rest = proc.communicate(timeout=120)
    return subprocess.CompletedProcess(proc.args, proc.returncode, stdout, "".join(seen) + rest)


@pytest.mark.parametrize("args", [LONG_RUN, POOLED_STUDY], ids=["run", "study-workers"])
def test_ctrl_c_ends_with_one_line_and_exit_130(args, tmp_path):
    done = _interrupt(args, tmp_path / "out")
    assert done.returncode == 130, done.stderr
    assert "Traceback" not in done.stderr, done.stderr
    assert done.stderr.rstrip().splitlines()[-1] == "interrupted"
    assert not (tmp_path / "out").exists()  # an interrupted run leaves no result folder


def test_sigterm_ends_like_ctrl_c_with_exit_143(tmp_path):
    """SIGTERM (kill, timeout, a batch scheduler) mid-run: one line, exit
    128 + 15, and neither the result folder nor the folder it was built in
    left behind (the latter was)."""
    done = _interrupt(LONG_RUN, tmp_path / "out", signal.SIGTERM)
    assert done.returncode == 143, done.stderr
    assert "Traceback" not in done.stderr and done.stderr.rstrip().splitlines()[-1] == "terminated"
    assert list(tmp_path.iterdir()) == []


def test_a_log_read_through_a_closed_pipe_does_not_abort_the_run(tmp_path):
    """``run … 2>&1 | head -1``: the reader goes after the first line, and
    PETSc (started by fe) caught the next write's SIGPIPE and aborted the
    run (status 59), leaving its build folder behind.  PETSc's handlers are
    off under the command line: the run ends normally and writes its
    result, and nothing else is left."""
    proc = subprocess.Popen([sys.executable, "-m", "verification", "run", "A", "--method", "fe", "--h", "0.2",
                             "--no-plots", "--out", str(tmp_path / "out")], cwd=ROOT,
                            stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    proc.stderr.readline()
    proc.stderr.close()  # the reader has gone
    assert proc.wait(timeout=120) == 0
    assert [p.name for p in tmp_path.iterdir()] == ["out"] and (tmp_path / "out" / "summary.md").exists()


#: The most lines a refusal may take on the user's screen.
ERROR_LINES = 2


def _refusal(scene_dict, edit, h) -> SolverError:
    data = scene_dict("A")
    edit(data)
    with pytest.raises(SolverError) as refused:
        methods.solver("fe")(scene_from_dict(data), h)
    return refused.value


def _coulomb(mu):
    def edit(data):
        data["interface"]["law"] = {"type": "coulomb", "kN": 1e10, "kT": 1e8, "mu": mu}
    return edit


def test_no_equilibrium_leads_with_the_friction_check(scene_dict):
    """Scene A's top traction (2.5e4, −1e5) asks the + block, held by Γ
    alone, for shear/normal = 0.25 on Γ; μ = 0.05 cannot carry it: the
    first line says so, the second that the scene's loads decided it
    before Newton (health.beyond_cone: no residual of a run that round-off
    could have moved, grader10 F1)."""
    error = _refusal(scene_dict, _coulomb(0.05), 0.1)
    lines = str(error).splitlines()
    assert len(lines) <= ERROR_LINES
    assert re.search(r"^scene A: increment 1 of 20: on Γ the loads ask for shear/normal = 0\.25 of body \+, "
                     r"above μ = 0\.05", lines[0]), lines[0]
    assert "before Newton" in lines[1] and "relative residual" not in str(error)


def test_friction_that_carries_the_load_is_not_blamed():
    """μ = 0.3 carries 0.25 of scene A: no friction check fails."""
    scene = load_scene("A").with_changes(law=CoulombLaw(1e10, 1e8, 0.3))
    assert health.friction_demand(scene, 1.0) == ""
    assert "shear/normal = 0.25" in health.friction_demand(scene.with_changes(law=CoulombLaw(1e10, 1e8, 0.2)), 1.0)


def test_a_nearly_incompressible_material_is_named_first(scene_dict):
    """Scene A in plane strain with ν = 0.4999999 (λ/μ = 2ν/(1 − 2ν) = 5e6)
    loses digits in every solve: the refusal names the material first, not
    the springs or a rigid mode."""
    def edit(data):
        data["plane"] = "strain"
        for m in data["materials"].values():
            m["nu"] = 0.4999999
    lines = str(_refusal(scene_dict, edit, None)).splitlines()
    assert len(lines) <= ERROR_LINES
    assert re.search(r"^scene A: materials\.minus\.nu and materials\.plus\.nu = 0\.4999999 in plane strain: "
                     r"λ/μ = 5\.0e\+06, nearly incompressible", lines[0]), lines[0]
    assert "rigid-body mode" not in str(lines)


def _subparsers(parser: argparse.ArgumentParser):
    for action in parser._actions:  # argparse keeps its subcommands on the subparsers action only
        if isinstance(action, argparse._SubParsersAction):
            yield from action.choices.items()


def test_every_cli_option_has_a_help_line():
    missing = [f"{name} {action.dest}" for name, sub in _subparsers(build_parser())
               for action in sub._actions if not action.help]
    assert not missing, missing


@pytest.mark.parametrize("scale, unit", [(500.0, "Pa"), (1.75e5, "kPa"), (2e6, "MPa"), (3e9, "GPa")])
def test_stress_axes_take_the_unit_that_fits(scale, unit):
    factor, label = plots.axis_unit("syy", scale)
    assert label == f"σyy ({unit})" and 1 <= scale / factor < 1000
    assert plots.axis_unit("gN", scale) == (1.0, "g_N (m)")


def test_a_run_folder_names_every_csv_columns_unit(tmp_path):
    """Scene A's stresses (≈ 1e5 Pa) are drawn in kPa; ``units.json``
    gives each CSV column's unit while the CSV headers stay bare names."""
    out = tmp_path / "run"
    assert verification_main.main(["run", "A", "--method", "fe", "--h", "0.2", "--no-plots", "-q",
                                   "--out", str(out)]) == 0
    units = json.loads((out / files.UNITS_FILE).read_text())
    assert units["fe/profiles/A2.csv"] == {"s": "m", "x": "m", "y": "m", "syy": "Pa"}  # a line profile: arc length
    assert units["fe/profiles/A5.csv"]["gN"] == "m"
    assert (out / "fe/profiles/A2.csv").read_text().splitlines()[0] == "s,x,y,syy"


def test_scene_a_stresses_are_drawn_in_kpa():
    """Scene A's σyy on Γ is about −1e5 Pa (its top traction): kPa."""
    scene = load_scene("A")
    result = methods.solver("fe")(scene, 0.2)
    a2 = next(p for p in sample_profiles(scene, result.fields, result.interface) if p.id == "A2")
    fig = plots.profile_figure("σyy", {"fe P1": a2, "fe P2": a2})
    assert [fig.axes[0].get_ylabel(), fig.axes[1].get_ylabel()] == ["σyy (kPa)", "Δσyy (kPa)"]
    plots.pyplot().close(fig)


def _study(tmp_path, *args) -> list[dict]:
    out = tmp_path / "study"
    assert verification_main.main(["study", *args, "--method", "fe", "--h", "0.2", "-q", "--out", str(out)]) == 0
    with open(out / "study.csv") as fh:
        return list(csv.DictReader(fh))


def test_study_varies_the_load(tmp_path):
    """A linear law: twice the load, twice the mean tractions on Γ (scene A's
    top traction (2.5e4, −1e5) averaged over Γ, to the solve's round-off)."""
    one, two = _study(tmp_path, "A", "--param", "load", "--values", "1", "2")
    for q in ("mean_tN", "mean_tT"):
        assert float(two[q]) == pytest.approx(2 * float(one[q]), rel=tol.PATCH_ROUNDOFF)  # a linear solve, scaled: round-off alone


def test_study_varies_mu_and_the_increments(tmp_path):
    """C-coulomb (μ = 0.2): μ and the increments reach the scene (a
    fractional count is refused before any solve: tests/test_cli.py)."""
    rows = _study(tmp_path, "C-coulomb", "--param", "mu", "--values", "0.2", "0.5", "--param", "increments",
                  "--values", "2")
    assert [(float(r["mu"]), float(r["increments"])) for r in rows] == [(0.2, 2), (0.5, 2)]
    assert all(r["status"] != "failed" for r in rows)
    scenes = [study_parameters.scene_at(load_scene("C-coulomb"), {"mu": mu, "increments": 2.0}) for mu in (0.2, 0.5)]
    assert [(s.law.mu, s.increments) for s in scenes] == [(0.2, 2), (0.5, 2)]


@pytest.mark.parametrize("scene, hint", [
    ("C-coulomb", 'vary it where --param enforcement is exact, or on a scene with enforcement = "exact"'),
    ("A", 'its limit k → ∞ is type = "bonded"')])
def test_study_refuses_a_stabilisation_of_springs(tmp_path, capsys, scene, hint):
    """Nitsche's β belongs to an exact law only: varied on a law enforced
    by its springs (its first point) the study ends before any solve with
    one line naming the parameter, and leaves no folder."""
    out = tmp_path / "study"
    args = ["study", scene, "--param", "stabilisation", "--values", "1", "10", "--method", "fe", "--h", "0.2", "-q",
            "--out", str(out)]
    assert verification_main.main(args) == 2
    err = capsys.readouterr().err
    assert err.startswith('error: --param stabilisation: applies to enforcement = "exact" only') and hint in err
    assert not out.exists()


EXACT_C = ("C-coulomb", {'type = "coulomb"': 'type = "coulomb"\nenforcement = "exact"'})


@pytest.mark.parametrize("param, edit, hint", [
    ("kN", EXACT_C, "vary kN where --param enforcement is penalty"),
    ("kT", EXACT_C, "vary kT where --param enforcement is penalty"),
    ("kN", ("C", {'type = "linear"': 'type = "bonded"', "kN = 1e10\n": "", "kT = 1e8\n": ""}),
     'type = "linear", with kN and kT, is its penalty counterpart'),
    ("stabilisation", EXACT_C, "must lie within"),
])
def test_study_refuses_springs_of_an_exact_law(tmp_path, capsys, param, edit, hint):
    """Under exact enforcement k_N, k_T play no part, and β outside its
    range is refused as a scene's is: varied on such a law (the study's
    first point) the study ends before any solve with one line naming the
    parameter, and leaves no folder."""
    from contactcore import scene_text
    base, replacements = edit
    text = scene_text(base)
    for old, new in replacements.items():
        text = text.replace(old, new)
    scene = tmp_path / "exact.toml"
    scene.write_text(text)
    out = tmp_path / "study"
    args = ["study", str(scene), "--param", param, "--values", "1e9", "1e11", "--method", "fe", "--h", "0.2", "-q",
            "--out", str(out)]
    assert verification_main.main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: --param {param}: ") and hint in err[0], err
    assert param == "stabilisation" or 'plays no part under enforcement = "exact"' in err[0]
    assert not out.exists()


@pytest.mark.parametrize("scene, values, message", [
    ("C-coulomb", ["exakt", "exact"], "--param enforcement: must be penalty or exact (got 'exakt')"),
    ("C", ["exact", "penalty"], "--param enforcement: interface.law.enforcement: the 'linear' law is enforced by "
                                "its springs only"),
])
def test_study_refuses_an_enforcement_it_cannot_give(tmp_path, capsys, scene, values, message):
    """An enforcement the scene's law cannot take, on the study's first
    point: one line naming the parameter once, exit 2, no folder."""
    out = tmp_path / "study"
    assert verification_main.main(["study", scene, "--param", "enforcement", "--values", *values, "--method", "fe",
                                   "--h", "0.2", "-q", "--out", str(out)]) == 2
    assert capsys.readouterr().err.startswith(f"error: {message}") and not out.exists()


def test_an_exact_law_has_no_penalty_to_fall_back_on():
    """``bonded`` exists only exactly: its penalty counterpart is named."""
    scene = load_scene("A").with_changes(law=make_law({"type": "bonded"}))
    with pytest.raises(SceneError, match=r'its file gives no kN or kT to enforce it by: add kN and kT to its '
                                         r'\[interface.law\] \(type = "linear", with kN and kT, is its penalty counterpart\)'):
        study_parameters.scene_at(scene, {"enforcement": "penalty"})


def test_a_study_enforces_an_exact_law_by_the_springs_its_file_gives():
    """docs/contact-enforcement.md: an exact law's kN, kT "may stay in the
    file … checked but not used"; the study's penalty point uses them (it
    refused: "an exact law keeps none, even those its file gives"), and
    without them it names what is missing."""
    given = {"type": "coulomb", "enforcement": "exact", "mu": 0.3, "kN": 2e9, "kT": 3e8}
    scene = load_scene("A").with_changes(law=make_law(given))
    law = study_parameters.scene_at(scene, {"enforcement": "penalty"}).law
    assert (law.enforcement, law.name, law.kN, law.kT, law.mu) == ("penalty", "coulomb", 2e9, 3e8, 0.3)
    bare = load_scene("A").with_changes(law=make_law({k: v for k, v in given.items() if k not in ("kN", "kT")}))
    with pytest.raises(SceneError, match=r"its file gives no kN or kT to enforce it by: add kN and kT"):
        study_parameters.scene_at(bare, {"enforcement": "penalty"})
    half = load_scene("A").with_changes(law=make_law({k: v for k, v in given.items() if k != "kN"}))
    with pytest.raises(SceneError, match=r"its file gives no kN to enforce it by: add kN to"):  # grader27 F5
        study_parameters.scene_at(half, {"enforcement": "penalty"})
    assert make_law(given) == bare.law  # the springs play no part in the exact law itself


def test_study_sets_the_enforcement_before_the_stabilisation(tmp_path):
    """In a product, whatever the order of the --param flags, β is set on
    the law as enforced: every exact point runs with its β, and the penalty
    points leave it aside and say so (as the exact points do k_N, k_T):
    their answer is the same at every β."""
    rows = _study(tmp_path, "C-coulomb", "--param", "stabilisation", "--values", "1", "10", "--param",
                  "enforcement", "--values", "exact", "penalty")
    assert all(r["status"] != "failed" for r in rows)
    exact = [r for r in rows if r["enforcement"] == "exact"]
    assert [float(r["stabilisation"]) for r in exact] == [1, 10] and not any("not applied" in r["message"]
                                                                             for r in exact)
    assert exact[0]["max_tN"] != exact[1]["max_tN"]                          # β reached the law
    penalty = [r for r in rows if r["enforcement"] == "penalty"]
    assert len(penalty) == 2 and all(r["message"].startswith('stabilisation not applied: it plays no part under '
                                                             'enforcement = "penalty"') for r in penalty)
    assert len({tuple(r[q] for q in study_table.OUTPUTS) for r in penalty}) == 1


def test_study_leaves_the_springs_aside_at_its_exact_points(tmp_path):
    """--param enforcement × --param kN (or kT): the penalty points take
    each spring, the exact points leave it aside and say so; their answer
    is the same at every spring, which moves the penalty's."""
    for spring in ("kN", "kT"):
        rows = _study(tmp_path, "C-coulomb", "--param", "enforcement", "--values", "penalty", "exact", "--param",
                      spring, "--values", "1e9", "1e10")
        penalty = [r for r in rows if r["enforcement"] == "penalty"]
        exact = [r for r in rows if r["enforcement"] == "exact"]
        assert all(r["status"] != "failed" for r in rows) and len(exact) == 2
        assert all(r["message"].startswith(f'{spring} not applied: it plays no part under enforcement = "exact"')
                   for r in exact) and not any("not applied" in r["message"] for r in penalty)
        assert len({tuple(r[q] for q in study_table.OUTPUTS) for r in exact}) == 1
        assert penalty[0]["max_tN"] != penalty[1]["max_tN"] or penalty[0]["max_tT"] != penalty[1]["max_tT"]


def test_study_plots_mark_failed_and_warned_points():
    """A ring on every warned point; at every failed one a vertical line
    across the panel (no mark at a height, which read as a value at the
    axis's bottom, grader2 item 12), named once in its series' legend entry."""
    rows = [{"value": v, "method": "fe", "status": st, **dict.fromkeys(study_table.OUTPUTS, 1.0 + v)}
            for v, st in ((1.0, "ok"), (2.0, "warned"), (3.0, "failed"))]
    fig = plots.pyplot().figure()
    ax = fig.add_subplot()
    colour = study_plots._series(ax, "value", "tN", 1.0, rows, study_plots._failed_label("fe", "value", rows))
    study_plots._mark(ax, "value", "tN", 1.0, rows, colour)
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert list(lines["fe: failed at 3 (dotted)"].get_xdata()) == [1.0, 2.0]
    assert list(lines["warned"].get_xdata()) == [2.0]
    vertical = [line for line in ax.get_lines() if line.get_transform() == ax.get_xaxis_transform()]
    assert len(vertical) == 1 and list(vertical[0].get_xdata()) == [3.0, 3.0]
    assert list(vertical[0].get_ydata()) == [0, 1]  # the whole panel's height, in axes units
    assert ax.get_legend_handles_labels()[1] == ["fe: failed at 3 (dotted)", "warned"]
    plots.pyplot().close(fig)


def _run(tmp_path, *args) -> Path:
    out = tmp_path / "run"
    assert verification_main.main(["run", "A", "--method", "xfem", "efgm", "--h", "0.2", "--no-plots", "-q",
                                   *args, "--out", str(out)]) == 0
    return out


def test_methods_are_compared_with_fe_p2_by_default(tmp_path):
    """Two degree-1 methods: fe at degree 2 is solved at the same h as the
    reference, listed in the summary, its profiles under reference/."""
    out = _run(tmp_path)
    summary = (out / "summary.md").read_text()
    assert "| reference: fe P2 | 2 |" in summary and "Each run against the reference: fe P2;" in summary
    assert json.loads((out / "run.json").read_text())["reference"] == "fe P2"
    assert (out / "reference" / "profiles" / "A1.csv").exists()


def test_the_reference_is_chosen_with_reference(tmp_path):
    """``--reference efgm:1``, one of the runs: nothing more is solved."""
    out = _run(tmp_path, "--reference", "efgm:1")
    assert "Each run against the reference: efgm P1;" in (out / "summary.md").read_text()
    assert not (out / "reference").exists()


def test_a_bad_reference_is_refused_by_the_parser(capsys):
    with pytest.raises(SystemExit) as ended:
        verification_main.main(["run", "A", "--reference", "fe:3", "--out", "unused"])
    err = capsys.readouterr().err.strip().splitlines()
    assert ended.value.code == 2 and len(err) == 1 and err[0].startswith("error: run: "), err
    assert "expected METHOD:DEGREE" in err[0]


@pytest.mark.parametrize("reached", ["building", "earlier-aside", "new-in-place"])
def test_a_build_settles_whichever_step_it_reached(tmp_path, reached):
    """A result folder under way (verification.janitor.Build), settled at
    each step of putting it in place: the build folder is gone, and the
    final name holds one whole run, the earlier one unless the new one was
    in place."""
    from verification.janitor import Build
    path, tmp = tmp_path / "out", tmp_path / ".out.abc"
    for folder, text in ((path, "earlier"), (tmp, "new")):
        folder.mkdir()
        (folder / "run.json").write_text(text)
    build = Build(path, tmp)
    if reached != "building":
        os.replace(path, build.earlier)
    if reached == "new-in-place":
        os.replace(tmp, path)
    build.settle()
    assert [p.name for p in tmp_path.iterdir()] == ["out"]
    assert (path / "run.json").read_text() == ("new" if reached == "new-in-place" else "earlier")


#: A process that builds a watched result folder (as rank 0 under mpirun),
#: handles SIGTERM in Python, then runs one call of compiled code that never
#: returns (Python runs no handler inside it).
STUCK_BUILDER = """
import signal, sys
from pathlib import Path
from verification import files
signal.signal(signal.SIGTERM, lambda *args: None)
with files.atomic_folder(Path(sys.argv[1]), watched=True) as tmp:
    (tmp / "half.csv").write_text("x\\n1\\n")
    print("building", flush=True)
    sum(range(2 ** 62))
"""


def test_a_janitor_speaks_and_settles_for_a_killed_process(tmp_path):
    """What mpirun does to rank 0 busy in one long call: SIGTERM, which
    Python cannot act on, then SIGKILL.  Its janitor says ``interrupted``
    once when the SIGTERM arrives (through the process's stderr) and
    removes the build folder when the process is gone."""
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-c", STUCK_BUILDER, str(out)], cwd=ROOT, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert proc.stdout.readline() == "building\n"
    os.kill(proc.pid, signal.SIGTERM)
    line = proc.stderr.readline()  # the janitor's, the process still stuck
    proc.kill()
    rest = proc.communicate(timeout=60)[1]  # its end: the janitor, holding the same stderr, has ended too
    assert line == "interrupted\n" and rest == ""
    assert list(tmp_path.iterdir()) == []


def test_a_janitor_whose_readers_are_gone_still_settles(tmp_path):
    """mpirun gone before the janitor speaks (its stderr's reader closed)
    and its process gone (the pipe for its byte closed): the janitor cannot
    say ``interrupted``, and still puts the earlier run back and removes
    the build folder at its pipe's end."""
    from verification import janitor
    from verification.janitor import Build
    path, tmp = tmp_path / "out", tmp_path / ".out.abc"
    for folder, text in ((path, "earlier"), (tmp, "new")):
        folder.mkdir()
        (folder / "run.json").write_text(text)
    build = Build(path, tmp)
    os.replace(path, build.earlier)
    signals, to_janitor = os.pipe()
    from_janitor, said = os.pipe()
    stderr_read, stderr_write = os.pipe()
    os.close(stderr_read)
    os.close(from_janitor)
    token = janitor._token()  # its process gone before taking it: the janitor takes it, and cannot say the line
    proc = subprocess.Popen([sys.executable, str(ROOT / "verification" / "janitor.py"), str(signals), str(said),
                             str(token), str(path), str(tmp)], pass_fds=(signals, said, token),
                            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=stderr_write)
    for fd in (signals, said, token, stderr_write):
        os.close(fd)
    os.write(to_janitor, bytes([signal.SIGTERM]))
    os.close(to_janitor)
    assert proc.wait(timeout=60) == 0
    assert [p.name for p in tmp_path.iterdir()] == ["out"] and (path / "run.json").read_text() == "earlier"


def test_a_janitor_that_cannot_start_leaves_no_build_folder(tmp_path, monkeypatch):
    """Rank 0's janitor refused by the system (no process to be had): the
    error goes on, and neither the build folder nor a record of it is left."""
    from verification import files, janitor
    from verification.files import result_folders

    def refused(*args, **kwargs):
        raise BlockingIOError("Resource temporarily unavailable")

    monkeypatch.setattr(janitor.subprocess, "Popen", refused)
    with pytest.raises(BlockingIOError):
        with files.atomic_folder(tmp_path / "out", watched=True):
            pass
    assert list(tmp_path.iterdir()) == [] and result_folders._BUILDING == [] and not janitor.watching()


#: A process that builds a watched result folder with PETSc started (as
#: rank 0 under mpirun: PETSc catches SIGPIPE and aborts on it), its janitor
#: killed by someone, then asked to end: what ``janitor.told`` answers.
KILLED_JANITOR = """
import sys
from pathlib import Path
import petsc4py
petsc4py.init()
from petsc4py import PETSc
from verification import files, janitor
with files.atomic_folder(Path(sys.argv[1]), watched=True):
    process = janitor._watching[0]
    process.kill()
    process.wait()
    print("told", janitor.told(15), flush=True)
print("watching", janitor.watching(), flush=True)
"""


def test_a_process_whose_janitor_was_killed_says_the_line_itself(tmp_path):
    """A janitor killed before its process is asked to end (someone's kill):
    telling it is no error (no SIGPIPE, on which PETSc aborts), and the
    process learns that no line was said, so that it says it itself
    (verification.cli.signals.end_now)."""
    done = subprocess.run([sys.executable, "-c", KILLED_JANITOR, str(tmp_path / "out")], cwd=ROOT, text=True,
                          capture_output=True, timeout=120)
    assert done.returncode == 0 and done.stdout.split() == ["told", "False", "watching", "False"], done
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


#: A ``sitecustomize`` that sends this process SIGINT the moment Python
#: opens ``verification/__main__.py`` (or its cached bytecode) to load it
#: (an audit hook on ``open``): a Ctrl-C that lands in that load.
_CTRL_C_AT_MAIN = '''
import os, signal, sys
def _hook(event, args):
    path = str(args[0]) if event == "open" and args and isinstance(args[0], (str, os.PathLike)) else ""
    if os.path.basename(path).startswith("__main__.") and f"{os.sep}verification{os.sep}" in path:
        os.kill(os.getpid(), signal.SIGINT)
sys.addaudithook(_hook)
'''


def test_ctrl_c_while_python_compiles_the_command_is_one_line(tmp_path):
    """``python -m verification``: Python imports the package, then reads
    and compiles ``__main__`` (10-20 ms without a bytecode cache),
    and only then ran the line that installs the start-up handler; a
    Ctrl-C meanwhile was Python's traceback.  The package installs it now,
    before ``__main__`` is read; imported any other way it installs none."""
    (tmp_path / "sitecustomize.py").write_text(_CTRL_C_AT_MAIN)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(tmp_path), os.environ.get("PYTHONPATH", "")])}
    done = subprocess.run([sys.executable, "-m", "verification", "run", "A", "--method", "efgm",
                           "--out", str(tmp_path / "out")], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=120, preexec_fn=with_ctrl_c)
    assert (done.returncode, done.stderr) == (130, "interrupted\n"), done.stderr[-2000:]
    assert not (tmp_path / "out").exists()
    imported = subprocess.run([sys.executable, "-c", "import signal, verification; "
                               "print(signal.getsignal(signal.SIGINT) is signal.default_int_handler)"],
                              cwd=ROOT, capture_output=True, text=True, timeout=120, preexec_fn=with_ctrl_c)
    assert imported.stdout.strip() == "True", imported.stderr


@pytest.mark.parametrize("orig, ours", [
    (["python", "-m", "verification"], True), (["python", "-Bm", "verification"], True),
    (["python", "-B", "-m", "verification"], True), (["python", "-mverification"], True),
    (["python", "-Wd", "-X", "dev", "-m", "verification"], True), (["python", "-Im", "verification"], True),
    (["python", "-m", "verification.janitor"], False), (["python", "-m", "other"], False),
    (["python", "-c", "import verification"], False),
])
def test_the_start_up_handler_knows_its_command_in_every_spelling(monkeypatch, orig, ours):
    """``python -Bm verification`` (flags joined before m) installed no
    start-up Ctrl-C handler, though -B is the no-bytecode case it is for
    (review, 2026-11-27)."""
    import verification
    monkeypatch.setattr(sys, "argv", ["-m"])
    monkeypatch.setattr(sys, "orig_argv", orig)
    assert verification._run_as_the_command() is ours


def test_two_series_failing_at_one_value_both_show():
    """grader11's fault 7: fe's dotted failure line lay exactly under
    xfem's; each series dashes it in its own phase, so both colours show."""
    fig = plots.pyplot().figure()
    ax = fig.add_subplot()
    for slot, method in enumerate(("fe", "xfem")):
        rows = [{"value": 1.0, "method": method, "status": "failed", **dict.fromkeys(study_table.OUTPUTS, 1.0)}]
        study_plots._mark(ax, "value", "tN", 1.0, rows, f"C{slot}", slot, 2)
    fe, xfem = ax.get_lines()
    assert list(fe.get_xdata()) == list(xfem.get_xdata())
    (fe_offset, fe_dashes), (xfem_offset, xfem_dashes) = fe._unscaled_dash_pattern, xfem._unscaled_dash_pattern
    assert fe_dashes == xfem_dashes and fe_dashes[0] == fe_dashes[1]  # a dash, a gap as long
    assert xfem_offset - fe_offset == fe_dashes[0]  # xfem's dashes fill fe's gaps
    plots.pyplot().close(fig)
