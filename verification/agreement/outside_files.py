"""An outside code's profiles read from CSV files (docs/api.md, "An
outside code's answer"): a file a profile, named ``ID.csv`` (as the
project's own ``METHOD/profiles/ID.csv``), or a folder of them.

Contract: :func:`read_outside` returns :class:`OutsideFiles`, profile id
(the file's stem) -> column name -> list of floats, whose ``lines`` name
each sample's file and line; it refuses, with a one-line
:class:`~contactcore.ContactError` naming the file, line and column, a
file it cannot read, a folder without CSVs, an empty file, a header
naming a column twice, a row of another length than the header and a
cell that is not a number.  It knows no scene: the columns are checked
against one by :func:`~verification.agreement.outside_input.outside_profiles`.
"""
from __future__ import annotations

import csv
from pathlib import Path

from contactcore import ContactError


class OutsideFiles(dict):
    """Profile id -> columns as :func:`read_outside` read them; ``lines``:
    id -> (the file, the file line of each sample, counted from 1 with the
    header line 1), so that an error names the line to open."""

    def __init__(self, columns=(), lines=None):
        super().__init__(columns)
        self.lines = dict(lines or {})


def read_outside(path) -> OutsideFiles:
    """Profile id -> columns of a CSV file (its id the file's stem, ``C4.csv``
    -> ``C4``: the project's own ``METHOD/profiles/ID.csv``) or of every
    ``*.csv`` in a folder; a header row of column names, then one row a
    sample (a leading UTF-8 byte-order mark, as spreadsheets write, is
    read past).  A file that cannot be read, a folder without CSVs, a
    header naming a column twice, or a cell that is not a number is refused
    naming the file, row and column."""
    path = Path(path)
    if path.is_dir():
        files = sorted(path.glob("*.csv"))
        if not files:
            raise ContactError(f"outside: no *.csv file in folder {path} (one CSV a profile, named ID.csv)")
    elif path.is_file():
        files = [path]
    else:
        raise ContactError(f"outside: {path} is neither a CSV file nor a folder of them")
    out, lines = {}, {}
    for f in files:
        try:
            with open(f, newline="", encoding="utf-8-sig") as fh:  # a spreadsheet's byte-order mark is no name
                rows = [(i, r) for i, r in enumerate(csv.reader(fh), start=1) if any(c.strip() for c in r)]
        except (OSError, UnicodeDecodeError) as exc:
            raise ContactError(f"outside: cannot read {f}: {exc}") from None
        if not rows:
            raise ContactError(f"outside: {f} is empty (a header row of column names, then one row a sample)")
        header = [c.strip() for c in rows[0][1]]
        twice = sorted({name for name in header if header.count(name) > 1})
        if twice:
            raise ContactError(f"outside: {f} line {rows[0][0]}: the header names {', '.join(twice)} more than once")
        columns = {name: [] for name in header}
        for i, r in rows[1:]:
            if len(r) != len(header):
                raise ContactError(f"outside: {f} line {i}: {len(r)} cells, the header names {len(header)}")
            for name, cell in zip(header, r):
                try:
                    columns[name].append(float(cell))
                except ValueError:
                    raise ContactError(f"outside: {f} line {i}, column {name}: {cell.strip()!r} is not a "
                                       "number") from None
        out[f.stem] = columns
        lines[f.stem] = (f, [i for i, _ in rows[1:]])
    return OutsideFiles(out, lines)
