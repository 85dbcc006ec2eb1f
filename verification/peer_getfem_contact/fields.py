"""GetFEM's displacement, stress and multiplier at points, each body from its own mesh.

The peer's fields are those of the XFEM peer
(:class:`verification.peer_getfem.GetFEMFields`: GetFEM's interpolation
of an expression of the model's variables at points), with one mesh and
one variable per body (``u1`` on the − body, ``u2`` on the +) instead of
one side of a level set each.  A point on Γ is moved by
:data:`~verification.peer_getfem.NUDGE` into its own body; a point just
outside its body's curved mesh (an O(h⁴) sliver of the circle) takes the
nearest cell's extension.

Contract: the :class:`contactcore.result.Fields` protocol of the parent,
and :meth:`GetFEMContactFields.multiplier`, λ at points of Γ.
"""
from __future__ import annotations

import numpy as np

from contactcore import Scene
from meshes.tags import BODY
from verification.peer_getfem import NUDGE, GetFEMFields

from .bodies import _Bodies


class GetFEMContactFields(GetFEMFields):
    """Displacement and stress of each body from its own GetFEM mesh (the
    XFEM peer's fields, :class:`~verification.peer_getfem.GetFEMFields`,
    with one mesh and one variable per body instead of one side each)."""

    #: The parent's expressions in a body's own variable ``{u}``.
    _OWN = {"u": "{u}", "Grad_u": "Grad_{u}"}

    def __init__(self, md, bodies: _Bodies, scene: Scene):
        super().__init__(md, None, scene, (bodies,))
        self.bodies = bodies

    def _eval(self, expr: str, points, bodies, width: int) -> np.ndarray:
        """``expr`` of each point's body, a point on Γ moved by NUDGE into
        it; a point just outside its body's curved mesh (an O(h⁴) sliver of
        the circle) takes the nearest cell's extension."""
        itf, L, bodies = self.scene.interface, self.scene.length_scale, np.asarray(bodies)
        points = np.asarray(points, float)[:, :2].copy()
        on = np.abs(itf.phi(points)) <= NUDGE * L
        points[on] += (NUDGE * L * (2 * bodies[on] - 1))[:, None] * itf.normals(points[on])
        out = np.zeros((len(points), width))
        for b, body in enumerate(BODY):
            sel = np.flatnonzero(bodies == b)
            if len(sel):
                own = self._OWN.get(expr, expr).format(u=_Bodies.VARS[body])
                vals = self.md.interpolation(own, points[sel].T.copy(), self.bodies.mesh[body], -1, 2)
                out[sel] = np.asarray(vals).reshape(len(sel), width)
        return out

    def multiplier(self, points) -> np.ndarray:
        """λ (m, 2), the traction on the − body, at points of Γ."""
        return self._eval("lambda", points, np.zeros(len(points), int), 2)
