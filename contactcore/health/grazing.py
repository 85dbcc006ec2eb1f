"""A warning on an answer of the ``unilateral`` law whose open zone is the
mesh's: Γ opened by the discretisation's error in ``g_N``, not by the loads.

The ``unilateral`` law ties a closed point (``t_T = k_T g_T``, exactly
``γ y_T``) and frees an open one (``t = 0``), so its tangential traction
jumps at ``g_N = 0``.  Where no load presses Γ across (grader17's
``shear-unilateral``: layers sheared by body forces, closed form
``g_N = 0``, ``t_N = 0``, ``t_T = 0.047`` on all of Γ) every point sits on
that switch, and the sign of each point's ``g_N`` is the discretisation's
error (1e-4 to 1e-3 of the jump in fe P1, docs/contact-enforcement.md, "No
normal load: Γ grazes everywhere").  Where Newton then finds a map, the
points whose error is a tension open, the others carry their shear, and
the answer's tractions are the mesh's: fe P1 at h = 0.05 opened 9 of 60
points by at most 1.1e-3 of the jump and put ``t_T`` 31 % above the
closed form, silently.

:func:`grazing_warnings` reads the converged path (gathered: the same on
every rank) and warns where, at some increment,

* Γ is open somewhere, and its largest opening ``max g_N`` over the open
  points is below ``GRAZING_OPENING`` of the displacement scale
  ``max(U, max |g|)`` (U the scene's displacement unit, 1 once
  dimensionless; ``max |g|`` Γ's largest jump, either component, at that
  increment): the scale the law's decisions already use
  (:class:`contactcore.laws.Decision`'s ``size``); and
* Γ's closed points carry a shear ``max |t_T|`` of at least
  ``GRAZING_SHEAR`` of the loads' stress (``stress_size``,
  :func:`contactcore.scaling.softer_stress`): the open/closed map then
  moves the tractions (a Γ whose every traction is the discretisation's
  noise, as ``tests/scenes/hung_on_gamma.toml``, opens by as little but its
  answer, ``t = 0``, is the same open or closed).

Both are ratios of a discretisation's error to a load's scale, never
round-off; on the cases measured (the constants' notes in
contactcore/tolerances.py) the opening bound lies 4.3 times above the
largest fe P1 grazing share and 6 below the smallest legitimate one, the
shear bound 3.8 and 4.7 times from its neighbours.  Known miss:
`shear-unilateral` pressed by 0.02 of its shear in efgm P2 at h = 0.1
grazes (76 of 80 points open, t_T up to 16 times the closed form on the
4 closed ones) with an opening share of 0.0135, above the bound.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol
from ..laws import OPEN


def grazing_zone(scene, path, stress_size: float) -> tuple[int, int, float, float] | None:
    """The first increment of a converged ``path`` (an
    :class:`~contactcore.interface_path.InterfacePath`) whose open zone is
    grazing (module doc): ``(increment, open points, points, opening
    share)``, or None (not the ``unilateral`` law, or no such increment)."""
    law = scene.law
    if path is None or not law.unilateral or law.frictional or law.has_history or law.is_linear:
        return None
    for step in path.steps:
        status = np.asarray(step.status)
        opened = status == OPEN
        if not opened.any() or opened.all():
            continue
        g = np.asarray(step.jump, float).reshape(-1, 2)
        t = np.asarray(step.traction, float).reshape(-1, 2)
        scale = max(1.0, float(np.max(np.abs(g))))  # U = 1 once dimensionless
        share = float(np.max(g[opened, 0])) / scale
        shear = float(np.max(np.abs(t[~opened, 1])))
        if share < tol.GRAZING_OPENING * (1 - tol.LIMIT_ROUNDOFF) and shear >= tol.GRAZING_SHEAR * stress_size:
            return step.step, int(np.count_nonzero(opened)), len(status), share
    return None


def grazing_warnings(scene, path, stress_size: float) -> list[str]:
    """One line where :func:`grazing_zone` finds a grazing open zone, naming its
    increment, how many points opened and by how much, and what to compare
    with; none otherwise."""
    found = grazing_zone(scene, path, stress_size)
    if found is None:
        return []
    step, count, points, share = found
    return [f"Γ opens at {count} of {points} points (increment {step:g}) by at most {share:.2g} of the displacement "
            f"jump's scale, below {tol.GRAZING_OPENING:g} (GRAZING_OPENING), while its closed points carry shear: an "
            "opening of the discretisation's size, where the loads leave Γ near g_N = 0 and the unilateral law "
            "ties a closed point's shear and frees an open one's, so the open/closed map is the mesh's, not the "
            "load's, and so are the tractions (grader17's shear-unilateral, fe P1 at h = 0.05: 9 points open, "
            "t_T 31 % above the closed form); compare with type = \"linear\" (the tie without opening) or at h/2 "
            "(docs/contact-enforcement.md, \"No normal load: Γ grazes everywhere\")"]
