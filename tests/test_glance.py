"""Outputs a user reads at a glance: Ctrl-C, error messages, refusals, help
lines, units."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

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
