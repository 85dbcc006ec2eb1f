"""The text of result tables: profile CSVs, CSVs of rows, Markdown tables.

Contract: a CSV holds every float at full precision (``repr``), so that it
reads back to the same numbers; a Markdown table's cells are rounded to 3
significant digits for reading and escaped so that no cell breaks its row.
Files are written through :func:`verification.files.atomic_files.write_text`.
"""
from __future__ import annotations

import csv
import io
import re
from pathlib import Path

from contactcore import ProfileData
from contactcore.estimate.runs import ERROR_SUFFIX

from .atomic_files import write_text


def write_profile_csv(path: Path, profile: ProfileData, errors: dict | None = None) -> Path:
    """Columns ``s, x, y`` then the quantities (docs/scenes.md), full precision;
    ``errors`` (``{q + "_err": per-sample error}``) each beside its quantity."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    names = [c for n in profile.names for c in (n, f"{n}{ERROR_SUFFIX}") if c == n or c in (errors or {})]
    writer.writerow(names)
    cols = [profile.columns[n] if n in profile.columns else errors[n] for n in names]
    for row in zip(*cols):
        writer.writerow([repr(float(v)) for v in row])
    return write_text(path, buf.getvalue())


def read_profile_csv(path: Path) -> dict:
    """The columns of a profile CSV as lists of floats."""
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    return {name: [float(r[i]) for r in rows[1:]] for i, name in enumerate(rows[0])}


def cell(value) -> str:
    """A table cell: floats to 3 significant digits (small or large ones in
    exponent form), anything else as text."""
    if isinstance(value, float):
        if value != value:
            return "nan"
        return f"{value:.2e}" if value != 0 and not 1e-2 <= abs(value) < 1e4 else f"{value:.3g}"
    return str(value)


def md_escape(text) -> str:
    """``text`` safe inside a Markdown table cell: its pipes escaped, its
    lines joined (a line break would end the row)."""
    return " ".join(str(text).replace("|", "\\|").split())


def markdown_table(rows: list[dict], columns: list[str], headers: list[str] | None = None) -> str:
    """A Markdown table of ``rows`` (dicts) with ``columns`` in order."""
    head = headers or columns
    lines = ["| " + " | ".join(md_escape(h) for h in head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(md_escape(cell(r.get(c, ""))) for c in columns) + " |" for r in rows]
    return "\n".join(lines) + "\n"


def write_csv(path: Path, rows: list[dict], columns: list[str]) -> Path:
    """``rows`` (dicts) as CSV with ``columns`` in order, full precision."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(columns)
    writer.writerows([[repr(r.get(c, "")) if isinstance(r.get(c), float) else r.get(c, "") for c in columns]
                      for r in rows])
    return write_text(path, buf.getvalue())


def relink(markdown: str, folder: str) -> str:
    """``markdown`` written in ``folder``, with its relative image and file
    links made relative to the folder above (for a report that gathers it)."""
    return re.sub(r"\]\((?!https?:|/)([^)]+)\)", lambda m: f"]({folder}/{m.group(1)})", markdown)
