"""The residual Newton drives to zero and the scales it is judged against.

    R(u) = A u − b(λ) + Gᵀ W t(G u, s)

on this rank's unknowns (``system.internal`` is ``A u``, the interface's
``internal`` is ``Gᵀ W t``).  Its rows are of two kinds: the equilibrium
rows (``balance``), whose residual is a force and is judged against the
larger of the loads and the internal forces there, and the constraint rows
(EFGM's multipliers, ``s (C u − ū)``), whose right-hand side is data, like
the forces the prescribed displacements alone exert (the lift).  The
round-off scale of a residual is at least RESIDUAL_FLOOR of the scene's
full loads, or the round-off of ``A u`` at ``u``'s size (PRODUCT_ROUNDOFF,
:meth:`_Residual._least`); the line search's merit is ``‖R‖₂`` over the free
rows.

Contract: a mixin of :class:`contactcore.newton.increments._Newton`; it
reads ``system``, ``itf``, ``ranks``, ``free``, ``balance``,
``constraint`` and ``_least_force`` and writes nothing.  Every figure is
reduced over the ranks (a collective), so every rank returns the same.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol


class _Residual:
    """The residual, its norms and its scales (module doc)."""

    def _residual(self, u, b, response) -> tuple[np.ndarray, float, float]:
        """The residual, the forces its equilibrium rows are judged against
        (the largest of the loads and the internal forces there), and the
        largest prescribed value of the constraint rows (data)."""
        internal = self.system.internal(u) + self.itf.internal(u, response.traction)
        R = internal - b
        forces = max(np.max(np.abs(b[self.balance]), initial=0.0),
                      np.max(np.abs(internal[~self.constraint]), initial=0.0))
        data = np.max(np.abs(b[self.constraint]), initial=0.0)
        return R, self.ranks.max(forces), self.ranks.max(data)

    def _least(self, u) -> float:
        """The least round-off scale of a residual at ``u``, for the health
        check (RESIDUAL_FAIL) only: RESIDUAL_FLOOR of the scene's full
        loads, or the scale at which the round-off ``A u`` carries,
        PRODUCT_ROUNDOFF of ``|u|``, is RESIDUAL_FAIL of it (``A u`` sums
        terms of ``u``'s size, however well they cancel: a body displaced
        rigidly, stress-free at zero load, has ``A u`` of round-off).  Never
        a convergence floor: NEWTON_RTOL of it would be round-off itself
        (PRODUCT_ROUNDOFF's note)."""
        size = self.ranks.max(float(np.max(np.abs(u[self.balance]), initial=0.0)))
        return max(self._least_force, tol.PRODUCT_ROUNDOFF / tol.RESIDUAL_FAIL * size)

    def _lift(self, supports) -> float:
        """The largest force on a free unknown of the prescribed
        displacements at the ``supports``' factors, every other unknown at
        zero, over the ranks: each takes part in ``internal`` (a collective)
        unless none holds a prescribed value."""
        prescribed = np.zeros(self.system.size)
        prescribed[self.system.fixed] = self.system.fixed_values(supports)
        if self.ranks.all(not prescribed.any()):
            return 0.0
        return self.ranks.max(float(np.max(np.abs(self.system.internal(prescribed)[self.free]), initial=0.0)))

    def _balance(self, R) -> float:
        """The largest residual of the equilibrium rows, over every rank."""
        return self.ranks.max(float(np.max(np.abs(R[self.balance]), initial=0.0)))

    def _merit(self, R: np.ndarray) -> float:
        """``‖R‖₂`` over the free rows of every rank."""
        return float(np.sqrt(self.ranks.sum(float(np.sum(R[self.free] ** 2)))))
