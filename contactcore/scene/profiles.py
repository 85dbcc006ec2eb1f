"""What a scene samples: quantities along a segment (:class:`LineProfile`)
or along Γ (:class:`InterfaceProfile`).  Declarations only: the sampling
itself is :mod:`contactcore.profiles`', the rules
:mod:`~contactcore.scene.check_profiles`'."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class LineProfile:
    """Quantities sampled on a segment from ``start`` to ``end``.

    On Γ the stress and displacement are taken from ``side`` (default +;
    ``"mean"``, the two sides' mean; docs/scenes.md).
    """

    id: str
    start: tuple[float, float]
    end: tuple[float, float]
    quantities: tuple[str, ...]
    side: str = "plus"
    title: str = ""


@dataclass(frozen=True)
class InterfaceProfile:
    """Quantities sampled along Γ against the polar angle or the arc length;
    ``parameter`` None takes Γ's own, as a scene file does: the angle on a
    circle, the arc length otherwise (the :class:`Scene` resolves it)."""

    id: str
    quantities: tuple[str, ...]
    parameter: str | None = None
    side: str = "plus"
    title: str = ""


Profile = LineProfile | InterfaceProfile
