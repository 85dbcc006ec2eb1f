"""One health policy for every solve of every method.

A solve of ``A x = b`` succeeds only if the *relative residual* of the
equations actually solved (the free block) is small:

    ρ = ‖b − A x‖∞ / max(‖b‖∞, F) <= RESIDUAL_FAIL,

``F`` the internal-force scale of a Newton iteration (0 for a plain linear
solve).  The normwise backward error ``‖b − A x‖/(‖A‖‖x‖ + ‖b‖)`` is
reported beside it, never instead: for a (nearly) singular ``A`` a huge
``x`` makes it tiny while ``ρ`` stays O(1).

Before any solve, :func:`check_springs` refuses springs so stiff that the
bulk is lost in their rows, and :func:`check_restraint` asks whether the supports, pins
and interface springs remove the six rigid-body modes of the two bodies; a
mode held by less than ``RIGID_MODE_FREE·E`` (springs lost in round-off, a
missing support) is refused with the body and the missing support named.
During Newton, :func:`lets_go` asks the same of each status map's closed
points (a body that Γ has let go makes the tangent singular), and
:func:`check_held` refuses a converged answer that leaves a body free:
its position is not determined.
:func:`material_warnings` warns about volumetric locking near ν = 0.5, and
about Coulomb friction across two materials beyond the uniqueness bound
μ|β_Dundurs| (:func:`dundurs_warnings`); :func:`friction_excess_warnings`
about points a converged path holds at stick beyond μ|t_N|.
A method may refuse more before its solve: :func:`check_friction_springs`
(EFGM) penalty Coulomb springs that dwarf the softer body.
When an increment finds no equilibrium, :func:`friction_demand` and
:func:`tie_cause` say whether the loads leave one; :func:`beyond_cone`
refuses, before Newton, a Coulomb load whose resultant leaves the cone.

One idea a module, each with its maths and sources:

- :mod:`~contactcore.health.residual`: a solve's residual test and the
  words a failed solve is named by;
- :mod:`~contactcore.health.stiffness`: what the law's springs and the
  materials leave a solve (refusals before it, hints after it failed);
- :mod:`~contactcore.health.restraint`: the rigid-body modes and whether
  the supports, pins and Γ hold them;
- :mod:`~contactcore.health.caveats`: the warnings on an answer found
  (locking, Dundurs' β, friction beyond μ|t_N|, closed points in tension,
  a body tipped onto a frictional hinge, slip beyond small sliding);
- :mod:`~contactcore.health.equilibrium`: whether the loads leave an
  equilibrium (Coulomb's cone on a body held by Γ alone, a body pulled
  off Γ, the unilateral law's tie);
- :mod:`~contactcore.health.grazing`: the warning on a ``unilateral``
  answer whose open zone is the mesh's (its closed points carry shear
  but no load presses them, so the discretisation's error in g_N decides
  which points open).

The arrows: ``equilibrium`` → ``restraint`` → ``stiffness``;
``equilibrium`` → ``residual``.

The package's public names, imported here as ``contactcore.health.NAME``,
are its modules' public functions, classes and the failure words
(:data:`NOT_CONVERGED`, :data:`DIVERGED`); a module's private helpers
stay in their home.
"""
from .caveats import (closed_tension_warnings, dundurs_beta, dundurs_warnings, friction_excess_warnings,
                      hinge_warnings, large_slip_warnings, material_warnings, traction_locking_warnings)
from .equilibrium import beyond_cone, friction_demand, tie_cause
from .grazing import grazing_warnings, grazing_zone
from .residual import (DIVERGED, NOT_CONVERGED, SHORT_OF_CHECK, backward_error, check_residual, options_chose,
                       relative_residual)
from .restraint import FreeBody, check_held, check_restraint, lets_go, modes_centre, slips_free
from .stiffness import (check_friction_springs, check_springs, contrast_cause, failure_hint, material_cause, spring_unit,
                        stiff_spring_warnings)

__all__ = [
    # residual
    "DIVERGED", "NOT_CONVERGED", "SHORT_OF_CHECK", "backward_error", "check_residual", "options_chose",
    "relative_residual",
    # stiffness
    "check_friction_springs", "check_springs", "contrast_cause", "failure_hint", "material_cause", "spring_unit",
    "stiff_spring_warnings",
    # restraint
    "FreeBody", "check_held", "check_restraint", "lets_go", "modes_centre", "slips_free",
    # caveats
    "closed_tension_warnings", "dundurs_beta", "dundurs_warnings", "friction_excess_warnings", "material_warnings",
    "hinge_warnings", "large_slip_warnings", "traction_locking_warnings",
    # equilibrium
    "beyond_cone", "friction_demand", "tie_cause",
    # grazing
    "grazing_warnings", "grazing_zone",
]
