"""The Zienkiewicz–Zhu estimate of one run's error in energy, by recovery.

**Zienkiewicz–Zhu** (Zienkiewicz and Zhu 1987, 1992).  From one run: its
stress ``σ_h`` is sampled at the Gauss points of background cells of the
run's size ``h`` (:mod:`contactcore.quadrature`, Γ followed exactly) and
recovered body by body with the core's patch recovery
(:class:`contactcore.recovery.PatchRecovery`, every Gauss point a sample
weighted by its quadrature weight: a local L2 projection onto quadratics
over one ring of cells, :data:`~contactcore.tolerances.ENERGY_RINGS`,
which filters the error's oscillation at the scale of the method's cells
and leaves the smooth σ to O(h³)) into ``σ*``; then

    η² = Σ_q w_q (σ* − σ_h)ᵀ C (σ* − σ_h)(x_q),   ‖σ_h‖²_E = Σ_q w_q σ_hᵀ C σ_h,

``C = D⁻¹`` the body's compliance, over the Gauss points farther than
``exclude`` from the singular points
(:func:`~contactcore.estimate.singular.singular_points`): corners and the
ends of Γ, whose stress singularities no recovery captures.  ``η`` is an
estimate of the energy norm of the error ``‖σ − σ_h‖_E`` (the same
integral with the exact σ), ``σ_h = σ(u_h)`` the stress of the computed
displacement itself.  A method that reports a recovered stress (xfem P1)
has already made ``σ*``: it is taken as it is, and ``σ_h`` is its
displacement's own (:func:`direct_stress`), so the estimate is of the
same error as every other method's, with one recovery (a second recovery
of the reported ``σ*`` read 0.15-0.61 of its error, falling with h, and
cost as much again; 2026-11-29).

numpy and scipy only; no method is imported.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .. import tolerances as tol
from ..errors import ContactError
from ..quadrature import background_cells, volume_rule
from ..recovery import PatchRecovery, incidence_of
from ..scaling import Sizes
from ..scene import Scene
from .singular import far_from_singular


@dataclass(frozen=True)
class EnergyRule:
    """Gauss points of the domain (``rule``), which points lie away from
    the singular points (``kept``), and the grid of background cells they
    were made on (lower corner ``origin``, side ``step``, cells per
    direction ``shape``): each point's background cell (``cell``) and the
    grid's node keys of every cell (``keys``), computed when first read
    (only :func:`recovered_stress` reads them; 0.05 s of CPU at 1.7e6
    points, tilt35 at h = 0.0015625)."""

    rule: object
    kept: np.ndarray
    origin: np.ndarray
    step: float
    shape: np.ndarray

    @cached_property
    def cell(self) -> np.ndarray:
        ij = np.clip(np.floor((self.rule.points - self.origin) / self.step).astype(int), 0, self.shape - 1)
        return ij[:, 0] * self.shape[1] + ij[:, 1]

    @cached_property
    def keys(self) -> np.ndarray:
        n = self.shape
        I, J = np.divmod(np.arange(n[0] * n[1]), n[1])
        node = lambda i, j: i * (n[1] + 1) + j  # noqa: E731
        return np.column_stack([node(I, J), node(I + 1, J), node(I, J + 1), node(I + 1, J + 1)])


def energy_rule(scene: Scene, h: float, exclude: float = 0.0, gauss: int = tol.ENERGY_GAUSS) -> EnergyRule:
    """The background cells of size ≈ h (:func:`contactcore.quadrature.background_cells`)
    with their Gauss points, Γ followed exactly."""
    lo, hi = background_cells(scene, h)
    rule = volume_rule(scene, h, gauss)
    step = hi[0] - lo[0]
    origin = lo.min(axis=0)
    n = np.round((hi.max(axis=0) - origin) / step).astype(int)
    return EnergyRule(rule, far_from_singular(scene, rule.points, exclude), origin, step, n)


def energy_norm(scene: Scene, er: EnergyRule, sigma: np.ndarray) -> float:
    """``(Σ_q w_q σᵀ C σ)^½`` over the kept points of ``er`` (σ Voigt, (Q, 3))."""
    return _kept_norm(scene, er.rule.weights[er.kept], er.rule.bodies[er.kept], sigma[er.kept])


def _kept_norm(scene: Scene, weights: np.ndarray, bodies: np.ndarray, sigma: np.ndarray) -> float:
    """:func:`energy_norm` of the kept points' ``weights``, ``bodies`` and ``sigma`` alone."""
    compliance = np.linalg.inv(scene.voigt_matrices())
    density = np.zeros(len(sigma))
    for body in np.flatnonzero(np.bincount(bodies)):  # np.unique(bodies) (0 and 1) without a sort
        # Σ_ij (σ_i C_ij) σ_j summed in einsum("qi,qij,qj->q")'s order, i then j (the same bits), body by
        # body with its C: no (points, 3, 3) gather, three times faster
        sel = np.flatnonzero(bodies == body)
        rows = np.take(sigma, sel, axis=0)
        s = [rows[:, i] for i in range(3)]
        terms = [(s[i] * compliance[body, i, j]) * s[j] for i in range(3) for j in range(3)]
        acc = terms[0]
        for term in terms[1:]:
            acc = acc + term
        density[sel] = acc
    return float(np.sqrt(max(weights @ density, 0.0)))


def recovered_stress(scene: Scene, er: EnergyRule, sigma: np.ndarray) -> np.ndarray:
    """σ* at the Gauss points of ``er`` from ``σ_h`` there (module doc): body
    by body, every Gauss point a sample (weight its quadrature weight, its
    cell's node keys), so each background cell's quadratic is the weighted
    least-squares fit to ``σ_h`` over the Gauss points of its patch, a local
    L2 projection; σ_h itself where a patch fits no line."""
    rule, out = er.rule, sigma.copy()
    keys = er.keys[er.cell]
    incidence = incidence_of(keys)  # the same cells for either body
    for body in (0, 1):
        mine = np.flatnonzero(rule.bodies == body)
        if not len(mine):
            continue
        sample = np.full(len(rule.weights), -1)
        sample[mine] = np.arange(len(mine))
        _, first, inverse = np.unique(er.cell[mine], return_index=True, return_inverse=True)
        recovery = PatchRecovery(keys, sample, rule.points[mine], rule.weights[mine], sigma[mine],
                                 rings=tol.ENERGY_RINGS, incidence=incidence)
        star = recovery.at(mine[first][inverse], rule.points[mine])
        ok = ~np.isnan(star[:, 0])
        out[mine[ok]] = star[ok]
    return out


@dataclass(frozen=True)
class EnergyEstimate:
    """The ZZ estimate ``eta`` of ``‖σ − σ_h‖_E`` and ``norm`` ``‖σ_h‖_E``
    (J^½ per unit thickness), away from singular points by ``exclude``;
    ``relative`` is ``eta`` over the norm floored by ``floor``, round-off of
    the scene's own energy (:data:`~contactcore.tolerances.NEGLIGIBLE_SHARE`
    of :class:`~contactcore.scaling.Sizes`' energy): a run that ends
    stress-free has a norm of round-off (7e-16 on a block pulled open), and
    η over it read as 40 %."""

    eta: float
    norm: float
    exclude: float
    floor: float = 0.0
    #: on a curved Γ, the energy norm of ``σ** − σ*``, the recovery applied
    #: again to its own σ* (:func:`recovery_moves`): how much of η the
    #: recovery's own error on the smooth stress may be; None on a straight Γ
    recovery: float | None = None

    @property
    def relative(self) -> float:
        size = max(self.norm, self.floor)
        return self.eta / size if size > 0 else float("nan")

    def record(self) -> dict:
        return {"eta": self.eta, "norm": self.norm, "relative": self.relative, "exclude": self.exclude,
                "floor": self.floor, "recovery": self.recovery}


def direct_stress(fields, points: np.ndarray, bodies: np.ndarray) -> np.ndarray:
    """``σ_h = σ(u_h)`` at ``points``: the fields' ``direct_stress`` where
    they have one (:class:`contactcore.result.Fields`' note: a method whose
    stress is recovered), else their stress."""
    return getattr(fields, "direct_stress", fields.stress)(points, bodies)


def energy_estimate(scene: Scene, fields, h: float, exclude: float = 0.0, gauss: int = tol.ENERGY_GAUSS,
                    recovered: bool = False) -> EnergyEstimate:
    """The Zienkiewicz–Zhu estimate of one run (module doc) on background
    cells of the run's size ``h``, ``gauss`` points per direction.  Where
    the method's stress is ``recovered`` already (xfem P1: the run's
    :attr:`~contactcore.result.MethodFacts.recovered_stress`), that stress is
    ``σ*`` and ``σ_h`` its displacement's own (:func:`direct_stress`): one
    recovery, not a second one of ``σ*``, which moved it less than its
    error (0.15-0.61 of it, falling with h)."""
    if recovered and not hasattr(fields, "direct_stress"):
        raise ContactError("energy estimate: the fields' stress is recovered but they have no direct_stress "
                           "(σ(u_h)) to set against it (contactcore.result.Fields' note)")
    er = energy_rule(scene, h, exclude, gauss)
    if recovered and scene.interface.straight_in(scene.domain):
        # η and the norm read σ_h and σ* at the kept points only (energy_norm); nothing recovers them again
        # on a straight Γ (recovery_moves), so the rest are not evaluated (tilt35, xfem P1 at h = 0.003125:
        # 12 % of 416 178 points, and their cells' patch fits), and the kept points' arrays are not spread
        # over the rule's and gathered again: the same numbers
        points, bodies, weights = er.rule.points[er.kept], er.rule.bodies[er.kept], er.rule.weights[er.kept]
        sigma = direct_stress(fields, points, bodies)
        star = fields.stress(points, bodies)
        return EnergyEstimate(_kept_norm(scene, weights, bodies, star - sigma),
                              _kept_norm(scene, weights, bodies, sigma), exclude,
                              tol.NEGLIGIBLE_SHARE * Sizes.of(scene).energy, None)  # recovery_moves': straight Γ
    sigma = direct_stress(fields, er.rule.points, er.rule.bodies)
    star = fields.stress(er.rule.points, er.rule.bodies) if recovered else recovered_stress(scene, er, sigma)
    return EnergyEstimate(energy_norm(scene, er, star - sigma), energy_norm(scene, er, sigma), exclude,
                          tol.NEGLIGIBLE_SHARE * Sizes.of(scene).energy, recovery_moves(scene, er, star))


def recovery_moves(scene: Scene, er: EnergyRule, star: np.ndarray) -> float | None:
    """``‖σ** − σ*‖_E``, σ** the recovery (:func:`recovered_stress`) of σ*
    itself, where Γ is curved; None where it is straight.  A recovery
    reproduces a quadratic exactly, so on a smooth σ* it moves it only by
    its own error there: on a straight Γ that is round-off, on a circle
    at coarse h as much as η (a held-out disc and the pressurised rod,
    2026-11-29: 0.60-0.78 of η where η read 2.3-4.7 times the error in
    P2 and EFGM; :data:`~contactcore.tolerances.ENERGY_RECOVERY_SHARE`).
    It costs one more recovery, taken only on a curved Γ."""
    if scene.interface.straight_in(scene.domain):
        return None
    return energy_norm(scene, er, recovered_stress(scene, er, star) - star)
