"""XFEM's unknowns: the standard ones of dolfinx's vector
space and two per enriched node, nothing fixed for being unused, and one
numbering of the enriched blocks shared by the matrix, the interface
operator and the fields.

The answers themselves are checked by the patch and cross-method tests of
tests/test_xfem.py, test_xfem_inclined.py and test_xfem_nodes.py."""
import numpy as np
import pytest
from dolfinx import geometry

import tolerances as tol
from contactcore import load_scene
from contactcore.result import method_fields
from xdolfinx import xfem

CASES = [("A", "quad", 1, 0.1), ("B", "gmsh", 1, 0.1), ("C", "triangle", 2, 0.2)]


@pytest.fixture(scope="module", params=CASES, ids=lambda c: "-".join(map(str, c[:3])))
def solved(request):
    """A solve of the case, the :class:`PETScSystem` it built (with the
    diagonal of its matrix, destroyed after the solve) and its fields."""
    name, cell, degree, h = request.param
    systems = []

    class Recorded(xfem.PETScSystem):
        def __init__(self, K, *args, **kwargs):
            super().__init__(K, *args, **kwargs)
            self.diagonal = K.getDiagonal().getArray().copy()
            systems.append(self)

    mp = pytest.MonkeyPatch()
    mp.setattr(xfem, "PETScSystem", Recorded)
    try:
        result = xfem.solve(load_scene(name), h, degree=degree, cell=cell)
    finally:
        mp.undo()
    fields = method_fields(result.fields)[0]
    return result, systems[0], fields


def test_unknowns_are_the_standard_ones_and_two_per_enriched_node(solved):
    result, system, fields = solved
    space = fields.space
    nodes = space.V.dofmap.index_map.size_local
    assert system.size == result.dofs == 2 * nodes + 2 * space.num_enriched
    assert 0 < space.num_enriched < nodes


def test_only_supports_and_pins_are_fixed(solved):
    """Every fixed unknown is a support's or a pin's, and every unknown is
    coupled: no zero diagonal, as an unused enriched component had."""
    _, system, fields = solved
    assert np.array_equal(system.fixed, np.unique(np.concatenate(xfem.support_rows(fields.space)[0])))
    assert np.all(system.diagonal > 0)


def test_interface_jump_reads_the_fields_enrichment(solved):
    """``G x`` (the interface operator's numbering) is, at each point of Γ,
    the fields' jump ``u₊ − u₋`` (their numbering) in the frame (n, t): the
    same |[[u]]|.  Points where a body is evaluated in a cell that does not
    hold them (slivers: a one-sided limit) are left out; most are kept."""
    _, system, fields = solved
    space = fields.space
    x = np.concatenate([fields.blocks[:, :2].ravel(), fields.blocks[space.enriched, 2:].ravel()])
    g = (system.interface.G @ x).reshape(-1, 2)
    points = system.interface.points
    p3 = np.column_stack([points, np.zeros(len(points))])
    holding = geometry.compute_colliding_cells(space.msh, geometry.compute_collisions(fields.locator.tree, p3), p3)
    same = np.all([[c in holding.links(i) for i, c in enumerate(fields.locator.cells(points, np.full(len(points), b)))]
                   for b in (0, 1)], axis=0)
    assert same.mean() > tol.MOST_POINTS_HELD
    jump = fields.displacement(points, np.ones(len(points), int)) - fields.displacement(points, np.zeros(len(points), int))
    gap = np.abs(np.linalg.norm(g, axis=1) - np.linalg.norm(jump, axis=1))[same]
    assert gap.max() <= tol.XFEM_NUMBERING * np.abs(g).max()
