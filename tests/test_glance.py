"""Outputs a user reads at a glance: Ctrl-C, error messages, refusals, help
lines, units."""
from __future__ import annotations

import argparse
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from contactcore import SolverError, health, load_scene, scene_from_dict
from contactcore.laws import CoulombLaw
from verification import __main__ as verification_main
from verification import methods

ROOT = Path(__file__).resolve().parents[1]
#: Long enough to be interrupted mid-solve: several seconds at h = 0.02, degree 2.
LONG_RUN = ["run", "A", "--method", "all", "--degree", "2", "--h", "0.02"]
#: A study on two local workers, interrupted while they solve.
POOLED_STUDY = ["study", "A", "--param", "kN", "--values", "1e9", "1e10", "1e11", "1e12", "--method", "fe",
                "--degree", "2", "--h", "0.02", "--workers", "2"]


def _interrupt(args: list[str], out: Path) -> subprocess.CompletedProcess:
    """Start ``python -m verification ARGS --out OUT`` in a process group of
    its own, wait for its first progress line, send SIGINT to the whole
    group (as a terminal's Ctrl-C does: pool workers too), collect its end."""
    proc = subprocess.Popen([sys.executable, "-m", "verification", *args, "--out", str(out)], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    seen = []
    for line in proc.stderr:
        seen.append(line)
        if line.startswith("INFO verification:"):
            break
    os.killpg(proc.pid, signal.SIGINT)
    stdout, rest = proc.communicate(timeout=120)
    return subprocess.CompletedProcess(proc.args, proc.returncode, stdout, "".join(seen) + rest)


@pytest.mark.parametrize("args", [LONG_RUN, POOLED_STUDY], ids=["run", "study-workers"])
def test_ctrl_c_ends_with_one_line_and_exit_130(args, tmp_path):
    done = _interrupt(args, tmp_path / "out")
    assert done.returncode == 130, done.stderr
    assert "Traceback" not in done.stderr, done.stderr
    assert done.stderr.rstrip().splitlines()[-1] == "interrupted"
    assert not (tmp_path / "out").exists()  # an interrupted run leaves no result folder


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
    first line says so, the residual history of every cut-back is kept in
    ``details`` and not shown."""
    error = _refusal(scene_dict, _coulomb(0.05), 0.1)
    lines = str(error).splitlines()
    assert len(lines) <= ERROR_LINES
    assert re.search(r"^scene A: increment 1 of 20: on Γ the loads ask for shear/normal = 0\.25 of body \+, "
                     r"above μ = 0\.05", lines[0]), lines[0]
    assert len(error.details.splitlines()) > len(lines) and "relative residual" in error.details


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
    missing = [f"{name} {action.dest}" for name, sub in _subparsers(verification_main._parser())
               for action in sub._actions if not action.help]
    assert not missing, missing
