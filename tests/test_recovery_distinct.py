"""The patch recovery factors each distinct patch matrix once
(contactcore.recovery.distinct_svd) and fills its padded stacks through
flat indices: the recovered stress is the same bits as the plain fit (every
patch factored, ``A[rows, pos]`` filled), on a grid whose patches repeat
and on the Zienkiewicz–Zhu estimate's Gauss points of scene C, cut by Γ.
numpy only."""
import numpy as np
import pytest

from contactcore import recovery
from contactcore.estimate import energy
from contactcore.recovery import PatchRecovery, distinct_svd, quadratic_basis
from contactcore.scene_files import load_scene


def _plain_fit(self, targets):
    """PatchRecovery._fit as it was before distinct_svd (2026-11-28): every
    patch factored, the stacks filled by (row, position) pairs."""
    index, centroids, areas, sig = self.sample, self.centroids, self.areas, self.sigma
    sub = self.patches(targets)
    rows = np.repeat(np.arange(len(targets)), np.diff(sub.indptr))
    member = index[sub.indices]
    keep = member >= 0
    rows, member = rows[keep], member[keep]
    count = np.bincount(rows, minlength=len(targets))
    pos = np.arange(len(rows)) - np.repeat(np.cumsum(count) - count, count)
    largest = np.zeros(len(targets))
    some = count > 0
    if some.any():
        largest[some] = np.maximum.reduceat(areas[member], (np.cumsum(count) - count)[some])
    origin, length = centroids[index[targets]], np.sqrt(largest)
    weight = np.sqrt(areas[member] / largest[rows])
    d = (centroids[member] - origin[rows]) / length[rows, None]
    A = np.zeros((len(targets), count.max(initial=0), 6))
    Y = np.zeros((len(targets), count.max(initial=0), 3))
    A[rows, pos] = quadratic_basis(d, 6) * weight[:, None]
    Y[rows, pos] = sig[member] * weight[:, None]
    coef = np.full((len(targets), 6, 3), np.nan)
    for terms in (6, 3):
        todo = np.flatnonzero(np.isnan(coef[:, 0, 0]) & (count > terms))
        if not len(todo):
            continue
        U, S, Vt = np.linalg.svd(A[todo, :, :terms], full_matrices=False)
        full = np.sum(S > S[:, :1] * max(count.max(), terms) * np.finfo(float).eps, axis=1) == terms
        solved = np.swapaxes(Vt, 1, 2) @ ((np.swapaxes(U, 1, 2) @ Y[todo]) / np.where(S > 0, S, 1.0)[:, :, None])
        coef[todo[full]] = 0.0
        coef[todo[full], :terms] = solved[full]
    self._fitted[targets] = True
    self._origin[targets], self._length[targets], self._coef[targets] = origin, length, coef


def _field(x):
    """A smooth stress with a kink at x = 0.3, nothing a quadratic holds exactly."""
    return np.column_stack([np.sin(3 * x[:, 0]) + np.abs(x[:, 0] - 0.3), np.cos(2 * x[:, 1]) * x[:, 0],
                            np.exp(x[:, 0] * x[:, 1])])


def test_a_repeated_matrix_gets_the_bits_of_its_own_factoring():
    rng = np.random.default_rng(5)
    distinct = rng.normal(size=(7, 30, 6))
    picks = rng.integers(0, 7, 200)
    stack = distinct[picks]
    stack[::9, -3:] = 0.0  # padded rows, as a short patch's
    U, S, Vt = distinct_svd(stack)
    U0, S0, Vt0 = np.linalg.svd(stack, full_matrices=False)
    assert len(np.unique(picks)) < len(stack)
    for got, plain in ((U, U0), (S, S0), (Vt, Vt0)):
        assert got.tobytes() == plain.tobytes()


def test_matrices_differing_in_a_zero_s_sign_are_factored_apart():
    """+0 and −0 are different bits: not taken for one matrix."""
    a = np.random.default_rng(6).normal(size=(2, 12, 3))
    a[1] = a[0]
    a[0, 5, 1], a[1, 5, 1] = 0.0, -0.0
    U, S, Vt = distinct_svd(a)
    U0, S0, Vt0 = np.linalg.svd(a, full_matrices=False)
    assert U.tobytes() == U0.tobytes() and S.tobytes() == S0.tobytes() and Vt.tobytes() == Vt0.tobytes()


def _grid_recovery():
    n = 12
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    i, j = i.ravel(), j.ravel()
    node = lambda a, b: a * (n + 1) + b  # noqa: E731
    keys = np.column_stack([node(i, j), node(i + 1, j), node(i, j + 1), node(i + 1, j + 1)])
    centroids = np.column_stack([i + 0.5, j + 0.5]) * 0.1
    mine = centroids[:, 0] + 0.3 * centroids[:, 1] < 0.9  # a body's part of the grid
    sample = np.full(len(keys), -1)
    sample[mine] = np.arange(mine.sum())
    areas = np.where(np.arange(mine.sum()) % 7 == 0, 0.004, 0.01)  # some cut cells' parts
    return PatchRecovery(keys, sample, centroids[mine], areas, _field(centroids[mine])), np.flatnonzero(mine), centroids


def test_the_recovery_on_a_grid_is_the_plain_fits_bits(monkeypatch):
    rec, cells, centroids = _grid_recovery()
    got = rec.at(cells, centroids[cells] + 0.01)
    monkeypatch.setattr(PatchRecovery, "_fit", _plain_fit)
    plain, _, _ = _grid_recovery()
    assert got.tobytes() == plain.at(cells, centroids[cells] + 0.01).tobytes()


@pytest.mark.parametrize("batch", [recovery.FIT_BATCH, 97])
def test_the_energy_estimate_s_recovery_on_scene_c_is_the_plain_fits_bits(monkeypatch, batch):
    """Γ cuts background cells (fan rules, patches of unequal length) and
    most interior patches repeat; ``batch`` also splits the fits into many
    stacks of different padding."""
    scene = load_scene("C")
    er = energy.energy_rule(scene, 0.1)
    sigma = _field(er.rule.points)
    monkeypatch.setattr(recovery, "FIT_BATCH", batch)
    got = energy.recovered_stress(scene, er, sigma)
    monkeypatch.setattr(PatchRecovery, "_fit", _plain_fit)
    plain = energy.recovered_stress(scene, er, sigma)
    assert not np.array_equal(got, sigma)  # recovered, not σ_h passed through
    assert got.tobytes() == plain.tobytes()


def test_a_memo_across_stacks_gives_each_matrix_the_bits_of_its_own_factoring():
    """distinct_svd's memo: a matrix factored in an earlier stack is taken
    from it; keyed by other arrays (``key``) than the matrix itself."""
    rng = np.random.default_rng(7)
    distinct = rng.normal(size=(9, 20, 6))
    memo, stacks = {}, [distinct[rng.integers(0, 9, n)] for n in (40, 3, 55, 1)]
    stacks.append(stacks[0][::-1])  # every matrix factored before: nothing new to factor
    for stack in stacks:
        key = [stack[..., 0], stack[..., 1:]]  # the matrix's words in two parts
        U, S, Vt = distinct_svd(stack, key, memo)
        U0, S0, Vt0 = np.linalg.svd(stack, full_matrices=False)
        assert U.tobytes() == U0.tobytes() and S.tobytes() == S0.tobytes() and Vt.tobytes() == Vt0.tobytes()
    assert sum(f.size for f in memo.values()) <= len(distinct)


def test_a_hash_met_again_with_other_words_is_factored_anew(monkeypatch):
    """Two stacks whose matrices share a hash code (only the first word
    hashed here) but not their words: the second is factored, not taken
    from the memo."""
    mix = np.zeros_like(recovery._MIX)
    mix[0] = 1
    monkeypatch.setattr(recovery, "_MIX", mix)
    a = np.random.default_rng(8).normal(size=(2, 10, 3))
    a[1, 0, 0] = a[0, 0, 0]  # the same first word, the same code
    memo = {}
    for stack in (a[:1], a[1:]):
        U, S, Vt = distinct_svd(stack, memo=memo)
        U0, S0, Vt0 = np.linalg.svd(stack, full_matrices=False)
        assert U.tobytes() == U0.tobytes() and S.tobytes() == S0.tobytes() and Vt.tobytes() == Vt0.tobytes()
