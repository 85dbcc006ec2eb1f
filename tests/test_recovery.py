"""The degree-1 patch recovery (contactcore/recovery.py): what it reproduces
exactly, where it gives up, and that its patches are a body's own cells.
numpy only: a structured grid of unit squares stands for a mesh."""
import numpy as np
import pytest

from contactcore import tolerances as ctol
from contactcore.collective import SERIAL
from contactcore.recovery import PatchRecovery
import tolerances as tol

N = 8  # cells per side


def _grid():
    """Keys (node ids) and centroids of an N × N grid of unit squares."""
    i, j = np.meshgrid(np.arange(N), np.arange(N), indexing="ij")
    i, j = i.ravel(), j.ravel()
    node = lambda a, b: a * (N + 1) + b  # noqa: E731
    keys = np.column_stack([node(i, j), node(i + 1, j), node(i, j + 1), node(i + 1, j + 1)])
    return keys, np.column_stack([i + 0.5, j + 0.5])


def _quadratic(x):
    return np.column_stack([1 + 2 * x[:, 0] - x[:, 1] + 0.3 * x[:, 0] ** 2,
                            -4 + 0.5 * x[:, 0] * x[:, 1], 7 - 0.2 * x[:, 1] ** 2 + x[:, 1]])


def _recovery(field, mine=None):
    keys, centroids = _grid()
    mine = np.ones(len(keys), bool) if mine is None else mine
    sample = np.full(len(keys), -1)
    sample[mine] = np.arange(mine.sum())
    return PatchRecovery.gather(SERIAL, keys, sample, centroids[mine], np.ones(mine.sum()), field(centroids[mine]))


@pytest.mark.parametrize("field", [lambda x: np.tile([3.0, -1.0, 2.0], (len(x), 1)), _quadratic],
                         ids=["constant", "quadratic"])
def test_a_quadratic_field_is_reproduced_exactly(field):
    """Cell values that are a quadratic's samples at the centroids come back
    as that quadratic anywhere in each cell, the domain's corners included."""
    recovery, rows = _recovery(field)
    rng = np.random.default_rng(1)
    cells = rng.integers(0, N * N, 200)
    _, centroids = _grid()
    points = centroids[cells] + rng.uniform(-0.5, 0.5, (200, 2))
    got = recovery.at(rows[cells], points)
    assert np.max(np.abs(got - field(points))) <= tol.RECOVERY_EXACT * np.max(np.abs(field(points)))


def test_a_patch_too_small_for_a_line_gives_nan():
    """A body of two cells cannot fit a line: the caller reads the cell's own stress."""
    mine = np.zeros(N * N, bool)
    mine[[0, 1]] = True
    recovery, rows = _recovery(_quadratic, mine)
    assert np.all(np.isnan(recovery.at(rows[[0, 1]], np.array([[0.5, 0.5], [1.5, 0.5]]))))


def test_a_body_sees_only_its_own_cells():
    """The other body's cells are in the patch's rings but not among its
    samples: a field that jumps between the bodies is recovered on each side
    as that side's own quadratic."""
    keys, centroids = _grid()
    lower = centroids[:, 1] < N / 2
    other = lambda x: _quadratic(x) + 100.0  # noqa: E731
    for mine, field in ((lower, _quadratic), (~lower, other)):
        recovery, rows = _recovery(field, mine)
        cells = np.flatnonzero(mine)
        got = recovery.at(rows[cells], centroids[cells])
        assert np.max(np.abs(got - field(centroids[cells]))) <= tol.RECOVERY_EXACT * np.max(np.abs(field(centroids[cells])))


def test_the_patch_is_the_rings_around_a_cell():
    """RECOVERY_RINGS vertex rings around an interior cell of a grid: a
    (2r + 1)² block of cells."""
    recovery, rows = _recovery(_quadratic)
    centre = (N // 2) * N + N // 2
    reach = 2 * ctol.RECOVERY_RINGS + 1
    assert recovery.patches(np.array([rows[centre]])).nnz == reach ** 2


def test_samples_on_one_line_fit_no_slope_across_it():
    """A strip of body thinner than its cells (Γ along a row of cells): its
    parts' centroids lie on one line, up to round-off across it.  That
    spread is below RECOVERY_RANK of the patch, so no slope is fitted
    across the line (xfem P1 on scene A with Γ at y = 0.995, h = 0.025,
    read σ up to 1e16 Pa a few 1e-4 off the line: a slope fitted to
    round-off, 2026-11-29): each value off the line is NaN (the caller
    reads the cell's own) or within the samples' own range."""
    keys, centroids = _grid()
    mine = centroids[:, 1] == N - 0.5  # the top row of cells
    rng = np.random.default_rng(2)
    across = rng.uniform(-1, 1, mine.sum()) * ROUND_OFF_ACROSS
    line = centroids[mine] + np.column_stack([np.zeros(mine.sum()), across])
    sigma = np.column_stack([1e5 + 10 * line[:, 0], np.full(mine.sum(), -1e5), np.full(mine.sum(), 2.5e4)])
    sigma += rng.uniform(-1, 1, sigma.shape) * ROUND_OFF_ACROSS * 1e5
    sample = np.full(len(keys), -1)
    sample[mine] = np.arange(mine.sum())
    recovery, rows = PatchRecovery.gather(SERIAL, keys, sample, line, np.ones(mine.sum()), sigma)
    cells = np.flatnonzero(mine)
    got = recovery.at(rows[cells], centroids[cells] + np.array([0.0, 0.4]))  # inside each cell, across the line
    low, high = sigma.min(axis=0), sigma.max(axis=0)
    inside = (got >= low - tol.RECOVERY_EXACT * 1e5) & (got <= high + tol.RECOVERY_EXACT * 1e5)
    assert np.all(np.isnan(got) | inside), got


#: The spread across the line of the samples' centroids and of their σ
#: (relative), as the round-off of a sliver part's centroid and stress
#: leaves it (the xfem strip: S_min/S_max about 1e-14).
ROUND_OFF_ACROSS = 1e-12
