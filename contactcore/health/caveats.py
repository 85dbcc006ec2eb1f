"""Warnings on an answer found: where the method or the problem may make it
off, or one of several.

- Volumetric locking: plane strain with ν at or above NU_LOCKING_WARN, where
  every method here (displacement-based) may lock (:func:`_locking_warnings`);
  fe P1's exactly enforced Γ traction from NU_LOCKING_WARN_FE_P1_EXACT on
  (:func:`traction_locking_warnings`).
- Friction across two materials: Dundurs' second parameter
  (J. Appl. Mech. 1969)

      β = [G₋(κ₊ − 1) − G₊(κ₋ − 1)] / [G₋(κ₊ + 1) + G₊(κ₋ + 1)],

  ``G = E / 2(1 + ν)``, ``κ = 3 − 4ν`` (plane strain) or ``(3 − ν)/(1 + ν)``
  (plane stress), couples slip and the normal gap; beyond
  ``μ|β| > MU_DUNDURS_WARN`` (μ the slope of the law's slip bound in the
  pressure, :func:`bound_slope`: Coulomb's μ, a threshold's 0) the answer
  may be one of several (:func:`dundurs_beta`, :func:`dundurs_warnings`).
- Points a converged path holds at stick with ``|t_T|`` beyond the law's
  slip bound (Coulomb's ``μ|t_N|``) by more than the traction's round-off
  (:func:`friction_excess_warnings`), and springs so stiff that this
  round-off exceeds the stick/slip band's whole excess
  (:func:`spring_band_warnings`).
- A frictional hinge: Γ pressed yet closed over a few points that hold by
  friction more shear than the pressure, a body tipped onto a corner of Γ
  (:func:`hinge_warnings`): one answer of several at μ > 1, whatever β.
- Slip beyond small sliding: a tangential jump above LARGE_SLIP_SHARE of
  Γ's size (:func:`large_slip_warnings`).
- Points a converged path holds closed in tension, ``t_N > 0`` beyond
  Newton's closed/open band in traction plus round-off
  (:func:`closed_tension_warnings`).

:func:`material_warnings` gathers the first two, asked of the scene before
Newton; the last two read the path after it.
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol
from ..geometry import CircleInterface
from ..laws import OPEN, STICK
from ..scaling import softer_stress


def material_warnings(scene) -> list[str]:
    """Volumetric locking: plane strain with ν at or above NU_LOCKING_WARN, in
    one warning that names every such body; and friction across two
    materials beyond the uniqueness bound (:func:`dundurs_warnings`)."""
    return _locking_warnings(scene) + dundurs_warnings(scene)


def dundurs_beta(scene) -> float:
    """Dundurs' second parameter β of the two bodies (J. Appl. Mech. 1969),
    ``[G₋(κ₊ − 1) − G₊(κ₋ − 1)] / [G₋(κ₊ + 1) + G₊(κ₋ + 1)]`` with
    ``G = E / 2(1 + ν)`` and ``κ = 3 − 4ν`` (plane strain) or
    ``(3 − ν)/(1 + ν)`` (plane stress): how far shear across Γ moves its
    normal gap (0 for equal materials, up to ±1/2 in plane strain)."""
    G, kappa = [], []
    for body in ("minus", "plus"):
        m = scene.materials[body]
        G.append(m.E / (2 * (1 + m.nu)))
        kappa.append(3 - 4 * m.nu if scene.plane == "strain" else (3 - m.nu) / (1 + m.nu))
    return (G[0] * (kappa[1] - 1) - G[1] * (kappa[0] - 1)) / (G[0] * (kappa[1] + 1) + G[1] * (kappa[0] + 1))


def pressure_scale(scene, h: float | None = None) -> float:
    """The pressure at which the scene's warnings ask the law's slip bound
    ``b(p)`` (``slip_bound(−p)``), from the scene's inputs alone (never the
    answer's, whose round-off would then decide): 1 for a homogeneous law,
    whose bound is ``b(1)·p`` so that every pressure gives the same
    ``b(p)/p`` and 1 gives Coulomb's μ to the bit; for another (a
    threshold, whose bound does not scale with p) the scene's stress scale
    :func:`contactcore.scaling.softer_stress` (its largest load, or the
    stress a prescribed displacement causes in the softer body), the
    pressure its loads put on Γ.  0 where nothing loads the scene."""
    return 1.0 if scene.law.homogeneous else float(softer_stress(scene, h))


def _bound(law, p: float) -> float:
    """The law's slip bound at the pressure ``p`` (``slip_bound(−p)``)."""
    return float(np.asarray(law.slip_bound(np.array([-p])), float).reshape(-1)[0])


def bound_slope(scene) -> float:
    """How the law's slip bound grows with the pressure, ``d b/d(−t_N)``,
    from its ``slip_bound`` on the scene's inputs: its mean slope
    ``(b(P) − b(0))/P`` over the pressures ``[0, P]``, ``P`` the scene's
    :func:`pressure_scale` (Coulomb: μ exactly; a threshold: 0; a bound
    concave in p, as the law contract asks, is steeper below P and flatter
    above it).  0 for a law that is not frictional or a scene with no load."""
    if not scene.law.frictional:
        return 0.0
    P = pressure_scale(scene)
    if not P > 0:
        return 0.0
    return (_bound(scene.law, P) - _bound(scene.law, 0.0)) / P


def dundurs_warnings(scene) -> list[str]:
    """A frictional law whose slip bound's slope in the pressure
    (:func:`bound_slope`, Coulomb's μ) times Dundurs' |β|
    (:func:`dundurs_beta`) exceeds MU_DUNDURS_WARN: the answer may be one
    of several, which one the method's (tolerances.py's note).  A bound
    that does not grow with the pressure (a threshold) couples no slip to
    the normal gap: no warning, whatever β.  Decided on the scene's inputs
    alone."""
    slope = bound_slope(scene)
    if not slope:
        return []
    beta = dundurs_beta(scene)
    if slope * abs(beta) <= tol.MU_DUNDURS_WARN:
        return []
    mu = getattr(scene.law, "mu", None)
    if mu is not None and slope == mu:  # Coulomb's words (its slope is μ to the bit)
        named, product, friction, seen, lower = f"mu = {mu:g}", "μ|β|", "Coulomb friction", "", "μ"
    else:
        named, product, friction, seen, lower = (
            f"the '{scene.law.name}' law's slip bound grows with the pressure by {slope:.3g} (its mean slope "
            "d(slip bound)/d(−t_N) up to the scene's stress scale)", "slope·|β|", "friction", "as Coulomb's μ|β|: ",
            "the bound's slope")
    return [f"{named} across two materials of Dundurs' β = {beta:.3g}: {product} = {slope * abs(beta):.3g} is above "
            f"{tol.MU_DUNDURS_WARN:g}, where slip and the normal gap are coupled strongly enough for {friction} "
            f"to have several answers ({seen}a layered block of contrast 1e3 at μ|β| = 1 to 5: fe, xfem and "
            "efgm held Γ closed or opened up to 20 of 24 points under pressure, tractions up to 164 p apart); "
            f"the answer given is one of them, the method's: compare methods, or lower {lower} "
            f"(below {tol.MU_DUNDURS_WARN / abs(beta):.3g} here) or the materials' contrast "
            "(docs/contact-enforcement.md, \"Known limits\")"]


def _carried(path) -> float:
    """The largest pressure Γ carries along ``path``: the scale of a
    traction's round-off (at a load back to zero the step's own pressure
    is round-off)."""
    return max((float(np.max(-np.asarray(s.traction, float).reshape(-1, 2)[:, 0], initial=0.0))
                for s in path.steps), default=0.0)


def _tally(path, offending) -> tuple[int, float, float | None]:
    """Over ``path``'s steps: how many (point, increment) pairs
    ``offending(t, status)`` flags, the largest share it gives them and
    that increment.  ``offending`` takes a step's tractions (m, 2) and
    statuses and returns the flagged points and each point's share."""
    count, worst, where = 0, 0.0, None
    for step in path.steps:
        held, share = offending(np.asarray(step.traction, float).reshape(-1, 2), np.asarray(step.status))
        if np.any(held):
            count += int(np.count_nonzero(held))
            if float(np.max(share[held])) > worst:
                worst, where = float(np.max(share[held])), step.step
    return count, worst, where


def spring_alpha(scene, h: float | None) -> float:
    """The larger ``α = k h / E₋`` of a penalty law's springs (E₋ the softer
    body's modulus, ``h`` the method's spacing); 0 for a law without
    springs (enforced exactly) or without ``h``."""
    if h is None or not hasattr(scene.law, "kN"):
        return 0.0
    return max(scene.law.kN, scene.law.kT) * h / scene.softer_modulus


def friction_excess_warnings(scene, path, stress_size: float = 0.0, h: float | None = None) -> list[str]:
    """Points a converged ``path`` (an
    :class:`~contactcore.interface_path.InterfacePath`) holds at stick with
    ``|t_T|`` beyond the law's ``slip_bound(t_N)`` (Coulomb's ``μ|t_N|``) by more than the traction's round-off
    (``STICK_ROUNDOFF`` of μp, or ``TRACTION_ROUNDOFF`` of the largest
    pressure along the path or of the scene's ``stress_size``, whichever is
    larger: on a Γ the loads leave unloaded every traction is round-off of
    the loads elsewhere, grader10 F2; for penalty springs at spacing ``h``,
    at least ``SPRING_TRACTION_ROUNDOFF·α`` of that pressure,
    :func:`spring_alpha`: a stiff spring's traction carries its jump's
    round-off times k, grader11 #5): Newton's stick/slip band (DECISION_BAND of Γ's
    largest μp) keeps a point's previous status within it, so a load whose
    shear/normal lies within 1e-5 of μ (above it: no sticking equilibrium)
    may come back sticking; and at a load back to zero the rest window
    (REST_ROUNDOFF) may hold a small real shear (docs/newton.md, "A small
    μ").  One warning naming how many (point, increment) pairs, the
    largest excess over μ|t_N| (or over the path's largest μp, where the
    point's is smaller) and its increment."""
    if not scene.law.frictional or path is None:
        return []
    carried = _carried(path)
    spring_roundoff = tol.SPRING_TRACTION_ROUNDOFF * spring_alpha(scene, h)
    bound = scene.law.slip_bound  # Coulomb's μ max(−t_N, 0), or the law's own
    largest = float(bound(np.array([-carried]))[0])

    def excess(t, status):
        limit = bound(t[:, 0])
        allowed = np.maximum(tol.STICK_ROUNDOFF * limit,
                             max(tol.TRACTION_ROUNDOFF * max(carried, stress_size), spring_roundoff * carried))
        over = np.abs(t[:, 1]) - limit
        return (status == STICK) & (over > allowed), over / np.maximum(limit, max(largest, np.finfo(float).tiny))

    count, worst, where = _tally(path, excess)
    blind = spring_band_warnings(scene, h)
    if not count:
        return blind
    mu = getattr(scene.law, "mu", None)
    if mu is not None:  # Coulomb's words
        named, of, largest_bound, ask, larger = (f"μ|t_N| = {mu:g}|t_N|", "μ|t_N|", "μp", "a shear/normal within that "
                                                 "band of μ", "a μ that much larger")
    else:
        named, of, largest_bound, ask, larger = ("the law's slip bound", "it", "slip bound", "a shear within that band "
                                                 "of the bound", "a bound that much larger")
    return blind + [
        f"Γ's points stick with |t_T| above {named} at {count} (point, increment) pair(s), by up to "
        f"{worst:.2g} of {of} (of its largest along the path where the point's is smaller; increment "
        f"{where:g}): Newton keeps a point's status within {tol.DECISION_BAND:g} of Γ's largest {largest_bound} "
        "(DECISION_BAND, above the round-off of its margins) and holds a point at rest where Γ is unloaded "
        f"(REST_ROUNDOFF), so the loads there ask {ask} or above it, where no "
        "sticking equilibrium exists, or leave a shear an unloaded Γ does not tell from round-off; "
        f"{larger} sticks (docs/newton.md, \"Decisions that round-off cannot move\")"]


def spring_band_warnings(scene, h: float | None) -> list[str]:
    """Penalty springs so stiff that their tractions' round-off
    (``SPRING_TRACTION_ROUNDOFF·α`` of Γ's largest pressure p,
    :func:`spring_alpha`) exceeds Newton's stick/slip band: DECISION_BAND
    of its traction scale, the largest slip bound of a closed point or
    TRACTION_ROUNDOFF·p if larger (:meth:`contactcore.laws.Decision.reduced`),
    ``max(b(p), TRACTION_ROUNDOFF·p)`` for a bound ``b`` non-decreasing in
    p (Coulomb's ``DECISION_BAND·μ`` of p).  :func:`friction_excess_warnings`
    then allows more than the band's whole excess, and a point held at
    stick above its slip bound by the band cannot be told from round-off.
    One line saying so, decided on the scene's inputs and ``h`` alone (never
    on the answer's round-off): both sides are shares of p, taken at the
    scene's :func:`pressure_scale` (a homogeneous law's ``b(p)/p`` is the
    same at every p, Coulomb's μ; a threshold's ``τ_c/P`` at the scene's
    stress scale P, so its springs are warned of where that load's
    round-off exceeds ``DECISION_BAND·τ_c``).  None for a zero bound
    (frictionless: nothing sticks by a band).  Measured (review5's fault
    4, layered closed form pushed 3e-6 past its slip limit, fe P1): the
    band's excess, 3.3e-6 of μp, is warned at α = 1e8 and silent at 1e9
    and 1e10, where the closed form exactly at the limit sticks up to
    3.8e-6 and 5.6e-6 of μp above it from round-off alone.  α within
    LIMIT_ROUNDOFF of the limit counts as at it (α in the user's units
    and in the solve's dimensionless ones differ in the last bits: review6
    #6, 20 of 200 h warned in one and not the other at α = 3e8 exactly)."""
    alpha = spring_alpha(scene, h)
    if not scene.law.frictional or not alpha:
        return []
    P = pressure_scale(scene, h)
    share = _bound(scene.law, P) / P if P > 0 else 0.0  # b(P)/P: Coulomb's μ
    if not share:  # a zero bound, or no load: no band to tell apart
        return []
    share = max(share, tol.TRACTION_ROUNDOFF)  # Newton's traction scale is at least TRACTION_ROUNDOFF·p
    limit = tol.DECISION_BAND * share / tol.SPRING_TRACTION_ROUNDOFF
    if alpha <= limit * (1 + tol.LIMIT_ROUNDOFF):
        return []
    mu = getattr(scene.law, "mu", None)
    if mu is not None and share == mu:  # Coulomb's words (its share is μ to the bit)
        return [f"penalty springs at α = k h/E₋ = {alpha:.2g} with μ = {mu:g}: their tractions' round-off "
                f"(SPRING_TRACTION_ROUNDOFF·α = {tol.SPRING_TRACTION_ROUNDOFF * alpha:.2g} of Γ's largest pressure) "
                f"exceeds Newton's stick/slip band (DECISION_BAND·μ = {tol.DECISION_BAND * mu:.2g} of it), so a point "
                "held at stick above μ|t_N| within that band cannot be told from round-off and is not reported; "
                f"springs with α at most {limit:.2g}, or "
                "enforcement = \"exact\", tell it apart (docs/newton.md, \"Decisions that round-off cannot move\")"]
    return [f"penalty springs at α = k h/E₋ = {alpha:.2g} with the '{scene.law.name}' law's slip bound at "
            f"{share:.2g} of the pressure (at the scene's stress scale: its largest load or prescribed stress): "
            f"their tractions' round-off (SPRING_TRACTION_ROUNDOFF·α = {tol.SPRING_TRACTION_ROUNDOFF * alpha:.2g} "
            "of Γ's largest pressure) exceeds Newton's stick/slip band (DECISION_BAND of Γ's largest slip bound, "
            f"{tol.DECISION_BAND * share:.2g} of that pressure), so a point held at stick above its slip bound "
            f"within that band cannot be told from round-off and is not reported; springs with α at most "
            f"{limit:.2g}, or enforcement = \"exact\", tell it apart (docs/newton.md, \"Decisions that round-off "
            "cannot move\")"]


def closed_tension_warnings(scene, path, stress_size: float = 0.0) -> list[str]:
    """Points a converged ``path`` (an
    :class:`~contactcore.interface_path.InterfacePath`) holds closed
    (``stick`` or ``slip``) with a tension ``t_N > 0`` beyond Newton's
    closed/open band in traction (DECISION_BAND of the largest pressure
    along the path) plus the traction's round-off (TRACTION_ROUNDOFF of
    Γ's largest traction along the path, normal or tangential, or of the
    scene's ``stress_size`` (:func:`contactcore.scaling.softer_stress`)
    if larger: on a Γ in pure shear every t_N is round-off of the shear,
    and on a Γ the loads leave unloaded, of the loads elsewhere).
    ``t_N`` is the law's traction at the point, the one its status was
    decided on (exact laws: ``γ min(y_N, 0)`` at the augmented jump, which
    is never positive where the status follows its sign), so such a point
    contradicts the law: an exact law's band is in traction
    (:meth:`contactcore.laws.Decision.in_traction`), a penalty law's is
    DECISION_BAND of Γ's largest |g_N|, which an open gap can make
    ``k_N`` times a tension of that size.  One warning naming how many
    (point, increment) pairs, the largest tension as a share of the path's
    largest pressure and its increment; none for a law without statuses
    (linear, bonded)."""
    if path is None or not scene.law.unilateral:
        return []
    carried = _carried(path)
    # the traction's round-off is relative to Γ's largest traction, shear
    # included: a Γ in pure shear carries no pressure, and its t_N of
    # round-off (1e-14 of the shear) is no tension
    largest = max((float(np.max(np.abs(np.asarray(s.traction, float)), initial=0.0)) for s in path.steps),
                  default=0.0)
    # and a Γ no load reaches has every traction of round-off of the loads
    allowed = tol.DECISION_BAND * carried + tol.TRACTION_ROUNDOFF * max(carried, largest, stress_size)
    count, worst, where = _tally(path, lambda t, status: ((status != OPEN) & (t[:, 0] > allowed),
                                                         t[:, 0] / max(carried, np.finfo(float).tiny)))
    if not count:
        return []
    return [f"Γ's points are closed in tension (t_N > 0) at {count} (point, increment) pair(s), up to {worst:.2g} "
            f"of the largest pressure along the path (increment {where:g}), where the law closes a point only "
            f"under pressure: Newton kept their status within its round-off band (DECISION_BAND = "
            f"{tol.DECISION_BAND:g} of Γ's largest gap for a penalty law, which an open gap sets; of the largest "
            "pressure, in traction, for an exact one), so these points' tractions are not the law's; refine h, "
            "or for springs compare with enforcement = \"exact\" (docs/contact-enforcement.md, \"The closed/open "
            "band is in traction\")"]


def traction_locking_warnings(scene, degree: int) -> list[str]:
    """fe P1 with an exactly enforced law in plane strain, a body's ν at or
    above NU_LOCKING_WARN_FE_P1_EXACT but below NU_LOCKING_WARN (which
    :func:`material_warnings` warns of for every method): Γ's traction
    σ(u)·n carries λ div u of the P1 field and locks first (the constant's
    measurement).  One line naming the bodies; none for other degrees,
    penalty laws or plane stress.  Asked by the method whose Γ traction
    this is, fe (:meth:`xdolfinx.options.FE.spacing_warnings`), not of
    another's."""
    if (degree != 1 or scene.plane != "strain"
            or getattr(scene.law, "enforcement", None) != "exact"):
        return []
    high = [(body, m.nu) for body, m in scene.materials.items()
            if tol.NU_LOCKING_WARN_FE_P1_EXACT <= m.nu < tol.NU_LOCKING_WARN]
    if not high:
        return []
    named = _named_nu(high)
    return [f"{named} in plane strain, at or above {tol.NU_LOCKING_WARN_FE_P1_EXACT:g}: fe P1's exactly enforced "
            "Γ traction is σ(u)·n of the P1 field, which carries λ div u and locks (a twisted rod of fixed shear "
            "moduli, whose exact t_T does not depend on ν: fe P1's error on Γ 3.3 times its ν = 0.3 value at "
            "ν = 0.44, 17 times at 0.49, h = 0.025); use degree = 2 (within 2.4–4.5 times at 0.49)"]


def _named_nu(high) -> str:
    """The bodies ``(name, ν)`` of ``high`` named with ν and ``λ/μ = 2ν/(1 − 2ν)``."""
    return " and ".join(f"materials.{body}.nu = {nu:.10g} (λ/μ = {2 * nu / (1 - 2 * nu):.1e})" for body, nu in high)


def _locking_warnings(scene) -> list[str]:
    """Volumetric locking: plane strain with ν at or above NU_LOCKING_WARN."""
    if scene.plane != "strain":
        return []
    high = [(body, m.nu) for body, m in scene.materials.items() if m.nu >= tol.NU_LOCKING_WARN]
    if not high:
        return []
    named = _named_nu(high)
    return [f"{named} in plane strain, at or above {tol.NU_LOCKING_WARN:g}: every method here is displacement-based and "
            "may lock volumetrically, its stresses off by tens of percent or more, degree 1 the most but degree 2 "
            "too (scene A at ν = 0.4999, h = 0.05: the upper block's moment from σyy on Γ 18 % off in fe P2, 180 % "
            "in xfem P2, 120 % in EFGM's quadratic basis); Γ's tractions come from the same fields and may be off "
            "as much (fe P1's t_N on a uniformly pressed Γ at ν = 0.499 ranged over 0.01–2.8 times the pressure)"]


def large_slip_warnings(scene, path, displacement_unit: float = 1.0) -> list[str]:
    """A converged ``path`` (an
    :class:`~contactcore.interface_path.InterfacePath`) whose tangential
    jump |g_T| somewhere exceeds ``LARGE_SLIP_SHARE`` of Γ's size: the
    radius of a circular Γ (a slip s turns the normal by s/R), else Γ's
    length (the sum of its quadrature weights; a slip s leaves s of it
    facing nothing).  Every method pairs Γ's two sides where they started
    (small sliding, as small strain, docs/scenes.md), so beyond that share
    the pairing, and the answer there, is not the physical one however
    well it solves its equations.  ``displacement_unit`` turns the path's
    jumps into its lengths' unit (U/L on a dimensionless scene,
    :mod:`contactcore.scaling`).  One line naming the share and its
    increment."""
    if path is None or not path.steps or not len(path.weights):
        return []
    size = (scene.interface.radius if isinstance(scene.interface, CircleInterface)
            else float(np.sum(path.weights)))
    if not size > 0:
        return []
    worst, where = 0.0, None
    for step in path.steps:
        slip = displacement_unit * float(np.max(np.abs(np.asarray(step.jump, float).reshape(-1, 2)[:, 1]),
                                                initial=0.0)) / size
        if slip > worst:
            worst, where = slip, step.step
    if not worst > tol.LARGE_SLIP_SHARE * (1 + tol.LIMIT_ROUNDOFF):  # at the share within round-off: not above it
        return []
    what = "Γ's radius" if isinstance(scene.interface, CircleInterface) else "Γ's length"
    return [f"Γ slips by up to {worst:.3g} of {what} (increment {where:g}), above {tol.LARGE_SLIP_SHARE:g}: every "
            "method is geometrically linear and pairs Γ's two sides where they started (small sliding, as small "
            "strain), so a point that slid that far is still paired with its first partner, and the part of Γ "
            "that has slid past the other body's end still carries traction: the answer solves the model, not "
            "the physical problem, there (docs/scenes.md, \"Small strain and small sliding\")"]


def hinge_warnings(scene, path, stress_size: float = 0.0, h: float | None = None) -> list[str]:
    """A converged Coulomb ``path`` (an
    :class:`~contactcore.interface_path.InterfacePath`) with an increment at
    which Γ is pressed (its normal resultant ``N = −∫ t_N ds`` positive
    beyond TRACTION_ROUNDOFF of Γ's largest traction along the path, or of
    the scene's ``stress_size`` if larger (on a Γ the loads leave unloaded
    every traction is round-off, :func:`closed_tension_warnings`), times
    its length) yet closed over less than HINGE_CLOSED_SHARE of its length
    (or, on a mesh of spacing ``h`` so coarse that a tenth of Γ is less
    than HINGE_CLOSED_CELLS cells, that many cells' share: a hinge is one
    point, which the method spreads over the cell around it; review7 #1:
    fe P1 at h = 0.5 tipped onto 2 of 6 points, share 0.28, unwarned),
    while its closed points hold by friction a shear resultant
    ``T = ∫ |t_T| ds`` above HINGE_SHEAR_RATIO·N: a body tipped onto a
    frictional hinge, which may be one answer of several (tolerances.py's note).  One
    line naming the first such increment, its closed share and T/N; none
    for another law."""
    mu = getattr(scene.law, "mu", None)
    if path is None or not scene.law.frictional or not mu or not len(path.weights):
        return []
    w = np.asarray(path.weights, float)
    length = float(np.sum(w))
    largest = max((float(np.max(np.abs(np.asarray(s.traction, float)), initial=0.0)) for s in path.steps),
                  default=0.0)
    bound = max(tol.HINGE_CLOSED_SHARE, tol.HINGE_CLOSED_CELLS * h / length if h else 0.0)
    count, first = 0, None
    for step in path.steps:
        t = np.asarray(step.traction, float).reshape(-1, 2)
        closed = np.asarray(step.status) != OPEN
        pressed = float(-(w @ t[:, 0]))
        share = float(np.sum(w[closed])) / length
        shear = float(w[closed] @ np.abs(t[closed, 1]))
        if (np.any(closed) and pressed > tol.TRACTION_ROUNDOFF * max(largest, stress_size) * length
                and share < bound and shear > tol.HINGE_SHEAR_RATIO * pressed):
            count += 1
            if first is None:
                first = (step.step, share, shear / pressed)
    if not count:
        return []
    step, share, ratio = first
    return [f"from increment {step:g} ({count} increment(s)) Γ is pressed yet closed over only {share:.2g} of its "
            f"length, its few closed points holding by friction (μ = {mu:g}) a shear {ratio:.3g} times the "
            "pressure's resultant: a body has tipped onto a corner of Γ and turns about it instead of sliding. "
            "That is an equilibrium, but not the only one: Coulomb friction above 1 lets the same loads be held "
            "with Γ closed and slipping too, whatever Dundurs' β, so the answer given may be one of several, the "
            "one the method's path found (grader13's shear block of equal layers tipped at μ = 300 and 1000 "
            "in every method; at 100 fe stayed closed, xfem P2 tipped); do not take it as the answer: lower μ, or compare "
            "methods and load paths (docs/contact-enforcement.md, \"Known limits\")"]
