"""Every command that solves or evaluates at a size the user chooses refuses
one too large for this machine in one line, exit 2, before any work, as
``run``, ``study`` and ``efficiency`` do (grader11's fault 1: ``timing --h
0.1`` on a 1000 mm scene filled 21.7 GB for 35 min)."""
from __future__ import annotations

import subprocess

import pytest

from verification import methods, pool, shapes
from verification.__main__ import main


def _no_work(*_, **__):
    raise AssertionError("work started")


@pytest.mark.parametrize("argv, start", [
    (["timing", "A", "--method", "fe", "--h", "0.05", "0.001"], "error: --h 0.001 with fe (degree 1"),
    (["timing", "A", "C", "--method", "efgm", "--degree", "2", "--h", "1e-4"], "error: --h 0.0001 with efgm (degree 2"),
    (["scaling", "A", "--method", "xfem", "--h", "5e-4"], "error: --h 0.0005 with xfem (degree 1"),
    (["paper", "--scene", "A", "--ref-h", "1e-4"], "error: --ref-h 0.0001 with fe (degree 2"),
    (["shapes", "--points", "100000000"], "error: --grid 101 and --points 100000000"),
    (["shapes", "--grid", "20000"], "error: --grid 20000 and --points 200000"),
    (["sweeps", "--workers", "100000"], "error: --workers 100000: about 2.5e+04 GB for the processes alone"),
    (["study", "A", "--param", "h", "--values", "0.2", "--workers", "50000"], "error: --workers 50000: about 1.25e+04 GB"),
    (["scaling", "A", "--h", "0.2", "--ranks", "1", "20000"], "error: --ranks 20000: about 5e+03 GB"),
])
def test_a_size_past_the_machines_memory_is_refused_before_any_work(tmp_path, capsys, monkeypatch, argv, start):
    monkeypatch.setattr(methods, "solver", lambda *_: _no_work)
    monkeypatch.setattr(pool, "map_cases", _no_work)
    monkeypatch.setattr(subprocess, "run", _no_work)
    monkeypatch.setattr(shapes, "measure", _no_work)
    out = tmp_path / "t"
    assert main([*argv, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(start), err
    assert ("--allow-large" in err[0]) == (argv[0] != "sweeps"), err  # offered where the command has it
    assert not out.exists()


@pytest.mark.parametrize("command", ["timing", "scaling", "paper", "shapes", "run", "study", "efficiency",
                                     "effectivity"])
def test_every_command_with_a_size_check_offers_allow_large(capsys, command):
    with pytest.raises(SystemExit):
        main([command, "--help"])
    assert "--allow-large" in capsys.readouterr().out
