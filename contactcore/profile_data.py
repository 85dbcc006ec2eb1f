"""A sampled profile's columns: the one type the profile sampler
(:mod:`contactcore.profiles`), the unit scaling (:mod:`contactcore.scaling`)
and the estimates share, kept apart so that the sampler may read the
scales (a law decided at the samples as the solve decided it)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class ProfileData:
    """The columns of one profile: ``s, x, y`` then its quantities.

    ``s`` is the arc length from the start, or the polar angle θ (rad) when
    ``parameter`` is ``"angle"``.
    """

    id: str
    parameter: str
    columns: dict[str, np.ndarray]

    @property
    def names(self) -> list[str]:
        return list(self.columns)
