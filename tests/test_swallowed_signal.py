"""A Ctrl-C or SIGTERM whose exception Python swallows (its handler ran in
a finalizer or a weakref callback: "Exception ignored in …") still ends
the command: the result folder is not put in place and the exception is
raised when the block ends (mainsplit, 2026-11-28: main's code printed the
ignored Terminated, wrote its results and exited 0)."""
from __future__ import annotations

import signal
import weakref

import pytest

from verification import files
from verification.cli.signals import Terminated, signals_end_the_command


class _Held:
    """An object whose finalizer raises ``sig`` in this process."""


@pytest.mark.filterwarnings("ignore::pytest.PytestUnraisableExceptionWarning")  # the swallowed exception, reported
@pytest.mark.parametrize("sig, ending", [(signal.SIGTERM, Terminated), (signal.SIGINT, KeyboardInterrupt)])
def test_a_signal_a_finalizer_swallows_still_ends_the_command(tmp_path, sig, ending):
    out = tmp_path / "R"
    with pytest.raises(ending), signals_end_the_command(0, False), files.result_folder(out) as tmp:
        held = _Held()
        weakref.finalize(held, signal.raise_signal, sig)
        del held  # the handler raises in the finalizer, which Python reports and ignores
        (tmp / "done.txt").write_text("the block went on")
    assert not out.exists()
    assert not list(tmp_path.iterdir())  # no temporary folder left either


def test_a_command_after_an_interrupted_one_is_not_ended_by_its_signal(tmp_path):
    """The record is the command's own: the next command in the same
    process writes its results."""
    with pytest.raises(Terminated), signals_end_the_command(0, False), files.result_folder(tmp_path / "A"):
        signal.raise_signal(signal.SIGTERM)
    with signals_end_the_command(0, False), files.result_folder(tmp_path / "B") as tmp:
        (tmp / "done.txt").write_text("written")
    assert (tmp_path / "B" / "done.txt").is_file()
