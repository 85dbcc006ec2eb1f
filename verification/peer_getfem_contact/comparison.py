"""The peer's answer against ours: profile differences, Γ's status split, Γ's means.

A difference between GetFEM's answer and ours is measured as the
agreement measures two of our methods (:mod:`verification.agreement`):
on the scene's profiles, away from singular points
(:func:`~verification.agreement.default_exclusion`), the largest and
the RMS difference as shares of our largest |value| (a gap floored,
:func:`~verification.agreement.measured_against`).  Γ's state at the
last increment is summed over its quadrature: the open, stick and slip
shares of its length and the largest |t_N|; along the path, Γ's weighted
means (the layered-slip closed form's uniform state).

Contract: :func:`differences` gives one :class:`Difference` per profile
quantity of ``ref``, in its order; :func:`status_split` and
:func:`path_means` read a :class:`~contactcore.Result`'s interface record.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contactcore import Result, Scene


@dataclass(frozen=True)
class Difference:
    """One profile quantity of the peer against ours, over the samples away
    from singular points: the largest and the RMS difference, each as a
    share of ours' largest |value| (a gap floored, as the agreement floors
    it), and where the largest lies (the profile's ``s``)."""

    profile: str
    quantity: str
    worst: float
    rms: float
    at: float
    scale: float


def differences(scene: Scene, got: dict, ref: dict, exclude: float | None = None) -> list[Difference]:
    """Every profile quantity of ``got`` (id -> ProfileData) against ``ref``."""
    from verification.agreement import default_exclusion, kept_samples, measured_against
    exclude = default_exclusion(scene) if exclude is None else exclude
    rows = []
    for pid, prof in ref.items():
        keep = kept_samples(scene, prof, exclude)
        for q in prof.names[3:]:
            d = got[pid].columns[q][keep] - prof.columns[q][keep]
            scale = float(np.max(np.abs(measured_against(scene, q, prof.columns[q][keep]))))
            i = int(np.argmax(np.abs(d)))
            rows.append(Difference(pid, q, float(abs(d[i]) / scale), float(np.sqrt(np.mean(d ** 2)) / scale),
                                   float(prof.columns["s"][keep][i]), scale))
    return rows


def status_split(result: Result) -> dict[str, float]:
    """Γ at the last increment: the open, stick and slip shares of its
    length (quadrature weights) and the largest |t_N| at a point."""
    path = result.interface
    w, status = path.weights, path.final.status
    split = {name: float(w[status == i].sum() / w.sum()) for i, name in enumerate(("open", "stick", "slip"))}
    return {**split, "max_tN": float(np.max(np.abs(path.final.traction[:, 0])))}


def path_means(result: Result) -> np.ndarray:
    """Γ's means per increment (n, 4): t_N, t_T, g_N and g_T, each weighted
    by the quadrature (the layered-slip closed form's uniform state)."""
    path = result.interface
    w = path.weights / path.weights.sum()
    return np.array([np.concatenate([w @ step.traction, w @ step.jump]) for step in path.steps])
