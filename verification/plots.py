"""Plots of profiles, overlaying methods: one PNG per profile.

Every curve of a (method, degree) has its own colour, line style and
marker, so coincident curves stay distinguishable; the reference's is
named ``reference: fe P2`` (:func:`contactcore.labels.reference_text`).
Under each overlay a panel shows each method minus the reference (the
run's ``--reference``, else fe at its highest degree, or the first curve)
over the size the agreement table measures it against (the reference's
largest |t| for t_N and t_T, |σ| for a stress, over the samples the table
keeps: :meth:`verification.agreement.AgreementTable.sizes`), in percent,
so that the panel's largest kept |Δ| is the table's worst sample; the
panel's y label names that size (``Δt_T / max|t| (%)``); without sizes
(a caller with no table) the panel is in the quantity's unit.  The
overlays are in the
quantity's unit in the scene's units (docs/scenes.md, "Units"), stresses
of an SI scene in kPa, MPa or GPa as fits (:func:`axis_unit`).
Legends sit outside the axes,
tick labels never carry an offset, and no panel zooms below
:data:`~contactcore.tolerances.PLOT_MIN_Y_SPAN` of its quantity's scale.
"""
from __future__ import annotations

import functools
import re
from pathlib import Path

import numpy as np

from contactcore import ProfileData
from contactcore.labels import reference_text, run_label
from contactcore.scene import Units
from contactcore.scene import DISPLACEMENT_QUANTITIES, STRESS_QUANTITIES
from contactcore.tolerances import PLOT_MIN_Y_SPAN

from .files import STRESS_COLUMNS, atomic_path, column_unit, parameter_unit


@functools.cache
def pyplot():
    """matplotlib's pyplot on the file-only Agg backend, imported when the
    first figure is drawn (a run without plots, or ``--help``, never pays
    for it)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt

#: Each quantity's symbol on a plot; its unit is the scene's (:func:`axis_unit`).
SYMBOLS = {"sxx": "σxx", "syy": "σyy", "sxy": "σxy", "tN": "t_N", "tT": "t_T", "gN": "g_N", "gT": "g_T", "ux": "u_x",
           "uy": "u_y"}
#: The symbol of a vector's or tensor's size (:data:`verification.agreement.GROUPS`)
#: when every component of it is measured: ``|t|``, ``|σ|``.
GROUP_SYMBOLS = {("tN", "tT"): "t", ("gN", "gT"): "g", STRESS_QUANTITIES: "σ", DISPLACEMENT_QUANTITIES: "u"}
#: The stress units of an SI scene's axis, from the largest: the first whose
#: factor is at most the largest |value| shown (Pa below 1 kPa).
STRESS_PREFIXES = ((1e9, "GPa"), (1e6, "MPa"), (1e3, "kPa"), (1.0, "Pa"))


def axis_unit(q: str, scale: float, units: Units = Units()) -> tuple[float, str]:
    """``(factor, label)`` of quantity ``q``'s axis when its largest |value|
    is ``scale``, in the scene's ``units``: a stress of a scene in Pa in kPa,
    MPa or GPa as fits (values divided by ``factor``), a stress in any other
    unit and any other quantity as given, labelled with its
    :func:`~verification.files.column_unit`."""
    if q not in SYMBOLS:
        return 1.0, q
    factor, unit = 1.0, column_unit(q, units)
    if q in STRESS_COLUMNS and units.stress == STRESS_PREFIXES[-1][1]:
        factor, unit = next(((f, u) for f, u in STRESS_PREFIXES if scale >= f), STRESS_PREFIXES[-1])
    return factor, f"{SYMBOLS[q]} ({unit})"


def size_symbol(q: str, against: str = "") -> str:
    """The size a Δ panel of ``q`` is over, in symbols: ``against`` (an
    :class:`~verification.agreement.Agreement`'s: ``|(tN, tT)|``, or "" for
    ``q`` itself) as ``|t|`` where it holds a whole group
    (:data:`GROUP_SYMBOLS`), else its components' symbols (``|σxy|``,
    ``|(σxx, σxy)|``)."""
    names = re.findall(r"\w+", against) or [q]
    whole = next((s for g, s in GROUP_SYMBOLS.items() if set(g) == set(names)), None)
    shown = [SYMBOLS.get(n, n) for n in names]
    return f"|{whole}|" if whole else f"|{shown[0]}|" if len(shown) == 1 else f"|({', '.join(shown)})|"


def xlabel(parameter: str, units: Units = Units()) -> str:
    """The label of a profile's ``s`` axis: an arc length in the scene's
    length unit, or a polar angle."""
    return f"{'θ' if parameter == 'angle' else 's'} ({parameter_unit(parameter, units)})"


#: Colour, line style and markers (by degree 1, 2, 3) of each method: no two
#: (method, degree) share a marker, so coincident curves show each one's.
METHOD_STYLE = {"fe": ("tab:blue", "-", "osp"), "xfem": ("tab:orange", "--", "^D*"),
                "efgm": ("tab:green", ":", "vXh"), "getfem": ("tab:purple", "-.", "<>H")}
OTHER_STYLE = ("tab:gray", (0, (5, 1, 1, 1)), "+x1")
#: Markers on a sampled curve: this many per curve, shifted from curve to
#: curve so that coincident curves show each one's markers.
MARKERS_PER_CURVE = 10
#: A curve's line width by degree (1, then 2 and higher): a method's two
#: degrees share its colour and line style, so the heavier line tells the
#: degree-2 run (the reference's, fe P2) from degree 1 without the markers.
LINE_WIDTH = (1.4, 2.6)


def variant(label: str) -> tuple[str, int]:
    """``(method, degree)`` of a curve label: the first known method name in
    it, and the degree written ``p<k>`` or ``P<k>`` (1 if none)."""
    words = re.findall(r"[a-z]+", label.lower())
    method = next((w for w in words if w in METHOD_STYLE), words[0] if words else "")
    degree = re.search(r"\b[pP](\d)\b", label)
    return method, int(degree.group(1)) if degree else 1


def style(label: str, index: int = 0, points: int = 0) -> dict:
    """Line keyword arguments of the curve ``label``, the ``index``-th of its
    figure; ``points`` > 0 spreads markers over a sampled curve."""
    method, degree = variant(label)
    colour, line, markers = METHOD_STYLE.get(method, OTHER_STYLE)
    kw = {"color": colour, "linestyle": line, "marker": markers[min(degree, len(markers)) - 1],
          "lw": LINE_WIDTH[min(degree, 2) - 1],
          "ms": 6, "mfc": "none", "label": label}
    if points > MARKERS_PER_CURVE:
        every = max(1, points // MARKERS_PER_CURVE)
        kw["markevery"] = (index * every // 4 % every, every)
    return kw


def reference_label(labels: list[str]) -> str:
    """The reference of a difference panel: fe at its highest degree, else
    the first curve."""
    fe = [lab for lab in labels if variant(lab)[0] == "fe"]
    return max(fe, key=lambda lab: variant(lab)[1]) if fe else labels[0]


def reference_of(runs, reference: str | None = None) -> str:
    """The label of ``runs`` (labels -> anything) the differences are taken
    against: ``reference`` where it is one of them, else
    :func:`reference_label`'s choice."""
    return reference if reference in runs else reference_label(list(runs))


def keep_span(ax, scale: float) -> None:
    """Widen the y range of ``ax`` to at least ``PLOT_MIN_Y_SPAN · scale``
    about its middle (no zoom onto round-off)."""
    low, high = ax.get_ylim()
    span = PLOT_MIN_Y_SPAN * scale
    if scale > 0 and high - low < span:
        mid = 0.5 * (low + high)
        ax.set_ylim(mid - span / 2, mid + span / 2)


def legend_outside(ax, **kw) -> None:
    """The legend of ``ax`` to the right of its axes, off the data."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, fontsize=8, **kw)


def plot_profile(path: Path, title: str | tuple[str, ...], runs: dict[str, ProfileData], reference: str | None = None,
                 floors: dict[str, float] | None = None, units: Units = Units(), left_out=None,
                 sizes: dict[str, tuple[float, str]] | None = None) -> Path:
    """Write :func:`profile_figure` as a PNG."""
    return save(profile_figure(title, runs, reference, floors, units, left_out, sizes), path)


def heading(pid: str, *parts: str) -> str:
    """A profile figure's title: the profile's id, then its non-blank
    ``parts`` (its title, what is compared) joined by "; " after a colon;
    the id alone when every part is blank (a profile without a title)."""
    said = "; ".join(p.strip() for p in parts if p and p.strip())
    return f"{pid}: {said}" if said else pid


def profile_figure(title: str | tuple[str, ...], runs: dict[str, ProfileData], reference: str | None = None,
                   floors: dict[str, float] | None = None, units: Units = Units(), left_out=None,
                   sizes: dict[str, tuple[float, str]] | None = None):
    """One figure for a profile, titled :func:`heading` of its id and
    ``title`` (a string, or the parts of one): per quantity, the methods
    overlaid (the ``reference`` curve, default :func:`reference_label`,
    named :func:`~contactcore.labels.reference_text`) and, under it, each
    method minus the reference over ``sizes[q]`` (quantity -> ``(size,
    against)``, :meth:`verification.agreement.AgreementTable.sizes`: the
    agreement table's scale; see module doc), which ``floors`` (quantity ->
    floor: an exact law's gaps, :func:`verification.agreement.floors`)
    floored and the panel's title says; the axes labelled in the scene's
    ``units``.  ``left_out`` (a mask of the reference's samples, or None):
    the samples the agreement table leaves out near singular points,
    shaded grey in the difference panels."""
    first = next(iter(runs.values()))
    quantities = [n for n in first.names if n not in ("s", "x", "y")]
    ref = reference_of(runs, reference)
    rows = 2 if len(runs) > 1 else 1
    fig, axes = pyplot().subplots(rows * len(quantities), 1, figsize=(8.5, (3.0 + 1.6 * (rows - 1)) * len(quantities)),
                             squeeze=False, sharex=True, layout="constrained",
                             gridspec_kw={"height_ratios": [2, 1][:rows] * len(quantities)})
    for k, q in enumerate(quantities):
        ax = axes[rows * k, 0]
        scale = max(float(np.nanmax(np.abs(p.columns[q]))) for p in runs.values())
        factor, unit = axis_unit(q, scale, units)
        for i, (label, prof) in enumerate(runs.items()):
            named = {"label": reference_text(label)} if label == ref and rows == 2 else {}
            ax.plot(prof.columns["s"], prof.columns[q] / factor, **{**style(label, i, len(prof.columns["s"])), **named})
        ax.set_ylabel(unit)
        ax.grid(alpha=0.3)
        keep_span(ax, scale / factor)
        if k == 0:
            legend_outside(ax)
        if rows == 2:
            _difference_panel(axes[rows * k + 1, 0], q, runs, ref, (floors or {}).get(q, 0.0), units, left_out,
                              (sizes or {}).get(q))
    axes[-1, 0].set_xlabel(xlabel(first.parameter, units))
    parts = (title,) if isinstance(title, str) else title
    axes[0, 0].set_title(heading(first.id, *parts), fontsize=10, wrap=True)
    _no_offsets(fig)
    return fig


#: The relative Δ panels are drawn in percent.
PERCENT = 100.0

#: How dark the spans of samples the agreement leaves out are drawn.
LEFT_OUT_SHADE = 0.15


def _left_out_spans(s: np.ndarray, left_out: np.ndarray) -> list[tuple[float, float]]:
    """The s-intervals of consecutive left-out samples, each reaching half
    way to its kept neighbours."""
    s, out = np.asarray(s, float), np.asarray(left_out, bool)
    mid = np.concatenate([[s[0]], (s[1:] + s[:-1]) / 2, [s[-1]]])
    edges = np.flatnonzero(np.diff(np.concatenate([[0], out.astype(int), [0]])))
    return [(float(mid[a]), float(mid[b])) for a, b in zip(edges[::2], edges[1::2])]


def _difference_panel(ax, q: str, runs: dict[str, ProfileData], ref: str, floor: float = 0.0,
                      units: Units = Units(), left_out=None, size: tuple[float, str] | None = None) -> None:
    """Each curve but the reference minus the reference, at its own samples,
    over ``size`` (``(value, against)``: the agreement table's largest scale
    of ``q`` over the samples it keeps, :class:`~verification.agreement.Agreement`'s
    ``size``, ``floor`` in it; a pointwise ratio would blow up where the
    reference crosses zero) in percent, the y label naming it
    (:func:`size_symbol`); without a size, in ``q``'s unit.  The floor is
    named in ``q``'s unit in the scene's ``units``."""
    s_ref, v_ref = runs[ref].columns["s"], runs[ref].columns[q]
    relative = size is not None and np.isfinite(size[0]) and size[0] > 0
    factor, unit = ((size[0] / PERCENT, f"Δ{SYMBOLS.get(q, q)} / max{size_symbol(q, size[1])} (%)") if relative
                    else axis_unit(q, float(np.nanmax(np.abs(v_ref))), units))
    for i, (label, prof) in enumerate(runs.items()):
        if label != ref:
            s = prof.columns["s"]
            ax.plot(s, (prof.columns[q] - np.interp(s, s_ref, v_ref)) / factor, **style(label, i, len(s)))
    ax.axhline(0.0, color="black", lw=0.6)
    ax.grid(alpha=0.3)
    ax.set_ylabel(unit if relative else f"Δ{unit}")
    keep_span(ax, PERCENT if relative else float(np.nanmax(np.abs(v_ref))) / factor)
    spans = _left_out_spans(s_ref, left_out) if left_out is not None and np.any(left_out) else []
    for a, b in spans:
        ax.axvspan(a, b, color="grey", alpha=LEFT_OUT_SHADE, lw=0)
    floored = f", floored at {floor:.3g} {column_unit(q, units)}" if floor else ""
    shaded = "; grey: left out of summary.md's table (near singular points)" if spans else ""
    over = (f", over its largest {size_symbol(q, size[1])} away from singular points" if relative
            else "")
    ax.set_title(f"each minus the {reference_text(ref)}{over}{floored}{shaded}", fontsize=8, loc="right")


def _no_offsets(fig) -> None:
    """Tick labels in full, never as an offset plus small differences."""
    from matplotlib.ticker import ScalarFormatter
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            if isinstance(axis.get_major_formatter(), ScalarFormatter):
                axis.get_major_formatter().set_useOffset(False)


def save(fig, path: Path) -> Path:
    """Lay out (constrained, so titles and outside legends fit), drop offset
    tick labels, write atomically as PNG, and close a figure."""
    if fig.get_layout_engine() is None:
        fig.set_layout_engine("constrained")
    _no_offsets(fig)
    with atomic_path(Path(path)) as tmp:
        fig.savefig(tmp, dpi=110, format="png")
    pyplot().close(fig)
    return Path(path)


def loglog_by_variant(path: Path, rows: list[dict], x: str, y: str, xlabel: str, ylabel: str, title: str,
                      bars: tuple[str, str] | None = None) -> Path:
    """``rows[y]`` against ``rows[x]``, log-log, one line per (method,
    degree); ``bars`` the keys of each point's lower and upper bound."""
    fig, ax = pyplot().subplots(figsize=(7.5, 4.5))
    for i, key in enumerate(dict.fromkeys((r["method"], r["degree"]) for r in rows)):
        mine = [r for r in rows if (r["method"], r["degree"]) == key and y in r]
        if mine:
            ax.loglog([r[x] for r in mine], [r[y] for r in mine], **style(run_label(*key), i))
        if mine and bars:
            ax.errorbar([r[x] for r in mine], [r[y] for r in mine], fmt="none", capsize=2, alpha=0.6,
                        yerr=[[r[y] - r[bars[0]] for r in mine], [r[bars[1]] - r[y] for r in mine]],
                        color=ax.lines[-1].get_color())
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(which="both", alpha=0.3)
    legend_outside(ax)
    return save(fig, path)
