"""The orders theory allows a profile quantity's error, by method and degree.

With two runs the Richardson estimate
(:mod:`~contactcore.estimate.extrapolation`) takes the method's
theoretical order for the quantity (:func:`theoretical_order`): ``k + 1``
for a displacement and a gap (the L2 rate of degree k), and for a penalty
law's traction on Γ, which the law computes from the gaps
(``t = k_N g_N`` …) not from the bulk stress; ``k`` for a stress (the H1
rate); under an exact law, at most 2 for the gaps and 1 for the traction
where Γ's status changes along it
(:func:`~contactcore.estimate.status.switches`), except at the samples
far from every point where it switches (:func:`smooth_range`).  A degree-1 stress that
a method recovers (its options' ``recovered_stress``,
:class:`~contactcore.result.MethodFacts`: xfem P1) converges as the
displacement.

Away from a singular point of exponent ``λ`` (``u ~ r^λ``: a
clamped-free corner, the end of a penalty Γ:
:mod:`~contactcore.estimate.singular`) a displacement's error converges
no faster than ``h^{2λ}`` once the singular term outweighs the smooth one
(pollution: Nitsche & Schatz, Math. Comp. 28, 1974), which depends on its
coefficient: a displacement, gap or penalty traction takes the orders
``[min(p, 2λ), p]`` (:func:`order_range`, ``2λ`` from
:func:`~contactcore.estimate.singular.pollution_order`).  EFGM holds its
supports by boundary multipliers (:mod:`efgm.method`), and its P2 takes
the orders of every other degree-2 method (until 2026-11-27 it collocated
them at the nodes of a basis that does not interpolate, whose defect set
its bulk displacements' order: a rule that went with it,
docs/error-estimates.md).

A degree-1 stress read at a point converges at its order ``p`` where the
point is generic in its cell and at ``p + 1`` where it superconverges
(the cell's centroid, a uniform grid aligned with the profile: Zienkiewicz
& Zhu, IJNME 33, 1992; Wahlbin, *Superconvergence in Galerkin finite
element methods*, 1995), and which holds at a sample is not known from
two runs: its orders are ``[p, p + 1]`` (:func:`order_range`), of which
the estimate takes the balanced one
(:func:`~contactcore.estimate.extrapolation.balanced_order`).

An exact law's degree-1 traction where Γ's status does not change (no
switch, or far from every change: :func:`smooth_range`) takes the same
range ``[1, 2]``.  It is Nitsche's multiplier read as its mean over each
piece of Γ (:meth:`~contactcore.interface_path.InterfacePath.piece_means`),
the consistent flux the bulk receives, and a consistent flux's weighted
means superconverge (Wheeler, SINUM 11, 1974, at the nodes in one
dimension; Carey, Chow & Seager, CMAME 50, 1985, on a boundary in two;
Babuška & Miller, IJNME 20, 1984): how much of that a mean over one piece
keeps, two runs cannot tell.  Measured 2026-11-29 beyond two coarse cells
of every status change (docs/error-estimates.md, "Known limits"): the
degree-1 tractions' true errors converged at 0.0-3.2 (fe, xfem and efgm
P1 on six scenes, 70 entries), half of them at 1.3-2.0; at order 1 their
estimates read up to 8.5 times the error, and 6 of the 24 entries of the
two scenes that never switch lay in [0.5, 2], at 1.45 20 (none below 0.5).

numpy only; no method is imported or named: what this module must know
of one, it reads from the run's :class:`~contactcore.result.MethodFacts`
(``facts``; the defaults, a mesh method's whose stress is its own).
"""
from __future__ import annotations

import numpy as np

from ..result import MethodFacts


#: Quantities that converge as the displacement (degree + 1): displacements,
#: gaps, and the tractions the law computes from the gaps.
DISPLACEMENT_LIKE = ("ux", "uy", "gN", "gT", "tN", "tT")


#: Γ's quantities under an exact law (:mod:`contactcore.exact`).
GAPS, TRACTIONS = ("gN", "gT"), ("tN", "tT")


def theoretical_order(quantity: str, degree: int, facts: MethodFacts = MethodFacts(), law=None,
                      switching: bool | None = None) -> int:
    """The rate of a profile quantity for a method of ``degree`` and
    ``facts`` (module doc; a recovered stress converges as the
    displacement).  Under an exact ``law`` the traction on Γ is Nitsche's multiplier,
    a stress (rate ``degree``, not the gaps' ``degree + 1``).  Where that
    law switches (open/closed, stick/slip: every exact law but ``bonded``)
    the solution is no smoother than H^{5/2-ε} at the points where Γ's
    status changes (Moussaoui & Khodja, Comm. PDE 17, 1992; Chouly, Hild &
    Renard, Math. Comp. 84, 2015), which caps the gaps' rate at 2 and the
    traction's at 1 in every degree: exact C-coulomb's profiles converge
    at about these rates (docs/contact-enforcement.md, "Convergence").
    ``switching`` False says that the runs' status never changed along Γ
    (:func:`~contactcore.estimate.status.switches`): no such point, the bonded
    law's rates."""
    if _exact(law):
        if quantity in TRACTIONS:
            return 1 if _switches(law, switching) else degree
        if quantity in GAPS and _switches(law, switching):
            return min(degree + 1, 2)
    if quantity in DISPLACEMENT_LIKE or facts.recovered_stress:
        return degree + 1
    return degree


#: Bulk stresses, and the degrees whose stress read at a point converges
#: at its theoretical order or one faster (module doc): the estimate's
#: order lies between (:func:`order_range`).  Measured at the theoretical
#: order, the Richardson effectivity of these stresses was 0.96-8.8 on
#: the paper's scenes and 0.98-2.31 on the closed forms (2026-11-27,
#: docs/error-estimates.md), of the degree-2 stresses 0.9-1.45.
STRESSES, SUPERCONVERGENT_DEGREES = ("sxx", "syy", "sxy"), (1,)


def order_range(quantity: str, degree: int, facts: MethodFacts = MethodFacts(), law=None,
                switching: bool | None = None, pollution: float = np.inf) -> tuple[float, float]:
    """The orders theory allows a profile quantity: ``(p, p)`` with ``p``
    the :func:`theoretical_order`, ``(p, p + 1)`` for a stress of a degree
    in :data:`SUPERCONVERGENT_DEGREES` and for an exact law's traction of
    such a degree where Γ's status never changes (module doc), ``(pollution, p)``
    for a displacement, a gap or a penalty law's traction whose ``p``
    exceeds the scene's
    :func:`~contactcore.estimate.singular.pollution_order`."""
    p = theoretical_order(quantity, degree, facts, law, switching)
    if degree in SUPERCONVERGENT_DEGREES and (quantity in STRESSES or _smooth_multiplier(quantity, law, switching)):
        return (p, p + 1)
    polluted = quantity in DISPLACEMENT_LIKE and not (quantity in TRACTIONS and _exact(law))
    return (pollution, p) if polluted and pollution < p else (p, p)


def polluted(quantity: str, degree: int, facts: MethodFacts = MethodFacts(), law=None,
             switching: bool | None = None, pollution: float = np.inf) -> bool:
    """Whether :func:`order_range` widened the quantity's orders for
    pollution (a displacement, gap or penalty traction whose order
    exceeds ``pollution``), in a method whose error at the scale of its
    cells converges at that order (not a ``meshfree`` one's: EFGM's
    includes its quadrature's, which does not converge)."""
    p = theoretical_order(quantity, degree, facts, law, switching)
    return (quantity in DISPLACEMENT_LIKE and not (quantity in TRACTIONS and _exact(law)) and pollution < p
            and not facts.meshfree)


#: Bulk displacements: of the quantities whose orders pollution widens,
#: those that take the lower end of the range from two runs where Γ's
#: ends are singular points of an exponent not taken
#: (:func:`lower_end`).
BULK_DISPLACEMENTS = ("ux", "uy")


def lower_end(quantity: str, theory: tuple[float, float], unknown_ends: bool) -> bool:
    """Whether a two-run estimate takes the lower end of ``theory`` (the
    orders :func:`order_range` allows) instead of their balanced order: a
    bulk displacement (:data:`BULK_DISPLACEMENTS`) whose range pollution
    widened, on a scene whose straight Γ has ``unknown_ends``, ends under
    an exact law whose exponent
    :func:`~contactcore.estimate.singular.pollution_order` does not take
    (:func:`~contactcore.estimate.singular.exact_interface_ends`), or
    under penalty springs stiff at the coarse cells' scale, which end as
    bonded (:func:`~contactcore.estimate.singular.stiff_spring_ends`;
    grader28's tilted block on springs: fe P2's displacements 0.44-0.48
    of their error at the balanced order, 0.84-0.94 at the lower end).  Such an
    end may pollute below the lower end, so that end, not the balanced
    order, is the one the estimate can least afford to miss: on grader17's
    tilted blocks the degree-2 displacements converged at 0.78-1.09 and
    their estimates at the balanced 2.15 read 0.33-0.49 of the error,
    unwarned (docs/error-estimates.md, "Near singular points").  Gaps and
    tractions keep the balanced order: on the same runs they were
    overestimated (gaps 0.90-2.91 at the balanced order)."""
    return unknown_ends and quantity in BULK_DISPLACEMENTS and theory[0] < theory[1]


def smooth_range(quantity: str, degree: int, facts: MethodFacts = MethodFacts(), law=None,
                 switching: bool | None = None) -> tuple[float, float] | None:
    """The orders an exact law's traction on Γ takes from two runs at a
    sample far from every point where Γ's status changes
    (:func:`~contactcore.estimate.status.far_from_changes`): the
    :func:`order_range` of a law whose status never changes there,
    ``(degree, degree)``, or ``(1, 2)`` at degree 1 (module doc), where
    its upper end exceeds the switching law's 1; None for any other
    quantity or law, or where the law never switched (every sample is then
    far, and :func:`order_range` already gives it).  The solution's
    H^{5/2-ε} limit is local to the points where the status changes:
    between them it is as smooth as the data, and the pieces of a degree-2
    multiplier converged at 1.5-2.5 beyond two coarse cells of a change
    (:data:`~contactcore.tolerances.STATUS_CHANGE_CELLS`), a degree-1
    multiplier's at 0.0-3.2 (half of them 1.3-2.0)."""
    if quantity not in TRACTIONS or not _switches(law, switching):
        return None
    near = theoretical_order(quantity, degree, facts, law, switching)
    far = order_range(quantity, degree, facts, law, switching=False)
    return far if far[1] > near else None


def _switches(law, switching: bool | None) -> bool:
    """Whether an exact ``law``'s status may change along Γ: a law that
    switches (every exact law but ``bonded``) whose runs did not show one
    status only (``switching`` False: :func:`theoretical_order`)."""
    return _exact(law) and not law.is_linear and switching is not False


def _smooth_multiplier(quantity: str, law, switching: bool | None) -> bool:
    """Whether ``quantity`` is an exact law's traction on Γ (Nitsche's
    multiplier) where Γ's status never changes: read as a stress of the
    degree, with its superconvergence (module doc)."""
    return quantity in TRACTIONS and _exact(law) and not _switches(law, switching)


def _exact(law) -> bool:
    """Whether ``law`` is enforced exactly (:mod:`contactcore.exact`)."""
    return law is not None and getattr(law, "enforcement", "penalty") == "exact"
