"""A singular moment matrix refused by name: where, why, and what to change.

The MLS fit at a point (Belytschko, Lu & Gu, IJNME 37, 1994) needs at
least m nodes in its support, not on one line (m = 3 for the linear basis,
6 for the quadratic; :mod:`efgm.shape.moments`).  A point whose moment
matrix has a regularity ``det(A) / Π A_ii`` below
:data:`contactcore.tolerances.MOMENT_REGULARITY` is refused with a
:class:`~contactcore.DiscretisationError` that gives the point in the
user's coordinates, how many nodes it sees and whether they lie on one
line, and the remedy: a larger ``dmax`` (the support growth that takes in
the m + 1 nearest nodes), more nodes where the ones in reach are too few,
or, where Γ's visibility cut (Belytschko et al. 1996) leaves a body's
points only the nodes on one line, that the body is thinner than the node
spacing, which efgm refuses (docs/usage.md, docs/methods/efgm.md).

Contract of the mixin: :meth:`_Refusal._check_regular` returns nothing or
raises; it reads :class:`efgm.shape.MLS`'s ``nodes``, ``radii``,
``rectangular``, ``m``, ``tree``, ``reach``, ``dilation``, ``seen_from``
and ``to_user`` (a point to the coordinates a message gives).
"""
from __future__ import annotations

import numpy as np

from contactcore import DiscretisationError
from contactcore import tolerances as tol

#: Bodies by index, as the messages name them (contactcore.bodies: 0 is −, 1 is +).
_BODY_NAMES = ("−", "+")


def _on_one_line(xy: np.ndarray) -> bool:
    """Whether the points ``xy`` (n, 2) lie on one line: their centred
    coordinates' second singular value is at most
    :data:`~contactcore.tolerances.EFGM_NODES_ON_ONE_LINE` of their first
    (two or fewer points always do)."""
    if len(xy) <= 2:
        return True
    s = np.linalg.svd(xy - xy.mean(axis=0), compute_uv=False)
    return bool(s[1] <= tol.EFGM_NODES_ON_ONE_LINE * s[0])


class _Refusal:
    """The refusal of a singular moment matrix by :class:`efgm.shape.MLS`."""

    def _check_regular(self, points, ratio, w, idx, per: int = 1) -> None:
        """A clear error at the first point whose moment matrix has a
        :meth:`regularity` ``ratio`` below :data:`contactcore.tolerances.MOMENT_REGULARITY`
        (``w`` (P, K) its weights, ``idx[p // per]`` the nodes of point p's
        columns).  It says whether the nodes in the support lie on one line
        (:func:`_on_one_line`), and names a body thinner than the node
        spacing where that is why (:meth:`_thin_body`)."""
        bad = ~(ratio > tol.MOMENT_REGULARITY)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            seen = np.asarray(idx[i // per])[w[i] > 0]
            count = len(seen)
            dist, _ = self.tree.query(points[i], k=min(self.m + 1, len(self.nodes)))
            radius = float(np.median(self.radii if not self.rectangular else self.radii.max(axis=1)))
            grow = 1.05 * float(np.max(dist)) / radius  # the m+1 nearest nodes inside the supports
            collinear = count >= 2 and _on_one_line(self.nodes[seen])
            thin = self._thin_body(points[i], seen) if collinear else ""
            if thin:
                need = thin
            elif grow <= 1.0:  # no reach to suggest: the nodes it sees are too few (a gap, Γ's visibility cut)
                need = ("the nodes it sees within reach are too few or on one line (a gap in the node set, a "
                        "boundary, or Γ's cut of what each side sees): add nodes there, or enlarge dmax")
            elif self.dilation:
                need = f"dmax = {self.dilation:g} is too small here: about {self.dilation * grow:.2g} is needed"
            else:
                need = f"enlarge the supports about {grow:.2g} times"
            line = ", all on one line;" if collinear else ","
            x, y = self.to_user(points[i])
            raise DiscretisationError(
                f"efgm: the moment matrix at point ({x:.6g}, {y:.6g}) is singular: "
                f"{count} node(s) in its support{line} at least {self.m} not on one line are needed "
                f"({int(bad.sum())} such point(s)); {need}")

    def _thin_body(self, point, seen) -> str:
        """Why a point's nodes ``seen`` (on one line) are all it has, if
        Γ's visibility cut is why: "" unless some nodes whose supports hold
        the point are hidden from it, hidden from one body b that sees
        every node of ``seen`` (so the point is b's), and would leave the
        line.  Then b's side sees nodes on that one line only here: a body
        thinner than the node spacing, which efgm refuses (docs/usage.md,
        docs/methods/efgm.md)."""
        if self.seen_from is None:
            return ""
        near = np.asarray(self.tree.query_ball_point(point, self.reach), int)
        offset = np.abs(self.nodes[near] - point)
        held = (np.all(offset < self.radii[near], axis=1) if self.rectangular
                else np.hypot(*offset.T) < self.radii[near])
        hidden = np.setdiff1d(near[held], seen)
        sides = [b for b in (0, 1) if self.seen_from[seen, b].all() and not self.seen_from[hidden, b].any()]
        if len(hidden) == 0 or len(sides) != 1 or _on_one_line(self.nodes[np.concatenate([seen, hidden])]):
            return ""
        b = sides[0]
        gap, _ = self.tree.query(self.nodes[seen], k=2)
        origin = self.to_user(np.zeros(2))
        spacing = float(np.median(gap[:, 1])) * float(np.linalg.norm(self.to_user(np.array([1.0, 0.0])) - origin))
        name = _BODY_NAMES[b]
        return (f"Γ cuts what each side sees, and body {name}'s side sees nodes on that one line only here: body {name} "
                f"is thinner than the node spacing ({spacing:.3g}), which efgm refuses: use fe, or a node spacing "
                f"finer than body {name}'s thickness")
