"""The one side vocabulary: which body a point belongs to.

Γ separates the − body (φ < 0) from the + body (φ ≥ 0: the + side
includes Γ itself, docs/scenes.md).  A body has three names, one per use:

* its index 0/1 (:class:`Body`), for arrays indexed by body;
* its label "minus"/"plus" (``Body.label``, :data:`contactcore.scene.BODIES`),
  in scene files and output;
* its symbol "−"/"+" (``Body.symbol``, :func:`symbol_of`), in messages;
* its sign −1/+1 (``Body.sign``), the Heaviside function ``H`` of both
  enrichments (XFEM's and EFGM's ``u = Σ N_I u_I + Σ N_J (H − H_J) a_J``).

The conversions between them live here and nowhere else.
"""
from __future__ import annotations

from enum import IntEnum

import numpy as np


class Body(IntEnum):
    """A body by index; ``label`` and ``sign`` its other names."""

    MINUS = 0
    PLUS = 1

    @property
    def label(self) -> str:
        return self.name.lower()

    @property
    def sign(self) -> int:
        return sign_of_index(int(self))

    @property
    def symbol(self) -> str:
        """"−" or "+", as messages and docs name a body."""
        return "−" if self is Body.MINUS else "+"


def symbol_of(label: str) -> str:
    """A body's label ("minus"/"plus") → its symbol ("−"/"+")."""
    return Body[label.upper()].symbol


def sign_of(phi) -> np.ndarray:
    """The side (+1/−1) of points with level-set values ``phi``: +1 on Γ."""
    return np.where(np.asarray(phi) >= 0, 1, -1)


def side(interface, points) -> np.ndarray:
    """The side (+1/−1) of ``points`` with respect to ``interface``."""
    return sign_of(interface.phi(points))


def sign_of_index(index):
    """Body index (0/1, int or array) → sign (−1/+1): ``H = 2b − 1``."""
    return 2 * index - 1


def index_of_sign(sign):
    """Sign (−1/+1, int or array) → body index (0/1)."""
    return (sign + 1) // 2
