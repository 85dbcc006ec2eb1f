"""A Result's fields read in the user's units.

Contract: :class:`ScaledFields` answers ``displacement``, ``stress`` and
``direct_stress`` at points in the user's coordinates and units, checked
against the user's scene (:func:`contactcore.result.check_points`) before
the method's own fields, over the dimensionless scene, see a point.
"""
from __future__ import annotations

import numpy as np

from ..result import check_points
from ..scene import Scene
from .scales import Scales


class ScaledFields:
    """A Result's fields: ``inner`` (the method's, over ``scales``'
    dimensionless scene) read in the user's units: ``u(x) = U u'(x')``,
    ``σ(x) = Σ σ'(x')``, ``x' = (x − o)/L``.

    With the user's ``scene``, every call holds to the contract of
    :class:`contactcore.result.Fields` (:func:`~contactcore.result.check_points`,
    in the user's coordinates and units) before the method sees a point;
    :attr:`extended` skips the geometric part of it, for a writer that reads
    a body's polynomial on a cut cell's vertices beyond Γ
    (:func:`xdolfinx.output.body_mesh`)."""

    def __init__(self, inner, scales: Scales, scene: Scene | None = None, reach: float = 0.0):
        self.inner, self.scales, self.scene, self.reach = inner, scales, scene, reach
        # the wrapper protocol of contactcore.result.method_fields
        self.base, self.origin, self.length_scale = inner, scales.origin, scales.length

    @property
    def extended(self) -> "ScaledFields":
        """The same fields without the check of points against the scene's
        geometry (the arrays are still checked)."""
        return ScaledFields(self.inner, self.scales)

    def displacement(self, points, bodies) -> np.ndarray:
        """``u`` (m, 2) of body ``bodies[i]`` (0 = −, 1 = +) at ``points[i]``
        ((m, 2)), both in the user's coordinates and length unit.  Refused
        by :func:`~contactcore.result.check_points` with a FieldsError
        naming the first bad point: outside the domain or the body named,
        not finite, a body other than 0 or 1, arrays of the wrong shape."""
        points, bodies = check_points(points, bodies, self.scene, "fields.displacement", self.reach)
        return self.scales.displacement * self.inner.displacement(self.scales.to_dimensionless(points), bodies)

    def stress(self, points, bodies) -> np.ndarray:
        """``(σxx, σyy, σxy)`` (m, 3) in the user's stress unit, of body
        ``bodies[i]`` at ``points[i]``; points refused as for
        :meth:`displacement`."""
        points, bodies = check_points(points, bodies, self.scene, "fields.stress", self.reach)
        return self.scales.stress * self.inner.stress(self.scales.to_dimensionless(points), bodies)

    def direct_stress(self, points, bodies) -> np.ndarray:
        """The stress of the computed displacement itself, ``σ(u_h)``
        (:class:`contactcore.result.Fields`' note): the method's own
        ``direct_stress`` where it has one (xfem), else :meth:`stress`
        (fe on curved cells: σ(u_h) interpolated per cell); points refused
        as for :meth:`displacement`."""
        direct = getattr(self.inner, "direct_stress", None)
        if direct is None:
            return self.stress(points, bodies)
        points, bodies = check_points(points, bodies, self.scene, "fields.direct_stress", self.reach)
        return self.scales.stress * direct(self.scales.to_dimensionless(points), bodies)
