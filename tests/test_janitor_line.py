"""Rank 0 under mpirun, asked to end, says ``interrupted`` once, and before
it exits (mpirun forwards a rank's output only while the rank lives),
however slow its janitor is to wake (verification.janitor: told, the
token).  Before the token, rank 0 waited 0.5 s (SAID_WAIT) for the
janitor's line and exited without it: a janitor not scheduled in time said
it after rank 0 had gone, and under mpirun the line was lost."""
import os
import signal
import sys
from contextlib import contextmanager

import pytest

from verification import janitor


@contextmanager
def _watched(tmp_path):
    """A janitor watching a build folder under ``tmp_path``, the signal
    SIGUSR1 handled in Python (so the C handler writes it to the janitor,
    :func:`signal.set_wakeup_fd`) while it watches."""
    tmp = tmp_path / ".out.abc"
    tmp.mkdir()
    before = signal.signal(signal.SIGUSR1, lambda *args: None)
    janitor.watch(janitor.Build(tmp_path / "out", tmp))
    process = janitor._watching[0]
    try:
        yield process
    finally:
        os.kill(process.pid, signal.SIGCONT)
        if janitor.watching():
            janitor.unwatch()
        signal.signal(signal.SIGUSR1, before)


def _end_as_rank_0(signum) -> None:
    """What rank 0's handler says (verification.cli.signals.end_now)."""
    if not janitor.told(signum):
        print(janitor.INTERRUPTED_LINE, file=sys.stderr, flush=True)


@pytest.mark.parametrize("janitor_runs", [False, True], ids=["janitor-not-scheduled", "janitor-running"])
def test_rank_0_ends_with_the_line_out_once(tmp_path, capfd, janitor_runs):
    """A janitor stopped (SIGSTOP: a loaded machine that does not schedule
    it) or running: by the time rank 0's handler returns, ``interrupted``
    is out exactly once, and the janitor, let go on, adds no second one
    and still removes the build folder."""
    with _watched(tmp_path) as process:
        if not janitor_runs:
            os.kill(process.pid, signal.SIGSTOP)
        os.kill(os.getpid(), signal.SIGUSR1)
        _end_as_rank_0(signal.SIGUSR1)
        assert capfd.readouterr().err.splitlines().count(janitor.INTERRUPTED_LINE) == 1
    assert capfd.readouterr().err.count(janitor.INTERRUPTED_LINE) == 0
    assert list(tmp_path.iterdir()) == []
