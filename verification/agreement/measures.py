"""The figures of a comparison: a difference's share of a size
(:func:`share`), in per cent (:func:`percent`), the relative RMS over the
kept samples (:func:`relative_rms`), and the first of the largest within
:data:`~contactcore.tolerances.WORST_TIE` (:func:`first_largest`)."""
from __future__ import annotations

import numpy as np

from contactcore import ProfileData, Scene
from contactcore.tolerances import WORST_TIE

from .samples import kept_samples
from .sizes import measured_against


def share(difference: float, size: float) -> float:
    """``difference / size``; 0 where both are 0, infinite where only the
    size is (a zero the compared run misses)."""
    return difference / size if size > 0 else (0.0 if difference == 0 else float("inf"))


def percent(fraction: float) -> str:
    """A relative difference in per cent, to three significant digits."""
    return f"{100 * fraction:.3g} %"


def relative_rms(scene: Scene, got: ProfileData, ref: ProfileData, quantity: str, exclude: float,
                 scale: np.ndarray | None = None) -> float:
    """RMS of ``got − ref`` over the kept samples, relative to the RMS of
    ``scale`` (default: the reference quantity itself; the table's measure
    is its group's size, :func:`scale_of`)."""
    keep = kept_samples(scene, ref, exclude)
    diff = got.columns[quantity][keep] - ref.columns[quantity][keep]
    base = measured_against(scene, quantity, ref.columns[quantity][keep]) if scale is None else np.asarray(scale)
    return share(float(np.sqrt(np.mean(diff ** 2))), float(np.sqrt(np.mean(base ** 2))))


def first_largest(items, key):
    """The first of ``items`` (in their order) whose ``key`` (≥ 0) lies
    within :data:`WORST_TIE` of the largest."""
    items = list(items)
    top = max(key(i) for i in items)
    return next(i for i in items if key(i) >= top * (1 - WORST_TIE))
