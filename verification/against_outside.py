"""``python -m verification against FILE_OR_DIR SCENE``: an outside code's
answer judged against one method's, with its estimated error
(:func:`verification.agreement.compare_outside`), written into the result
folder: ``outside.md`` (the units and sign conventions, the verdict per
profile quantity and region along s), ``outside.csv`` (every outside
sample: both values, the project's estimated error there, the difference,
the verdict; ``s_unit`` and ``unit`` name each row's units, which
``units.json`` lists per column) and ``run.json`` (the command and what it
ran: method, degree, h, levels, exclude, as ``run``'s).  The folder is
built aside and put in place whole (:mod:`verification.cli.folders`), as
every command's."""
from __future__ import annotations

from pathlib import Path

from . import files
from .agreement.outside import compare_outside
from .run_summary import conventions

#: outside.csv's columns, in order.
CSV_COLUMNS = ["profile", "quantity", "s", "s_unit", "x", "y", "outside", "project", "estimate", "difference",
               "unit", "verdict"]

#: outside.csv's columns in the quantity's unit (the row's ``unit``).
QUANTITY_COLUMNS = ("outside", "project", "estimate", "difference")


def csv_units(table, rows: list[dict]) -> dict[str, str]:
    """``units.json``'s entry for outside.csv: every column with a unit.
    One unit where every row shares it; else the units found and the
    column naming each row's (``s_unit``: m or rad by profile; ``unit``:
    the quantity's)."""
    def one(column, found):
        found = sorted(set(found))
        return found[0] if len(found) == 1 else f"{' or '.join(found)}: the row's {column}"
    return {"s": one("s_unit", [r["s_unit"] for r in rows]), "x": table.units.length, "y": table.units.length,
            **dict.fromkeys(QUANTITY_COLUMNS, one("unit", [r["unit"] for r in rows]))}


def against(outside, scene, method: str, degree: int, out: Path, *, h: float | None = None, levels: int = 2,
            exclude: float | None = None, floors: dict | None = None, argv=(), **options) -> str:
    """Judge ``outside`` (a CSV file or a folder of ID.csv) on ``scene``
    against ``method`` at ``degree`` (solved at h, h/2 (, h/4): ``levels``,
    the CLI's ``--estimate``); write outside.md, outside.csv, units.json's
    entry for it and run.json into ``out``; return outside.md's text."""
    table = compare_outside(scene, outside, method=f"{method}:{degree}", h=h, levels=levels, exclude=exclude,
                            floors=floors, **options)
    text = table.markdown(conventions(table.units))
    rows = table.csv_rows()
    files.write_text(Path(out) / "outside.md", text)
    files.write_csv(Path(out) / "outside.csv", rows, CSV_COLUMNS)
    files.write_json(Path(out) / files.UNITS_FILE, {"outside.csv": csv_units(table, rows)})
    files.write_json(Path(out) / files.MANIFEST, {
        **files.provenance(list(argv)), "scene": str(scene), "outside": str(outside), "method": method,
        "degree": degree, "h": table.hs[0], "hs": list(table.hs), "levels": len(table.hs), "exclude": table.exclude,
        "floors": floors or {}, **{k: v for k, v in options.items() if v is not None}, **files.run_units(table.units)})
    return text
