"""The class :class:`MLS`: a node set's moving-least-squares shape functions.

One object per node set and its supports (Belytschko, Lu & Gu, IJNME 37,
1994; the paper's §VII): it checks the options, keeps the nodes, radii,
weight, basis and visibility, and indexes the nodes for the neighbour
search.  What it computes comes from its mixins, one idea each:
:class:`~efgm.shape.neighbours._Neighbours` (which nodes hold a point),
:class:`~efgm.shape.weights._Weights` (their weights),
:class:`~efgm.shape.evaluation._Evaluation` (Φ and ∇Φ at points),
:class:`~efgm.shape.cells._CellShapes` (at groups of points),
:class:`~efgm.shape.moments._Moments` (the moment matrix and its
regularity) and :class:`~efgm.shape.refusal._Refusal` (a singular one
refused by name).

Contract: the attributes set here are the ones the mixins read, each
mixin's module doc listing its own; after construction nothing changes
but the neighbour search's bucket tables, filled on first use under a
lock, so one object serves several threads.
"""
from __future__ import annotations

import numpy as np

from contactcore import DiscretisationError

from .basis import basis_size
from .cells import _CellShapes
from .evaluation import _Evaluation
from .moments import _Moments
from .neighbours import _Neighbours
from .refusal import _Refusal
from .weights import WEIGHTS, _Weights


class MLS(_Neighbours, _Weights, _Evaluation, _CellShapes, _Moments, _Refusal):
    """MLS shape functions of a node set.

    ``radii``: support radius of each node, shape (N,) for circular supports
    or (N, 2) for rectangular ones (half-widths in x and y).  ``seen_from``:
    (N, 2) bool, the bodies each node takes part in (:mod:`efgm.shape`), or None.
    ``to_user``: maps a point to the coordinates an error message gives
    (the user's, where the nodes are those of a dimensionless scene), or None.
    ``dilation``: the ``dmax`` the radii were made with, named in the
    refusal of a singular moment matrix, or None.
    """

    def __init__(self, nodes: np.ndarray, radii: np.ndarray, *, degree: int = 1, weight: str = "cubic",
                 dilation: float | None = None, seen_from: np.ndarray | None = None, to_user=None):
        if degree not in (1, 2):
            raise DiscretisationError(f"efgm: the MLS basis degree must be 1 or 2 (got {degree})")
        if weight not in WEIGHTS:
            raise DiscretisationError(f"efgm: unknown weight {weight!r} (known: {', '.join(WEIGHTS)})")
        self.nodes = np.asarray(nodes, float)
        self.radii = np.asarray(radii, float)
        self.rectangular = self.radii.ndim == 2
        self.degree, self.weight, self.dilation = degree, WEIGHTS[weight], dilation
        self.seen_from = None if seen_from is None else np.asarray(seen_from, bool)
        self.to_user = to_user or (lambda p: np.asarray(p, float))
        self.m = basis_size(degree)
        self._index_nodes()
