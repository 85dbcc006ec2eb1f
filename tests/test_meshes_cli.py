"""``python -m meshes`` refuses what ``python -m verification`` refuses, in
one ``error:`` line with exit 2 and before any meshing (grader9 #1, #2): an
``--out`` in a folder that cannot be written, below a file, that is an
existing folder, of an extension gmsh writes no mesh to, or empty; an ``--h``
that ``run`` refuses (larger than the domain, or a mesh too large for the
machine).  The path check is the one both commands share
(:func:`contactcore.errors.check_writable`)."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import meshes.__main__ as cli
from contactcore.errors import check_writable
from verification import files

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture
def never_meshes(monkeypatch):
    """Fail at once if the command gets as far as meshing (the old code ran
    gmsh for 80 s at h = 1e-6 and died of it)."""
    calls = []
    monkeypatch.setattr(cli, "write_mesh", lambda *a, **k: calls.append(a) or pytest.fail("meshed"))
    return calls


def _refusal(capsys, *argv) -> str:
    assert cli.main(["A", *map(str, argv)]) == 2
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    return lines[0]


@pytest.fixture
def read_only(tmp_path, monkeypatch):
    """A folder this process cannot write (root ignores the mode: chattr +i).
    Where neither makes it read-only (root without chattr), ``os.access``
    reports it unwritable, as it would for a read-only folder: the check
    under test reads the folder through ``os.access`` alone
    (``contactcore.errors.check_writable``), so the test still runs."""
    folder = tmp_path / "ro"
    folder.mkdir()
    frozen = (os.geteuid() == 0 and shutil.which("chattr") is not None
              and subprocess.run(["chattr", "+i", str(folder)], capture_output=True).returncode == 0)
    if not frozen:
        folder.chmod(0o555)
    if os.access(folder, os.W_OK):
        access = os.access
        monkeypatch.setattr(os, "access", lambda path, mode, *a, **k:
                            access(path, mode, *a, **k) and not (Path(path) == folder and mode & os.W_OK))
    yield folder
    if frozen:
        subprocess.run(["chattr", "-i", str(folder)], check=True)
    folder.chmod(0o755)


def _refused_as_verification_refuses(capsys, out, verification_out) -> None:
    line = _refusal(capsys, "--h", 0.2, "--out", out)
    with pytest.raises(files.OutFolderError) as refused:
        files.check_out(verification_out)
    assert line == f"error: {refused.value}".replace(str(verification_out), str(out))


def test_an_out_path_below_a_file_is_refused_as_verification_refuses_it(tmp_path, capsys, never_meshes):
    (tmp_path / "afile").write_text("")
    _refused_as_verification_refuses(capsys, tmp_path / "afile" / "x.msh", tmp_path / "afile" / "x")


def test_an_unwritable_out_path_is_refused_as_verification_refuses_it(read_only, capsys, never_meshes):
    _refused_as_verification_refuses(capsys, read_only / "x.msh", read_only / "x")


@pytest.mark.parametrize("name,problem", [("", "must name a file"), (".", "is a folder"),
                                          ("x.txt", "gmsh writes no mesh format of extension '.txt'"),
                                          ("x", "gmsh writes no mesh format of extension none")])
def test_an_out_that_is_a_folder_empty_or_of_no_mesh_format_is_refused(tmp_path, name, problem, capsys, never_meshes):
    out = str(tmp_path / name) if name else ""
    assert problem in _refusal(capsys, "--h", 0.2, "--out", out)


def test_an_h_that_run_refuses_is_refused_before_meshing(tmp_path, capsys, never_meshes):
    out = tmp_path / "x.msh"
    assert "exceeds the domain's smallest dimension" in _refusal(capsys, "--h", 100, "--out", out)
    assert "GB usable on this machine" in _refusal(capsys, "--h", 1e-6, "--out", out)
    assert "must be a finite number > 0" in _refusal(capsys, "--h", "nan", "--out", out)
    assert never_meshes == [] and not out.exists()


def test_a_grading_is_checked_at_its_size_on_the_interface(tmp_path, capsys, never_meshes):
    """The memory check takes h × the grade factor (a safe upper bound:
    as if the whole domain took it), not h: --grade 1e-5 at h = 0.1 meshed
    1.6e5 nodes, and smaller factors more, past the check at h (review6's
    fault 4)."""
    out = tmp_path / "x.msh"
    line = _refusal(capsys, "--h", 0.1, "--grade", 1e-3, "--out", out)
    assert line.startswith("error: --h 0.1 × --grade 0.001: the size 0.0001 with fe") and "GB usable" in line, line
    assert never_meshes == [] and not out.exists()


@pytest.mark.parametrize("argv, problem", [
    (["--grade", 1e-8, "--allow-large"], "--grade: 1e-08 makes the size on Γ h × 1e-08 = 1e-09, below 1e-06"),
    (["--grade", 1e-20, "--allow-large"], "--grade: 1e-20 makes the size on Γ"),
    (["--grade", "nan"], "--grade: the factor must be a finite number in (0, 1] (got nan)"),
    (["--grade", 2], "--grade: the factor must be a finite number in (0, 1] (got 2)"),
    (["--grade", 0.5, "--grade-distance", "inf"], "--grade-distance: must be a finite number > 0 (got inf)"),
    (["--grade", 0.5, "--grade-distance", 0], "--grade-distance: must be a finite number > 0 (got 0)"),
])
def test_a_grading_gmsh_cannot_mesh_is_refused_by_its_option(tmp_path, capsys, never_meshes, argv, problem):
    """A factor so small that gmsh aborts the process (--grade 1e-8 at
    h = 0.1: exit 134, "terminate called after throwing…", even with
    --allow-large), and an infinite distance (graded the whole domain), are
    refused in one line naming the option, before any meshing."""
    out = tmp_path / "x.msh"
    line = _refusal(capsys, "--h", 0.1, *argv, "--out", out)
    assert line.startswith(f"error: {problem}"), line
    assert never_meshes == [] and not out.exists()


def test_the_path_check_is_shared_and_touches_nothing(tmp_path):
    target = tmp_path / "new" / "deeper" / "x.msh"
    assert check_writable(target, kind="file") == target and not (tmp_path / "new").exists()
    with pytest.raises(ValueError, match="kind"):
        check_writable(target, kind="files")


def test_the_command_exits_2_with_one_line_and_no_traceback(tmp_path):
    done = subprocess.run([sys.executable, "-m", "meshes", "A", "--h", "0.2", "--out", str(tmp_path)],
                          cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and done.stderr.splitlines() == [f"error: --out: {tmp_path} is a folder; give the "
                                                                  "name of the file to write"]
