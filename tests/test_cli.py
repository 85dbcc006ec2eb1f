"""The command line's own rules, checked before any solve: one way to name
the result folder, one ``--workers`` default, help that explains its
choices, and refusals in one line with exit status 2."""
import argparse

import pytest

from verification.__main__ import _parser, main
from verification.study import PARAMETERS
from verification.sweeps import sweeps


def _subparsers(parser: argparse.ArgumentParser):
    for action in parser._actions:  # argparse keeps its subcommands on the subparsers action only
        if isinstance(action, argparse._SubParsersAction):
            yield from action.choices.items()


def _refused(argv, capsys) -> str:
    """The one line with which the parser refuses ``argv`` (exit status 2)."""
    with pytest.raises(SystemExit) as ended:
        main(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert ended.value.code == 2 and len(err) == 1, err
    return err[0]


def test_every_command_takes_its_folder_as_out(capsys):
    """``--out DIR`` on every command, ``report`` too; a bare folder is refused."""
    for name, sub in _subparsers(_parser()):
        outs = [a for a in sub._actions if a.dest == "out"]
        assert [a.option_strings for a in outs] == [["--out"]], name
    assert _parser().parse_args(["report", "--out", "R", "--quick"]).out.name == "R"
    assert _refused(["report", "R", "--quick"], capsys).startswith("error: report: ")


def test_every_command_that_takes_workers_has_one_default_and_one_help():
    """``--workers``: the same default (:data:`~verification.pool.DEFAULT_WORKERS`)
    and the same help line wherever it is taken."""
    from verification.pool import DEFAULT_WORKERS
    found = {name: a for name, sub in _subparsers(_parser()) for a in sub._actions if a.dest == "workers"}
    assert set(found) == {"study", "sweeps", "efficiency", "paper", "benchmark", "report"}
    assert {a.default for a in found.values()} == {DEFAULT_WORKERS} == {1}
    assert len({a.help for a in found.values()}) == 1 and f"default {DEFAULT_WORKERS}" in found["study"].help


@pytest.mark.parametrize("command, option, expected", [
    ("sweeps", "--sweep NAME", {s.name: s.what for s in sweeps()}),
    ("study", "--param NAME", {p: what for p, (what, _) in PARAMETERS.items()}),
])
def test_help_explains_each_choice_in_one_line(capsys, command, option, expected):
    """``sweeps --help`` and ``study --help`` list every sweep or parameter
    on a line of its own, with what it is."""
    with pytest.raises(SystemExit) as ended:
        main([command, "--help"])
    text = capsys.readouterr().out
    assert ended.value.code == 0 and f"\n{option}:\n" in text
    lines = text.split(f"\n{option}:\n")[1].splitlines()
    assert [line.split()[0] for line in lines] == list(expected)
    assert all(line.endswith(f"  {what}") for line, what in zip(lines, expected.values()))
