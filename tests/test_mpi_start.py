"""MPI starts before a result folder is made (grader22's F1, 2026-11-28):
an Open MPI start that aborts the process from C (1 of 209 launches, a
session directory's mkdir racing another run's) left the folder built
aside, ``.NAME.xxxx``, behind.  Reproduced here on demand by giving Open
MPI a session directory it cannot make."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("mpi4py")

#: A session directory base Open MPI cannot create: its start aborts, as
#: the race's "mkdir … File exists" did.
UNMAKEABLE = "/proc/no-such-dir"


@pytest.mark.parametrize("method", ["fe", "efgm"])
def test_an_mpi_start_that_aborts_leaves_no_folder(tmp_path, method):
    env = {**os.environ, "OMPI_MCA_orte_tmpdir_base": UNMAKEABLE}
    done = subprocess.run([sys.executable, "-m", "verification", "run", "A", "--method", method, "--h", "0.25",
                           "--reference", "none", "--no-plots", "-q", "--out", str(tmp_path / "r")],
                          cwd=Path(__file__).resolve().parents[1], env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode != 0 and "mkdir" in done.stderr, done.stderr[-500:]
    assert os.listdir(tmp_path) == []
