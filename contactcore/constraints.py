"""The one constraint type every method's builder returns.

The supports and pins of a scene become prescribed values ``C u = g f``:
row ``i`` takes ``g_i`` times the current factor of support
``owners[i]`` (its load path, :meth:`Scene.factors`), or stays at zero for
``owners[i] = −1`` (a pin, a field held at zero off its body, an unused
unknown).  A method whose unknowns are nodal values (fe, xfem) gives the
rows as unknowns, ``dofs`` (C a selection: the unknowns are eliminated);
one whose shape functions do not interpolate (EFGM) gives ``C`` itself,
``operator``, one row per multiplier of its supports (Lagrange
multipliers: a pin's point value, a supported edge's hat-weighted means,
:func:`efgm.method.support_multipliers`), with the ``points`` that name them.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from .collective import SERIAL, Collective
from .errors import SceneError


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
    def on_dofs(cls, dofs: list, values: list, owners: list, ranks: Collective = SERIAL) -> "Constraints":
        """Rows on unknowns given as lists of arrays; an unknown given twice
        keeps its first entry (a corner shared by two supports, a field
        already held at zero) where both prescribe the same: the same value,
        and the same load path unless that value is zero.  Otherwise which
        support won would depend on their order: a :class:`SceneError`,
        raised on every rank alike (``ranks``, each rank giving its owned
        unknowns), as EFGM's supports refuse the same clash."""
        if not dofs:
            return cls(np.zeros(0), np.zeros(0, int), dofs=np.zeros(0, np.int64))
        d, v, o = (np.concatenate([np.ravel(p) for p in a]) for a in (dofs, values, owners))
        unique, first, inverse = np.unique(d.astype(np.int64), return_index=True, return_inverse=True)
        kept_v, kept_o = v[first][inverse.ravel()], o[first][inverse.ravel()]
        clash = np.flatnonzero((v != kept_v) | ((v != 0) & (o != kept_o)))
        i = clash[0] if len(clash) else None
        ranks.raise_any(None if i is None else SceneError(
            _prescriber(o[i]), f"prescribes a displacement that {_prescriber(kept_o[i])} prescribes too, with "
            f"another value or load path ({len(clash)} unknown(s)); make them agree where they meet"))
        return cls(v[first], o[first], dofs=unique)

    def at(self, support_factors) -> np.ndarray:
        """The prescribed values at the supports' ``support_factors``."""
        factor = np.asarray(tuple(support_factors) + (0.0,))[self.owners]
        return self.values * np.where(self.owners >= 0, factor, 0.0)


def _prescriber(owner: int) -> str:
    """What prescribes a row of ``owner`` (Constraints' ``owners``)."""
    return f"supports[{owner}]" if owner >= 0 else "pins"
