"""Where a stress recovery's own error may set the estimate.

xfem P1's recovered stress (its options' ``recovered_stress``,
:class:`~contactcore.result.MethodFacts`) converges at order 1 in a layer
one cell thick along a curved Γ, where the recovery patch is one-sided
and cut cells' samples carry an O(h) bias, against 2 to 3 elsewhere: from
h = 0.025 that layer sets a ray's error and the two-run estimate, taken at
the order elsewhere, reads 0.42 to 0.47 of it (docs/methods/xfem.md,
"Degree-1 stress"); on other scenes such entries read 0.18-2.2.  The
estimate names such profiles without a direction (:func:`curved_layer`).
On a curved Γ the Zienkiewicz–Zhu estimate's recovery may be much of it
(:func:`recovery_floor`)."""
from __future__ import annotations

import numpy as np

from ... import tolerances as tol
from ...profiles import ProfileData
from ...result import MethodFacts
from ...scene import Scene
from ..energy import EnergyEstimate
from ..orders import STRESSES
from ..singular import far_from_singular
from .lines import see


def curved_layer(scene: Scene, levels: list[list[ProfileData]], facts: MethodFacts, h: float,
                 exclude: float) -> list[str]:
    """The ``PID:Q`` of a recovered stress (``facts.recovered_stress``:
    xfem P1's) on profiles with
    a sample kept (at least ``exclude`` from the singular points) within one
    cell of the coarser run, ``h``, of a curved Γ: there that stress
    converges at order 1 and the estimate, taken at the order elsewhere,
    is not to be trusted: too small on the rays of the pressurised rods
    (module doc), but 0.18-2.2 times the error on the 54 entries it named
    on four sets (2026-11-28), so the warning gives no direction.  Empty for a straight Γ or a stress not recovered.
    A sample at h within :data:`~contactcore.tolerances.GEOMETRY`
    (relative) counts, so round-off does not decide it."""
    if not facts.recovered_stress or scene.interface.straight_in(scene.domain):
        return []
    names = []
    for prof in levels[-1]:
        xy = np.column_stack([prof.columns["x"], prof.columns["y"]])
        kept = far_from_singular(scene, xy, exclude)
        near = np.abs(scene.interface.signed_distance(xy[kept])) <= h * (1 + tol.GEOMETRY)
        if np.any(near):
            names += [f"{prof.id}:{q}" for q in prof.names[3:] if q in STRESSES]
    return names


def curved_layer_warning(names: list[str], h: float, length: str = "m") -> list[str]:
    """One line naming :func:`curved_layer`'s quantities; lengths in the
    scene's unit named ``length``."""
    if not names:
        return []
    return [f"{', '.join(names)}: the recovered stress converges at order 1 within a cell ({h:g} {length}) of the "
            f"curved Γ: off either way; degree 2 avoids it{see('curved layer')}"]


def recovery_floor(energy: EnergyEstimate | None) -> list[str]:
    """One line where the recovery's own error may be much of the
    Zienkiewicz–Zhu estimate: on a curved Γ, a second recovery of σ*
    moves it by more than :data:`~contactcore.tolerances.ENERGY_RECOVERY_SHARE`
    of η (:func:`~contactcore.estimate.energy.recovery_moves`).  No
    direction: of the 16 entries it named, 15 read 1.35-4.70 times the
    error, but EFGM P2's on a disc whose Γ is open 0.67 (2026-11-29)."""
    if energy is None or energy.recovery is None or not energy.recovery > tol.ENERGY_RECOVERY_SHARE * energy.eta:
        return []
    return [f"energy (ZZ): on this curved Γ the recovery's own error is much of the estimate (a second recovery "
            f"moves it by {energy.recovery / energy.eta:.2g} of η): off either way; refine"
            f"{see('recovery floor')}"]
