"""The words a scene is written in: its bodies, the components a support
or pin holds, and the quantities a profile samples (docs/scenes.md)."""
from __future__ import annotations

from ..bodies import Body

BODIES = tuple(b.label for b in Body)
#: A profile's side on Γ besides a body's: the mean of the two sides'
#: limits, {σ} = (σ⁺ + σ⁻)/2 (contactcore.profiles.evaluate_quantities)
MEAN_SIDE = "mean"
PROFILE_SIDES = BODIES + (MEAN_SIDE,)
COMPONENTS = ("xy", "x", "y")
STRESS_QUANTITIES = ("sxx", "syy", "sxy")
DISPLACEMENT_QUANTITIES = ("ux", "uy")
INTERFACE_QUANTITIES = ("tN", "tT", "gN", "gT")
QUANTITIES = STRESS_QUANTITIES + DISPLACEMENT_QUANTITIES + INTERFACE_QUANTITIES
