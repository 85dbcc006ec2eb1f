"""A result folder under way, put right when the process that builds it
cannot: rank 0 under mpirun.

:func:`verification.files.atomic_folder` builds a result folder beside
its final name and moves an earlier folder aside until the new one is in
place (:class:`Build`); an interrupted process puts that right as it
ends.  mpirun passes Ctrl-C (and its own SIGTERM) on to its ranks as
SIGTERM and kills them a second later (Open MPI's
``odls_base_sigkill_timeout``): a rank busy in one long call of a compiled
library (a factorisation, loading a library) is killed before Python can
run its handler.  So rank 0 starts a janitor (:func:`watch`), a process of
a session of its own, which mpirun does not signal.  Python's C signal
handler writes each signal's number to a pipe to the janitor the moment
the signal arrives, whatever rank 0 is doing (:func:`signal.set_wakeup_fd`):
at the first the janitor says ``interrupted`` (through rank 0's stderr,
which mpirun forwards while rank 0 lives); at the pipe's end (rank 0's,
however it came) it settles the folder (:meth:`Build.settle`).  It
imports nothing but the standard library, so that it starts at once.
"""
from __future__ import annotations

import os
import select
import shutil
import signal
import subprocess
import sys
from contextlib import suppress
from pathlib import Path

#: The line the command ends with when it is interrupted.
INTERRUPTED_LINE = "interrupted"


class Build:
    """An atomic folder under way: ``tmp`` built to replace ``path``; an
    earlier folder at ``path`` moves to ``earlier`` (a name made from
    ``tmp``'s, known before anything is moved) until the new one is in place."""

    def __init__(self, path: Path, tmp: Path):
        self.path, self.tmp = Path(path), Path(tmp)
        self.earlier = self.tmp.with_name(f".{self.path.name}.earlier."
                                          f"{self.tmp.name.removeprefix(f'.{self.path.name}.')}")

    def settle(self) -> None:
        """Leave ``path`` holding one whole run, whichever step was reached:
        the earlier folder put back unless the new one is in place, then
        the build folder and the earlier one removed."""
        if self.earlier.exists():
            if self.path.exists():
                shutil.rmtree(self.earlier)
            else:
                os.replace(self.earlier, self.path)
        if self.tmp.exists():
            shutil.rmtree(self.tmp)


#: How long a rank 0 that ends by itself waits for its janitor's line:
#: well within the second mpirun leaves it.
SAID_WAIT = 0.5

#: This process's janitor and its ends of the pipes to and from it, once one watches.
_watching: tuple[subprocess.Popen, int, int] | None = None
#: Whether a janitor that no longer watches said the line.
_said = False


def watch(build: Build) -> None:
    """Start ``build``'s janitor (module doc) and send it every signal this
    process handles in Python, as the signal arrives; where it cannot be
    started, the error, with no pipe left open."""
    global _watching
    signals, to_janitor = os.pipe()
    from_janitor, said = os.pipe()
    try:
        process = subprocess.Popen([sys.executable, __file__, str(signals), str(said), str(build.path.absolute()),
                                    str(build.tmp.absolute())], pass_fds=(signals, said), stdin=subprocess.DEVNULL,
                                   start_new_session=True)
    except BaseException:
        os.close(to_janitor)
        os.close(from_janitor)
        raise
    finally:
        os.close(signals)
        os.close(said)
    os.set_blocking(to_janitor, False)
    _watching = process, to_janitor, from_janitor
    signal.set_wakeup_fd(to_janitor)


def watching() -> bool:
    """Whether a janitor watches this process's build (:func:`watch`)."""
    return _watching is not None


def unwatch() -> None:
    """The build settled by this process itself: signals no longer go to
    the janitor; it ends (the end of its pipe), and whether it said the
    line (a signal came just before) is kept for :func:`told`."""
    global _watching, _said
    process, to_janitor, from_janitor = _watching
    signal.set_wakeup_fd(-1)
    os.close(to_janitor)
    _said = os.read(from_janitor, 1) != b""  # its byte, or the end of the pipe as it ends
    os.close(from_janitor)
    process.wait()
    _watching = None


def told(signum: int) -> bool:
    """Tell this process's janitor that it was asked to end by ``signum``
    and wait (at most :data:`SAID_WAIT`) for its line, so that the line is
    out before this process ends; whether a janitor says it (or said it:
    a janitor that is gone, killed by someone, may have)."""
    if _watching is None:
        return _said
    process, to_janitor, from_janitor = _watching
    if process.poll() is not None:  # gone: a write to its pipe would raise SIGPIPE, on which PETSc aborts
        return _heard(from_janitor)
    with suppress(OSError):
        os.write(to_janitor, bytes([signum]))
    select.select([from_janitor], [], [], SAID_WAIT)
    return True


def _heard(from_janitor: int) -> bool:
    """Whether the janitor's byte is waiting on pipe ``from_janitor`` (not
    the pipe's end)."""
    with suppress(OSError):
        return bool(select.select([from_janitor], [], [], 0)[0]) and os.read(from_janitor, 1) != b""
    return False


def janitor(signals: int, said: int, build: Build) -> None:
    """Read the signals from pipe ``signals``: at the first, one line (mpirun
    forwards it while the rank lives), then a byte to pipe ``said``
    (:func:`_say`); at the pipe's end (its writer's), or whatever ends the
    reading, settle ``build``."""
    first = True
    try:
        while os.read(signals, 64):
            if first:
                first = False
                _say(said)
    finally:
        build.settle()


def _say(said: int) -> None:
    """The line, then a byte to pipe ``said``; either may find its reader
    gone (mpirun ended, the process killed), which leaves the folder to
    settle all the same."""
    with suppress(OSError):
        print(INTERRUPTED_LINE, file=sys.stderr, flush=True)
    with suppress(OSError):
        os.write(said, b"\0")


if __name__ == "__main__":
    janitor(int(sys.argv[1]), int(sys.argv[2]), Build(Path(sys.argv[3]), Path(sys.argv[4])))
