"""Error estimates without a reference: Richardson on profiles, ZZ in energy.

Two estimates of how far a run is from the exact answer, method-independent
(they read a run only through its :class:`~contactcore.result.Result`):

**Richardson extrapolation** (Richardson 1911; Roache, *Verification and
Validation in Computational Science*, 1998, ch. 5).  One method at ``h``
and ``h/2`` samples every profile at the same points.  If a quantity's
sample converges as ``q_h = q + C h^p``, the finer run's error is

    e_{h/2} = q_{h/2} − q ≈ (q_{h/2} − q_h) / (2^p − 1),

estimated sample by sample; the profile's worst sample and RMS summarise
it.  With a third run at ``h/4`` the order is observed,

    p = log₂ (‖q_{h/2} − q_h‖ / ‖q_{h/4} − q_{h/2}‖)        (RMS over the samples),

over the samples away from singular points (a singularity's differences
shrink at its own rate), clipped to
:data:`~contactcore.tolerances.ORDER_RANGE`, and the estimate is the
finest run's, at the least of that order and the two-run order below
(an observed order above theory is the coarse run's error cancelling,
not a faster rate: Roache's GCI, ASME V&V 20).  With two runs the method's theoretical order for the
quantity is used (:func:`theoretical_order`): ``k + 1`` for a displacement
and a gap (the L2 rate of degree k), and for a penalty law's traction on
Γ, which the law computes from the gaps (``t = k_N g_N`` …) not from the
bulk stress; ``k`` for a stress (the H1 rate); under an exact law, at most
2 for the gaps and 1 for the traction where Γ's status changes along it
(:func:`switches`).  Away from a singular point of exponent ``λ``
(``u ~ r^λ``: a clamped-free corner, the end of a penalty Γ) a
displacement's error converges no faster than ``h^{2λ}`` once the
singular term outweighs the smooth one (pollution: Nitsche & Schatz,
Math. Comp. 28, 1974), which depends on its coefficient: a displacement,
gap or penalty traction takes the orders ``[min(p, 2λ), p]``
(:func:`pollution_order`); with two runs of fe or xfem, the part of their
difference at the scale of the coarse run's cells (:func:`cell_scale_part`),
their local error, takes ``p`` and only the smooth rest, where the
pollution lies, the range (:func:`profile_estimates`).  EFGM holds its supports by boundary
multipliers (:mod:`efgm.method`), and its P2 takes the orders of every
other degree-2 method (until 2026-11-27 it collocated them at the nodes
of a basis that does not interpolate, whose defect set its bulk
displacements' order: a rule that went with it, docs/error-estimates.md).
A degree-1 stress read at a point converges at its
order ``p`` where the point is generic in its cell and at ``p + 1`` where
it superconverges (the cell's centroid, a uniform grid aligned with the
profile: Zienkiewicz & Zhu, IJNME 33, 1992; Wahlbin, *Superconvergence in
Galerkin finite element methods*, 1995), and which holds at a sample is
not known from two runs.  For such a range the estimate takes the
order between whose Richardson factor ``1/(2^q − 1)`` is the geometric mean of the two
(:func:`balanced_order`), so its effectivity lies within
``[(1/3)^½, 3^½]`` for ``p = 1`` (``[(3/7)^½, (7/3)^½]`` for ``p = 2``)
whichever holds (:func:`order_range`).  An observed order further than
:data:`~contactcore.tolerances.ORDER_MISMATCH` from that range means the
runs are not yet in the asymptotic range: the estimate carries a warning.

Two runs are not asymptotic where the coarser one's stencil (a cell,
EFGM's support, xfem P1's recovery patch: :func:`stencil_radius`) is not
small against what it resolves: within two stencils of a singular point
that run's error is still the singular point's own, and a stencil over
1/:data:`~contactcore.tolerances.FEATURE_STENCILS` of the scene's smallest
feature (:func:`feature_size`) resolves it pre-asymptotically.  Richardson
cannot see either from two runs; the estimate names the quantities
concerned in a warning (:func:`unsettled`).  It names too the quantities
whose coarse run varies from cell to cell faster than theory allows
(:func:`cell_scale_orders`), and those whose runs differ a thousand times
less than others of their kind in the same runs, where the error's
leading term cancels and a smaller one of another order may set the rate
(:func:`residues`).

For a law with history (unilateral, Coulomb) the profiles are the final
increment's, and the status along Γ (open, stick, slip) of the two runs is
compared at :data:`~contactcore.tolerances.PROFILE_POINTS` points: where it
differs, the error there is not asymptotic, and the estimate says so.

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
``exclude`` from the singular points (:func:`singular_points`): corners and
the ends of Γ, whose stress singularities no recovery captures.  ``η`` is
an estimate of the energy norm of the error ``‖σ − σ_h‖_E`` (the same
integral with the exact σ).

numpy and scipy only; no method is imported.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import tolerances as tol
from .geometry import LineInterface, Rectangle
from .interface_path import along
from .laws import SLIP
from .profiles import ProfileData, sample_points, sample_profiles
from .quadrature import background_cells, volume_rule
from .recovery import PatchRecovery
from .scene import InterfaceProfile, Scene

#: Quantities that converge as the displacement (degree + 1): displacements,
#: gaps, and the tractions the law computes from the gaps.
DISPLACEMENT_LIKE = ("ux", "uy", "gN", "gT", "tN", "tT")


#: Methods whose degree-1 stress is recovered (:mod:`contactcore.recovery`:
#: xfem P1), not read from the cell: it converges one order faster, as
#: the displacement (measured with the orders of the other methods, the
#: Richardson effectivity of xfem P1's stresses was 3.0-6.2 on the
#: pressurised and twisted rods: a rate 2 read as 1).
RECOVERED_STRESS = (("xfem", 1),)


#: Γ's quantities under an exact law (:mod:`contactcore.exact`).
GAPS, TRACTIONS = ("gN", "gT"), ("tN", "tT")


def theoretical_order(quantity: str, degree: int, method: str = "", law=None, switching: bool | None = None) -> int:
    """The rate of a profile quantity for ``method`` of ``degree`` (module
    doc).  Under an exact ``law`` the traction on Γ is Nitsche's multiplier,
    a stress (rate ``degree``, not the gaps' ``degree + 1``).  Where that
    law switches (open/closed, stick/slip: every exact law but ``bonded``)
    the solution is no smoother than H^{5/2-ε} at the points where Γ's
    status changes (Moussaoui & Khodja, Comm. PDE 17, 1992; Chouly, Hild &
    Renard, Math. Comp. 84, 2015), which caps the gaps' rate at 2 and the
    traction's at 1 in every degree: exact C-coulomb's profiles converge
    at about these rates (docs/contact-enforcement.md, "Convergence").
    ``switching`` False says that the runs' status never changed along Γ
    (:func:`switches`): no such point, the bonded law's rates."""
    if law is not None and getattr(law, "enforcement", "penalty") == "exact":
        switches = not law.is_linear and switching is not False
        if quantity in TRACTIONS:
            return 1 if switches else degree
        if quantity in GAPS and switches:
            return min(degree + 1, 2)
    if quantity in DISPLACEMENT_LIKE or (method, degree) in RECOVERED_STRESS:
        return degree + 1
    return degree


#: Bulk stresses, and the degrees whose stress read at a point converges
#: at its theoretical order or one faster (module doc): the estimate's
#: order lies between (:func:`order_range`).  Measured at the theoretical
#: order, the Richardson effectivity of these stresses was 0.96-8.8 on
#: the paper's scenes and 0.98-2.31 on the closed forms (2026-11-27,
#: docs/error-estimates.md), of the degree-2 stresses 0.9-1.45.
STRESSES, SUPERCONVERGENT_DEGREES = ("sxx", "syy", "sxy"), (1,)


def order_range(quantity: str, degree: int, method: str = "", law=None, switching: bool | None = None,
                pollution: float = np.inf) -> tuple[float, float]:
    """The orders theory allows a profile quantity: ``(p, p)`` with ``p``
    the :func:`theoretical_order`, ``(p, p + 1)`` for a stress of a degree
    in :data:`SUPERCONVERGENT_DEGREES` (module doc), ``(pollution, p)``
    for a displacement, a gap or a penalty law's traction whose ``p``
    exceeds the scene's :func:`pollution_order`."""
    p = theoretical_order(quantity, degree, method, law, switching)
    if quantity in STRESSES and degree in SUPERCONVERGENT_DEGREES:
        return (p, p + 1)
    polluted = quantity in DISPLACEMENT_LIKE and not (quantity in TRACTIONS and _exact(law))
    return (pollution, p) if polluted and pollution < p else (p, p)


def _exact(law) -> bool:
    """Whether ``law`` is enforced exactly (:mod:`contactcore.exact`)."""
    return law is not None and getattr(law, "enforcement", "penalty") == "exact"


# ----- pollution from singular points -----------------------------------------

def kolosov(nu: float, plane: str) -> float:
    """Kolosov's constant ``κ``: ``3 − 4ν`` in plane strain, ``(3 − ν)/(1 + ν)`` in plane stress."""
    return 3.0 - 4.0 * nu if plane == "strain" else (3.0 - nu) / (1.0 + nu)


def clamped_free_exponent(alpha: float, kappa: float) -> float:
    """The least ``Re λ > 0`` of an elastic wedge of angle ``alpha`` with
    one face clamped and the other free (``u ~ r^λ``, ``σ ~ r^(λ−1)``):
    a root of Williams' eigen-equation

        κ sin²(λα) = (κ + 1)²/4 − λ² sin²α

    (Williams, J. Appl. Mech. 19, 1952; the 4×4 determinant of the
    wedge's Kolosov–Muskhelishvili potentials has the same roots).  A
    right angle gives 0.758 in plane stress and 0.711 in plane strain at
    ν = 0.3, the half-plane (α = π) ½ ± iε.  Complex roots are found by
    Newton's method from a grid of starts in ``0 < Re λ < 2``.  A real
    integer root is left out: its Airy function ``r^(λ+1) F(θ)``, F of
    ``(λ ± 1)θ``, is a polynomial, its field smooth (at ν = 0, κ = 3, a
    right angle has λ = 1, ``u = (0, c y)`` clamped at y = 0 and free at
    x = 0; its singular exponent is 1.352)."""
    s2 = np.sin(alpha) ** 2
    f = lambda lam: kappa * np.sin(lam * alpha) ** 2 - (kappa + 1) ** 2 / 4 + lam ** 2 * s2  # noqa: E731
    df = lambda lam: kappa * alpha * np.sin(2 * lam * alpha) + 2 * lam * s2  # noqa: E731
    lam = (np.linspace(0.05, 2.0, 40)[:, None] + 1j * np.array([0.0, 0.3, 1.0])[None]).ravel()
    with np.errstate(all="ignore"):
        for _ in range(WEDGE_NEWTON_STEPS):
            lam = lam - f(lam) / np.where(df(lam) == 0, 1.0, df(lam))
        polynomial = (np.abs(lam.imag) <= tol.WEDGE_ROOT) & (np.abs(lam.real - np.round(lam.real)) <= tol.WEDGE_ROOT)
        found = np.isfinite(lam) & (np.abs(f(lam)) <= tol.WEDGE_ROOT) & (lam.real > tol.WEDGE_ROOT) & ~polynomial
    return float(np.min(lam.real[found]))


#: Newton steps of :func:`clamped_free_exponent` from each start (its
#: roots converge quadratically within about ten from the nearest start).
WEDGE_NEWTON_STEPS = 60


def _edge_supports(scene: Scene) -> dict[str, str]:
    """``{edge: "clamped" | "roller"}`` of a rectangle's supported edges
    (both components held, by one support or by several, or one); an edge
    not named is free or loaded."""
    held: dict[str, set] = {}
    for s in scene.supports:
        held.setdefault(s.boundary, set()).update(s.fix)
    return {edge: "clamped" if fix == {"x", "y"} else "roller" for edge, fix in held.items()}


def corner_exponents(scene: Scene) -> list[float]:
    """``λ`` of each corner of a rectangular domain where a clamped edge
    meets a free (or loaded) one: a clamped–free right angle
    (:func:`clamped_free_exponent`, the κ of the body holding the
    corner, the least of both bodies' where Γ passes through it).  Left
    out: a corner between two clamped edges (2λ = 2.98 in plane stress,
    2.84 in plane strain at ν = 0.3: degree 2's Richardson factor changes
    by 2 % and 14 %; but 2.32 at ν = 0.45 in plane strain, a factor 1.75,
    which :func:`pollution_warning` names), one with a roller (reflected across
    it, a half-plane: integer exponents, a smooth solution), and a
    convex one between two free edges (no stress singularity)."""
    if not isinstance(scene.domain, Rectangle):
        return []
    kinds, out = _edge_supports(scene), []
    for corner in scene.domain.corners:
        edges = [kinds.get(e, "free") for e in scene.domain.boundary_of(corner, tol.GEOMETRY * scene.length_scale)]
        if sorted(edges) == ["clamped", "free"]:
            out.append(min(clamped_free_exponent(np.pi / 2, kolosov(scene.materials[b].nu, scene.plane))
                           for b in _bodies_at(scene, corner)))
    return out


def _bodies_at(scene: Scene, point) -> tuple[str, ...]:
    """The bodies holding ``point``: both where it lies on Γ (within
    GEOMETRY of the scene's length), so that no sign of round-off picks one."""
    d = scene.interface.signed_distance([point])[0]
    if abs(d) <= tol.GEOMETRY * scene.length_scale:
        return ("minus", "plus")
    return ("minus",) if d < 0 else ("plus",)


def interface_end_exponents(scene: Scene) -> list[float]:
    """``λ`` of each end of a straight Γ (where it meets a rectangle's
    boundary) under a penalty law: the least over the wedges Γ makes
    with the edges at that end (:func:`_wedges_at`; two on an edge, of
    angles α and π − α, one per edge at a corner, of angles β and
    π/2 − β).  A wedge on a clamped edge is a clamped–free wedge of its
    angle (the springs' traction is a load of lower order):
    :func:`clamped_free_exponent`, the least over both bodies.  On a
    free, loaded or roller edge the springs' traction at the end does
    not vanish, while the edge prescribes its own there: no uniform
    stress near the vertex takes both, so the stress there, bounded,
    depends on the direction (the wedge's ``r² θ`` Airy term) and
    ``u ~ r log r`` (Sinclair, Appl. Mech. Rev. 57, 2004; the stress is
    ``~ log r`` only where that term fails too, a wedge of 180° or
    257°), ``λ = 1``.  Under an exactly enforced law Γ's end is a bonded
    bimaterial edge (Bogy's exponents, none for equal materials), not
    taken here."""
    if not (isinstance(scene.interface, LineInterface) and isinstance(scene.domain, Rectangle)) or _exact(scene.law):
        return []
    ends = scene.interface.chord(scene.domain)
    kinds, out = _edge_supports(scene), []
    kappas = [kolosov(scene.materials[b].nu, scene.plane) for b in ("minus", "plus")]
    for end, other in (() if ends is None else (ends, ends[::-1])):
        out.append(min(min(clamped_free_exponent(angle, k) for k in kappas) if kinds.get(edge) == "clamped" else 1.0
                       for edge, angle in _wedges_at(scene, end, other)))
    return out


#: The direction along each edge of a rectangle.
EDGE_DIRECTIONS = {"left": (0.0, 1.0), "right": (0.0, 1.0), "bottom": (1.0, 0.0), "top": (1.0, 0.0)}


def _wedges_at(scene: Scene, end, other) -> list[tuple[str, float]]:
    """``(edge, angle)`` of each wedge between Γ, leaving ``end`` towards
    ``other``, and an edge at ``end``, along that edge's directions that
    stay on the rectangle: α and π − α at a point inside an edge, one
    angle per edge at a corner (their sum π/2)."""
    tol_ = tol.GEOMETRY * scene.length_scale
    d = (other - end) / np.linalg.norm(other - end)
    wedges = []
    for edge in scene.domain.boundary_of(end, tol_):
        for e in (np.array(EDGE_DIRECTIONS[edge]), -np.array(EDGE_DIRECTIONS[edge])):
            if scene.domain.contains([end + tol.WEDGE_PROBE * scene.length_scale * e], tol_)[0]:
                wedges.append((edge, float(np.arccos(np.clip(d @ e, -1.0, 1.0)))))
    return wedges


def pollution_order(scene: Scene | None) -> float:
    """``2 λ_min`` over the scene's singular points (:func:`corner_exponents`,
    :func:`interface_end_exponents`), inf where there are none: away from
    a singularity ``r^λ`` the error of a displacement converges no faster
    than ``h^{2λ}`` (pollution: Nitsche & Schatz, Math. Comp. 28, 1974;
    Wahlbin, *Local behavior in finite element methods*, 1991), though
    only once the singular term outweighs the smooth one, which depends
    on its coefficient: the orders lie in ``[min(p, 2λ), p]``
    (:func:`order_range`)."""
    lams = corner_exponents(scene) + interface_end_exponents(scene) if scene is not None else []
    return 2 * min(lams) if lams else np.inf


def balanced_order(low: float, high: float, ratio: float = 2.0) -> float:
    """The order ``q`` whose Richardson factor is the geometric mean of
    those of ``low`` and ``high``: ``r^q − 1 = ((r^low − 1)(r^high − 1))^½``
    (``r`` the refinement ratio).  If the error converges at either, the
    estimate at ``q`` is off by at most ``((r^high − 1)/(r^low − 1))^½``,
    up or down; ``low`` itself where the two are equal."""
    return float(np.log1p(np.sqrt((ratio ** low - 1) * (ratio ** high - 1))) / np.log(ratio))


def singular_regions(scene: Scene) -> list[tuple[str, np.ndarray]]:
    """The singular points, named: ``("corners", points)`` of a rectangular
    domain and ``("ends of Γ", points)`` where a straight Γ meets the outer
    boundary (each an (m, 2) array)."""
    regions = []
    if isinstance(scene.domain, Rectangle):
        regions.append(("corners", np.asarray(scene.domain.corners, float)))
    if isinstance(scene.interface, LineInterface):
        regions.append(("ends of Γ", np.asarray(scene.interface.chord(scene.domain), float)))
    return regions


def singular_points(scene: Scene) -> np.ndarray:
    """Domain corners and the points where a straight Γ meets the outer boundary."""
    pts = [points for _, points in singular_regions(scene)]
    return np.vstack(pts) if pts else np.zeros((0, 2))


def far_from_singular(scene: Scene, points: np.ndarray, exclude: float) -> np.ndarray:
    """Mask of the points at least ``exclude`` from every singular point."""
    sing = singular_points(scene)
    if len(sing) == 0 or exclude <= 0:
        return np.ones(len(points), bool)
    return np.min(np.linalg.norm(points[:, None, :] - sing[None], axis=-1), axis=1) >= exclude


def rms(x: np.ndarray) -> float:
    """The root mean square of ``x`` (0 for none)."""
    return float(np.sqrt(np.mean(np.square(x)))) if len(x) else 0.0


# ----- Richardson -------------------------------------------------------------

@dataclass(frozen=True)
class QuantityEstimate:
    """The finest run's estimated error of one quantity on one profile:
    ``error`` (per sample, ≥ 0, in the quantity's units), the ``order`` used,
    whether it was ``observed`` (three runs) or taken from the orders
    ``theory`` allows (:func:`order_range`; recorded as ``"orders"``, so
    that a user sees why a two-run order is, say, 2.205: the balanced
    order of ``[1.52, 3]``); ``measured``, the order three runs showed
    (recorded as ``"observed_order"``), of which ``order`` is the least
    with the two-run one.  ``cell_scale``, where the difference of
    the runs was split (:func:`cell_scale_part`): the share (RMS) of its
    part at the scale of the coarse run's cells, estimated at the upper
    order of ``theory`` (recorded as ``"cell_scale"``)."""

    error: np.ndarray
    order: float
    observed: bool
    theory: tuple[float, float]
    cell_scale: float | None = None
    measured: float | None = None

    @property
    def max(self) -> float:
        return float(np.max(self.error)) if len(self.error) else 0.0

    @property
    def rms(self) -> float:
        return rms(self.error)

    def record(self) -> dict:
        out = {"max": self.max, "rms": self.rms, "order": self.order, "observed": self.observed,
               "orders": [float(t) for t in self.theory]}
        if self.cell_scale is not None:
            out["cell_scale"] = self.cell_scale
        if self.measured is not None:
            out["observed_order"] = self.measured
        return out


def observed_order(coarse: np.ndarray, mid: np.ndarray, fine: np.ndarray, ratio: float = 2.0) -> float | None:
    """``log_ratio(‖mid − coarse‖ / ‖fine − mid‖)`` (RMS), clipped to
    :data:`~contactcore.tolerances.ORDER_RANGE`; None when the finer
    difference is at round-off of the quantity's scale
    (:data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF`): no order to see."""
    scale = max(np.max(np.abs(fine)), np.max(np.abs(mid)), 0.0) if len(fine) else 0.0
    d1, d2 = rms(mid - coarse), rms(fine - mid)
    if d2 <= tol.ESTIMATE_ROUNDOFF * scale or d1 <= tol.ESTIMATE_ROUNDOFF * scale:
        return None
    p = np.log(d1 / d2) / np.log(ratio)
    return float(np.clip(p, *tol.ORDER_RANGE))


def cell_scale_part(values: np.ndarray, s: np.ndarray, groups: np.ndarray, width: float) -> np.ndarray:
    """The part of ``values`` (samples at arc length ``s``) at the scale of
    a run's cells: ``values`` minus their local linear regression with a
    Gaussian kernel of standard deviation ``width`` (the coarse run's h),
    fitted within each group of samples (``groups``: a label per sample,
    −1 for none: contiguous samples away from singular points, in one
    body); 0 outside the groups and in a group too short to fit a line
    through its neighbours (:data:`CELL_SCALE_MIN_SAMPLES`)."""
    out = np.zeros(len(values))
    for g in np.unique(groups[groups >= 0]):
        idx = np.flatnonzero(groups == g)
        if len(idx) < CELL_SCALE_MIN_SAMPLES:
            continue
        si, vi = s[idx], values[idx]
        w = np.exp(-0.5 * ((si[None, :] - si[:, None]) / width) ** 2)            # (target, sample)
        d = si[None, :] - si[:, None]
        s0, s1, s2 = w.sum(1), (w * d).sum(1), (w * d * d).sum(1)
        t0, t1 = (w * vi[None, :]).sum(1), (w * d * vi[None, :]).sum(1)
        det = s0 * s2 - s1 * s1
        smooth = np.where(det > 0, (s2 * t0 - s1 * t1) / np.where(det > 0, det, 1.0), t0 / s0)
        out[idx] = vi - smooth
    return out


#: The fewest samples in a group through which :func:`cell_scale_part`
#: fits its local lines (fewer: the whole difference is taken as smooth).
CELL_SCALE_MIN_SAMPLES = 5


def richardson(values: list[np.ndarray], theory: tuple[float, float], ratio: float = 2.0, coarse: bool = False,
               kept: np.ndarray | None = None, cells=None) -> QuantityEstimate:
    """The estimate of one quantity from its samples at h, h/2 (and h/4),
    coarse to fine (module doc): the finest run's error, or with
    ``coarse`` the coarsest run's (``(q_{h/2} − q_h) r^p / (r^p − 1)``,
    two levels only).  The order is observed on the ``kept`` samples (all
    by default): near a singular point the differences shrink at the
    singularity's rate, not the smooth solution's, and would set it.
    Without a third run it is the :func:`balanced_order` of the orders
    ``theory`` allows (:func:`order_range`); with one, the least of the
    observed order (``measured``) and that one; with ``cells`` (a function
    that returns a difference's part at the scale of the coarse run's
    cells, :func:`cell_scale_part`), that part is estimated at the upper
    order ``theory[1]`` and the rest at the balanced one: for a range
    that pollution widened (:func:`profile_estimates`)."""
    kept = slice(None) if kept is None or not np.any(kept) else kept
    p = observed_order(*(v[kept] for v in values[-3:]), ratio=ratio) if len(values) >= 3 else None
    order = balanced_order(*theory, ratio=ratio)
    if p is not None:  # an observed order above the two-run one is pre-asymptotic cancellation: not used
        order = min(p, order)
    factor = lambda o: ratio ** o / (ratio ** o - 1) if coarse else 1 / (ratio ** o - 1)  # noqa: E731
    signed = values[-1] - values[-2]
    if p is not None or cells is None or theory[0] >= theory[1]:
        return QuantityEstimate(np.abs(signed) * factor(order), order, p is not None, theory, measured=p)
    fine = cells(signed)
    share = rms(fine[kept]) / rms(signed[kept]) if rms(signed[kept]) > 0 else 0.0
    error = np.abs((signed - fine) * factor(order) + fine * factor(theory[1]))
    return QuantityEstimate(error, order, False, theory, float(share))


def polluted(quantity: str, degree: int, method: str = "", law=None, switching: bool | None = None,
             pollution: float = np.inf) -> bool:
    """Whether :func:`order_range` widened the quantity's orders for
    pollution (a displacement, gap or penalty traction whose order
    exceeds ``pollution``), in a method whose error at the scale of its
    cells converges at that order (not :data:`MESHFREE`: EFGM's includes
    its quadrature's, which does not converge)."""
    p = theoretical_order(quantity, degree, method, law, switching)
    return (quantity in DISPLACEMENT_LIKE and not (quantity in TRACTIONS and _exact(law)) and pollution < p
            and method not in MESHFREE)


def sample_groups(scene: Scene, xy: np.ndarray, kept: np.ndarray) -> np.ndarray:
    """A label per sample of a profile (−1 for none): runs of consecutive
    ``kept`` samples in one body (a line that crosses Γ is split there,
    where its quantities kink or jump; samples on Γ are one group)."""
    d = scene.interface.signed_distance(xy)
    side = np.where(np.abs(d) <= tol.GEOMETRY * scene.length_scale, 0, np.sign(d))
    if not np.any(side != 0):
        side = np.ones(len(xy))
    ok = kept & (side != 0)
    labels, current, prev = np.full(len(xy), -1), -1, None
    for i in range(len(xy)):
        if not ok[i]:
            prev = None
            continue
        if prev is None or side[i] != side[prev]:
            current += 1
        labels[i], prev = current, i
    return labels


def profile_estimates(levels: list[list[ProfileData]], degree: int, method: str = "", coarse: bool = False,
                      scene: Scene | None = None, exclude: float = 0.0,
                      switching: bool | None = None, h: float | None = None) -> dict[str, dict[str, QuantityEstimate]]:
    """``{profile id: {quantity: estimate}}`` from the profiles of each run,
    coarse to fine (each a list in the scene's order); an observed order
    from the samples at least ``exclude`` from the ``scene``'s singular
    points; ``switching`` as :func:`theoretical_order` takes it; the
    ``scene``'s :func:`pollution_order` widens the orders of its
    displacements, gaps and penalty tractions (:func:`order_range`).  With the coarse run's ``h``,
    a two-run estimate of a range that pollution widened (:func:`polluted`)
    takes the difference's part at the scale of that run's cells
    (:func:`cell_scale_part`, over :func:`sample_groups`) at the upper
    order: away from a singular point its pollution solves the
    homogeneous equations, smooth at that scale, so what varies cell by
    cell is the runs' local error, which converges at the method's order."""
    out, law = {}, scene.law if scene else None
    pollution = pollution_order(scene)
    for profs in zip(*levels):
        pid, cols = profs[-1].id, profs[-1].columns
        xy = np.column_stack([cols["x"], cols["y"]])
        kept = far_from_singular(scene, xy, exclude) if scene else None
        cells = None
        if scene is not None and h is not None:
            s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(xy, axis=0), axis=1))])
            groups = sample_groups(scene, xy, kept)
            cells = lambda v, s=s, groups=groups: cell_scale_part(v, s, groups, h)  # noqa: E731
        out[pid] = {q: richardson([p.columns[q] for p in profs],
                                  order_range(q, degree, method, law, switching, pollution),
                                  coarse=coarse, kept=kept,
                                  cells=cells if polluted(q, degree, method, law, switching, pollution) else None)
                    for q in profs[-1].names[3:]}
    return out


def _orders(theory: tuple[float, float]) -> str:
    """``"2"``, or ``"1-2"`` for a range."""
    low, high = theory
    return f"{low:.3g}" if low == high else f"{low:.3g}-{high:.3g}"


def order_warnings(estimates: dict[str, dict[str, QuantityEstimate]]) -> list[str]:
    """One line per quantity whose observed order is further than
    :data:`~contactcore.tolerances.ORDER_MISMATCH` from the orders theory
    allows, or was clipped to an end of
    :data:`~contactcore.tolerances.ORDER_RANGE` (the differences do not
    shrink like a power of h at all)."""
    return [f"{pid}:{q}: observed order {e.measured:.2f}{_clipped(e.measured)} against {_orders(e.theory)} in "
            f"theory: the runs are not in the asymptotic range, the estimate is not to be trusted"
            for pid, qs in estimates.items() for q, e in qs.items()
            if e.measured is not None and order_mismatch(e)]


def order_mismatch(e: QuantityEstimate) -> bool:
    """Whether ``e``'s observed order (three runs) lies further than
    :data:`~contactcore.tolerances.ORDER_MISMATCH` from the orders theory
    allows, or was clipped to an end of
    :data:`~contactcore.tolerances.ORDER_RANGE`."""
    p = e.measured
    return p is not None and bool(_clipped(p) or not e.theory[0] - tol.ORDER_MISMATCH <= p
                                  <= e.theory[1] + tol.ORDER_MISMATCH)


def _clipped(order: float) -> str:
    """``" (clipped)"`` where an observed order sits at an end of ORDER_RANGE."""
    return " (clipped)" if order <= tol.ORDER_RANGE[0] or order >= tol.ORDER_RANGE[1] else ""


#: The least order at which a corner's pollution shows: the degree-2
#: displacement and gaps (order 3) converged at 1.5-1.9 away from the
#: singular points of nine scenes the estimate was not tuned on, their
#: two-run estimates at order 3 0.15-0.46 of the error
#: (docs/error-estimates.md).  :func:`pollution_order` takes the
#: clamped-free corners and Γ's ends under a penalty law; what is left at
#: this order lies on a domain whose singular points it does not take.
POLLUTED_ORDER = 3


def pollution_warning(scene: Scene, profiles: dict[str, dict[str, QuantityEstimate]]) -> list[str]:
    """A line when quantities are estimated from two runs at an order of
    :data:`POLLUTED_ORDER` or more on a domain with singular points that
    :func:`pollution_order` does not take (corners between two clamped or
    two free edges, the end of an exactly enforced Γ, a straight Γ's ends
    on a disc): if one of them
    slows them everywhere after all, the estimate may be several times
    too small."""
    names = [f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items()
             if not e.observed and e.order >= POLLUTED_ORDER]
    if not names or not len(singular_points(scene)):
        return []
    return [f"{', '.join(names)}: estimated at order {POLLUTED_ORDER} from two runs, but the domain has singular "
            f"points (corners, Γ's ends) which, where they slow such quantities to 1.5-2 everywhere, make the "
            f"estimate 2-7 times too small: --estimate 3 observes the order"]


# ----- runs that are not asymptotic: their stencils ---------------------------

#: Meshfree methods, whose stencil is their supports (the run's record
#: holds ``dmax`` and ``support``: :mod:`efgm.method`).
MESHFREE = ("efgm",)


def stencil_radius(record: dict, method: str, degree: int, quantity: str) -> float:
    """The radius around a point within which lie the unknowns that set a
    run's ``quantity`` there: a support of ``dmax · h`` for a meshfree
    method (``√2`` times that to a rectangular support's corner), the
    recovery patch of :data:`~contactcore.tolerances.RECOVERY_RINGS`
    vertex rings around the point's cell for a recovered stress
    (:data:`RECOVERED_STRESS`), and one cell, ``h``, otherwise."""
    h = float(record["h"])
    if method in MESHFREE:
        return float(record["dmax"]) * h * (np.sqrt(2.0) if record.get("support") == "rectangular" else 1.0)
    if quantity in STRESSES and (method, degree) in RECOVERED_STRESS:
        return (tol.RECOVERY_RINGS + 1) * h
    return h


def feature_size(scene: Scene) -> float:
    """The scene's smallest feature: the domain's smallest extent (a
    rectangle's shorter side, a disc's diameter), or a circular Γ's
    diameter where that is less."""
    domain = scene.domain
    size = float(min(domain.size)) if isinstance(domain, Rectangle) else domain.length_scale
    radius = getattr(scene.interface, "radius", None)
    return min(size, 2.0 * float(radius)) if radius is not None else size


def unsettled(scene: Scene, levels: list[list[ProfileData]], record: dict, method: str, degree: int,
              exclude: float) -> dict[str, dict[str, tuple[float, float]]]:
    """The quantities whose two-run estimate is not asymptotic, by cause,
    from the coarser run (``record``, its discretisation) of the pair
    that makes it: ``{"reach": {PID:Q: (ρ, h_ok)}, "coarse": {...}}``
    with ``ρ`` the quantity's :func:`stencil_radius` in that run and
    ``h_ok`` the coarse run's h from which the cause is gone (ρ scales
    with h).  ``reach``: a sample kept (at least ``exclude`` from the
    singular points) lies within
    :data:`~contactcore.tolerances.REACH_STENCILS` stencils of a singular
    point, where that run's error is still the singular point's own.
    ``coarse``: the stencil exceeds
    1/:data:`~contactcore.tolerances.FEATURE_STENCILS` of the scene's
    :func:`feature_size`.  A tie within
    :data:`~contactcore.tolerances.GEOMETRY` (relative) is no cause: h =
    0.05 with supports of 2h on a feature of 0.8 sits on the threshold,
    and round-off must not decide it."""
    sing, feature, h = singular_points(scene), feature_size(scene), float(record["h"])
    out = {"reach": {}, "coarse": {}}
    for prof in levels[-1]:
        xy = np.column_stack([prof.columns["x"], prof.columns["y"]])
        kept = far_from_singular(scene, xy, exclude)
        near = (np.min(np.linalg.norm(xy[kept][:, None] - sing[None], axis=-1))
                if len(sing) and np.any(kept) else np.inf)
        for q in prof.names[3:]:
            rho = stencil_radius(record, method, degree, q)
            if near < tol.REACH_STENCILS * rho * (1 - tol.GEOMETRY):
                out["reach"][f"{prof.id}:{q}"] = (rho, h * near / (tol.REACH_STENCILS * rho))
            if rho * tol.FEATURE_STENCILS > feature * (1 + tol.GEOMETRY):
                out["coarse"][f"{prof.id}:{q}"] = (rho, h * feature / (tol.FEATURE_STENCILS * rho))
    return out


def unsettled_warnings(found: dict[str, dict[str, tuple[float, float]]], h: float, feature: float,
                       length: str = "m") -> list[str]:
    """One line per cause of :func:`unsettled` and per stencil, naming the
    quantities and the coarse h from which the cause is gone; its lengths
    in the scene's unit named ``length`` (:class:`~contactcore.scene.Units`)."""
    lines = []
    for cause, entries in found.items():
        for rho in sorted({v[0] for v in entries.values()}):
            names = [k for k, v in entries.items() if v[0] == rho]
            h_ok = min(entries[k][1] for k in names)
            why = (f"samples kept within {tol.REACH_STENCILS * rho:.3g} of a singular point, the reach of its own "
                   f"error in the run at h = {h:g} (two stencils of {rho:.3g})" if cause == "reach" else
                   f"the run at h = {h:g} has stencils (cells, supports, recovery patches) of {rho:.3g}, more than "
                   f"1/{tol.FEATURE_STENCILS:g} of the scene's smallest feature ({feature:.3g})")
            lines.append(f"{', '.join(names)}: {why}: the runs are not in the asymptotic range, the estimate is an "
                         f"indication only (starting below h = {h_ok:.3g} avoids this; lengths in {length})")
    return lines


def cell_scale_orders(scene: Scene, levels: list[list[ProfileData]],
                      estimates: dict[str, dict[str, QuantityEstimate]], exclude: float,
                      h: float) -> dict[str, tuple[float, float]]:
    """``{PID:Q: (order, high)}`` of the two-run estimates whose coarse
    run is rough at the scale of its cells: the RMS over the kept
    samples (at least ``exclude`` from the singular points) of each run's
    part at that scale (:func:`cell_scale_part`, the same kernel of the
    coarse run's ``h`` for both, fitted over :func:`sample_groups`)
    shrinks between the runs at an ``order`` above the highest that
    theory allows the quantity (``high``, :func:`order_range`) by more
    than :data:`~contactcore.tolerances.CELL_SCALE_EXCESS`.  A smooth
    exact value leaves the same part in both runs (ratio 1); what
    varies from cell to cell beyond it is each run's local error, which
    shrinks at the method's order once the runs are asymptotic.  Faster
    means the coarse run's is not yet (the runs of
    docs/error-estimates.md, "Which estimates to warn of").  Quantities
    with an observed order (three runs) are left to
    :func:`order_warnings`; a part at round-off shows no order: of the
    quantity (:data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF` of its
    largest |value|), or of the scene's own size of its kind
    (:data:`~contactcore.tolerances.NEGLIGIBLE_SHARE` of
    :class:`~contactcore.scaling.Sizes`' stress for a stress or traction,
    displacement otherwise), so that a quantity whose values are all
    round-off (σxy of a bonded patch, 1e-14) is named by no kernel."""
    from .scaling import Sizes
    sizes, out = Sizes.of(scene), {}
    for coarse, fine in zip(levels[-2], levels[-1]):
        cols = fine.columns
        xy = np.column_stack([cols["x"], cols["y"]])
        kept = far_from_singular(scene, xy, exclude)
        s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(xy, axis=0), axis=1))])
        groups = sample_groups(scene, xy, kept)
        for q in fine.names[3:]:
            e = estimates.get(fine.id, {}).get(q)
            if e is None or e.observed or not np.any(kept):
                continue
            a, b = (rms(cell_scale_part(v, s, groups, h)[kept]) for v in (coarse.columns[q], cols[q]))
            scale = max(float(np.max(np.abs(cols[q]))), float(np.max(np.abs(coarse.columns[q]))))
            own = sizes.stress if q in STRESSES + TRACTIONS else sizes.displacement
            if min(a, b) <= max(tol.ESTIMATE_ROUNDOFF * scale, tol.NEGLIGIBLE_SHARE * own):
                continue
            order = float(np.log2(a / b))
            if order > e.theory[1] + tol.CELL_SCALE_EXCESS:
                out[f"{fine.id}:{q}"] = (order, float(e.theory[1]))
    return out


def cell_scale_warnings(found: dict[str, tuple[float, float]], hs: tuple[float, float]) -> list[str]:
    """One line naming the quantities of :func:`cell_scale_orders`, each
    with the order at which its runs' variation at the cells' scale
    shrank and the highest order theory allows it."""
    if not found:
        return []
    names = ", ".join(f"{k} ({o:.2f} against {hi:.3g})" for k, (o, hi) in found.items())
    return [f"{names}: the runs' variation from cell to cell shrinks between h = {hs[0]:g} and {hs[1]:g} faster "
            f"than theory allows the error (orders in brackets): the coarse run is not in the asymptotic range, "
            f"the estimate is an indication only and likely too large"]


#: The kinds of profile quantity whose errors a run compares
#: (:func:`residues`): bulk displacements, bulk stresses, gaps and
#: tractions on Γ.
KINDS = {"ux": "displacement", "uy": "displacement", "sxx": "stress", "syy": "stress", "sxy": "stress",
         "gN": "gap", "gT": "gap", "tN": "traction", "tT": "traction"}


def residues(scene: Scene, levels: list[list[ProfileData]],
             estimates: dict[str, dict[str, QuantityEstimate]], exclude: float) -> dict[str, tuple[float, str]]:
    """``{PID:Q: (share, PID:Q')}`` of the two-run estimates whose runs
    differ (RMS over the kept samples, at least ``exclude`` from the
    singular points) by less than
    :data:`~contactcore.tolerances.RESIDUE_SHARE` of the largest such
    difference among the quantities of its kind (:data:`KINDS`) on every
    profile of the same runs (``PID:Q'``).  The theoretical order is
    that of the error's leading term ``C h^p``, whose ``C`` the
    solution's derivatives near the sample set; where the runs differ a
    thousand times less than elsewhere that term nearly cancels, and a
    term whose coefficient is as small (the representation of Γ in the
    cut cells, quadrature) may set the rate: σxx along scene B's
    clamped top edge in xfem P2 converges at 1.28 and 0.96 between h =
    0.05, 0.025 and 0.0125, against 2 in theory and 1.98 for σxy in the
    same runs (docs/error-estimates.md, "Which estimates to warn of").
    Quantities with an observed order (three runs) are left to
    :func:`order_warnings` but count in their kind's largest; a
    difference at round-off (of the
    quantity, :data:`~contactcore.tolerances.ESTIMATE_ROUNDOFF`, or of
    the scene's size of its kind, :data:`~contactcore.tolerances.NEGLIGIBLE_SHARE`
    of :class:`~contactcore.scaling.Sizes`) shows nothing and is neither
    named nor the kind's largest."""
    from .scaling import Sizes
    sizes, found = Sizes.of(scene), {}
    for coarse, fine in zip(levels[-2], levels[-1]):
        cols = fine.columns
        xy = np.column_stack([cols["x"], cols["y"]])
        kept = far_from_singular(scene, xy, exclude)
        for q in fine.names[3:]:
            e = estimates.get(fine.id, {}).get(q)
            if e is None or q not in KINDS or not np.any(kept):
                continue
            d = rms((cols[q] - coarse.columns[q])[kept])
            scale = max(float(np.max(np.abs(cols[q]))), float(np.max(np.abs(coarse.columns[q]))))
            own = sizes.stress if q in STRESSES + TRACTIONS else sizes.displacement
            if d > max(tol.ESTIMATE_ROUNDOFF * scale, tol.NEGLIGIBLE_SHARE * own):
                found[f"{fine.id}:{q}"] = (d, KINDS[q], e.observed)
    largest = {}
    for key, (d, kind, _) in found.items():
        if d > largest.get(kind, (0.0, ""))[0]:
            largest[kind] = (d, key)
    return {key: (d / largest[kind][0], largest[kind][1]) for key, (d, kind, observed) in found.items()
            if not observed and d < tol.RESIDUE_SHARE * largest[kind][0]}


def residue_warnings(found: dict[str, tuple[float, str]], observed: bool = False) -> list[str]:
    """One line naming the quantities of :func:`residues`, each with its
    difference's share of the largest of its kind; from ``observed``
    runs (three) it does not advise a third."""
    if not found:
        return []
    names = ", ".join(f"{k} ({share:.2g} of {other}'s)" for k, (share, other) in found.items())
    return [f"{names}: the runs differ there by less than {tol.RESIDUE_SHARE:g} of the most they differ in a "
            f"quantity of the same kind (in brackets): the error's leading term nearly cancels there, a smaller "
            f"term of another order may set its rate, the estimate is an indication only"
            + ("" if observed else " (--estimate 3 observes the order)")]


# ----- the status along Γ -----------------------------------------------------

def switches(paths) -> bool:
    """Whether Γ's status (open, stick, slip forwards, slip backwards: the
    sign of t_T) took more than one value over all increments of the runs'
    interface ``paths``.  Where it never did (scene A under the exact
    unilateral law: closed and tied everywhere), no point of Γ separates
    two statuses, now or in the history that set a Coulomb slip, so nothing
    limits the solution's smoothness there (:func:`theoretical_order`).
    Slip in both directions is a switch: t_T jumps between ±μp."""
    seen = set()
    for path in paths:
        for step in path.steps:
            status = np.asarray(step.status)
            backwards = (status == SLIP) & (np.asarray(step.traction)[:, 1] < 0)
            seen.update(np.unique(np.where(backwards, -1, status)).tolist())
    return len(seen) > 1


def status_along(scene: Scene, path) -> np.ndarray:
    """The final increment's status (index into ``STATUS_NAMES``) at the
    profile samples of Γ, each the status of the nearest quadrature point
    along Γ."""
    _, pts, _ = sample_points(scene, InterfaceProfile("gamma", ("gN",)))
    a, b = along(scene.interface, path.points), along(scene.interface, pts)
    nearest = np.argmin(np.abs(b[:, None] - a[None, :]), axis=1)
    return path.final.status[nearest]


def status_change(scene: Scene, coarse_path, fine_path, hs: tuple[float, float] | None = None) -> dict:
    """The final status of two runs (at ``hs``, coarse and fine) compared
    along Γ: the share of Γ in each status per run, and the samples whose
    status differs."""
    from .laws import STATUS_NAMES
    s0, s1 = status_along(scene, coarse_path), status_along(scene, fine_path)
    shares = lambda s: {n: float(np.mean(s == i)) for i, n in enumerate(STATUS_NAMES)}  # noqa: E731
    return {"coarse": shares(s0), "fine": shares(s1), "differ": int(np.sum(s0 != s1)), "samples": len(s0),
            "h": list(hs) if hs else None}


def status_warning(change: dict) -> list[str]:
    """A line when the two compared runs' status differs somewhere along Γ."""
    if not change or change["differ"] == 0:
        return []
    show = lambda s: ", ".join(f"{v:.0%} {k}" for k, v in s.items())  # noqa: E731
    runs = f"h = {change['h'][0]:g} and {change['h'][1]:g}" if change.get("h") else "the two finest runs"
    return [f"the status along Γ differs between {runs} at {change['differ']} of {change['samples']} samples "
            f"({show(change['coarse'])} → {show(change['fine'])}): the estimate is not asymptotic there"]


# ----- Zienkiewicz–Zhu ----------------------------------------------------------

@dataclass(frozen=True)
class EnergyRule:
    """Gauss points of the domain (``rule``) with each point's background
    cell (``cell``), the grid's node keys of every cell (``keys``), and
    which points lie away from the singular points (``kept``)."""

    rule: object
    cell: np.ndarray
    keys: np.ndarray
    kept: np.ndarray


def energy_rule(scene: Scene, h: float, exclude: float = 0.0, gauss: int = tol.ENERGY_GAUSS) -> EnergyRule:
    """The background cells of size ≈ h (:func:`contactcore.quadrature.background_cells`)
    with their Gauss points, Γ followed exactly."""
    lo, hi = background_cells(scene, h)
    rule = volume_rule(scene, h, gauss)
    step = hi[0] - lo[0]
    origin = lo.min(axis=0)
    n = np.round((hi.max(axis=0) - origin) / step).astype(int)
    ij = np.clip(np.floor((rule.points - origin) / step).astype(int), 0, n - 1)
    cell = ij[:, 0] * n[1] + ij[:, 1]
    I, J = np.divmod(np.arange(n[0] * n[1]), n[1])
    node = lambda i, j: i * (n[1] + 1) + j  # noqa: E731
    keys = np.column_stack([node(I, J), node(I + 1, J), node(I, J + 1), node(I + 1, J + 1)])
    return EnergyRule(rule, cell, keys, far_from_singular(scene, rule.points, exclude))


def energy_norm(scene: Scene, er: EnergyRule, sigma: np.ndarray) -> float:
    """``(Σ_q w_q σᵀ C σ)^½`` over the kept points of ``er`` (σ Voigt, (Q, 3))."""
    C = np.linalg.inv(scene.voigt_matrices())[er.rule.bodies]
    density = np.einsum("qi,qij,qj->q", sigma, C, sigma)
    return float(np.sqrt(max(er.rule.weights[er.kept] @ density[er.kept], 0.0)))


def recovered_stress(scene: Scene, er: EnergyRule, sigma: np.ndarray) -> np.ndarray:
    """σ* at the Gauss points of ``er`` from ``σ_h`` there (module doc): body
    by body, every Gauss point a sample (weight its quadrature weight, its
    cell's node keys), so each background cell's quadratic is the weighted
    least-squares fit to ``σ_h`` over the Gauss points of its patch, a local
    L2 projection; σ_h itself where a patch fits no line."""
    rule, out = er.rule, sigma.copy()
    for body in (0, 1):
        mine = np.flatnonzero(rule.bodies == body)
        if not len(mine):
            continue
        sample = np.full(len(rule.weights), -1)
        sample[mine] = np.arange(len(mine))
        _, first, inverse = np.unique(er.cell[mine], return_index=True, return_inverse=True)
        recovery = PatchRecovery(er.keys[er.cell], sample, rule.points[mine], rule.weights[mine], sigma[mine],
                                 rings=tol.ENERGY_RINGS)
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

    @property
    def relative(self) -> float:
        size = max(self.norm, self.floor)
        return self.eta / size if size > 0 else float("nan")

    def record(self) -> dict:
        return {"eta": self.eta, "norm": self.norm, "relative": self.relative, "exclude": self.exclude,
                "floor": self.floor}


def energy_estimate(scene: Scene, fields, h: float, exclude: float = 0.0, gauss: int = tol.ENERGY_GAUSS
                    ) -> EnergyEstimate:
    """The Zienkiewicz–Zhu estimate of one run (module doc) on background
    cells of the run's size ``h``, ``gauss`` points per direction."""
    from .scaling import Sizes
    er = energy_rule(scene, h, exclude, gauss)
    sigma = fields.stress(er.rule.points, er.rule.bodies)
    star = recovered_stress(scene, er, sigma)
    return EnergyEstimate(energy_norm(scene, er, star - sigma), energy_norm(scene, er, sigma), exclude,
                          tol.NEGLIGIBLE_SHARE * Sizes.of(scene).energy)


# ----- one estimate of a run ---------------------------------------------------

#: The suffix of an estimated error's column beside its quantity
#: (``q_err``, in q's unit).
ERROR_SUFFIX = "_err"


@dataclass
class Estimate:
    """Everything estimated about the finest of a method's runs at ``hs``
    (coarse to fine): per profile and quantity (:class:`QuantityEstimate`),
    in energy (:class:`EnergyEstimate`), the status along Γ compared
    between the two finest runs (a law with history), warnings, the
    finest run's profiles as sampled (``sampled``, in the scene's order:
    what a driver writes, not sampled again), and the ``PID:Q`` whose
    estimate a warning calls not asymptotic (:func:`unsettled`,
    :func:`cell_scale_orders`, and with three runs :func:`order_mismatch`) or not
    to be trusted (:func:`residues`)."""

    hs: tuple
    profiles: dict[str, dict[str, QuantityEstimate]]
    energy: EnergyEstimate | None
    status: dict | None = None
    warnings: list[str] = field(default_factory=list)
    sampled: list[ProfileData] = field(default_factory=list)
    unsettled: set[str] = field(default_factory=set)

    def error_columns(self, pid: str) -> dict[str, np.ndarray]:
        """``{q + ERROR_SUFFIX: per-sample error}`` of profile ``pid``."""
        return {f"{q}{ERROR_SUFFIX}": e.error for q, e in self.profiles.get(pid, {}).items()}

    def summary(self) -> dict:
        """JSON-ready: ``{PROFILE: {QUANTITY: {max, rms, order, observed}}}``
        plus ``energy``, ``h`` (the runs), ``status`` and ``warnings``."""
        out = {pid: {q: e.record() for q, e in qs.items()} for pid, qs in self.profiles.items()}
        out.update({"energy": self.energy.record() if self.energy else None, "h": list(self.hs),
                    "status": self.status, "warnings": list(self.warnings)})
        return out


def levels_of(h: float, levels: int) -> list[float]:
    """``h, h/2`` (and ``h/4``), coarse to fine."""
    if levels not in (2, 3):
        raise ValueError(f"levels must be 2 or 3 (got {levels})")
    return [h / 2 ** k for k in range(levels)]


def estimate_runs(scene: Scene, results: list, exclude: float = 0.0, energy: bool = True,
                  coarse: bool = False) -> Estimate:
    """The :class:`Estimate` of the finest of ``results`` (one method at
    h, h/2 (, h/4), coarse to fine), or with ``coarse`` of the coarser of
    two (its profiles' errors; the energy estimate still the finest run's);
    the energy and an observed order leave out what lies within
    ``exclude`` of a singular point."""
    hs = tuple(float(r.discretisation["h"]) for r in results)
    levels = [sample_profiles(scene, r.fields, r.interface) for r in results]
    switching = None if scene.law.is_linear else switches([r.interface for r in results])
    profiles = profile_estimates(levels, results[-1].degree, results[-1].method, coarse, scene, exclude, switching,
                                 h=hs[-2])
    found = unsettled(scene, levels, results[-2].discretisation, results[-1].method, results[-1].degree, exclude)
    rough = cell_scale_orders(scene, levels, profiles, exclude, hs[-2])
    residue = residues(scene, levels, profiles, exclude)
    warnings = (order_warnings(profiles) + pollution_warning(scene, profiles)
                + unsettled_warnings(found, hs[-2], feature_size(scene), scene.user.units.length)
                + cell_scale_warnings(rough, hs[-2:]) + residue_warnings(residue, len(levels) > 2))
    status = None
    if scene.law.has_history or not scene.law.is_linear:
        status = status_change(scene, results[-2].interface, results[-1].interface, hs[-2:])
        warnings += status_warning(status)
    zz = energy_estimate(scene, results[-1].fields, hs[-1], exclude) if energy else None
    return Estimate(hs, profiles, zz, status, warnings, levels[-1],
                    {k for v in found.values() for k in v} | set(rough) | set(residue)
                    | {f"{pid}:{q}" for pid, qs in profiles.items() for q, e in qs.items() if order_mismatch(e)})


def estimate(scene: Scene, discretisation, h: float, levels: int = 2, *, exclude: float = 0.0, reuse=None,
             progress=None):
    """Solve ``scene`` with ``discretisation`` (:mod:`contactcore.discretisation`)
    at ``h``, ``h/2`` (and ``h/4`` with ``levels=3``) and return the finest
    :class:`~contactcore.result.Result` with its :class:`Estimate`; the
    energy estimate leaves out Gauss points within ``exclude`` of the
    singular points."""
    from .discretisation import solve
    results = [solve(scene, discretisation, hk, reuse=reuse, progress=progress) for hk in levels_of(h, levels)]
    return results[-1], estimate_runs(scene, results, exclude)
