"""The plots of a study (:mod:`verification.study`): the response on Γ
against each parameter, one series per method and values of the others,
warned points ringed and failed values drawn as dotted lines."""
from __future__ import annotations

from pathlib import Path

from . import files


def _shown(value) -> str:
    """A parameter's value as the tables show it (a number, or a word)."""
    return value if isinstance(value, str) else f"{value:g}"


#: How a study plot marks a point that solved with warnings, and the value at which one failed (a
#: vertical line across the panel, in the series' colour).
WARNED_MARK = {"marker": "o", "ms": 11, "mfc": "none", "mec": "tab:red", "linestyle": "none"}
FAILED_MARK = {"linewidth": 1.2, "alpha": 0.8, "label": "_"}
#: The dashes of a failed value's line, in points: series k of n draws
#: dashes of FAILED_DASH offset by k of them, with n − 1 gaps between, so
#: that two series failing at the same value interleave their colours
#: instead of the last one hiding the others (grader11's fault 7: fe's lines
#: lay exactly under xfem's).
FAILED_DASH = 2.0


def failed_style(slot: int, count: int) -> tuple:
    """The ``linestyle`` of series ``slot`` of ``count`` (:data:`FAILED_DASH`)."""
    return (slot * FAILED_DASH, (FAILED_DASH, max(count - 1, 1) * FAILED_DASH))


def _series(ax, column: str, q: str, factor: float, rows: list[dict], label: str):
    """One series' solved points (``max_q`` / ``factor`` against ``column``);
    its colour (a series may have no solved point)."""
    pts = [(r[column], r[f"max_{q}"] / factor) for r in rows if r["status"] != "failed"]
    return ax.plot(*(zip(*pts) if pts else ([], [])), "o-", label=label)[0].get_color()


def _mark(ax, column: str, q: str, factor: float, rows: list[dict], colour, slot: int = 0, count: int = 1) -> None:
    """Ring the warned points (one "warned" entry in the legend per panel);
    draw a dotted vertical line across the panel at each failed one, in the
    series' colour: it has no value, so no mark at any height that could be
    read as one (the series' legend entry names its failed values,
    :func:`_failed_label`); series ``slot`` of ``count`` dashes it in its
    own phase (:func:`failed_style`), so coincident lines show each colour."""
    seen = {h.get_label() for h in ax.get_lines()}
    warned = [(r[column], r[f"max_{q}"] / factor) for r in rows if r["status"] == "warned"]
    if warned:
        ax.plot(*zip(*warned), **WARNED_MARK, label="_" if "warned" in seen else "warned")
    for x in (r[column] for r in rows if r["status"] == "failed"):
        ax.axvline(x, color=colour, linestyle=failed_style(slot, count), **FAILED_MARK)


def _failed_label(label: str, column: str, rows: list[dict]) -> str:
    """A series' legend entry: its label, and the values at which it failed."""
    failed = [_shown(r[column]) for r in rows if r["status"] == "failed"]
    if not failed:
        return label
    if len(failed) == len(rows):
        return f"{label}: failed at every value (dotted)"
    return f"{label}: failed at {', '.join(failed)} (dotted)"


def plot(path: Path, scene, param: str, column: str, others: list[str], rows: list[dict]) -> None:
    """The response on Γ against ``param`` (the table's ``column``); one
    series per method and values of the ``others`` columns; the axes in
    the ``scene``'s units."""
    from .plots import axis_unit, pyplot, save

    fig, axes = pyplot().subplots(2, 2, figsize=(9, 6.5), squeeze=False)
    values = [r[column] for r in rows]
    numbers = all(not isinstance(v, str) for v in values)  # words (enforcement) are categories
    logx = numbers and min(values) > 0 and max(values) / min(values) > 100
    series = dict.fromkeys((r["method"], *(r[o] for o in others)) for r in rows)
    for ax, q in zip(axes.ravel(), ("gN", "gT", "tN", "tT")):
        factor, unit = axis_unit(q, max((abs(r[f"max_{q}"]) for r in rows if r["status"] != "failed"), default=0.0),
                                 scene.units)
        for slot, key in enumerate(series):
            chosen = [r for r in rows if (r["method"], *(r[o] for o in others)) == key]
            line = _series(ax, column, q, factor, chosen, _failed_label(
                ", ".join([key[0], *(f"{o} = {_shown(v)}" for o, v in zip(others, key[1:]))]), column, chosen))
            _mark(ax, column, q, factor, chosen, line, slot, len(series))
        symbol, _, shown = unit.partition(" ")
        ax.set_ylabel(f"max |{symbol}| {shown}")
        ax.set_xlabel(files.labelled(param, param, scene.units))
        if logx:
            ax.set_xscale("log")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(f"Scene {scene.name}: interface response against {param}")
    save(fig, path)
