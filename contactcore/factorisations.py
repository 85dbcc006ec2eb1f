"""The factorisations Newton keeps, and their low-rank corrections.

The tangent ``J = A + Gᵀ W D G`` of a piecewise-linear law changes only
where a point of Γ changes status, so most of a load path's solves can reuse
a factorisation made before.  :class:`KeptFactorisations` answers
``J δu = r`` for the points' tangent ``D``:

* by the factorisation kept for ``D`` itself (up to
  :data:`~contactcore.tolerances.FACTORISATIONS_KEPT` of them, in the
  system's slots);
* or, on one process, by a kept factorisation corrected to ``D`` where the
  two differ in a few rows (:class:`_Update`, Woodbury's identity), with the
  columns it needs solved as one block and kept for the next corrections
  (:class:`_Columns`; a full set keeps only the rows ``D`` needs);
* or by a correction of a new factorisation of a map Newton is heading
  for (:meth:`KeptFactorisations._ahead`), where that map is within a
  correction of ``D``;
* or by a new factorisation, into the slot of one made in the same Newton
  step that ``D`` has moved past a correction's reach of (MUMPS then redoes
  its numeric factorisation only, in the memory it has), else a free slot,
  else the one used longest ago.

Every solve is held to the health policy (:mod:`contactcore.health`) by its
residual with ``J`` itself, so a correction of a singular ``J`` fails as a
factorisation of it would.  docs/newton.md, "What a run pays in
factorisations", gives the counts this saves.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from . import health
from . import tolerances as tol
from .errors import SolverError


class _Columns:
    """The columns ``M⁻¹ Tᵀ e`` kept for one factorisation ``M``, by the
    row ``e`` (point, row of its tangent) they were solved for, in the order
    solved: ``rows[k]`` is column k (:class:`_Update`)."""

    def __init__(self, size: int):
        self.index, self.rows = {}, np.zeros((0, size))

    def __len__(self) -> int:
        return len(self.index)

    def add(self, keys: list[tuple[int, int]], columns: np.ndarray, most: int) -> None:
        """Keep ``columns`` (n, q), the solutions for the rows ``keys``;
        the storage grows by doubling, up to ``most`` columns."""
        count = len(self.index)
        if count + len(keys) > len(self.rows):
            grown = np.zeros((min(max(2 * (count + len(keys)), 8), most), self.rows.shape[1]))
            grown[:count] = self.rows[:count]
            self.rows = grown
        self.rows[count:count + len(keys)] = columns.T
        self.index.update(zip(keys, range(count, count + len(keys))))

    def kept_for(self, keys: list[tuple[int, int]]) -> "_Columns":
        """The columns of the rows ``keys`` only, in their order here."""
        kept = sorted((self.index[k], k) for k in keys if k in self.index)
        out = _Columns(self.rows.shape[1])
        out.index = {k: i for i, (_, k) in enumerate(kept)}
        out.rows = self.rows[[i for i, _ in kept]]
        return out


class _Update:
    """A kept factorisation ``M`` (of the points' tangent ``D₀``) corrected
    to the tangent ``D`` that differs from ``D₀`` in a few rows: with
    ``K_Γ = Tᵀ W D G`` (:meth:`~contactcore.system.InterfaceOperator.sides`),
    ``J = M + U B``, ``U`` the columns ``Tᵀ e`` of the changed rows ``e``
    (point p, row c) and ``B`` their rows ``w_p (D − D₀)_{c,:} G_p``, and by
    Woodbury's identity (Golub & Van Loan, *Matrix Computations*, 4th ed.,
    §2.1.4)

        J⁻¹ b = x₀ − Z (I + B Z)⁻¹ B x₀,   x₀ = M⁻¹ b,  Z = M⁻¹ U:

    one solve with ``M`` per use, and the columns of ``Z`` to make it, solved
    as one block (:meth:`~contactcore.system.ContactSystem.solve_columns`) and kept for the
    next corrections of ``M`` (:class:`_Columns`), at most ``most`` of them
    (:meth:`~contactcore.system.ContactSystem.correction_columns`).  Each solve is held to
    the health policy by its residual with ``J`` itself: a singular ``J``
    fails it."""

    def __init__(self, kept_by, slot: int, kept: np.ndarray, tangent: np.ndarray, changed: list[tuple[int, int]],
                 most: int):
        self.slot, self.tangent = slot, tangent
        test, self.trial = kept_by.interface.sides()
        self.columns = kept_by.columns.setdefault(slot, _Columns(kept_by.system.size))
        new = [pc for pc in changed if pc not in self.columns.index]
        if new:
            self.columns.add(new, kept_by.system.solve_columns(test[[2 * p + c for p, c in new]].T, slot),
                             most)
        self.used = len(self.columns)  # the columns it reads: the first ones, kept in place
        self.at = np.array([self.columns.index[pc] for pc in changed], int)
        points, rows = (np.array([pc[i] for pc in changed], int) for i in (0, 1))
        delta = kept_by.interface.weights[points, None] * (tangent - kept)[points, rows, :]
        picked = sp.csr_matrix((delta.ravel(), (np.repeat(np.arange(len(changed)), 2),
                                                (2 * points[:, None] + np.arange(2)).ravel())),
                               shape=(len(changed), self.trial.shape[0]))
        self.B = (picked @ self.trial).tocsr()
        reach = np.unique(self.B.indices)  # the unknowns B reads: B Z from those rows of Z only
        BZ = self.B[:, reach].toarray() @ self.columns.rows[self.at[:, None], reach].T
        self.capacitance = np.eye(len(changed)) + BZ

    def solve(self, kept_by, rhs: np.ndarray, scale: float, solved=None):
        """``(δu, report)`` with ``J δu = rhs`` on the free rows; SolverError
        if its residual fails the health policy.  ``solved``: ``M⁻¹ rhs``
        and its report, where known."""
        x, report = kept_by.system.solve(None, rhs, force_scale=scale, slot=self.slot) if solved is None else solved
        w = np.zeros(self.used)
        try:
            w[self.at] = np.linalg.solve(self.capacitance, self.B @ x)
        except np.linalg.LinAlgError:
            raise SolverError("the corrected factorisation is singular") from None
        x = x - self.columns.rows[:self.used].T @ w
        jumps = (self.trial @ x).reshape(-1, 2)
        Jx = kept_by.system.internal(x) + kept_by.interface.internal(x, np.einsum("pij,pj->pi", self.tangent, jumps))
        r = (rhs - Jx)[kept_by.free]
        report.residual = health.relative_residual(r, rhs[kept_by.free], scale)
        health.check_residual(report.residual, "the corrected factorisation")
        return x, report


def _changed_rows(kept: np.ndarray, tangent: np.ndarray) -> int:
    """How many rows of the points' 2 × 2 tangents differ."""
    return int(np.count_nonzero(np.any(tangent != kept, axis=2)))


class KeptFactorisations:
    """The factorisations of one system's tangent kept for one interface
    (:class:`~contactcore.system.InterfaceOperator` or an exact law's
    :class:`~contactcore.exact.NitscheInterface`): a new interface, or a
    softened one, starts a new set."""

    def __init__(self, system, interface, free: np.ndarray, ranks):
        self.system, self.interface, self.free, self.ranks = system, interface, free, ranks
        self.kept = []  # (slot, interface tangent) of the system's factorisations, last used last
        self.updates = []  # low-rank corrections of them (_Update), last made first
        self.columns = {}  # slot -> the _Columns its corrections share
        self.this_step = set()  # the slots factorised since the step began (begin_step)

    def solve(self, tangent: np.ndarray, rhs: np.ndarray, scale: float, detour: bool = False, ahead=()):
        """``(δu, report)`` with the points' ``tangent``: by the
        factorisation kept for it, or the low-rank correction of one
        (:meth:`_corrected`), if there is one; else by a correction of a
        new factorisation of a tangent Newton is heading for (``ahead``,
        :meth:`_ahead`); else factorised into its :meth:`_slot`.  A
        ``detour`` (a regularised tangent, which Newton leaves for the
        law's own) takes no factorisation of the step's maps."""
        for i, (slot, kept) in enumerate(self.kept):
            if self.ranks.all(np.array_equal(kept, tangent)):
                self.kept.append(self.kept.pop(i))
                return self.system.solve(None, rhs, force_scale=scale, slot=slot)
        corrected = self._corrected(tangent, rhs, scale, ahead=() if detour else ahead)
        if corrected is None and not detour:
            corrected = self._ahead(tangent, rhs, scale, ahead)
        return corrected if corrected is not None else self._factorise(tangent, rhs, scale, detour)

    def _ahead(self, tangent: np.ndarray, rhs: np.ndarray, scale: float, ahead):
        """``(δu, report)`` by a new factorisation of the first tangent of
        ``ahead`` (the maps Newton is heading for) within AHEAD_SHARE of the
        new columns a correction of the refilled slot may solve
        (:meth:`~contactcore.system.ContactSystem.correction_columns`) of
        ``tangent``, corrected to ``tangent``; None where none is, on
        several processes, or before a factorisation has given the slot a
        budget.  A factorisation need only be near the maps solved with it,
        not one of them: a status search that moves the map a few points
        per iteration (an exact law's first increment) stays within a
        correction of a map further along for longer than of the one it
        stands at."""
        if self.ranks.parallel:
            return None
        for guess in ahead:
            slot = self._slot(guess, False)
            if slot not in {s for s, _ in self.kept}:
                return None  # no factorisation of this size yet, no budget to judge by
            if 0 < _changed_rows(guess, tangent) <= tol.AHEAD_SHARE * min(self.system.correction_columns(slot)):
                break
        else:
            return None
        try:
            x0, report = self._factorise(guess, rhs, scale, False)
        except SolverError:
            return None
        corrected = self._corrected(tangent, rhs, scale, (x0, report))
        if corrected is not None and corrected[1] is not report:
            corrected[1].factorisations += report.factorisations
        return corrected

    def begin_step(self) -> None:
        """A new Newton step: the factorisations kept so far are of maps
        a load path may return to (:meth:`_slot`)."""
        self.this_step = set()

    def _slot(self, tangent: np.ndarray, detour: bool) -> int:
        """The slot a factorisation of ``tangent`` goes into: one factorised
        in this step whose tangent differs from ``tangent`` in more rows than
        a correction of it may (the status map moved past it, as it does
        from the first iterate's map, every point sticking), refilled with
        the same nonzero pattern, so that MUMPS redoes only its numeric
        factorisation; else a free slot; else the one used longest ago."""
        for slot, kept in ([] if detour else self.kept):
            if slot in self.this_step and (self.ranks.sum(_changed_rows(kept, tangent))
                                           > self.system.correction_columns(slot)[1]):
                return slot
        used = {slot for slot, _ in self.kept}
        free = [s for s in range(tol.FACTORISATIONS_KEPT) if s not in used]
        return free[0] if free else self.kept[0][0]

    def _factorise(self, tangent: np.ndarray, rhs: np.ndarray, scale: float, detour: bool):
        """Factorise ``J`` with ``tangent`` into its :meth:`_slot`, dropping
        what was kept of that slot, and solve."""
        slot = self._slot(tangent, detour)
        self.kept = [(s, t) for s, t in self.kept if s != slot]  # until the solve succeeds
        self.updates = [u for u in self.updates if u.slot != slot]
        self.columns.pop(slot, None)
        du, report = self.system.solve(self.interface.stiffness(tangent), rhs, force_scale=scale, slot=slot)
        self.kept.append((slot, tangent))
        self.this_step.add(slot)
        return du, report

    def _corrected(self, tangent: np.ndarray, rhs: np.ndarray, scale: float, solved=None, ahead=()):
        """``(δu, report)`` by a kept factorisation corrected to ``tangent``
        (:class:`_Update`), or None where none is close enough: one process
        only, a correction within the system's
        :meth:`~contactcore.system.ContactSystem.correction_columns` of the factorisation (rows
        of the points' tangents that need a solve, and kept in all), the
        fewest new ones of the kept factorisations; a correction whose solve
        fails its residual check (a singular tangent) is left to a
        factorisation.  A correction that would solve more than
        AHEAD_FIRST_SHARE of the slot's new columns in one go first offers
        the maps Newton is heading for (``ahead``, :meth:`_ahead`): the map
        moved that far in one iterate, so the next would take the slot past
        its budget and into a new factorisation, and the columns solved now
        would be thrown away with it (exact C-coulomb's first increment,
        fe and xfem P1 at h = 0.05: 52 and 59 columns solved, then the slot
        refilled one iterate later)."""
        if self.ranks.parallel:
            return None
        for update in self.updates:
            if np.array_equal(update.tangent, tangent):
                try:
                    return update.solve(self, rhs, scale)
                except SolverError:
                    self.updates.remove(update)
                    return None
        best = None
        for slot, kept in reversed(self.kept):
            changed = [tuple(pc) for pc in np.argwhere(np.any(tangent != kept, axis=2))]
            columns = self.columns.get(slot, _Columns(0))
            new = sum(pc not in columns.index for pc in changed)
            most_new, most = self.system.correction_columns(slot)
            if len(changed) <= most and new <= most_new and (best is None or new < best[0]):
                best = (new, slot, kept, changed, most)
        if best is None:
            return None
        new, slot, kept, changed, most = best
        if ahead and new > tol.AHEAD_FIRST_SHARE * self.system.correction_columns(slot)[0]:
            first = self._ahead(tangent, rhs, scale, ahead)
            # none ahead within reach: the correction, planned again (a
            # factorisation ahead whose own solve failed refilled a slot)
            return first if first is not None else self._corrected(tangent, rhs, scale)
        if len(self.columns.get(slot, ())) + new > most:
            self._drop_columns(slot, changed)
        update = _Update(self, slot, kept, tangent, changed, most)
        try:
            solved = update.solve(self, rhs, scale, solved if slot == self.kept[-1][0] else None)
        except SolverError:
            return None
        self.updates = [update, *self.updates][:tol.FACTORISATIONS_KEPT]
        return solved

    def _drop_columns(self, slot: int, changed: list[tuple[int, int]]) -> None:
        """Keep of ``slot``'s columns those of the rows ``changed`` only, and
        none of its corrections (they read the columns by place): a budget
        full of rows that have changed back, or that this tangent shares
        with the factorised one, no longer costs a factorisation."""
        self.columns[slot] = self.columns[slot].kept_for(changed)
        self.updates = [u for u in self.updates if u.slot != slot]
