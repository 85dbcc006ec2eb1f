"""One argument's text to its value: the ``type=`` callables of the command
table (:mod:`verification.cli.commands`).

Contract: each takes the text as typed and returns the value, or raises
:class:`argparse.ArgumentTypeError` whose message names the problem, which
the parser turns into one line ``error: COMMAND: argument --X: problem``
and exit status 2 (:class:`verification.cli.parser.OneLineParser`).
"""
from __future__ import annotations

import argparse
from pathlib import Path

from .. import methods


def folder(text: str) -> Path:
    """A result folder's path: an empty one names no folder (Path("") is
    the current folder)."""
    if not text.strip():
        raise argparse.ArgumentTypeError("must name a folder (got an empty path)")
    return Path(text)


def petsc_option(text: str) -> tuple[str, str]:
    """``--petsc-option KEY=VALUE``: the key (leading dashes dropped) and its value."""
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    return key.lstrip("-"), value


def floor(text: str) -> tuple[str, float]:
    """``--floor Q=VALUE``: a profile quantity and its floor, a finite number > 0 in its unit
    (:func:`verification.agreement.floor_problem`, the rule of ``floors={...}`` too)."""
    from contactcore.scene import QUANTITIES
    name, sep, value = text.partition("=")
    if not sep or name not in QUANTITIES:
        raise argparse.ArgumentTypeError(f"expected Q=VALUE with Q one of {', '.join(QUANTITIES)} (got {text!r})")
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{name}: the floor must be a number (got {value!r})") from None
    from ..agreement import floor_problem
    problem = floor_problem(name, number)
    if problem:
        raise argparse.ArgumentTypeError(problem)
    return name, number


def reference(text: str) -> tuple[str, int] | None:
    """``--reference METHOD:DEGREE`` (or ``none``)."""
    if text == "none":
        return None
    name, sep, degree = text.partition(":")
    if not sep or name not in methods.METHODS or degree not in ("1", "2"):
        raise argparse.ArgumentTypeError(f"expected METHOD:DEGREE with METHOD one of {', '.join(methods.METHODS)} "
                                         f"and DEGREE 1 or 2, or none (got {text!r})")
    return name, int(degree)


def number_or_word(text: str):
    """A study's value: a number, or a word (``--param enforcement``)."""
    try:
        return float(text)
    except ValueError:
        return text
