"""The drivers and the command line (``python -m verification``).

Run as ``python -m verification``, this package is imported before its
``__main__`` module is read and compiled (10-20 ms without a bytecode
cache, as under ``PYTHONDONTWRITEBYTECODE``), so Ctrl-C's start-up
handler is installed here, before that: a Ctrl-C then ends the command in
one line (:func:`interrupted_while_starting`) instead of a traceback from
the compiler.  Imported any other way (a user's script, the tests), it
installs nothing.
"""
import os
import signal
import sys


def interrupted_while_starting(signum, frame) -> None:
    """Ctrl-C (or SIGTERM) before :func:`verification.__main__.main` takes
    over: the imports take a second or more on a loaded machine, and
    nothing is under way yet, so one line and the status of the signal, at
    once (a KeyboardInterrupt there was a traceback and exit 1)."""
    if all(os.environ.get(n, "0") == "0" for n in ("OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK")):  # one line
        print("interrupted" if signum == signal.SIGINT else "terminated", file=sys.stderr, flush=True)
    os._exit(128 + signum)


#: The handlers the command line started with, until ``main`` takes over
#: (a signal already ignored, as in a shell's background job, stays ignored).
STARTING: dict = {}


def hold_signals_while_starting() -> dict:
    """Install :func:`interrupted_while_starting` for Ctrl-C and SIGTERM
    where Python's defaults hold them (once): :data:`STARTING`."""
    if not STARTING:
        for sig, default in ((signal.SIGINT, signal.default_int_handler), (signal.SIGTERM, signal.SIG_DFL)):
            if signal.getsignal(sig) is default:
                STARTING[sig] = signal.signal(sig, interrupted_while_starting)
    return STARTING


def _run_as_the_command() -> bool:
    """Whether Python is locating ``-m verification`` itself (``sys.argv[0]``
    is ``-m`` while it does, and the module named after ``-m`` is this one)."""
    if sys.argv[:1] != ["-m"]:
        return False
    args = getattr(sys, "orig_argv", [])
    for i, a in enumerate(args[1:], 1):
        flags, m, name = a.partition("m")
        if a.startswith("-") and not a.startswith("--") and m and set(flags[1:]) <= NO_VALUE_FLAGS:
            return (name or (args[i + 1] if i + 1 < len(args) else "")) == "verification"
    return False


#: Python's one-letter options that take no value, which may stand before
#: ``m`` in one argument (``-Bm verification``, ``-Iqm verification``).
NO_VALUE_FLAGS = set("bBdEhiIOPqsSuvx")


if _run_as_the_command():
    hold_signals_while_starting()
