"""EFGM's stiffness accumulated per background cell (issue 16 item 2)
against the per-point reference ``K = Bᵀ W D B``, and the block sink of
contactcore.assembly against dense sums."""
import numpy as np
import pytest
import scipy.sparse as sp

import tolerances as tol
from contactcore import BODIES, load_scene
from contactcore import discretisation
from contactcore.assembly import blocks_to_csr, sum_csr
from contactcore.elasticity import voigt_matrix
from contactcore.quadrature import background_cells, volume_rule
from efgm import method
from efgm.nodes import check_nodes, grid_nodes, perturbed_nodes, support_radii
from efgm.operators import Approximation, block_diagonal, find_enrichment
from efgm.shape import MLS


def _discretise(name, h, degree, rectangular=False, perturb=0.0):
    """Quadrature, approximation and Voigt matrices of scene ``name`` as
    efgm.method.solve builds them."""
    scene = load_scene(name)
    ns = check_nodes(scene, perturbed_nodes(scene, h, perturb, 0)) if perturb else grid_nodes(scene, h)
    dmax = method.DMAX[degree]
    radii = support_radii(ns, dmax, rectangular)
    vol = volume_rule(scene, ns.h, method.GAUSS_POINTS[degree])
    enrichment = find_enrichment(scene, ns.x, radii, vol.points, vol.bodies)
    approx = Approximation(MLS(ns.x, radii, degree=degree, dilation=dmax, seen_from=enrichment.seen_from),
                           enrichment)
    D = np.array([voigt_matrix(scene.materials[b].E, scene.materials[b].nu, scene.plane) for b in BODIES])
    lo, hi = background_cells(scene, ns.h)
    return vol, approx, D, lo.min(axis=0), hi[0] - lo[0]


def _per_point(vol, approx, D):
    """The reference: one strain operator row block per Gauss point."""
    B = approx.strain_operator(approx.mls.evaluate(vol.points, vol.bodies), vol.bodies)
    return B.T @ block_diagonal(vol.weights[:, None, None] * D[vol.bodies]) @ B


def _relative(K, R):
    return abs(K - R).max() / abs(R).max()


@pytest.mark.parametrize("name, h, degree, rectangular, perturb", [
    ("C", 0.2, 1, False, 0.0),  # Γ a circle: cut cells, enriched nodes
    ("A", 0.1, 1, True, 0.0),  # a straight Γ, rectangular supports
    ("C", 0.25, 2, False, 0.0),  # the quadratic basis
    ("A", 0.1, 1, False, 0.3),  # nodes off the grid
])
def test_cell_stiffness_is_the_per_point_one(name, h, degree, rectangular, perturb):
    vol, approx, D, origin, step = _discretise(name, h, degree, rectangular, perturb)
    assert approx.enr.count > 0
    R = _per_point(vol, approx, D)
    K = approx.stiffness(vol, origin, step, D)
    assert _relative(K, R) <= tol.EFGM_CELL_ASSEMBLY, _relative(K, R)


def test_any_grouping_gives_the_same_stiffness():
    """Cells of another size, off the background grid, split and merge the
    groups: the sums are the same."""
    vol, approx, D, origin, step = _discretise("C", 0.2, 1)
    K = approx.stiffness(vol, origin, step, D)
    for other in (0.37 * step, 2.5 * step):
        assert _relative(approx.stiffness(vol, origin - 0.1 * step, other, D), K) <= tol.EFGM_CELL_ASSEMBLY


def test_blocks_to_csr_sums_dense_blocks():
    rng = np.random.default_rng(3)
    dofs = rng.integers(-1, 9, (20, 4))
    blocks = rng.normal(size=(20, 4, 4))
    dense = np.zeros((9, 9))
    for d, b in zip(dofs, blocks):
        keep = d >= 0
        np.add.at(dense, (d[keep][:, None], d[keep][None, :]), b[np.ix_(keep, keep)])  # a dof may repeat
    K = blocks_to_csr((9, 9), dofs, blocks)
    assert np.allclose(K.toarray(), dense, rtol=0, atol=tol.SAME_SUMS * np.abs(dense).max())
    parts = [blocks_to_csr((9, 9), dofs[i:i + 7], blocks[i:i + 7]) for i in range(0, 20, 7)]
    total = sum_csr((9, 9), parts)
    assert total.has_sorted_indices and np.allclose(total.toarray(), dense, rtol=0,
                                                    atol=tol.SAME_SUMS * np.abs(dense).max())
    assert sum_csr((9, 9), []).nnz == 0 and isinstance(sum_csr((9, 9), []), sp.csr_matrix)


def test_newton_reuses_the_shape_functions(monkeypatch):
    """The coulomb law's increments and Newton iterations reuse K, Γ's
    operator and the loads: no shape function is evaluated while they run."""
    during, inside = [], []
    cell_shape, solve_increments = MLS.cell_shape, discretisation.solve_increments

    def counting(self, points, idx):
        during.append(bool(inside))
        return cell_shape(self, points, idx)

    def marked(*args, **kwargs):
        inside.append(True)
        try:
            return solve_increments(*args, **kwargs)
        finally:
            inside.pop()

    monkeypatch.setattr(MLS, "cell_shape", counting)
    monkeypatch.setattr(discretisation, "solve_increments", marked)
    result = method.solve(load_scene("C-coulomb"), 0.2)
    assert result.solver.increments > 1 and sum(result.solver.iterations) > result.solver.increments
    assert during and not any(during)


def test_blocks_to_csr_reads_shaped_local_dofs():
    """dofs (E, nodes, 2) with blocks (E, nodes, 2, nodes, 2), as a strided
    view: the same matrix as the flattened (E, n, n) blocks."""
    rng = np.random.default_rng(4)
    dofs = rng.integers(-1, 12, (6, 3, 2))
    blocks = rng.normal(size=(6, 2, 2, 3, 3)).transpose(0, 3, 1, 4, 2)
    flat = blocks_to_csr((12, 12), dofs.reshape(6, 6), blocks.reshape(6, 6, 6))
    assert abs(blocks_to_csr((12, 12), dofs, blocks) - flat).max() == 0.0
