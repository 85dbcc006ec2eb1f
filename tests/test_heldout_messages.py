"""Messages and option handling faulted by the held-out user test
(/work/reports/grader1.md items 3, 9, 10, 11 and its last paragraph): a
refusal that names the wrong cause, a refused value quoted inside the range
it is refused for, an option silently replaced, a column described without
its sign convention, and a pooled study's Ctrl-C that printed a traceback."""
from __future__ import annotations

import argparse
import multiprocessing
import os
import re
import signal
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import pytest
from terminal import with_ctrl_c

from contactcore import SceneError, health, load_scene, scene_from_dict
from contactcore.scene import check_resolution
from contactcore.tolerances import NITSCHE_STABILISATION_RANGE
from verification import __main__ as verification_main
from verification import pool
from verification.cli.checks import check_cell

ROOT = Path(__file__).resolve().parents[1]
SCENES = Path(__file__).resolve().parent / "scenes"
#: grader1's presspull with its top pulled by a traction [0, 3] MPa; + held by Γ and an x-roller on the left.
PULL_ROLLER = SCENES / "pullroller.toml"


def _pull(edit=None):
    data = tomllib.loads(PULL_ROLLER.read_text())
    if edit:
        edit(data)
    return scene_from_dict(data).validated()


# ----- 1. the free-body check reads which directions the supports hold ----------

PULL_OFF = r"body \+: its supports and pins leave it free to move straight off Γ, and the loads pull it off Γ"


@pytest.mark.parametrize("law", ["unilateral", "coulomb"])
def test_a_body_held_by_a_roller_and_pulled_off_gamma_is_named(law):
    """The x-roller holds + in x only: nothing holds it in y but Γ, which
    only pushes, so the upward traction has no equilibrium.  The message
    blamed the unilateral law under shear (and coulomb, then advised, failed
    on "another stabilisation")."""
    def edit(d):
        if law == "coulomb":
            d["interface"]["law"].update(type="coulomb", mu=5.0)
    assert re.match(PULL_OFF, health.friction_demand(_pull(edit), 1.0))


def test_without_the_roller_the_body_is_held_by_gamma_alone():
    def edit(d):
        d["supports"] = d["supports"][:1]
    assert health.friction_demand(_pull(edit), 1.0) == ("body + is held by Γ alone and the loads pull it off Γ: no "
                                                        "equilibrium without a support")


@pytest.mark.parametrize("value", [[0.0, -3.0], [0.0, 0.0]])
def test_a_roller_held_body_pressed_onto_gamma_or_unloaded_is_not_refused(value):
    def edit(d):
        d["loads"][0]["value"] = value
    assert health.friction_demand(_pull(edit), 1.0) == ""


def test_a_body_free_to_turn_about_an_end_of_gamma_and_pulled_is_named():
    """A pin at Γ's left end (on +, within 1e-9 mm) holds + in x and y; the turn about it opens Γ
    everywhere, and an upward pull does work in it."""
    def edit(d):
        d["supports"] = d["supports"][:1]
        d["pins"] = [{"point": [3.0, -1.63 + 1e-9], "fix": "xy"}]
    assert re.match(r"body \+: its supports and pins leave it free to turn off Γ about \(3, -1\.63\), and the loads "
                    r"pull it off Γ", health.friction_demand(_pull(edit), 1.0))


def test_the_run_refuses_the_roller_held_pull_with_the_pull_off(tmp_path, capsys):
    out = tmp_path / "out"
    assert verification_main.main(["run", str(PULL_ROLLER), "--method", "efgm", "--h", "0.25", "--reference", "none",
                                   "--no-plots", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert re.search("^error: scene presspull: increment 1 of 1: " + PULL_OFF, err, re.M), err
    assert "unilateral law" not in err, err
    assert not out.exists()


def test_the_run_names_the_pivot_of_a_pin_held_pull_in_the_scenes_own_coordinates(tmp_path, capsys):
    """The run's refusal is decided on the dimensionless scene: its pivot
    is named in the user's coordinates, (3, -1.63) mm as the scene check
    names it, not the dimensionless (-1.1e-16, 0.185) it named before
    2026-11-29."""
    text = PULL_ROLLER.read_text().replace('[[supports]]\nboundary = "left"\nfix = "x"\n', "")
    assert text != PULL_ROLLER.read_text()
    scene = tmp_path / "pin.toml"
    scene.write_text(text + '\n[[pins]]\npoint = [3.0, -1.629999999]\nfix = "xy"\n')
    assert verification_main.main(["run", str(scene), "--method", "fe", "--h", "0.25", "--reference", "none",
                                   "--no-plots", "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "free to turn off Γ about (3, -1.63), and the loads pull it off Γ" in err, err


# ----- 2. a refused value is quoted on its own side of the range ----------------

@pytest.mark.parametrize("beta", ["30.000001", "0.2999999999"])
def test_an_out_of_range_stabilisation_is_quoted_outside_the_range(beta):
    """(grader1's test, on our own scene) `must lie within 0.3..30 (got 30)`."""
    text = PULL_ROLLER.read_text().replace('enforcement = "exact"\n', f'enforcement = "exact"\nstabilisation = {beta}\n')
    with pytest.raises(SceneError) as err:
        scene_from_dict(tomllib.loads(text)).validated()
    got = re.search(r"\(got ([^)]*)\)", str(err.value)).group(1)
    low, high = NITSCHE_STABILISATION_RANGE
    assert not low <= float(got) <= high, f"the refusal quotes {got}, inside the range it names: {err.value}"


def test_an_h_just_above_the_domain_is_quoted_above_it():
    scene = load_scene(str(PULL_ROLLER))  # 2 x 1 mm: h may be at most 1
    with pytest.raises(SceneError) as err:
        check_resolution(scene, 1.0000001)
    assert str(err.value).startswith("--h: 1.0000001 mm exceeds"), err.value


# ----- 3. --cell quad|triangle on a disc ----------------------------------------

@pytest.mark.parametrize("cell", ["triangle", "quad"])
def test_a_structured_cell_on_a_disc_is_refused(cell, tmp_path, capsys):
    """The docs: gmsh is the only choice for a disc; the run used it silently."""
    out = tmp_path / "out"
    assert verification_main.main(["run", str(SCENES / "cylinder.toml"), "--method", "xfem", "--cell", cell,
                                   "--no-plots", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0] == (f"error: --cell {cell}: the domain of scene cylinder is a disc, which only "
                                        f"gmsh meshes (structured {cell} cells fill a rectangle); use --cell gmsh or "
                                        "leave --cell out"), err
    assert not out.exists()



@pytest.mark.parametrize("command", [["run"], ["study", "--param", "kN", "--values", "1e9"]])
@pytest.mark.parametrize("method", ["fe", "efgm"])
def test_a_cell_for_a_method_that_takes_none_is_refused_before_the_disc(command, method, tmp_path, capsys):
    """``--method fe --cell quad`` on a disc got the disc refusal; fixing
    the disc (``--cell gmsh``) then met the refusal of --cell for fe: the
    first refusal names the first problem, a --cell fe does not take."""
    out = tmp_path / "out"
    argv = [command[0], str(SCENES / "cylinder.toml"), *command[1:], "--method", method, "--cell", "quad",
            "--out", str(out)]
    assert verification_main.main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"error: --cell: means nothing for {method} (only xfem take it)"], err
    assert not out.exists()

def test_gmsh_cells_on_a_disc_and_any_cell_on_a_rectangle_pass_the_check():
    for scene, cell in ((SCENES / "cylinder.toml", "gmsh"), (PULL_ROLLER, "triangle"), (PULL_ROLLER, "quad")):
        check_cell(argparse.Namespace(scene=str(scene), cell=cell))


# ----- 4. q_err columns are magnitudes ------------------------------------------

@pytest.mark.parametrize("doc", ["scenes.md", "error-estimates.md"])
def test_the_docs_say_the_error_columns_are_magnitudes(doc):
    text = " ".join((ROOT / "docs" / doc).read_text().split())
    said = [text[m.start():m.start() + 300] for m in re.finditer(r"`q_err`", text)]
    assert any("magnitude" in s and "unsigned" in s for s in said), said


# ----- 5. Ctrl-C of a pooled study ----------------------------------------------

def _square(x):
    return x * x


def _stopped_at(x):
    if x == 2:
        raise KeyboardInterrupt
    return x


def test_the_pool_is_shut_before_the_last_result_is_handed_over():
    """study zips its cases with the results and never asks past the last:
    the generator was left in the pool's `with`, whose shutdown then ran
    when the generator was collected, where a Ctrl-C became a traceback
    "ignored" and the command exited 0 with its output."""
    results = pool.map_cases(_square, [1, 2, 3], workers=2)
    got = [r for _, r in zip(range(3), results)]
    assert got == [1, 4, 9]
    assert multiprocessing.active_children() == []  # the workers were joined before 9 was handed over
    assert results.gi_frame is not None  # suspended at the last yield, which no try or with encloses...
    results.close()


def test_ctrl_c_in_a_serial_case_stops_the_cases_after_it():
    ran = []

    def case(x):
        ran.append(x)
        return _stopped_at(x)
    with pytest.raises(KeyboardInterrupt):
        list(pool.map_cases(case, [1, 2, 3]))
    assert ran == [1, 2]


def _mask_and_handler(_):
    return signal.SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, []), signal.getsignal(signal.SIGINT)


def _blocked_at_start(queue):
    queue.put(signal.SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, []))


def test_workers_start_with_ctrl_c_blocked_and_then_ignore_it():
    """A Ctrl-C that reached a worker while it started (the interpreter, the
    imports) raised KeyboardInterrupt there, a traceback per worker."""
    ctx = pool._SpawnDeaf()
    queue = ctx.SimpleQueue()
    child = ctx.Process(target=_blocked_at_start, args=(queue,))
    child.start()
    assert queue.get() is True
    child.join()
    assert not signal.SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, [])  # the parent's mask put back
    assert list(pool.map_cases(_mask_and_handler, [0], workers=2)) == [(False, signal.SIG_IGN)]


def test_ctrl_c_ends_the_workers_under_way():
    """`_stop` read the workers after the shutdown, which forgets them: none
    was ended, and the exit waited for the cases under way."""
    before = set(multiprocessing.active_children())  # other tests' processes in this worker: not this pool's
    executor = pool.executor(2)
    future = executor.submit(time.sleep, 600)
    while not future.running():
        time.sleep(0.05)
    children = [c for c in multiprocessing.active_children() if c not in before]
    assert children
    pool._stop(executor)
    for child in children:
        child.join(timeout=60)
    assert [c for c in children if _running(c)] == []


def _running(child) -> bool:
    """Whether ``child`` still runs.  Not ``is_alive()``: the pool's own
    thread joins its workers too, and where it reaps one first, this
    thread's ``waitpid`` fails and ``is_alive()`` stays True for a process
    that has ended (2 of 6 runs of this file at 7be9590, 2026-11-27).  A
    process runs while /proc has it and it is not a zombie."""
    if child.exitcode is not None:
        return False
    try:
        stat = Path(f"/proc/{child.pid}/stat").read_text()
    except FileNotFoundError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


#: A study on two local workers, still solving at the last delay below: with
#: tests/test_glance.py's four points at h = 0.02 it ended within 5 s on a
#: quiet AMD EPYC machine, before its interrupt (four at h = 0.01: 4.7 s);
#: twelve at h = 0.01 take about 10 s.
POOLED_STUDY = ["study", "A", "--param", "kN", "--values", "1e9", "2e9", "5e9", "1e10", "2e10", "5e10", "1e11",
                "2e11", "5e11", "1e12", "2e12", "5e12", "--method", "fe", "--degree", "2", "--h", "0.01",
                "--workers", "2"]


@pytest.mark.slow
@pytest.mark.parametrize("delay", [0.5, 1.0, 1.5, 2.0, 3.0, 4.0])
def test_ctrl_c_at_any_moment_of_a_pooled_study(delay, tmp_path):
    """Ctrl-C (SIGINT to the process group, as a terminal sends it) at a
    fixed delay, not after the first progress line: while the command
    imports, while the workers start, while they solve.  Before: exit -2
    with a traceback (imports), a traceback per starting worker, the pool's
    thread's InvalidStateError, or (grader1, under load) exit 0 with the
    output and a KeyboardInterrupt "ignored" in the pool's shutdown.  Not
    before 0.5 s: in the interpreter's own start (its site module, 0.15-0.2 s
    here under load 16) no code of ours runs yet, and Python prints "Fatal
    Python error: init_import_site" with a traceback."""
    for _ in range(3):
        out = tmp_path / "out"
        proc = subprocess.Popen([sys.executable, "-m", "verification", *POOLED_STUDY, "--out", str(out)], cwd=ROOT,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
                                preexec_fn=with_ctrl_c)
        time.sleep(delay)
        assert proc.poll() is None, "the study ended before its interrupt: lengthen POOLED_STUDY"
        os.killpg(proc.pid, signal.SIGINT)
        _, err = proc.communicate(timeout=300)
        assert proc.returncode == 130, err
        assert "Traceback" not in err and err.rstrip().splitlines()[-1] == "interrupted", err
        assert not out.exists()
