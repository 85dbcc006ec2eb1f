"""The one constraint type every method's builder returns.

The supports and pins of a scene become prescribed values ``C u = g f``:
row ``i`` takes ``g_i`` times the current factor of support
``owners[i]`` (its load path, :meth:`Scene.factors`), or stays at zero for
``owners[i] = −1`` (a pin, a field held at zero off its body, an unused
unknown).  A method whose unknowns are nodal values (fe, xfem) gives the
rows as unknowns, ``dofs`` (C a selection: the unknowns are eliminated);
one whose shape functions do not interpolate (EFGM) gives ``C`` itself,
``operator``, with the ``points`` it collocates (Lagrange multipliers).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp


@dataclass
class Constraints:
    """Prescribed values (module doc): ``values`` at a factor of 1,
    ``owners`` the support of each row (−1: always zero), and either
    ``dofs`` or ``operator`` (+ ``points``)."""

    values: np.ndarray
    owners: np.ndarray
    dofs: np.ndarray | None = None
    operator: sp.csr_matrix | None = None
    points: np.ndarray | None = None

    def __post_init__(self):
        self.values = np.asarray(self.values, float)
        self.owners = np.asarray(self.owners, int)
        if self.dofs is not None:
            self.dofs = np.asarray(self.dofs, np.int64)

    def __len__(self) -> int:
        return len(self.values)

    @classmethod
    def on_dofs(cls, dofs: list, values: list, owners: list) -> "Constraints":
        """Rows on unknowns given as lists of arrays; an unknown given twice
        keeps its first entry (a corner shared by two supports, a field
        already held at zero)."""
        if not dofs:
            return cls(np.zeros(0), np.zeros(0, int), dofs=np.zeros(0, np.int64))
        d, v, o = (np.concatenate([np.ravel(p) for p in a]) for a in (dofs, values, owners))
        unique, first = np.unique(d.astype(np.int64), return_index=True)
        return cls(v[first], o[first], dofs=unique)

    def at(self, support_factors) -> np.ndarray:
        """The prescribed values at the supports' ``support_factors``."""
        factor = np.asarray(tuple(support_factors) + (0.0,))[self.owners]
        return self.values * np.where(self.owners >= 0, factor, 0.0)
