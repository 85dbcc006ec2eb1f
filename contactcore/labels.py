"""How a run is named wherever a user reads it: a method at a degree
(:func:`run_label`, ``fe P2``), and the run the others are compared with
(:func:`reference_text`, ``reference: fe P2``).  summary.md's tables, its
warnings, the plots' legends, the agreement API's labels and the
estimates' warnings all take their names from here, so one run has one
name (newuser32 read ``fe (reference)``, ``fe (p2)``, ``fe p2`` and
``fe P2`` for one run)."""
from __future__ import annotations


def run_label(method: str, degree: int) -> str:
    """Method ``method`` at polynomial degree ``degree``: ``fe P2``."""
    return f"{method} P{degree}"


def reference_text(label: str) -> str:
    """The run ``label`` (:func:`run_label`) named as the reference the
    others are compared with: ``reference: fe P2``."""
    return f"reference: {label}"
