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
at the first, the line ``interrupted`` is said once, through rank 0's
stderr, which mpirun forwards only while rank 0 lives, by whichever of
the two takes the one byte of a token pipe first (a pipe's read is
atomic): rank 0 itself when its handler runs (:func:`told`), the janitor
when rank 0 is stuck in compiled code.  At the pipe's end (rank 0's,
however it came) the janitor settles the folder (:meth:`Build.settle`).
It imports nothing but the standard library, so that it starts at once.
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


#: The temporary names' random part (``tempfile``'s: 8 characters).
RANDOM_PART = 8
#: The prefix of a temporary beside a name too long to carry in it.
SHORT_PREFIX = ".build."


def name_max(folder: Path) -> int:
    """The longest file name (bytes) that ``folder``'s file system takes."""
    try:
        return os.pathconf(folder, "PC_NAME_MAX")
    except (OSError, ValueError):
        return 255


def build_prefix(path: Path) -> str:
    """The prefix of ``path``'s temporary sibling: ``.NAME.`` where its
    longest sibling, ``.NAME.earlier.`` and the random part, fits the file
    system's names; else :data:`SHORT_PREFIX` (a legal ``NAME`` of 238
    bytes or more made every sibling too long to create, and was refused)."""
    path = Path(path)
    fits = len(os.fsencode(f".{path.name}.earlier.")) + RANDOM_PART <= name_max(path.parent)
    return f".{path.name}." if fits else SHORT_PREFIX


class Build:
    """An atomic folder under way: ``tmp`` built to replace ``path``; an
    earlier folder at ``path`` moves to ``earlier`` (a name made from
    ``tmp``'s, known before anything is moved) until the new one is in
    place: ``.NAME.earlier.RANDOM`` beside ``.NAME.RANDOM``, or
    ``.build.earlier.RANDOM`` beside ``.build.RANDOM`` (:func:`build_prefix`)."""

    def __init__(self, path: Path, tmp: Path):
        self.path, self.tmp = Path(path), Path(tmp)
        prefix = f".{self.path.name}." if self.tmp.name.startswith(f".{self.path.name}.") else SHORT_PREFIX
        self.earlier = self.tmp.with_name(f"{prefix}earlier.{self.tmp.name.removeprefix(prefix)}")

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


#: How long a rank 0 that ends by itself waits for the line of a janitor
#: that took the token (:func:`told`): the janitor is running then, and
#: says it in microseconds; mpirun kills rank 0 a second after its SIGTERM
#: whatever this is, so the bound only ends the wait where no mpirun
#: would (a janitor stopped, never answering).  It was the whole wait
#: before the token: 0.5 s, and a janitor not scheduled within it (a
#: loaded machine) said the line after rank 0 had gone, and mpirun, which
#: forwards only a live rank's output, lost it (measured with the
#: janitor delayed 0.7, 1.5 and 3 s: no ``interrupted``, 2026-11-27).
SAID_WAIT = 5.0

#: This process's janitor, its ends of the pipes to and from it, and its
#: end of the token pipe, once one watches.
_watching: tuple[subprocess.Popen, int, int, int] | None = None
#: Whether a janitor that no longer watches said the line.
_said = False


def watch(build: Build) -> None:
    """Start ``build``'s janitor (module doc) and send it every signal this
    process handles in Python, as the signal arrives; where it cannot be
    started, the error, with no pipe left open."""
    global _watching
    signals, to_janitor = os.pipe()
    from_janitor, said = os.pipe()
    token = _token()
    try:
        process = subprocess.Popen([sys.executable, __file__, str(signals), str(said), str(token),
                                    str(build.path.absolute()), str(build.tmp.absolute())],
                                   pass_fds=(signals, said, token), stdin=subprocess.DEVNULL, start_new_session=True)
    except BaseException:
        os.close(to_janitor)
        os.close(from_janitor)
        os.close(token)
        raise
    finally:
        os.close(signals)
        os.close(said)
    os.set_blocking(to_janitor, False)
    _watching = process, to_janitor, from_janitor, token
    signal.set_wakeup_fd(to_janitor)


def _token() -> int:
    """The read end of a pipe that holds one byte, its write end closed: of
    the processes that read it, one gets the byte, the others its end."""
    token, put = os.pipe()
    os.write(put, b"\0")
    os.close(put)
    return token


def _take(token: int) -> bool:
    """Whether this process took the token's byte (pipe ``token``,
    :func:`_token`): the right, and the duty, to say the line."""
    with suppress(OSError):
        return os.read(token, 1) != b""
    return False


def watching() -> bool:
    """Whether a janitor watches this process's build (:func:`watch`)."""
    return _watching is not None


def unwatch() -> None:
    """The build settled by this process itself: signals no longer go to
    the janitor; it ends (the end of its pipe), and whether it said the
    line (a signal came just before) is kept for :func:`told`."""
    global _watching, _said
    process, to_janitor, from_janitor, token = _watching
    signal.set_wakeup_fd(-1)
    os.close(to_janitor)
    os.close(token)
    _said = os.read(from_janitor, 1) != b""  # its byte, or the end of the pipe as it ends
    os.close(from_janitor)
    process.wait()
    _watching = None


def told(signum: int) -> bool:
    """Whether this process's janitor says the line for this process, asked
    to end by ``signum`` (or said it: a janitor that no longer watches, or
    one that is gone, killed by someone, may have): False if this process
    took the token (:func:`_take`), and must say it itself, now, while
    mpirun forwards its output.  A janitor that took it is waited for (at
    most :data:`SAID_WAIT`), so that the line is out before this process
    ends."""
    if _watching is None:
        return _said
    process, to_janitor, from_janitor, token = _watching
    if _take(token):
        return False
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


def janitor(signals: int, said: int, token: int, build: Build) -> None:
    """Read the signals from pipe ``signals``: at the first, if this janitor
    takes the token (pipe ``token``, :func:`_take`; else its process has,
    and says the line itself), one line (mpirun forwards it while the rank
    lives), then a byte to pipe ``said`` (:func:`_say`); at the pipe's end
    (its writer's), or whatever ends the reading, settle ``build``."""
    first = True
    try:
        while os.read(signals, 64):
            if first:
                first = False
                if _take(token):
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
    janitor(int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), Build(Path(sys.argv[4]), Path(sys.argv[5])))
