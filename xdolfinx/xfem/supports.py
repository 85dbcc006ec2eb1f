"""XFEM's prescribed unknowns: supports on boundary facets and pins at nodes."""
from __future__ import annotations

import numpy as np
from dolfinx import fem, mesh

from contactcore import DiscretisationError
from contactcore import tolerances as tol

from .space import EnrichedFunctionSpace


def _facets_gamma_meets(space: EnrichedFunctionSpace, facets: np.ndarray) -> np.ndarray:
    """Which of the boundary ``facets`` hold points of both bodies: those
    whose nodes are not all on one side of Γ (a node on Γ is on its + side,
    :attr:`~xdolfinx.xfem.cells.CellBasis.node_side`, with each node's own
    snap distance).  Only there does a support hold both bodies' fields;
    elsewhere the enriched unknowns belong to the body that does not reach
    the support, and stay free."""
    sides = space.cells.node_side
    met = [np.ptp(sides[fem.locate_dofs_topological(space.V, 1, np.array([f], np.int32), remote=False)]) > 0
           for f in facets]  # this rank's own closure of each facet: no collective call per facet
    return np.array(met, bool)


def support_rows(space: EnrichedFunctionSpace) -> tuple[list, list, list]:
    """Rows (owned unknowns) of the supports and pins, their values at a
    factor of 1 and the support each follows (−1 for a pin or a fixed
    zero), as lists of arrays for :meth:`Constraints.on_dofs`.  Each rank
    finds them among its local nodes (a rank may not see every facet around
    a node it owns); the owners read the sums."""
    scene, msh, V = space.scene, space.msh, space.V
    rows, vals, owners = [], [], []
    tol_L = tol.NODE_MATCH * scene.length_scale

    def fix(blocks, j: int, value: float, owner: int) -> None:
        flags = np.zeros(2 * space.num_blocks)
        flags[2 * np.asarray(blocks, np.int64) + j] = 1.0
        found = space.owned_rows(flags)
        rows.append(found)
        vals.append(np.full(len(found), value))
        owners.append(np.full(len(found), owner))

    for i, sup in enumerate(scene.supports):
        facets = mesh.locate_entities_boundary(msh, 1, lambda x, n=sup.boundary: scene.domain.on_boundary(n, x[:2].T, tol_L))
        blocks = fem.locate_dofs_topological(V, 1, facets)
        # an enriched node of a supported facet that Γ meets: u_J + (H − H_J) a_J
        # must take the value on both sides, so a_J = 0 as well
        met = fem.locate_dofs_topological(V, 1, facets[_facets_gamma_meets(space, facets)])
        enriched = space.enriched_blocks[met[space.enriched[met]]]
        for comp in sup.fix:
            j = "xy".index(comp)
            fix(blocks, j, sup.value[j], i)
            fix(enriched, j, 0.0, -1)
    coords = V.tabulate_dof_coordinates()[:, :2]
    for i, pin in enumerate(scene.pins):
        d = np.linalg.norm(coords - np.asarray(pin.point), axis=1)
        at = np.flatnonzero(d <= tol_L)
        nearest = -space.cells.ranks.max(-float(np.min(d, initial=np.inf)))
        if nearest > tol_L:
            raise DiscretisationError(f"pins[{i}]: xfem needs pins at mesh nodes; the nearest is {nearest:.3g} away")
        for comp in pin.fix:
            fix(at, "xy".index(comp), 0.0, -1)
    return rows, vals, owners
