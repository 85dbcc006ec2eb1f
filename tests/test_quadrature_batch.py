"""The domain's Gauss points cut all at once (contactcore.cutcell.cut_squares,
contactcore.quadrature.volume_rule) are the cell-by-cell rule's, bit for bit:
points, weights, bodies and their order, on cut and rim cells of lines and
circles across rectangles and discs, with the awkward cells (a circle
tangent to grid lines, a circle inside one cell, a line along grid lines,
Γ and the rim in one cell) left to the cell-by-cell path; and the weights
sum to each body's area."""
from types import SimpleNamespace

import numpy as np
import pytest

from contactcore import quadrature as Q
from contactcore.cutcell import Rule, cut_cell, cut_squares
from contactcore.geometry import CircleInterface, Disc, LineInterface, Rectangle

import tolerances as tol


def _per_cell_volume_rule(scene, h: float, n: int) -> Rule:
    """The oracle: volume_rule as it was, one cell at a time (every cell
    that Γ or the rim may cross through _gamma_cell / _rim_cell)."""
    lo, hi = Q.background_cells(scene, h)
    centre = (lo + hi) / 2
    near_gamma = Q._near(scene.interface, lo, hi)
    outer = Q._outer_circle(scene)
    near_rim = Q._near(outer, lo, hi) if outer else np.zeros(len(lo), bool)
    plain = ~near_gamma & ~near_rim
    pts, w = Q.tensor_cells(lo[plain], hi[plain], n)
    rules = [Rule(pts, w, np.repeat((scene.interface.phi(centre[plain]) >= 0).astype(int), n * n))]
    for c in np.flatnonzero(~plain):
        if near_rim[c]:
            rules += Q._rim_cell(scene, outer, lo[c], hi[c], n, near_gamma[c])
        else:
            rules += Q._gamma_cell(scene, lo[c], hi[c], n)
    rule = Rule.concatenate(rules)
    keep = rule.weights > 0
    return Rule(rule.points[keep], rule.weights[keep], rule.bodies[keep])


def _unit(x, y):
    return (x / np.hypot(x, y), y / np.hypot(x, y))


#: name -> (domain, Γ, its − body's area); cells of h = 0.1, 0.05 and 1/30
GEOMETRIES = {
    "line on grid lines": (Rectangle((0.0, 0.0), (1.0, 1.0)), LineInterface((0.0, 0.5), (0.0, 1.0)), 0.5),
    "inclined line": (Rectangle((0.0, 0.0), (1.0, 1.0)), LineInterface((0.37, 0.52), _unit(0.3, 1.0)), None),
    "circle in a block": (Rectangle((0.0, 0.0), (2.0, 3.0)), CircleInterface((1.0, 1.5), 0.45), np.pi * 0.45 ** 2),
    "circle tangent to grid lines": (Rectangle((0.0, 0.0), (1.0, 1.0)), CircleInterface((0.5, 0.5), 0.25),
                                     np.pi * 0.25 ** 2),
    "circle centred on a node": (Rectangle((-1.0, -1.0), (2.0, 2.0)), CircleInterface((0.0, 0.0), 0.3),
                                 np.pi * 0.3 ** 2),
    "circle inside one cell": (Rectangle((0.0, 0.0), (1.0, 1.0)), CircleInterface((0.512, 0.513), 0.01),
                               np.pi * 0.01 ** 2),
    "circle in a disc": (Disc((0.0, 0.0), 1.0), CircleInterface((0.0, 0.0), 0.5), np.pi * 0.5 ** 2),
    "off-centre circle in a disc": (Disc((0.3, -0.2), 0.7), CircleInterface((0.35, -0.1), 0.3), np.pi * 0.3 ** 2),
    "line across a disc": (Disc((0.0, 0.0), 1.0), LineInterface((0.1, 0.1), _unit(0.3, 1.0)), None),
}


def _scene(name):
    domain, interface, _ = GEOMETRIES[name]
    return SimpleNamespace(domain=domain, interface=interface)


@pytest.mark.parametrize("name", list(GEOMETRIES))
@pytest.mark.parametrize("h, n", [(0.1, 2), (0.05, 3), (1 / 30, 4)])
def test_the_batched_volume_rule_is_the_per_cell_rule_bit_for_bit(name, h, n):
    scene = _scene(name)
    batched, oracle = Q.volume_rule(scene, h, n), _per_cell_volume_rule(scene, h, n)
    assert batched.points.shape == oracle.points.shape
    assert np.array_equal(batched.points, oracle.points)
    assert np.array_equal(batched.weights, oracle.weights)
    assert np.array_equal(batched.bodies, oracle.bodies)


@pytest.mark.parametrize("name", list(GEOMETRIES))
def test_the_batched_rule_s_weights_sum_to_the_bodies_areas(name):
    domain, interface, minus = GEOMETRIES[name]
    if minus is None:
        minus = interface.minus_area(domain)
    rule = Q.volume_rule(_scene(name), 0.05, 3)
    bound = tol.SPLIT_CIRCLE_AREA if name == "circle inside one cell" else tol.DISC_SPLIT_AREA
    assert rule.weights.sum() == pytest.approx(domain.area, rel=tol.DISC_SPLIT_AREA)
    assert rule.weights[rule.bodies == 0].sum() == pytest.approx(minus, rel=bound)


@pytest.mark.parametrize("name", ["inclined line", "circle in a block", "circle tangent to grid lines",
                                  "circle inside one cell"])
@pytest.mark.parametrize("tensor", [True, False], ids=["tensor", "fans"])
def test_cut_squares_settles_the_plain_cuts_as_cut_cell_does(name, tensor):
    """Each cell cut_squares settles holds cut_cell's regions (sides,
    points, weights) bit for bit, a whole cell given the tensor rule or the
    fans alike (``tensor``); it settles most of the cells Γ may cross and
    leaves the awkward ones (a tangent, a circle inside one cell) to
    cut_cell."""
    scene = _scene(name)
    lo, hi = Q.background_cells(scene, 0.05)
    near = np.flatnonzero(Q._near(scene.interface, lo, hi))
    done, chunks = cut_squares(scene.interface, lo[near], hi[near], 3, tensor)
    found = {}
    for cells, slot, side, pts, w in chunks:
        for k, c in enumerate(cells):
            found.setdefault(int(c), []).append((slot, int(side[k]), pts[k], w[k]))
    for k in np.flatnonzero(done):
        old = cut_cell(scene.interface, lo[near[k]], hi[near[k]], 3, tensor)
        new = [r[1:] for r in sorted(found[int(k)], key=lambda r: r[0])]
        assert [s for s, _, _ in old] == [s for s, _, _ in new]
        assert all(np.array_equal(a[1], b[1]) and np.array_equal(a[2], b[2]) for a, b in zip(old, new))
    if name == "circle inside one cell":  # the cell holding the circle is split, cell by cell
        holds = np.all((lo[near] <= scene.interface.centre) & (scene.interface.centre <= hi[near]), axis=1)
        assert holds.sum() == 1 and not done[holds].any()
    else:
        assert done.sum() >= tol.BATCH_SETTLED * len(near)
    if name == "circle tangent to grid lines":
        assert not done.all()
