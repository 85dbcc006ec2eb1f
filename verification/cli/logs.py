"""The command's log on stderr: our progress by verbosity, everyone else's
warnings, and each repeated message once.

Contract: :func:`configure_logging` is called once a command, by ``main``
alone (it replaces the root logger's handlers and the ``verification``
logger's, which a library must not do); it returns the :class:`Repeats`
filter whose counts :func:`print_repeats` prints before the command's last
line.  The workers of a pool set their own log (:func:`verification.pool.worker_logging`).
"""
from __future__ import annotations

import logging
import sys

from ..pool import LOG_FORMAT


class Repeats(logging.Filter):
    """Lets a message through once; counts its repeats (a sweep warns about
    the same thing in every case) for one line at the end."""

    def __init__(self):
        super().__init__()
        self.counts = {}

    def filter(self, record) -> bool:
        """Whether the record is the first with its level and message (and count it)."""
        key = (record.levelno, record.getMessage())
        self.counts[key] = self.counts.get(key, 0) + 1
        return self.counts[key] == 1

    def summary(self) -> list[str]:
        """One line for each message that came more than once: how many more times."""
        return [f"(the {logging.getLevelName(level).lower()} \"{msg[:80]}…\" repeated {n - 1} more time(s))"
                for (level, msg), n in self.counts.items() if n > 1]


def configure_logging(verbosity: int = 0) -> Repeats:
    """Our progress at INFO (WARNING with --quiet, DEBUG with --verbose,
    nothing at -2: the ranks after the first under mpirun);
    everything else (ffcx's JIT goes through setuptools, which lowers the
    root logger's level) only from WARNING on, enforced on the handler,
    which setuptools does not touch.  Repeated messages are collapsed."""
    fmt = logging.Formatter(LOG_FORMAT)
    root = logging.StreamHandler()
    root.setLevel(logging.WARNING)
    root.setFormatter(fmt)
    logging.basicConfig(handlers=[root], force=True)
    ours = logging.getLogger("verification")
    repeats = Repeats()
    ours.handlers[:] = [logging.StreamHandler()]
    ours.handlers[0].setFormatter(fmt)
    ours.handlers[0].addFilter(repeats)
    ours.setLevel({-2: logging.CRITICAL + 1, -1: logging.WARNING, 0: logging.INFO, 1: logging.DEBUG}[verbosity])
    ours.propagate = False
    return repeats


def print_repeats(repeats: Repeats) -> None:
    """The count of each repeated message, before the command's last line
    (an error, ``interrupted``): a failed run ends on why it failed."""
    for line in repeats.summary():
        print(line, file=sys.stderr)
