"""What the law's springs and the materials leave a solve: refusals before
it, hints after it failed.

A spring ``k`` on Γ adds entries ``k w`` (``w`` a quadrature weight) to
rows that carry the bulk's ``~E``; in double precision those rows keep the
bulk's share only while ``k w / E`` stays below ``SPRING_ENTRY_MAX``
(:func:`check_springs`, refused before any solve), and a body held by
springs far below ``E/h`` is nearly free (:func:`failure_hint`, named after
a solve failed).  A nearly incompressible material in plane strain carries
``λ/μ = 2ν/(1 − 2ν)`` in its bulk rows, and a solve loses about
log10(λ/μ) digits (:func:`material_cause`; Hughes 2000, §4.1); a softer
body whose modulus lies ``CONTRAST_CAUSE`` or less of the stiffer's loses
as many to the stiffer's rows (:func:`contrast_cause`).  A penalty
Coulomb spring above a method's limit of ``α = k h / E`` makes its
tractions oscillate from point to point (:func:`check_friction_springs`,
the limits measured in contactcore.tolerances, EFGM_FRICTION_SPRINGS).
Springs are named in the scene's units (:func:`spring_unit`).
"""
from __future__ import annotations

import numpy as np

from .. import tolerances as tol
from ..errors import SolverError
from ..labels import run_label
from ..scaling import Scales


def failure_hint(scene, weights) -> str:
    """Why a solve may fail, naming the springs (their entries ``k w``
    against the stiffer modulus ``E``: round-off in the spring rows grows as
    eps·k w/E; a body held by springs far below E/h is nearly free)."""
    E = max(m.E for m in scene.materials.values())
    w = float(np.max(weights)) if len(weights) else 0.0
    out, unit = [], spring_unit(scene)
    for c, k, k_user in _springs(scene):
        ratio = k * w / E
        if ratio > 1 / tol.SPRING_HINT_RANGE:
            out.append(f"interface.law.k{c} = {k_user:.3g} {unit} is too stiff: k w = {ratio:.1e} E, its round-off "
                       f"(~2e-16 k w/E) swamps the bulk — soften it")
        elif ratio < tol.SPRING_HINT_RANGE:
            out.append(f"interface.law.k{c} = {k_user:.3g} {unit} is very soft: k w = {ratio:.1e} E, a body held by it "
                       "is nearly free — stiffen it or add a support")
    return "; ".join(out) or "a rigid-body mode may be nearly free"


def contrast_cause(scene) -> str:
    """The two bodies' moduli ``CONTRAST_CAUSE`` or further apart, named
    with their ratio: the softer body's rows lie that far below the
    stiffer's, whose round-off (~2e-16 of them) a solve then carries into
    the softer body's answer; "" if they are closer."""
    materials = scene.user.materials
    soft, stiff = sorted(materials, key=lambda body: materials[body].E)
    ratio = materials[soft].E / materials[stiff].E
    if ratio > tol.CONTRAST_CAUSE:
        return ""
    unit = scene.user.units.stress
    return (f"materials.{soft}.E = {materials[soft].E:.3g} {unit} is {ratio:.1e} of materials.{stiff}.E = "
            f"{materials[stiff].E:.3g} {unit} (at or below {tol.CONTRAST_CAUSE:g}), and the solve keeps too few digits "
            "of the softer body")


def material_cause(scene) -> str:
    """A nearly incompressible material in plane strain (ν at or above
    NU_LOCKING_WARN), named with ``λ/μ = 2ν/(1 − 2ν)``: the bulk rows
    carry λ, the shear rows μ, and a solve loses about log10(λ/μ) digits
    to round-off (Hughes 2000, §4.1); "" if none."""
    if scene.plane != "strain":
        return ""
    bad = [(body, m.nu) for body, m in scene.user.materials.items() if m.nu >= tol.NU_LOCKING_WARN]
    if not bad:
        return ""
    nu = max(v for _, v in bad)
    names = " and ".join(f"materials.{body}.nu" for body, _ in bad)
    return (f"{names} = {nu:.10g} in plane strain: λ/μ = {2 * nu / (1 - 2 * nu):.1e}, nearly incompressible, "
            "and the solve keeps too few digits")


def check_springs(scene, weights) -> None:
    """Refuse springs whose entries ``k w`` (w the largest quadrature weight
    on Γ) exceed ``SPRING_ENTRY_MAX·E``: the bulk stiffness (~E) added to
    those rows keeps fewer digits than the residual policy asks for, so the
    matrix itself is wrong (t_N = k g_N loses the bulk's share) and no
    residual of it can tell."""
    E = max(m.E for m in scene.materials.values())
    w = float(np.max(weights)) if len(weights) else 0.0
    for c, k, k_user in _springs(scene):
        if k * w > tol.SPRING_ENTRY_MAX * E:
            unit = spring_unit(scene)
            raise SolverError(f"interface.law.k{c}: {k_user:.3g} {unit} is too stiff for double precision here: its "
                              f"entries k w = {k * w / E:.1e} E exceed {tol.SPRING_ENTRY_MAX:.1e} E, beyond which "
                              f"the bulk stiffness in the interface rows is lost to round-off (no accurate solve "
                              f"exists); use k_{c} <= {tol.SPRING_ENTRY_MAX * E / w * k_user / k:.2e} {unit}")


def check_friction_springs(scene, h: float, limits: dict, method: str) -> None:
    """Refuse a penalty Coulomb law whose spring ``k_c`` (c = N, T)
    exceeds ``limits[c]`` times the softer body's ``E/h`` (``α = k_c h /
    E``): ``method``'s tractions at Γ's points oscillate there, and its
    stick/slip decisions with them (the measurements are in
    contactcore.tolerances, EFGM_FRICTION_SPRINGS).  Springs at the limit
    to round-off (``α`` is formed from the scene made dimensionless) are
    carried, and the largest spring the message offers is rounded down, so
    that it is carried too."""
    if not getattr(scene.law, "frictional", False) or not hasattr(scene.law, "kN"):
        return
    for c, k, k_user in _springs(scene):
        alpha, limit = k * h / scene.softer_modulus, limits[c]
        if alpha > limit * (1 + tol.LIMIT_ROUNDOFF):
            h_user, unit = h * Scales.of(scene.user).length, spring_unit(scene)
            raise SolverError(f"interface.law.k{c}: {k_user:.3g} {unit} is {alpha:.1e} times the softer body's E/h "
                              f"(h = {h_user:.3g}, {method}'s spacing), above the {limit:.0e} {method} carries for "
                              f"k_{c} under Coulomb friction: its tractions at Γ's points oscillate from point to "
                              f"point and the stick/slip decisions follow the oscillation; use k_{c} <= "
                              f"{_rounded_down(k_user * limit / alpha):.2e} {unit}, a spacing h <= "
                              f"{_rounded_down(h_user * limit / alpha):.2e} {scene.user.units.length}, or fe or xfem")


def stiff_spring_warnings(scene, h: float, limit: float, method: str, degree: int) -> list[str]:
    """A penalty law of any kind (``linear``, ``unilateral``, ``coulomb``)
    whose larger spring exceeds ``limit`` times the softer body's ``E/h``
    (``α = k h / E``, ``h`` the method's spacing): ``method``'s tractions
    at Γ's points and in the profiles oscillate from point to point by
    about α times the jump's discretisation error, beyond the accuracy its
    docs state (efgm: EFGM_SPRING_WARN, measured on grader15's uniform-
    stress closed form).  Decided on the inputs and ``h`` alone, round-off
    in ``α`` within LIMIT_ROUNDOFF of the limit carried."""
    if not hasattr(scene.law, "kN"):
        return []
    stiff = [(c, k * h / scene.softer_modulus) for c, k, _ in _springs(scene)]
    stiff = [(c, a) for c, a in stiff if a > limit * (1 + tol.LIMIT_ROUNDOFF)]
    if not stiff:
        return []
    named = " and ".join(f"k_{c} h/E = {a:.2g}" for c, a in stiff)
    return [f"interface springs of {named} (E the softer body's, h = {method}'s spacing) above the {limit:g} "
            f"{run_label(method, degree)} carries to about 1e-3 of the stress: its tractions on Γ oscillate from point to "
            f"point by about α times its jump error (measured on a uniform stress across a straight Γ: 8 % of the "
            f"stress at α = 1e3 for P1, 1.2 % for P2; docs/methods/efgm.md, \"Limits\"); soften the springs, "
            f"refine, enforce the law exactly, or use fe or xfem"]


def _rounded_down(x: float, digits: int = 3) -> float:
    """``x > 0`` rounded down to ``digits`` significant digits (a limit
    quoted so that the quoted value stays within it), its round-off
    within :data:`~contactcore.tolerances.LIMIT_ROUNDOFF` rounded up."""
    unit = 10.0 ** (np.floor(np.log10(x)) - digits + 1)
    return float(np.floor(x / unit * (1 + tol.LIMIT_ROUNDOFF)) * unit)


def _springs(scene):
    """``(component, k, k in the user's units)`` of the law's springs (none
    for a law enforced exactly)."""
    if not hasattr(scene.law, "kN"):
        return ()
    user = scene.user.law
    return (("N", scene.law.kN, user.kN), ("T", scene.law.kT, user.kT))


def spring_unit(scene) -> str:
    """The unit a spring is named in: the scene's stress over its length
    (:class:`contactcore.scene.Units`, labels only)."""
    units = scene.user.units
    return f"{units.stress}/{units.length}"
