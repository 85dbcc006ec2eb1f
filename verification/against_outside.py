"""``python -m verification against FILE_OR_DIR SCENE``: an outside code's
answer judged against one method's, with its estimated error
(:func:`verification.agreement.compare_outside`), written into the result
folder: ``outside.md`` (the verdict per profile quantity and region along
s) and ``outside.csv`` (every outside sample: both values, the project's
estimated error there, the difference, the verdict).  The folder is built
aside and put in place whole (:mod:`verification.cli.folders`), as every
command's."""
from __future__ import annotations

from pathlib import Path

from . import files
from .agreement.outside import compare_outside

#: outside.csv's columns, in order.
CSV_COLUMNS = ["profile", "quantity", "s", "x", "y", "outside", "project", "estimate", "difference", "verdict"]


def against(outside, scene, method: str, degree: int, out: Path, *, h: float | None = None, levels: int = 2,
            exclude: float | None = None, floors: dict | None = None, argv=(), **options) -> str:
    """Judge ``outside`` (a CSV file or a folder of ID.csv) on ``scene``
    against ``method`` at ``degree`` (solved at h, h/2 (, h/4)); write
    outside.md and outside.csv into ``out``; return outside.md's text."""
    table = compare_outside(scene, outside, method=f"{method}:{degree}", h=h, levels=levels, exclude=exclude,
                            floors=floors, **options)
    text = table.markdown()
    files.write_text(Path(out) / "outside.md", text)
    files.write_csv(Path(out) / "outside.csv", table.csv_rows(), CSV_COLUMNS)
    return text
