"""How Ctrl-C and SIGTERM end a command: one line, the result folder under
way discarded, and the exit status a shell expects.

Contract: in one process, while :func:`signals_end_the_command` holds,
Ctrl-C raises KeyboardInterrupt and SIGTERM :class:`Terminated` (a
KeyboardInterrupt), wherever the command is; ``main`` prints
``interrupted`` or ``terminated`` and returns :data:`INTERRUPTED` (130) or
:data:`TERMINATED` (143).  Under mpirun rank 0 says ``interrupted`` and
exits at once (:func:`end_now`), the other ranks wait for mpirun to end
them (:func:`handlers`).  Before the command runs, :func:`python_handles_signals`
keeps PETSc from taking the signals and :func:`take_over_signals` removes
the start-up's handlers (:data:`verification.STARTING`).
"""
from __future__ import annotations

import os
import signal
import sys
import threading
from contextlib import contextmanager

from contactcore.endings import INTERRUPTED, TERMINATED, Terminated

from .. import STARTING, files, interrupted_while_starting, janitor

#: The signals that end a command, SIGTERM as Ctrl-C ends it.
ENDING = files.HELD_SIGNALS


def raise_terminated(signum, frame) -> None:
    """SIGTERM's handler in one process: raise :class:`Terminated`, noted
    (:func:`verification.files.note_signal`) where a finalizer swallows it."""
    files.note_signal(Terminated)
    raise Terminated


def raise_interrupted(signum, frame) -> None:
    """Ctrl-C's handler in one process: raise KeyboardInterrupt, as
    Python's own does, noted as :func:`raise_terminated`'s is."""
    files.note_signal(KeyboardInterrupt)
    raise KeyboardInterrupt


def end_now(signum, frame) -> None:
    """Rank 0 under mpirun, asked to end: one line (its own, or its
    janitor's if the janitor took the token first: :func:`janitor.told`),
    first, as mpirun forwards it only while this process lives; the result
    folder under way discarded (:func:`files.discard_unfinished`); exit
    now, without unwinding: the way out would meet collectives (a MUMPS
    factorisation's end is one) that the other ranks never join."""
    if not janitor.told(signum):
        print(janitor.INTERRUPTED_LINE, file=sys.stderr, flush=True)
    files.discard_unfinished()
    sys.stdout.flush()
    os._exit(INTERRUPTED)


def handlers(rank: int, distributed: bool) -> dict:
    """How each of :data:`ENDING` ends the command.  In one process Ctrl-C
    raises KeyboardInterrupt and SIGTERM :class:`Terminated`, each noted
    so that a result folder is not put in place if a finalizer swallowed it
    (:func:`verification.files.note_signal`).  mpirun
    passes on Ctrl-C and its own SIGTERM alike, to its ranks as SIGTERM,
    and kills them a second later (Open MPI's ``odls_base_sigkill_timeout``):
    rank 0 ends at once (:func:`end_now`; its janitor puts its result
    folder right if mpirun kills it first), and the other ranks ignore
    both signals, so that they keep joining every collective rank 0 is in
    until it has ended (they hold nothing to discard) and mpirun kills them."""
    if not distributed:
        return {signal.SIGINT: raise_interrupted, signal.SIGTERM: raise_terminated}
    return dict.fromkeys(ENDING, end_now if rank == 0 else signal.SIG_IGN)


@contextmanager
def signals_end_the_command(rank: int, distributed: bool):
    """:func:`handlers` while the block runs (the handlers before it
    restored after; only the main thread may set one)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    files.forget_signals()
    before = {sig: signal.signal(sig, handler) for sig, handler in handlers(rank, distributed).items()}
    try:
        yield
    finally:
        for sig, handler in before.items():
            signal.signal(sig, handler)
        files.forget_signals()


#: PETSc's option that leaves every signal to the process (see :func:`python_handles_signals`).
NO_PETSC_SIGNALS = "-no_signal_handler"


def python_handles_signals() -> None:
    """PETSc, once started, catches SIGPIPE (with SIGSEGV, SIGFPE, …) and
    aborts with status 59: ``run … 2>&1 | head -1`` left its build folder
    behind.  Its handlers are turned off before it starts (``PETSC_OPTIONS``,
    which mpirun's ranks and a pool's workers inherit), so that Python's
    own handling applies: a closed pipe is an error the log ignores, and
    Ctrl-C and SIGTERM end the command in one line."""
    given = os.environ.get("PETSC_OPTIONS", "")
    if NO_PETSC_SIGNALS not in given.split():
        os.environ["PETSC_OPTIONS"] = f"{given} {NO_PETSC_SIGNALS}".strip()


def take_over_signals() -> None:
    """From here on Ctrl-C raises KeyboardInterrupt, which ``main``
    turns into its one line once the result folder under way is discarded
    (the start-up's handlers, :data:`verification.STARTING`, put back as Python has them)."""
    for sig, handler in STARTING.items():
        if signal.getsignal(sig) is interrupted_while_starting:
            signal.signal(sig, handler)
