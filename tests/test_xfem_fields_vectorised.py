"""xfem's displacement and stress at many points (XFEMFields._at: affine
cells vectorised over the points, curved cells one by one) equal the simple
per-point evaluation in each point's cell (XFEMFields._local), on cut and
uncut cells, for both bodies of a cut cell, on a curved Γ (the rod: gmsh
cells, curved at the rim at P2) and a straight inclined one (the patch) and
scene C (quads and triangles), and Γ snapped to a node line (its nodes
count as + in the cells beside it: docs/methods/xfem.md, "Evaluation at
many points")."""
from pathlib import Path

import numpy as np
import pytest

from contactcore.result import method_fields
from contactcore.scene_files import load_scene
from verification import methods
from verification.closed_forms import interface_patch, pressurised_rod

from tolerances import XFEM_VECTORISED_EVALUATION


def _nodeline():
    """A bar whose Γ lies on a node line (x = 1.2, 6 h at h = 0.2) moved
    1e-7 h off it: snapped, its nodes on Γ count as + (docs/methods/xfem.md,
    "Enrichment")."""
    from contactcore import LineInterface
    scene = load_scene(str(Path(__file__).resolve().parent / "scenes" / "nodeline_bar.toml"))
    return scene.with_changes(interface=LineInterface((1.2 + 2e-8, 0.0), (1.0, 0.0))).validated()


def _points(fields, per_cell: int = 3):
    """``per_cell`` points inside each owned cell that resolves a body (a
    fixed seed), with that body; a cut cell's points once for either body."""
    space = fields.space
    basis, rng = space.cells, np.random.default_rng(3)
    cells, bodies = [], []
    for body, side in ((0, -1), (1, 1)):
        c = space.cells_resolving(side)
        c = c[c < basis.owned_cells]
        cells.append(np.repeat(c, per_cell))
        bodies.append(np.full(len(c) * per_cell, body))
    cells, bodies = np.concatenate(cells), np.concatenate(bodies)
    # barycentric weights of the cell's corners: inside every cell, curved ones up to their bulge
    w = rng.dirichlet(np.ones(basis.corners.shape[1]), len(cells))
    points = np.einsum("pk,pkd->pd", w, basis.corners[cells])
    return cells, bodies, points


@pytest.mark.parametrize("case, cell", [(pressurised_rod, "gmsh"), (interface_patch, "gmsh"), (lambda: load_scene("C"), "quad"),
                                        (lambda: load_scene("C"), "triangle"), (_nodeline, "quad")])
@pytest.mark.parametrize("degree", [1, 2])
def test_vectorised_evaluation_equals_the_per_point_reference(case, cell, degree):
    """Every point of every resolving cell: u and σ of the cell's own
    polynomial, at once and point by point, agree to
    XFEM_VECTORISED_EVALUATION of the field's largest value; the points
    cover cut cells (both bodies) and uncut ones."""
    scene = case()
    scene = getattr(scene, "scene", scene)
    result = methods.solver("xfem")(scene, 0.2, degree=degree, cell=cell)
    fields, _ = method_fields(result.fields)
    cells, bodies, points = _points(fields)
    cut = np.isin(cells, list(fields.space.cut.regions))
    if case is _nodeline:  # no cell cut: the snapped nodes on Γ, enriched, count as + in the cells beside them
        basis = fields.space.cells
        assert basis.node_on[basis.cell_dofs[cells[bodies == 0]]].any()
    else:
        assert cut.any() and (~cut).any()
        assert set(bodies[cut]) == {0, 1}
    if case is pressurised_rod and degree == 2:
        assert fields.space.cells.curved[cells].any()  # the curved path too
    for gradient in (False, True):
        fast = fields._at(cells, bodies, points, gradient)
        slow = np.vstack([fields._local(int(c), int(b), p[None], gradient) for c, b, p in zip(cells, bodies, points)])
        scale = np.max(np.abs(slow))
        assert scale > 0
        assert np.max(np.abs(fast - slow)) <= XFEM_VECTORISED_EVALUATION * scale, (gradient, np.max(np.abs(fast - slow)) / scale)
