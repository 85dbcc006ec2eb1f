"""contactcore.cutcell.polygon_rule: the n×n tensor rule on an axis-aligned
rectangle (its vertices from any corner, in any unit), exact for x^a y^b
with a, b ≤ 2n − 1; the fans (2n² points) on any other quadrilateral."""
import numpy as np
import pytest

from contactcore.cutcell import polygon_rule
from contactcore.cutcell.polygons import _rectangle_test, _split

import tolerances as tol


def _rectangle(lo, hi) -> np.ndarray:
    """The rectangle [lo, hi] counter-clockwise from lo, as cut_cell builds it."""
    (a, b), (c, d) = lo, hi
    return np.array([[a, b], [c, b], [c, d], [a, d]], float)


def _monomial_integral(lo, hi, a: int, b: int) -> float:
    return (hi[0] ** (a + 1) - lo[0] ** (a + 1)) / (a + 1) * (hi[1] ** (b + 1) - lo[1] ** (b + 1)) / (b + 1)


def _relative_error(points, weights, lo, hi, a: int, b: int) -> float:
    exact = _monomial_integral(lo, hi, a, b)
    return abs(float(weights @ (points[:, 0] ** a * points[:, 1] ** b)) - exact) / abs(exact)


@pytest.mark.parametrize("n", [2, 3, 4, 6])
@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3])
@pytest.mark.parametrize("start", [0, 1, 2, 3])
def test_axis_rectangle_takes_the_tensor_rule(n, scale, start):
    """n² points on an axis-aligned rectangle whichever corner its vertices
    start from, exact for every x^a y^b with a, b ≤ 2n − 1 (relative to
    the integral: the rectangle is off the origin so that none vanishes)."""
    lo, hi = np.array([0.5, 1.25]) * scale, np.array([1.5, 1.75]) * scale
    points, weights = polygon_rule(np.roll(_rectangle(lo, hi), -start, axis=0), n)
    assert len(weights) == n * n
    for a in range(2 * n):
        for b in range(2 * n):
            assert _relative_error(points, weights, lo, hi, a, b) <= tol.TENSOR_RULE_EXACT, (a, b)


@pytest.mark.parametrize("n", [2, 3])
def test_the_tensor_rule_misses_degree_2n(n):
    """The check above can fail: x^{2n} is beyond an n-point Gauss rule."""
    lo, hi = np.array([0.5, 1.25]), np.array([1.5, 1.75])
    points, weights = polygon_rule(_rectangle(lo, hi), n)
    assert _relative_error(points, weights, lo, hi, 2 * n, 0) > tol.TENSOR_RULE_EXACT


def test_split_pieces_are_rectangles():
    """The four quarters of a cell split about its centre (cutcell.polygons._split,
    their vertices starting at each corner in turn, the centre a mean of
    four corners, off the halves by an ulp) each take the tensor rule, and
    their weights sum to the cell's area."""
    cell = _rectangle((0.1, 0.3), (0.1 + 1 / 3, 0.3 + 1 / 7))
    pieces = _split(cell)
    assert _rectangle_test(np.array(pieces)).all()
    rules = [polygon_rule(piece, 3) for piece in pieces]
    assert all(len(w) == 9 for _, w in rules)
    area = (1 / 3) * (1 / 7)
    assert abs(sum(float(w.sum()) for _, w in rules) - area) <= tol.TENSOR_RULE_EXACT * area


@pytest.mark.parametrize("quad", [
    [[0.0, 0.0], [1.0, 0.1], [1.1, 1.0], [0.0, 0.9]],        # a distorted cell
    [[0.0, 0.0], [1.0, 1.0], [0.0, 2.0], [-1.0, 1.0]],       # a square turned by 45°
])
def test_other_quadrilaterals_are_fanned(quad):
    """Any other quadrilateral: fans from its first vertex, 2n² points,
    its area whole."""
    V = np.array(quad)
    assert not _rectangle_test(V[None])[0]
    points, weights = polygon_rule(V, 3)
    assert len(weights) == 2 * 9
    x, y = V[:, 0], V[:, 1]
    area = 0.5 * abs(float(x @ np.roll(y, -1) - y @ np.roll(x, -1)))
    assert abs(float(weights.sum()) - area) <= tol.TENSOR_RULE_EXACT * area
