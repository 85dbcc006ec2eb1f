"""How two methods' profiles are compared, in one place, and the public
agreement check built on it.

Per profile and quantity, two figures over the *kept* samples:

* the **RMS** of the difference relative to the RMS of the reference;
* the **worst sample**: the largest |difference| relative to the reference's
  largest |value|, with where it lies (s, x, y) and both values there.

Samples closer than ``exclude`` to a *singular point* — a corner of the
domain, or a point where a straight Γ meets the outer boundary — are left
out: there the stresses have boundary layers or singularities that no
method resolves at these resolutions, so a pointwise difference there
measures resolution, not agreement.  A quantity is a component of a vector
or tensor (:data:`GROUPS`), and is measured against that vector's or
tensor's size at each sample (:func:`scale_of`): t_N and t_T against |t|
(a wrong friction shows in the status map, not in t_T's share),
g_N and g_T against |g| (at a point of Γ, whichever profiles sample them:
scene B's B6 t_N against B5's t_T), a stress against the size of the
stresses its profile samples, a displacement against |u|.  So a component
zero by symmetry (scene B's t_N, a pressed disc's t_T) is measured against
the size of its vector, not its own residue (scene B's are labelled class
``zero``, :data:`KNOWN_ZEROS`).  Under an exactly enforced law the gaps g_N, g_T of a
closed, sticking Γ are zero but for the enforcement's residue, so a gap is
measured against its size floored by a share of the scene's displacement
scale (:func:`measured_against`); and every size is floored by round-off of
the scene's own scale (:func:`roundoff`), so a run whose values are all
round-off (a Γ pulled open, stress-free) reports no error.  Under a law
that opens or slips, each method's status map along Γ is compared with the
reference's over all of Γ, a boundary's move by a cell allowed
(:mod:`~verification.agreement.status`).

:func:`compare` solves a scene with several methods and a reference and
returns the :class:`AgreementTable`; :func:`assert_methods_agree` is the
pytest helper built on it, :func:`assert_table_agrees` its check of a
table of runs already made (docs/api.md).

One idea a module:

- :mod:`~verification.agreement.sizes`: the sizes below which a
  difference does not count (:func:`roundoff`, :func:`negligible`,
  :func:`gap_floor`, :func:`floors`, :func:`measured_against`), and the
  user's floors (:func:`user_floors`, :func:`floor_problem`);
- :mod:`~verification.agreement.samples`: which samples are compared
  (:func:`default_exclusion`, :func:`check_exclusion`,
  :func:`kept_samples`);
- :mod:`~verification.agreement.groups`: what a quantity is measured
  against, its group's size (:data:`GROUPS`, :func:`scale_of`,
  :func:`scale_name`);
- :mod:`~verification.agreement.classes`: the class a row is labelled
  with (:func:`quantity_class`, :data:`KNOWN_ZEROS`, :func:`is_zero`);
- :mod:`~verification.agreement.measures`: the figures (:func:`share`,
  :func:`percent`, :func:`relative_rms`, :func:`first_largest`);
- :mod:`~verification.agreement.records`: one row, :class:`Agreement`, and
  the rows of a method's profiles (:func:`profile_agreements`,
  :func:`agreements`);
- :mod:`~verification.agreement.status`: Γ's status map (stick/slip/open)
  against the reference's, over all of Γ, a cell's move of a boundary
  allowed (:class:`StatusMap`, :func:`status_map`, :class:`StatusAgreement`,
  :func:`status_agreements`, :data:`STATUS_ALLOWANCE_CELLS`,
  :data:`STATUS_TOLERATED_SHARE`);
- :mod:`~verification.agreement.tables`: :class:`AgreementTable` and
  :func:`table`;
- :mod:`~verification.agreement.estimates`: runs against their estimated
  errors (:func:`estimated_shares`, :func:`worst_estimate`,
  :func:`within_estimates`, :func:`beyond_own_estimate`);
- :mod:`~verification.agreement.api`: the public check (:func:`compare`,
  :func:`assert_methods_agree`, :func:`assert_table_agrees`, :func:`compare_estimates`, :func:`check_rtol`, :func:`variant`,
  :func:`label`, :func:`sampled`).
- :mod:`~verification.agreement.outside`: an outside code's answer against
  one method's and its estimated error (:func:`compare_outside`, its
  :class:`OutsideTable` of :class:`OutsideRow`, each with its
  :class:`Region`), in
  parts: the input read (``outside_files``) and checked against the scene
  (``outside_input``), a profile's geometry along ``s``
  (``profile_geometry``), the project's answer and error at the outside
  samples (``outside_budget``), the verdicts (``outside_verdicts``) and
  the table (``outside_table``).

The arrows: ``api`` → ``tables`` → ``records`` → ``classes`` → ``groups``
→ ``sizes``; ``records`` → ``measures`` → ``samples``; ``api``, ``tables`` →
``status`` → ``measures``; ``tables`` → ``groups``; ``estimates`` →
``groups``, ``measures``, ``samples``, ``sizes``; ``outside`` → ``api``,
``outside_input``, ``outside_table``, ``outside_budget``, ``outside_verdicts``,
``profile_geometry``, ``records``, ``samples``, ``sizes``; ``outside_input``
→ ``outside_files``, ``profile_geometry``; ``outside_table`` →
``outside_verdicts``, ``outside_budget``, ``records``, ``measures``.

The package's public names, imported here as ``verification.agreement.NAME``,
are its modules' public functions, classes and tables, and the
comparison's tolerances (:data:`EXACT_GAP_FLOOR`, :data:`EXCLUDE_FRACTION`,
:data:`EXCLUDE_KEEP_SHARE`, :data:`NEGLIGIBLE_SHARE`, :data:`STATUS_ALLOWANCE_CELLS`,
:data:`STATUS_TOLERATED_SHARE`, :data:`WORST_TIE`:
contactcore.tolerances', with their reasons, still importable from here).
"""
# The comparison's tolerances, with their reasons, are contactcore.tolerances'
# and stay importable from here (tests and users import them from this package).
from contactcore.tolerances import (EXACT_GAP_FLOOR, EXCLUDE_FRACTION, EXCLUDE_KEEP_SHARE, NEGLIGIBLE_SHARE,
                                    STATUS_ALLOWANCE_CELLS, STATUS_TOLERATED_SHARE, WORST_TIE)

from .api import (MEASURES, EstimateVerdict, assert_methods_agree, assert_table_agrees, check_rtol, compare, compare_estimates,
                  compared_variants, label, sampled, variant)
from .classes import KNOWN_ZEROS, is_zero, quantity_class
from .estimates import beyond_own_estimate, estimated_shares, within_estimates, worst_estimate
from .groups import GROUPS, ON_GAMMA, components, group_of, group_size, scale_name, scale_of
from .measures import first_largest, percent, relative_rms, share
from .outside import compare_outside  # an outside code's answer against the project's (docs/api.md)
from .outside_table import OutsideRow, OutsideTable
from .outside_verdicts import Region
from .records import Agreement, agreements, profile_agreements
from .samples import check_exclusion, default_exclusion, kept_samples
from .status import StatusAgreement, StatusMap, compare_status, gamma_profiles, status_agreements, status_map
from .sizes import (KINDS, displacement_scale, floor_problem, floors, gap_floor, gap_floors, measured_against,
                    measured_floor, negligible, roundoff, size_floor, user_floors)
from .tables import AgreementTable, table

__all__ = [
    # tolerances
    "EXACT_GAP_FLOOR", "EXCLUDE_FRACTION", "EXCLUDE_KEEP_SHARE", "NEGLIGIBLE_SHARE", "STATUS_ALLOWANCE_CELLS",
    "STATUS_TOLERATED_SHARE", "WORST_TIE",
    # sizes
    "KINDS", "displacement_scale", "floor_problem", "floors", "gap_floor", "gap_floors", "measured_against",
    "measured_floor", "negligible", "roundoff", "size_floor", "user_floors",
    # samples
    "check_exclusion", "default_exclusion", "kept_samples",
    # groups
    "GROUPS", "ON_GAMMA", "components", "group_of", "group_size", "scale_name", "scale_of",
    # classes
    "KNOWN_ZEROS", "is_zero", "quantity_class",
    # measures
    "first_largest", "percent", "relative_rms", "share",
    # records
    "Agreement", "agreements", "profile_agreements",
    # status
    "StatusAgreement", "StatusMap", "compare_status", "gamma_profiles", "status_agreements", "status_map",
    # tables
    "AgreementTable", "table",
    # estimates
    "beyond_own_estimate", "estimated_shares", "within_estimates", "worst_estimate",
    # api
    "MEASURES", "EstimateVerdict", "assert_methods_agree", "assert_table_agrees", "check_rtol", "compare", "compare_estimates",
    "compared_variants", "label", "sampled", "variant",
    # outside: an outside code's answer, and the types of its verdict
    "OutsideRow", "OutsideTable", "Region", "compare_outside",
]
