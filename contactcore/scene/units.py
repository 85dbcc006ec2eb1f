"""The names of a scene's units: labels of its numbers, never conversions."""
from __future__ import annotations

from dataclasses import dataclass

#: The longest unit name a scene may give (docs/scenes.md, "Units"): a
#: label such as "mm", "MPa" or "N/mm²", not a sentence.
MAX_UNIT_NAME = 16


@dataclass(frozen=True)
class Units:
    """The names of a scene's length and stress units: labels only.

    A scene may be given in any consistent set of units (docs/scenes.md,
    "Units"): lengths in ℓ, forces in F, stresses F/ℓ².  The numbers are
    never converted; these names label the results (plots, tables,
    ``units.json``): a spring stiffness in ``stress/length``, a
    displacement or a gap in ``length``.
    """

    length: str = "m"
    stress: str = "Pa"
