"""Error norms of a dolfinx result against an exact solution.

``‖u_h − u‖²_{L2} = Σ_b ∫_{Ω_b,h} |u_{h,b} − u_b|² dx``, with the exact
field ``u_b`` (any :class:`~contactcore.result.Fields`, e.g. a closed form)
interpolated in Lagrange of degree ``k + 2`` so that its interpolation error
is of higher order than the one measured.
"""
from __future__ import annotations

import numpy as np
import ufl
from dolfinx import fem
from dolfinx.mesh import meshtags

from contactcore.scaling import dimensionless_view

from .evaluation import BodyFields

#: The exact field is interpolated this many degrees above the solution's.
EXACT_DEGREE_RAISE = 2


def l2_error(fields: BodyFields, exact) -> tuple[float, float]:
    """``(‖u_h − u‖, ‖u‖)`` in L2 over both bodies.

    A Result's fields (:class:`contactcore.scaling.ScaledFields`) are
    measured on the method's dimensionless mesh: ``‖u‖ = U L ‖u'‖'``
    (u = U u', dA = L² dA')."""
    scales = getattr(fields, "scales", None)
    if scales is not None:
        err, ref = l2_error(fields.inner, dimensionless_view(exact, scales))
        return scales.displacement * scales.length * err, scales.displacement * scales.length * ref
    msh = fields.locator.msh
    cells = fields.locator.body_cells
    tags = meshtags(msh, 2, np.concatenate(cells), np.concatenate([np.full(len(c), b, np.int32)
                                                                   for b, c in enumerate(cells)]))
    order = np.argsort(tags.indices)
    tags = meshtags(msh, 2, tags.indices[order], tags.values[order])
    dx = ufl.Measure("dx", domain=msh, subdomain_data=tags)
    err2 = ref2 = 0.0
    for b, uh in enumerate(fields.displacements):
        degree = uh.function_space.ufl_element().degree() + EXACT_DEGREE_RAISE
        Ve = fem.VectorFunctionSpace(msh, ("Lagrange", degree))
        ue = fem.Function(Ve)
        ue.interpolate(lambda x, b=b: exact.displacement(x[:2].T, np.full(x.shape[1], b)).T)
        err2 += fem.assemble_scalar(fem.form(ufl.inner(uh - ue, uh - ue) * dx(b)))
        ref2 += fem.assemble_scalar(fem.form(ufl.inner(ue, ue) * dx(b)))
    return float(np.sqrt(err2)), float(np.sqrt(ref2))
