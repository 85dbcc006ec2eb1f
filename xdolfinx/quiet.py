"""dolfinx's JIT compiler kept quiet in a user's own script.

ffcx calls ``logging.basicConfig()`` when it is imported, which gives the
root logger a stderr handler, and the C compile of a form or an element goes
through setuptools, whose ``set_threshold`` lowers the root logger to INFO:
every compile then prints ``INFO:root:running build_ext`` and the compiler
command lines.  :func:`quiet_jit` drops the root logger's records below
WARNING while the wrapped code runs and restores the root logger's level
afterwards; the user's own loggers, handlers and levels are not touched,
and nothing is changed once the wrapped code returns.
"""
from __future__ import annotations

import functools
import logging
from contextlib import contextmanager


class _BelowWarning(logging.Filter):
    """Lets through only records of WARNING and above."""

    def filter(self, record) -> bool:
        return record.levelno >= logging.WARNING


@contextmanager
def quiet_compiler():
    """Inside the block, the root logger (the one setuptools logs the
    compiler's steps to) passes on warnings and errors only; its level is
    restored on the way out."""
    root = logging.getLogger()
    level, only_warnings = root.level, _BelowWarning()
    root.addFilter(only_warnings)
    try:
        yield
    finally:
        root.removeFilter(only_warnings)
        root.setLevel(level)


def quiet_jit(function):
    """``function`` run inside :func:`quiet_compiler` (for the functions of
    this package that create dolfinx forms, spaces or expressions)."""
    @functools.wraps(function)
    def wrapped(*args, **kwargs):
        with quiet_compiler():
            return function(*args, **kwargs)
    return wrapped
