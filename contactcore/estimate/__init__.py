"""Error estimates without a reference: Richardson on profiles, Zienkiewicz–Zhu in energy.

Two estimates of how far a run is from the exact answer, method-independent
(they read a run only through its :class:`~contactcore.result.Result`):
Richardson extrapolation of every profile quantity from one method's runs
at h, h/2 (and h/4), and the Zienkiewicz–Zhu estimate of one run's error
in energy by recovery.  One idea a module, each with its maths and
sources:

- :mod:`~contactcore.estimate.runs`: the entry point, :func:`estimate`
  and :func:`estimate_runs`, which gather the parts into an
  :class:`Estimate`;
- :mod:`~contactcore.estimate.extrapolation`: Richardson's estimate of a
  profile quantity (:class:`QuantityEstimate`);
- :mod:`~contactcore.estimate.caveats`: the warnings that say where not
  to trust it (order, pollution, stencils, cell scale, residues, a
  curved Γ's layer, a recovered stress's energy);
- :mod:`~contactcore.estimate.status`: Γ's status in the runs (whether it
  switches; where two runs differ);
- :mod:`~contactcore.estimate.energy`: the Zienkiewicz–Zhu estimate;
- :mod:`~contactcore.estimate.orders`: the orders theory allows a
  quantity, by method and degree;
- :mod:`~contactcore.estimate.singular`: the singular points and their
  exponents (pollution).

The arrows point from the entry point to the parts: ``runs`` →
``caveats`` → ``extrapolation`` → ``orders``, ``singular``; ``runs`` →
``status``, ``energy`` (→ ``singular``).

The package's public names, imported here as ``contactcore.estimate.NAME``,
are its modules' public functions and classes; a module's constants stay
in their home.

numpy and scipy only; no method is imported.
"""
from .caveats import (above_range, above_range_warning, beyond_reach, cell_scale_orders, cell_scale_warnings, curved_layer, curved_layer_warning,
                      exact_traction_warning, exact_tractions, fast_gamma, fast_gamma_warning, feature_size,
                      near_status_changes, observed_exact_traction_warning, observed_exact_tractions, order_mismatch,
                      steady_exact_traction_warning, steady_exact_tractions,
                      enforced_gaps, enforced_gap_warning,
                      order_warnings, pollution_warning, quadrature_energy, quadrature_stress, quadrature_stress_warning, recovery_floor, residue_warnings, residues,
                      slow_halving, slow_halving_warning, split_cell_share, split_cell_share_warning,
                      status_change_warnings, stencil_radius, thinnest_body, unlike_differences,
                      unlike_differences_warning, unlike_runs, unlike_runs_warning, unsettled,
                      unsettled_warnings)
from .energy import (EnergyEstimate, EnergyRule, direct_stress, energy_estimate, energy_norm, energy_rule,
                     recovered_stress, recovery_moves)
from .extrapolation import (QuantityEstimate, balanced_order, cell_scale_part, cosine, differences_cosine, observed_order, profile_estimates,
                            richardson, rms, roundoff_floor, sample_groups, three_run_order)
from .orders import lower_end, order_range, polluted, smooth_range, theoretical_order
from .runs import Estimate, estimate, estimate_runs, levels_of
from .singular import (clamped_free_exponent, compliance_length, corner_exponents, exact_interface_ends, far_from_singular,
                       interface_end_exponents, kolosov, pollution_order, reflected, singular_points, singular_regions,
                       stiff_spring_ends, stress_singular_points, unknown_ends)
from .status import (change_points, far_from_changes, status_along, status_change, status_changes, status_warning,
                     switches)

__all__ = [
    # runs
    "Estimate", "estimate", "estimate_runs", "levels_of",
    # extrapolation
    "QuantityEstimate", "balanced_order", "cell_scale_part", "cosine", "differences_cosine", "observed_order", "profile_estimates", "richardson",
    "rms", "roundoff_floor", "sample_groups", "three_run_order",
    # caveats
    "above_range", "above_range_warning", "beyond_reach", "cell_scale_orders", "cell_scale_warnings", "curved_layer", "curved_layer_warning",
    "exact_traction_warning", "exact_tractions", "fast_gamma", "fast_gamma_warning", "feature_size",
    "near_status_changes", "observed_exact_traction_warning", "observed_exact_tractions", "order_mismatch",
    "steady_exact_traction_warning", "steady_exact_tractions", "enforced_gaps", "enforced_gap_warning",
    "order_warnings", "pollution_warning", "quadrature_energy", "quadrature_stress", "quadrature_stress_warning", "recovery_floor", "residue_warnings", "residues",
    "slow_halving", "slow_halving_warning", "split_cell_share", "split_cell_share_warning",
    "status_change_warnings", "stencil_radius", "thinnest_body", "unlike_differences", "unlike_differences_warning",
    "unlike_runs", "unlike_runs_warning", "unsettled", "unsettled_warnings",
    # status
    "change_points", "far_from_changes", "status_along", "status_change", "status_changes", "status_warning",
    "switches",
    # energy
    "EnergyEstimate", "EnergyRule", "direct_stress", "energy_estimate", "energy_norm", "energy_rule",
    "recovered_stress", "recovery_moves",
    # orders
    "lower_end", "order_range", "polluted", "smooth_range", "theoretical_order",
    # singular
    "clamped_free_exponent", "compliance_length", "corner_exponents", "exact_interface_ends", "far_from_singular",
    "interface_end_exponents", "kolosov", "pollution_order", "reflected", "singular_points", "singular_regions",
    "stiff_spring_ends", "stress_singular_points", "unknown_ends",
]
