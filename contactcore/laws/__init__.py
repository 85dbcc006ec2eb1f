"""Interface laws: jumps (and state) in, tractions and tangents out.

A law works in the local frame of Γ.  For ``m`` interface points it takes the
jumps ``g = [g_N, g_T]`` (shape ``(m, 2)``, ``g_N = [[u]]·n``,
``g_T = [[u]]·t``) and returns the tractions ``[t_N, t_T]`` (Pa) and the
tangent ``∂t/∂g`` (shape ``(m, 2, 2)``, Pa/m).  The traction acting on the +
body is ``τ⁺ = −(t_N n + t_T t)``; the − body receives ``−τ⁺`` (docs/scenes.md).

In a weak form the law contributes ``∫_Γ t(g(u)) · g(δu) dΓ`` to the
internal virtual work.  Laws are looked up by name in :data:`LAWS`; every
method calls the same code.

The contract of a law class (:class:`_Law`), checked when it is registered
(:func:`registry`) and again when a scene is made dimensionless
(:func:`law_contract`), so that a law missing a declaration is refused by
name rather than answered wrongly:

* ``parameters``: the names of its parameters, and ``dimensions``: the
  dimension of each (:data:`DIMENSIONS`).  :mod:`contactcore.scaling`
  makes every parameter dimensionless by its declared dimension and by
  nothing else: a gap ``g0`` (m) compared with a jump is a
  :data:`DISPLACEMENT`, scaled as the jumps are; undeclared, it would
  reach every method in the user's metres against dimensionless jumps.
  The response must be dimensionally consistent (the same formula in any
  consistent units), which every physical law is.
* ``homogeneous``: whether ``t(c·g) = c·t(g)`` for every ``c > 0`` at an
  untouched history (positively homogeneous of degree one), as
  ``linear``, ``unilateral`` and ``coulomb`` are and a law with a gap, a
  threshold or a cohesive strength is not.  Newton's cut-backs rely on it
  only where it is declared (:meth:`contactcore.newton.increments._Newton._from_rest`:
  from rest a smaller step is then the same problem scaled).
* ``unilateral`` (the law can open: no tension, ``t_N <= 0``) and
  ``frictional`` (a closed point may slip: its ``|t_T|`` is bounded by the
  law's :meth:`slip_bound`, Coulomb's ``μ max(−t_N, 0)`` or any other):
  the capabilities the health checks and refusals read
  (:mod:`contactcore.health`), never the law's name.
* a frictional law's ``slip_bound(t_N)``: the largest ``|t_T|`` a closed
  point carries at the normal traction ``t_N`` (an array in the scene's
  stress unit, made dimensionless as the law is), non-decreasing and
  concave in the pressure ``p = −t_N`` (so that Γ's resultant obeys
  ``|F_T| <= |Γ| slip_bound(−F_N/|Γ|)``, Jensen).  Everything that needs
  the bound asks the law for it, never for a parameter by name: the
  refusal before Newton of a load Γ cannot hold (:meth:`_Law.slides_off`,
  :func:`contactcore.health.beyond_cone`), the traction scale of
  :class:`Decision` (:meth:`_Law.decision_scales`), the rigid slide
  (:mod:`contactcore.slide`), a profile's slipping samples
  (:mod:`contactcore.profiles`), the exact form (:mod:`contactcore.exact`)
  and the layered closed form (verification/closed_forms.py).
* parameters beyond ``kN``, ``kT`` are read and checked by the class's
  :meth:`_Law.extra_parameters` (its exact form reads them through it too).

A new law is one class declaring these, registered in :data:`LAWS`
(:func:`register` for a law from outside the package), its row in
docs/scenes.md and a closed-form test: the checklist is docs/architecture.md,
"A new law".

One idea a module:

- :mod:`~contactcore.laws.response`: what a law answers (:class:`LawResponse`,
  the statuses :data:`OPEN`, :data:`STICK`, :data:`SLIP`, :data:`PARTIAL`)
  and :func:`secant_tangent`;
- :mod:`~contactcore.laws.contract`: the declarations above and their check
  (:data:`DIMENSIONS`, :data:`CAPABILITIES`, :func:`law_contract`,
  :func:`registry`, :func:`frictionless`);
- :mod:`~contactcore.laws.decision`: :class:`Decision`, Newton's status
  decision held against round-off;
- :mod:`~contactcore.laws.springs`: :class:`_Law`, what every penalty law
  shares (its parameters read and checked, its decision scales, its
  refusal of a load Γ cannot hold);
- :mod:`~contactcore.laws.linear`, :mod:`~contactcore.laws.unilateral`,
  :mod:`~contactcore.laws.coulomb`: one shipped law each
  (:class:`LinearLaw`, :class:`UnilateralLaw`, :class:`CoulombLaw`);
- :mod:`~contactcore.laws.registered`: :data:`LAWS`, :func:`register`,
  :func:`unregister`, :data:`InterfaceLaw`.

Their public names are imported here, as ``contactcore.laws.NAME``.  The
exact (Nitsche) forms of these laws are :mod:`contactcore.exact`'s.
"""
from .response import OPEN, PARTIAL, REPORTED_STATUS_NAMES, SLIP, STATUS_NAMES, STICK, LawResponse, secant_tangent
from .contract import (CAPABILITIES, DIMENSIONLESS, DIMENSIONS, DISPLACEMENT, LENGTH, STIFFNESS, STRESS,
                       frictionless, law_contract, registry)
from .decision import Decision
from .springs import _Law
from .linear import LinearLaw
from .unilateral import UnilateralLaw
from .coulomb import CoulombLaw
from .registered import LAWS, InterfaceLaw, register, unregister

__all__ = [
    "OPEN", "PARTIAL", "REPORTED_STATUS_NAMES", "SLIP", "STATUS_NAMES", "STICK", "LawResponse", "secant_tangent",
    "CAPABILITIES", "DIMENSIONLESS", "DIMENSIONS", "DISPLACEMENT", "LENGTH", "STIFFNESS", "STRESS", "frictionless",
    "law_contract", "registry", "Decision", "_Law", "LinearLaw", "UnilateralLaw", "CoulombLaw", "LAWS",
    "InterfaceLaw", "register", "unregister",
]
