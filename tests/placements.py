"""Scenes with Γ placed off the node rows, and the pointwise agreement
measure of issues 19 and 22, for the EFGM and XFEM tests.

``inclined_A(angle, height)`` is scene A with a straight Γ turned ``angle``
degrees through ``(0.5, height)``, its profiles A1, A2, A3, A5 along Γ's
chord (A4 on y = 1 as shipped).  ``circle_C(centre, radius)`` is scene C
with the rod moved.  ``worst_sample`` is the largest ``|got − ref|`` over
the samples at least ``exclude`` from the domain's corners and Γ's ends,
relative to the largest ``|ref|`` there (the profile's scale).
"""
from __future__ import annotations

import dataclasses

import numpy as np

from contactcore import load_scene
from contactcore.tolerances import EXCLUDE_FRACTION
from contactcore.geometry import CircleInterface, LineInterface
from contactcore.scene import LineProfile
from verification.agreement import kept_samples

import tolerances as tol

def inclined_A(angle: float, height: float):
    """Scene A with Γ through ``(0.5, height)`` at ``angle`` degrees to x."""
    t = np.radians(angle)
    normal = (-float(np.sin(t)), float(np.cos(t)))
    base = load_scene("A")
    itf = LineInterface((0.0, height - 0.5 * float(np.tan(t))), normal)
    a, b = itf.chord(base.domain)
    profiles = tuple(p if p.id == "A4" else dataclasses.replace(p, start=tuple(a), end=tuple(b))
                     for p in base.profiles if isinstance(p, LineProfile))
    return base.with_changes(name=f"A-tilt{angle:.1f}_{height:.2f}", interface=itf, profiles=profiles)


def circle_C(centre, radius: float):
    """Scene C with its rod centred at ``centre`` with ``radius``."""
    base = load_scene("C")
    return base.with_changes(name=f"C-rod{centre[0]:.2f}_{centre[1]:.2f}",
                             interface=CircleInterface(tuple(centre), radius))


def exclusion(scene) -> float:
    """Samples nearer than EXCLUDE_FRACTION of the domain's shorter side to a
    corner or to an end of Γ are left out (issue 22: 0.1 on scene A)."""
    return EXCLUDE_FRACTION * float(min(scene.domain.size))


def worst_sample(scene, got: dict, ref: dict) -> tuple[float, str, str]:
    """``(worst relative difference, profile id, quantity)`` over every
    quantity of every profile (see module doc)."""
    worst = (0.0, "", "")
    for pid, prof in ref.items():
        keep = kept_samples(scene, prof, exclusion(scene))
        for q in prof.names[3:]:
            r, g = prof.columns[q][keep], got[pid].columns[q][keep]
            value = float(np.max(np.abs(g - r)) / np.max(np.abs(r)))
            worst = max(worst, (value, pid, q))
    return worst


def seeded_inclined(count: int, seed: int = 22) -> list[tuple[float, float]]:
    """``count`` seeded ``(angle in ±30°, height in 0.35–0.65)`` placements
    of a straight Γ in scene A (issue 22), 4 decimals."""
    rng = np.random.default_rng(seed)
    return [tuple(float(v) for v in np.round(rng.uniform((-30.0, 0.35), (30.0, 0.65)), 4)) for _ in range(count)]


def one_sided_gaps(fields, scene, x: float, angle: float, h: float) -> tuple[float, float]:
    """σ of the + body at the point of Γ above ``x`` (Γ turned ``angle``°)
    against σ 1e-6 off Γ, and against the quadratic extrapolation to Γ of σ
    at h/8, h/4 and 3h/8 off Γ: both differences over |σ| 1e-6 off Γ."""
    n = np.asarray(scene.interface.normal)
    on = np.array([[x, scene.interface.point[1] + x * np.tan(np.radians(angle))]])
    assert abs(scene.interface.phi(on)[0]) < tol.ON_GAMMA_PHI
    offs = np.array([0.0, 1e-6, h / 8, h / 4, 3 * h / 8])
    sig = fields.stress(on + offs[:, None] * n, np.ones(len(offs), int))
    scale = np.linalg.norm(sig[1])
    extrapolated = np.polynomial.polynomial.polyfit(offs[2:], sig[2:], 2)[0]
    return float(np.linalg.norm(sig[0] - sig[1]) / scale), float(np.linalg.norm(sig[0] - extrapolated) / scale)
