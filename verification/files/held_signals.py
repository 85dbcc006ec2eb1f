"""Ctrl-C and SIGTERM held while result files are swapped, and the ending
signals that arrived recorded.

Contract: inside :func:`signals_held` the handlers of :data:`HELD_SIGNALS`
only note a signal; the first that came acts, as its handler would have,
once the block ends (so a swap of result folders is never cut in half).
:func:`note_signal` records an ending signal whose exception may be
swallowed on its way (a finalizer); :func:`end_if_signalled` raises it
where a result would otherwise be put in place.
"""
from __future__ import annotations

import os
import signal
from contextlib import contextmanager


#: The signals that end a command (``verification.cli.signals.ENDING``), held
#: while a result folder is swapped in and the one it replaces removed.
HELD_SIGNALS = (signal.SIGINT, signal.SIGTERM)


@contextmanager
def signals_held():
    """Hold Ctrl-C and SIGTERM until the block ends, then let the first
    that came act as it would have: a swap of result folders and the
    removal of the one replaced are not cut in half (a SIGTERM in
    ``shutil.rmtree`` left half of an earlier run in
    ``.NAME.earlier.RANDOM``, grader4, 2026-11-27).  The handlers are
    swapped, not the signal mask: a process-directed signal goes to any
    thread that does not block it (OpenBLAS's, MPI's).  Off the main
    thread, where Python sets no handler, or where a handler was set
    outside Python, the block runs as is."""
    came: list = []
    try:
        before = {sig: signal.getsignal(sig) for sig in HELD_SIGNALS}
        if None in before.values():  # a handler set outside Python, which could not be put back
            before = None
        for sig in before or ():
            signal.signal(sig, lambda *arrived: came.append(arrived))
    except ValueError:  # not the main thread
        before = None
    try:
        yield
    finally:
        if before is not None:
            for sig, handler in before.items():
                signal.signal(sig, handler)
            if came:
                _act(before[came[0][0]], *came[0])


def _act(handler, sig: int, frame) -> None:
    """Do what ``handler`` (a Python handler, SIG_DFL or SIG_IGN) does with ``sig``."""
    if callable(handler):
        handler(sig, frame)
    elif handler == signal.SIG_DFL:
        os.kill(os.getpid(), sig)


#: The exceptions of the ending signals that arrived while a command ran
#: (:func:`note_signal`), first first.  Python discards an exception raised
#: in a finalizer or a weakref callback ("Exception ignored in …"): a
#: SIGTERM whose handler ran there was lost, and the run went on to write
#: its results and exit 0 (mainsplit, 2026-11-28).
_ARRIVED: list[type[BaseException]] = []


def note_signal(ending: type[BaseException]) -> None:
    """Record that a signal ending the command arrived, as ``ending`` (the
    exception its handler raises): a block of :func:`~verification.files.result_folders.atomic_folder` that
    ends anyway, its exception swallowed on the way, raises it then."""
    _ARRIVED.append(ending)


def forget_signals() -> None:
    """Clear :func:`note_signal`'s record: a command starts with none (one
    process may run several commands: ``main`` called in turn)."""
    _ARRIVED.clear()


def end_if_signalled() -> None:
    """Raise the first recorded ending signal's exception
    (:func:`note_signal`): a result folder is not put in place after the
    command was asked to end."""
    if _ARRIVED:
        raise _ARRIVED[0]
