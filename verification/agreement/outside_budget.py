"""The project's answer and its estimated error at an outside answer's
samples (issue 34; docs/api.md, "An outside code's answer"): what a
difference is measured against.

Contract: :func:`interpolated` gives the project's profile values at any
``s`` of the profile (linear, wrapping round a circle) and the linear
interpolation's error there (0 at the project's own samples);
:func:`envelope` gives, at each of the project's samples, the largest
``q_err`` within a window along ``s`` (:data:`ESTIMATE_WINDOW_CELLS`
coarse cells either side) among the kept samples of the same body.
``geo`` is the profile's geometry
(:func:`~verification.agreement.profile_geometry.geometry`). numpy only;
no solve.
"""
from __future__ import annotations

import numpy as np

#: The project's estimate at a sample is the largest ``q_err`` within this
#: many of the coarse run's cells along the profile, either side: the
#: Richardson estimate ``|q_{h/2} − q_h|/(2^p − 1)`` vanishes where the two
#: runs cross, at the coarse cells' scale (docs/error-estimates.md: ``q_err``
#: is an indicator, not a bound, at a sample), so a sample there would blame
#: any difference.  Measured (2026-11-29, fe P2 at h = 0.1 and 0.05 on the
#: cylinder, A, B, C, every profile quantity, the project's own answer at
#: h/4 as the outside one, all 101 samples): the largest |difference| /
#: estimate of an unwarned quantity read 4.39-4.54 with one cell (G's g_T,
#: t_N, t_T on the cylinder: one sample each blamed wrongly, an exact law's
#: traction varying at the fine cells' scale), 3.68 with 1.5, 2.52 with two
#: cells (none blamed), 2.17 with three.  Within the same body: a profile
#: crossing Γ samples two fields, and the runs' error where Γ cuts it
#: (scene C's C3 σyy) is not the other side's.  Among kept samples only
#: (:func:`envelope`; outside2, 2026-11-29): the same figures at h = 0.1;
#: at h = 0.05 A, B, C blame none (2.50 at most) and the cylinder's Γ 7
#: single samples (up to 13.5; 3 cells: 2), as before the change
#: (docs/error-estimates-log.md, "the outside verdict's window").
ESTIMATE_WINDOW_CELLS = 2.0


def _periodic(geo, s: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The project's samples, closed around a circle (its first sample
    repeated one period on) so that interpolation wraps."""
    if not geo.periodic:
        return s, values
    return np.append(s, s[0] + geo.span), np.append(values, values[0])


def interpolated(geo, s_p: np.ndarray, q_p: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The project's ``q_p`` at its samples ``s_p`` interpolated linearly to
    ``s``, and the interpolation's error there: ``α(1 − α)/2 · |Δ²q|`` (the
    linear interpolant's error of a quadratic, ``α`` the share of the
    interval, ``Δ²q`` the larger second difference at its ends): 0 at the
    project's own samples."""
    sp, qp = _periodic(geo, s_p, q_p)
    if geo.periodic:
        d2 = np.abs(np.roll(q_p, 1) - 2 * q_p + np.roll(q_p, -1))
        d2 = np.append(d2, d2[0])
    else:
        d2 = np.zeros_like(q_p)
        d2[1:-1] = np.abs(q_p[:-2] - 2 * q_p[1:-1] + q_p[2:])
        d2[0], d2[-1] = d2[1], d2[-2]
    value = np.interp(s, sp, qp)
    j = np.clip(np.searchsorted(sp, s, side="right") - 1, 0, len(sp) - 2)
    alpha = np.clip((s - sp[j]) / (sp[j + 1] - sp[j]), 0.0, 1.0)
    return value, alpha * (1 - alpha) / 2 * np.maximum(d2[j], d2[j + 1])


def envelope(geo, s_p: np.ndarray, err: np.ndarray, window: float, body: np.ndarray,
              kept: np.ndarray) -> np.ndarray:
    """The largest ``err`` within ``window`` (in ``s``'s unit) of each
    sample, among the ``kept`` samples (those the agreement compares: the
    runs' error near a singular point, left out, would swell the estimate
    of samples beside it, newuser34's A3 σxx 22× its true error) in the same
    ``body`` (a profile crossing Γ samples two fields: the runs' error where
    Γ cuts it is not the other side's)."""
    d = np.abs(s_p[:, None] - s_p[None, :])
    if geo.periodic:
        d = np.minimum(d, geo.span - d)
    near = (d <= window) & (body[:, None] == body[None, :]) & kept[None, :]
    return np.max(np.where(near, err[None, :], 0.0), axis=1)
