"""The interface's history, written and drawn: contact status, tractions and
Newton iterations per increment.

``DIR/<method>/increments.csv``  one row per converged (sub-)increment:
    iterations, final relative residual, open/stick/slip counts (and a
    ``partial`` count where the unilateral law's partial answer has
    partial points: contactcore.newton.partial), mean and RMS of t_N, t_T
    and mean g_N, g_T over Γ, and the open and slipping fractions of Γ
    (all weighted by the quadrature).
``DIR/<method>/interface.csv``   one row per increment and Γ point:
    x, y, s (along Γ), g_N, g_T, t_N, t_T, status (open, stick, slip or
    partial), and where a step has partial points a last column ``theta``:
    a partial point's share θ of the tie's shear, empty at the others.
``DIR/plots/status_<method>.png`` status along Γ (x) against the increment (y).
``DIR/plots/response.png``       against the increment, methods overlaid:
    RMS t_N and t_T on Γ and the open and slipping fractions of Γ; on a
    straight Γ also mean t_T against mean g_T (a frictional hysteresis loop
    under cyclic shear).  On a closed Γ (a circle) the mean of t_T is the
    net torque over 2πR², zero to round-off under a load without torque
    (about 1e-4 Pa on scene C-coulomb), so no loop is drawn there.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from contactcore import LineInterface
from contactcore.laws import REPORTED_STATUS_NAMES
from contactcore.interface_path import InterfacePath, along_from_entry

from . import files
from .plots import keep_span, legend_outside, pyplot, save, style

STATUS_COLOURS = ("#bbbbbb", "#2c7fb8", "#d95f0e", "#7b3294")  # open, stick, slip, partial


def step_value(k: float) -> int | float:
    """A step as ``increments.csv`` and ``interface.csv`` write it: an
    increment's number as an integer (``1``, not ``1.0``), a cut-back's
    sub-step (halved after a failure) as the fraction it is (``1.5``)."""
    return int(k) if float(k).is_integer() else float(k)


def increment_rows(path: InterfacePath) -> list[dict]:
    """One row per converged step (see module doc); a ``partial`` count in
    every row (0 where none) where any step has partial points."""
    w = path.weights / path.weights.sum()
    partial = any(s.partial.any() for s in path.steps)
    rows = []
    for s in path.steps:
        means, rms = path.means(s), np.sqrt(w @ s.traction ** 2)
        counts = {**s.counts(), **({"partial": int(s.partial.sum())} if partial else {})}
        rows.append({"step": step_value(s.step), "iterations": s.iterations, "residual": s.residuals[-1], **counts,
                     **dict(zip(("mean_tN", "mean_tT", "mean_gN", "mean_gT"), map(float, means))),
                     "rms_tN": float(rms[0]), "rms_tT": float(rms[1]),
                     **{f"{name}_fraction": path.status_shares(s)[name] for name in ("open", "slip")}})
    return rows


def write_history(folder: Path, scene, path: InterfacePath) -> None:
    """``increments.csv`` and ``interface.csv`` of one method's run."""
    rows = increment_rows(path)
    files.write_csv(folder / "increments.csv", rows, list(rows[0]))
    s = along_from_entry(scene, path.points)
    partial = any(step.partial.any() for step in path.steps)  # then a theta column
    points = []
    for step in path.steps:
        names, theta = step.status_names(), step.theta
        for i in range(len(s)):
            points.append({"step": step_value(step.step), "x": float(path.points[i, 0]), "y": float(path.points[i, 1]),
                           "s": float(s[i]), "gN": float(step.jump[i, 0]), "gT": float(step.jump[i, 1]),
                           "tN": float(step.traction[i, 0]), "tT": float(step.traction[i, 1]),
                           "status": names[i]})
            if partial:
                points[-1]["theta"] = float(theta[i]) if names[i] == "partial" else ""
    files.write_csv(folder / "interface.csv", points, list(points[0]))


def _integer_steps(axis) -> None:
    """Increments are counted: integer ticks only."""
    axis.set_major_locator(pyplot().MaxNLocator(integer=True))


def plot_status(out: Path, scene, label: str, path: InterfacePath) -> Path:
    """Status of every Γ point (x: along Γ) at every step (y)."""
    s = along_from_entry(scene, path.points)
    fig, ax = pyplot().subplots(figsize=(8, 4), layout="constrained")
    for code, (name, colour) in enumerate(zip(REPORTED_STATUS_NAMES, STATUS_COLOURS)):
        xs = [s[step.reported_status() == code] for step in path.steps]
        ys = [np.full(len(x), step.step) for x, step in zip(xs, path.steps)]
        if any(len(x) for x in xs):
            ax.scatter(np.concatenate(xs), np.concatenate(ys), s=6, c=colour, label=name, marker="s")
    ax.set_xlabel("polar angle θ (rad)" if hasattr(scene.interface, "radius")
                  else f"position along Γ ({files.parameter_unit('arclength', scene.units)})")
    ax.set_ylabel("increment")
    _integer_steps(ax.yaxis)
    ax.set_title(f"scene {scene.name}, {label}: contact status on Γ", fontsize=10)
    legend_outside(ax, markerscale=2)
    return save(fig, out)


#: Panels of the response figure against the increment: (column, label, scale
#: key); a label's unit is its column's in the scene's units (:func:`files.labelled`).
RESPONSE_PANELS = (("rms_tN", "RMS t_N on Γ", "traction"), ("rms_tT", "RMS t_T on Γ", "traction"),
                   ("open_fraction", "open fraction of Γ", "fraction"),
                   ("slip_fraction", "slipping fraction of Γ", "fraction"))


def plot_response(out: Path, scene, paths: dict[str, InterfacePath]) -> Path:
    """Write :func:`response_figure` as a PNG."""
    return save(response_figure(scene, paths), out)


def response_figure(scene, paths: dict[str, InterfacePath]):
    """The interface's response over the steps, one style per method (see
    module doc); the loop of mean t_T against mean g_T on a straight Γ."""
    loop = isinstance(scene.interface, LineInterface)
    mosaic = ([["loop", "loop"]] if loop else []) + [["rms_tN", "rms_tT"], ["open_fraction", "slip_fraction"]]
    fig, axes = pyplot().subplot_mosaic(mosaic, figsize=(10, 3.2 * len(mosaic)), layout="constrained")
    rows = {label: increment_rows(path) for label, path in paths.items()}
    traction = max(max(r["rms_tN"], r["rms_tT"]) for rs in rows.values() for r in rs)
    for i, (label, rs) in enumerate(rows.items()):
        steps = [r["step"] for r in rs]
        for key, _, _ in RESPONSE_PANELS:
            axes[key].plot(steps, [r[key] for r in rs], **style(label, i))
        if loop:
            axes["loop"].plot([r["mean_gT"] for r in rs], [r["mean_tT"] for r in rs], **style(label, i))
    for key, ylabel, kind in RESPONSE_PANELS:
        axes[key].set_xlabel("increment")
        axes[key].set_ylabel(files.labelled(ylabel, key, scene.units))
        _integer_steps(axes[key].xaxis)
        axes[key].grid(alpha=0.3)
        if kind == "fraction":
            axes[key].set_ylim(-0.05, 1.05)
        else:
            keep_span(axes[key], traction)
    if loop:
        axes["loop"].set_xlabel(files.labelled("mean slip g_T on Γ", "mean_gT", scene.units))
        axes["loop"].set_ylabel(files.labelled("mean t_T on Γ", "mean_tT", scene.units))
        axes["loop"].grid(alpha=0.3)
        keep_span(axes["loop"], traction)
    legend_outside(axes["loop" if loop else "rms_tT"])
    fig.suptitle(f"scene {scene.name}: the interface's response over the increments", fontsize=11)
    return fig


def iterations_table(paths: dict[str, InterfacePath]) -> str:
    """Markdown: Newton iterations of every step, one column per method."""
    labels = list(paths)
    steps = sorted({s.step for p in paths.values() for s in p.steps})
    rows = []
    for k in steps:
        row = {"step": f"{k:g}"}
        for label in labels:
            found = [s for s in paths[label].steps if s.step == k]
            row[label] = f"{found[0].iterations} ({found[0].residuals[-1]:.0e})" if found else "—"
        rows.append(row)
    return files.markdown_table(rows, ["step"] + labels)
