"""When not to trust the Richardson estimate: the warnings, each naming the quantities concerned.

The Richardson estimate (:mod:`~contactcore.estimate.extrapolation`)
holds once the runs are in the asymptotic range, where the error is
``C h^p`` at an order theory allows
(:func:`~contactcore.estimate.orders.order_range`).  Each function here
finds quantities whose runs are not, and a ``*_warning(s)`` function
says so in one short line: the quantities, what was found with its
numbers in their units, and the row of docs/error-estimates.md, "The
warnings", that explains it (:func:`see`), which holds the measured
ranges and the reasons the line leaves out (newuser32: twelve lines of
250-520 characters on one run).

An observed order (three runs) further than
:data:`~contactcore.tolerances.ORDER_MISMATCH` from the orders theory
allows, or clipped to an end of :data:`~contactcore.tolerances.ORDER_RANGE`,
means the runs are not yet in the asymptotic range
(:func:`order_mismatch`, :func:`order_warnings`).  An order of
:data:`POLLUTED_ORDER` or more taken from two runs on a domain with
singular points that :func:`~contactcore.estimate.singular.pollution_order`
does not take may make the estimate several times too small
(:func:`pollution_warning`).

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
(:func:`residues`), and, for a polluted range split at the cells'
scale, those whose difference lies mostly at that scale, the part
taken at the range's upper order, which two runs cannot check
(:func:`split_cell_share`, an empirical marker of scene A's A5 fe P2
``g_N``, 0.485).

xfem P1's recovered stress (its options' ``recovered_stress``,
:class:`~contactcore.result.MethodFacts`) converges at order 1 in a
layer one cell thick along a curved Γ, where the recovery patch is one-sided and cut cells' samples carry an O(h)
bias, against 2 to 3 elsewhere: from h = 0.025 that layer sets a ray's
error and the two-run estimate, taken at the order elsewhere, reads 0.42
to 0.47 of it (docs/methods/xfem.md, "Degree-1 stress"); on other
scenes such entries read 0.18-2.2.  The estimate names such profiles
without a direction (:func:`curved_layer`).  (xfem P1's Zienkiewicz–Zhu
estimate takes that recovered stress as its ``σ*`` and the displacement's
own as ``σ_h``: :func:`~contactcore.estimate.energy.energy_estimate`.)  EFGM P1's
Zienkiewicz–Zhu estimate at a tiny share of the run's energy, where its
quadrature's error may be most of the error, is named too
(:func:`quadrature_energy`: the layered slip's 0.41).

An exact law's traction on Γ (Nitsche's multiplier) estimated from two
runs where theory allows it order 1 (within
:data:`~contactcore.tolerances.STATUS_CHANGE_CELLS` coarse cells of a
status change, at order 1; beyond, at 2 at degree 2 and at 1.45 of
``[1, 2]`` at degree 1: :func:`~contactcore.estimate.orders.smooth_range`)
is most often too
large: its pieces converge faster (up to 13.7 times the error on
grader17's tilted block, xfem P1), but not always (0.19 on a held-out
wedge; :func:`exact_tractions`).  A warning claims a direction (too
large, too small) only where every entry it named on the measured sets
lay that way; otherwise it gives the measured range.

Under an exact law a point where Γ's final status changes is a weak
singular point (the solution no smoother than H^{5/2-ε} there): a bulk
quantity's samples within
:data:`~contactcore.tolerances.STATUS_CHANGE_STENCILS` coarse stencils
of one are left out of its ``kept_rms`` as a singular point's are, and a
line says so (:func:`beyond_reach`, :func:`near_status_changes`).

Where Γ's status differs between the runs: :mod:`~contactcore.estimate.status`.


One idea per module, each a detector and its ``*_warning(s)`` line:

- :mod:`~contactcore.estimate.caveats.lines`
- :mod:`~contactcore.estimate.caveats.observed`
- :mod:`~contactcore.estimate.caveats.pollution`
- :mod:`~contactcore.estimate.caveats.tractions`
- :mod:`~contactcore.estimate.caveats.reach`
- :mod:`~contactcore.estimate.caveats.unsettled`
- :mod:`~contactcore.estimate.caveats.cell_scale`
- :mod:`~contactcore.estimate.caveats.residues`
- :mod:`~contactcore.estimate.caveats.recovery`
- :mod:`~contactcore.estimate.caveats.quadrature`
- :mod:`~contactcore.estimate.caveats.unlike`
- :mod:`~contactcore.estimate.caveats.unlike_runs`

Their public names are imported here, as ``contactcore.estimate.caveats.NAME``.

numpy only; no method is imported or named: what a warning must know of
one, it reads from the run's :class:`~contactcore.result.MethodFacts`
(``facts``), as its options declared them.
"""
from .lines import ENERGY_KEY, GAMMA, OBSERVE, see, WARNINGS_PAGE
from .observed import above_range, above_range_warning, order_mismatch, order_warnings, slow_halving, slow_halving_warning
from .pollution import POLLUTED_ORDER, pollution_warning
from .tractions import (enforced_gap_warning, enforced_gaps, exact_traction_warning, exact_tractions, fast_gamma,
                        fast_gamma_warning,
                        observed_exact_traction_warning, observed_exact_tractions, steady_exact_traction_warning,
                        steady_exact_tractions)
from .reach import beyond_reach, distances, near_status_changes, status_change_warnings, stencil_radius
from .unsettled import feature_size, roundoff_runs, thinnest_body, unsettled, unsettled_warnings
from .cell_scale import (cell_scale_orders, cell_scale_warnings, SPLIT_CELL_DEGREE, split_cell_share,
                         split_cell_share_warning)
from .residues import KINDS, residue_warnings, residues
from .recovery import curved_layer, curved_layer_warning, recovery_floor
from .quadrature import quadrature_energy, quadrature_stress, quadrature_stress_warning
from .unlike import unlike_differences, unlike_differences_warning
from .unlike_runs import unlike_runs, unlike_runs_warning

__all__ = [
    "above_range", "above_range_warning", "ENERGY_KEY", "GAMMA", "OBSERVE", "see", "WARNINGS_PAGE", "order_mismatch", "order_warnings", "slow_halving",
    "slow_halving_warning", "POLLUTED_ORDER", "pollution_warning", "exact_traction_warning", "exact_tractions",
    "fast_gamma", "fast_gamma_warning", "observed_exact_traction_warning", "observed_exact_tractions",
    "steady_exact_traction_warning", "steady_exact_tractions", "enforced_gaps", "enforced_gap_warning",
    "beyond_reach",
    "distances", "near_status_changes", "status_change_warnings", "stencil_radius", "feature_size", "roundoff_runs",
    "thinnest_body",
    "unsettled", "unsettled_warnings", "cell_scale_orders", "cell_scale_warnings", "SPLIT_CELL_DEGREE",
    "split_cell_share", "split_cell_share_warning", "KINDS", "residue_warnings", "residues", "curved_layer",
    "curved_layer_warning", "recovery_floor", "quadrature_energy", "quadrature_stress", "quadrature_stress_warning",
    "unlike_differences", "unlike_differences_warning", "unlike_runs", "unlike_runs_warning"
]
