"""The interface's history, written and drawn: contact status, tractions and
Newton iterations per increment (issue 6).

``DIR/<method>/increments.csv``  one row per converged (sub-)increment:
    iterations, final relative residual, open/stick/slip counts, mean t_N,
    t_T, g_N, g_T over Γ (weighted by the quadrature).
``DIR/<method>/interface.csv``   one row per increment and Γ point:
    x, y, s (along Γ), g_N, g_T, t_N, t_T, status.
``DIR/plots/status_<method>.png`` status along Γ (x) against the increment (y).
``DIR/plots/response.png``       mean t_T against mean g_T over the increments,
    methods overlaid: a frictional hysteresis loop under cyclic shear.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from contactcore.laws import STATUS_NAMES
from contactcore.newton import InterfacePath, along

from . import files
from .plots import plt, save

STATUS_COLOURS = ("#bbbbbb", "#2c7fb8", "#d95f0e")  # open, stick, slip


def increment_rows(path: InterfacePath) -> list[dict]:
    """One row per converged step (see module doc)."""
    w = path.weights / path.weights.sum()
    rows = []
    for s in path.steps:
        means = w @ np.column_stack([s.traction, s.jump])
        rows.append({"step": s.step, "iterations": s.iterations, "residual": s.residuals[-1], **s.counts(),
                     **dict(zip(("mean_tN", "mean_tT", "mean_gN", "mean_gT"), map(float, means)))})
    return rows


def write_history(folder: Path, scene, path: InterfacePath) -> None:
    """``increments.csv`` and ``interface.csv`` of one method's run."""
    rows = increment_rows(path)
    files.write_csv(folder / "increments.csv", rows, list(rows[0]))
    s = along(scene.interface, path.points)
    points = []
    for step in path.steps:
        for i in range(len(s)):
            points.append({"step": step.step, "x": float(path.points[i, 0]), "y": float(path.points[i, 1]),
                           "s": float(s[i]), "gN": float(step.jump[i, 0]), "gT": float(step.jump[i, 1]),
                           "tN": float(step.traction[i, 0]), "tT": float(step.traction[i, 1]),
                           "status": STATUS_NAMES[step.status[i]]})
    files.write_csv(folder / "interface.csv", points, list(points[0]))


def plot_status(out: Path, scene, label: str, path: InterfacePath) -> Path:
    """Status of every Γ point (x: along Γ) at every step (y)."""
    s = along(scene.interface, path.points)
    fig, ax = plt.subplots(figsize=(7, 4))
    for code, (name, colour) in enumerate(zip(STATUS_NAMES, STATUS_COLOURS)):
        xs = [s[step.status == code] for step in path.steps]
        ys = [np.full(len(x), step.step) for x, step in zip(xs, path.steps)]
        if any(len(x) for x in xs):
            ax.scatter(np.concatenate(xs), np.concatenate(ys), s=6, c=colour, label=name, marker="s")
    ax.set_xlabel("polar angle θ (rad)" if hasattr(scene.interface, "radius") else "position along Γ (m)")
    ax.set_ylabel("increment")
    ax.set_title(f"scene {scene.name}, {label}: contact status on Γ")
    ax.legend(loc="upper right", fontsize=8)
    return save(fig, out)


def plot_response(out: Path, scene, paths: dict[str, InterfacePath]) -> Path:
    """Mean t_T against mean g_T over the steps, one line per method."""
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for label, path in paths.items():
        rows = increment_rows(path)
        ax.plot([r["mean_gT"] for r in rows], [r["mean_tT"] for r in rows], "o-", ms=3, label=label)
    ax.set_xlabel("mean slip g_T on Γ (m)")
    ax.set_ylabel("mean t_T on Γ (Pa)")
    ax.set_title(f"scene {scene.name}: interface shear against slip over the increments")
    ax.grid(alpha=0.3)
    ax.legend()
    return save(fig, out)


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
