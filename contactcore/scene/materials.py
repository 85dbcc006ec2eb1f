"""What each body is made of: an isotropic linear elastic material."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Material:
    """Isotropic linear elastic material (E in Pa)."""

    E: float
    nu: float
