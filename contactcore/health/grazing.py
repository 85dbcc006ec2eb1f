"""A warning on an answer of the ``unilateral`` law whose open zone is the
mesh's: Γ carries shear but no load presses it, so which of its points
open is decided by the discretisation's error in ``g_N``, not by the loads.

The ``unilateral`` law ties a closed point (``t_T = k_T g_T``, exactly
``γ y_T``) and frees an open one (``t = 0``), so its tangential traction
jumps at ``g_N = 0``.  Where no load presses Γ across (grader17's
``shear-unilateral``, ``tests/scenes/shear_unilateral.toml``: layers
sheared by body forces, closed form ``g_N = 0``, ``t_N = 0``,
``t_T = 0.047`` on all of Γ) every point sits on that switch, and the sign
of each point's ``g_N`` is the discretisation's error (1e-4 to 1e-3 of the
jump in fe P1, docs/contact-enforcement.md, "No normal load: Γ grazes
everywhere").  Where Newton then finds a map, the points whose error is a
tension open, the others carry the shear, and the answer's tractions are
the mesh's: fe P1 at h = 0.05 opened 9 of 60 points and put ``t_T`` 31 %
above the closed form; efgm P2 at h = 0.1, pressed by 0.02 of the shear,
opened 76 of 80 and put ``t_T`` up to 16 times above it on the other 4.

:func:`grazing_zone` reads the converged path (gathered: the same on
every rank) and finds the first increment at which Γ is partly open
(some points open, not all) and its closed points

* carry a shear ``max |t_T|`` above ``GRAZING_SHEAR`` of the loads'
  stress Σ (``stress_size``, :func:`contactcore.scaling.softer_stress`):
  the tie's shear is what the open/closed map moves (a Γ whose every
  traction is the discretisation's noise, as
  ``tests/scenes/hung_on_gamma.toml``, opens as much at random but its
  answer, ``t = 0``, is the same open or closed); and
* are pressed by at most ``max(−t_N)`` below ``GRAZING_PRESSURE`` of Σ:
  no load presses Γ where it carries that shear, so its closed points sit
  on the switch with its open ones.  An opening the loads make presses
  the rest of Γ by the loads' size (a moment, a lift: the closed zone
  then bears them).

Both are ratios of tractions to the loads' stress, the same in any units.
Measured (the constants' notes in contactcore/tolerances.py and
docs/contact-enforcement-log.md, "Γ grazing: the closed points' pressure"):
every grazing answer found (fe P1 at h = 0.05 pressed by 0 to 0.1 of the
shear, efgm P2 at h = 0.1 pressed by 0.02 and 0.05) has its closed points
pressed by at most 0.024 of Σ, every legitimate opening with a closed
shear above the bound by 1.15 of it or more (the two bounds are not
independent: scene C on springs, pressed by 0.104-0.108 of Σ, 1.4 times
below the pressure bound, is kept silent by its closed shear, at most
9.8e-4 of Σ, 51 times below the shear bound); the shear bound lies 3.3
times below the smallest grazing shear and 4.7 above the hung body's.
At a bound within round-off the answer is not warned of (either
condition), so no kernel's last digits decide it.

The warning prints the largest opening in the scene's length unit and as
a share of the displacement scale ``max(U, max |g|)`` (U the displacement
the loads cause, L τ/E, :class:`contactcore.scaling.Scales`; ``max |g|``
Γ's largest jump at that increment: the scale of the law's decisions,
:class:`contactcore.laws.Decision`'s ``size``), and the shear and the
pressure in the scene's stress unit and as shares of Σ.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .. import tolerances as tol
from ..laws import OPEN
from ..scaling import Scales
from ..scene.units import Units


class Grazing(NamedTuple):
    """A grazing open zone at one increment, dimensionless as the path:
    ``opening`` the largest open ``g_N``, ``scale`` ``max(1, max |g|)`` (U
    = 1), ``shear`` and ``pressure`` the closed points' largest ``|t_T|``
    and ``−t_N``, ``stress`` the loads' stress Σ."""

    step: float
    open: int
    points: int
    opening: float
    scale: float
    shear: float
    pressure: float
    stress: float


def grazing_zone(scene, path, stress_size: float) -> Grazing | None:
    """The first increment of a converged ``path`` (an
    :class:`~contactcore.interface_path.InterfacePath`) whose open zone is
    grazing (module doc), or None (not the ``unilateral`` law, or no such
    increment)."""
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
        shear = float(np.max(np.abs(t[~opened, 1])))
        pressure = float(np.max(-t[~opened, 0], initial=0.0))
        # at a bound within round-off: silent (review9 #7), on both conditions alike
        if (shear > tol.GRAZING_SHEAR * stress_size * (1 + tol.LIMIT_ROUNDOFF)
                and pressure < tol.GRAZING_PRESSURE * stress_size * (1 - tol.LIMIT_ROUNDOFF)):
            scale = max(1.0, float(np.max(np.abs(g))))  # U = 1 once dimensionless
            return Grazing(step.step, int(np.count_nonzero(opened)), len(status), float(np.max(g[opened, 0])),
                           scale, shear, pressure, stress_size)
    return None


def _user_units(scene) -> tuple[float, float, Units]:
    """``(U, Σ unit, units)``: the displacement and stress units of a
    dimensionless ``scene`` in its user's numbers and their names; 1, 1
    and the scene's own names where it is the user's."""
    source = getattr(scene, "source", None)
    if source is None:
        return 1.0, 1.0, getattr(scene, "units", Units())
    scales = Scales.of(source)
    return scales.displacement, scales.stress, source.units


def grazing_warnings(scene, path, stress_size: float) -> list[str]:
    """One line where :func:`grazing_zone` finds a grazing open zone, naming
    its increment, how many points opened and by how much (in the scene's
    length unit and as a share of the displacement scale), the closed
    points' shear and pressure (in its stress unit and as shares of the
    loads' stress), and what to compare with; none otherwise."""
    found = grazing_zone(scene, path, stress_size)
    if found is None:
        return []
    U, stress_unit, units = _user_units(scene)
    length, stress = units.length, units.stress
    share = found.opening / found.scale
    return [f"Γ grazes: no load presses it where it carries shear, so which of its points the unilateral law opens "
            "is the discretisation's error in g_N, and the open/closed map and the tractions are the mesh's, not the "
            "load's (compare with type = \"linear\" or at h/2; docs/contact-enforcement.md, \"No normal load: Γ "
            f"grazes everywhere\"). Γ opens at {found.open} of {found.points} points (increment {found.step:g}) by at "
            f"most {found.opening * U:.2g} {length} ({share:.2g} of max(U, max|g|) = {found.scale * U:.2g} {length}, "
            f"U = {U:.2g} {length} from the loads), while its closed points carry a shear of up to "
            f"{found.shear * stress_unit:.2g} {stress} ({found.shear / found.stress:.2g} of the loads' stress Σ = "
            f"{found.stress * stress_unit:.2g} {stress}) on a pressure of at most {found.pressure * stress_unit:.2g} "
            f"{stress} ({found.pressure / found.stress:.2g} of Σ, below {tol.GRAZING_PRESSURE:g}, GRAZING_PRESSURE)"]
