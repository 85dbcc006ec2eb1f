"""Plots of profiles, overlaying methods: one PNG per profile."""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from contactcore import ProfileData  # noqa: E402

from .files import atomic_path  # noqa: E402

UNITS = {"sxx": "σxx (Pa)", "syy": "σyy (Pa)", "sxy": "σxy (Pa)", "tN": "t_N (Pa)", "tT": "t_T (Pa)",
         "gN": "g_N (m)", "gT": "g_T (m)", "ux": "u_x (m)", "uy": "u_y (m)"}
XLABEL = {"arclength": "s (m)", "angle": "θ (rad)"}


def plot_profile(path: Path, title: str, runs: dict[str, ProfileData]) -> Path:
    """One figure for a profile: a panel per quantity, a line per method."""
    first = next(iter(runs.values()))
    quantities = [n for n in first.names if n not in ("s", "x", "y")]
    fig, axes = plt.subplots(len(quantities), 1, figsize=(7, 3.2 * len(quantities)), squeeze=False)
    for ax, q in zip(axes[:, 0], quantities):
        for label, prof in runs.items():
            ax.plot(prof.columns["s"], prof.columns[q], label=label, lw=1.4)
        ax.set_ylabel(UNITS.get(q, q))
        ax.grid(alpha=0.3)
        ax.legend()
    axes[-1, 0].set_xlabel(XLABEL.get(first.parameter, "s"))
    axes[0, 0].set_title(f"{first.id}: {title}")
    return save(fig, path)


def save(fig, path: Path) -> Path:
    """Lay out, write atomically as PNG, and close a figure."""
    fig.tight_layout()
    with atomic_path(Path(path)) as tmp:
        fig.savefig(tmp, dpi=110, format="png")
    plt.close(fig)
    return Path(path)


def loglog_by_variant(path: Path, rows: list[dict], x: str, y: str, xlabel: str, ylabel: str, title: str) -> Path:
    """``rows[y]`` against ``rows[x]``, log-log, one line per (method, degree)."""
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for key in dict.fromkeys((r["method"], r["degree"]) for r in rows):
        pts = [(r[x], r[y]) for r in rows if (r["method"], r["degree"]) == key and y in r]
        if pts:
            ax.loglog(*zip(*pts), "o-", label=f"{key[0]} p{key[1]}")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(which="both", alpha=0.3)
    ax.legend()
    return save(fig, path)
