"""fix37 (2026-11-29): estimate warnings true to the runs on a Γ whose
final status never changes along it (docs/error-estimates.md, "The
warnings": steady tractions, enforced gaps; round-off skipped by every
line, contactcore.estimate.caveats.unsettled.roundoff_runs)."""
import numpy as np

import tolerances as tol
from contactcore import estimate as est
from contactcore import load_scene
from contactcore.discretisation import solve
from contactcore.profiles import ProfileData
from verification import methods
from verification.agreement import default_exclusion

CRACK = "tests/scenes/tilted_crack_slip_exact.toml"
BLOCK = "tests/scenes/tilted_block_weight_exact.toml"


def _estimate(path: str, method: str = "fe", levels: int = 2):
    scene = load_scene(path)
    disc = methods.discretisation(method)(degree=1)
    runs = [solve(scene, disc, h) for h in est.levels_of(tol.HELD_GAMMA_H, levels)]
    return est.estimate_runs(scene, runs, default_exclusion(scene) if levels > 2 else 0.0, energy=False)


def test_runs_that_differ_only_at_round_off_are_named_by_no_warning():
    """fe P1 on the inclined crack in slip is exact (its runs differ at
    1e-14 of scale): before fix37 the estimate named G:gT, G:tN, G:tT and
    D's quantities "within ... of a singular point" and Γ's tractions as
    exact tractions "at order 1 near status changes"; now no line."""
    estimate = _estimate(CRACK)
    assert not estimate.warnings and not estimate.unsettled, estimate.warnings


def test_a_held_gamma_names_its_tractions_and_gaps_by_what_the_runs_took():
    """fe P1 on the inclined block that sticks under its weight: Γ's
    status never changes, so no sample took order 1 (the line "at order 1
    near status changes" named G:tN, G:tT before fix37); its tractions
    took 1.45 of [1, 2] (steady tractions) and its gaps are the
    enforcement's residue (enforced gaps: g_T's estimate read 0.39 of its
    error, unwarned)."""
    estimate = _estimate(BLOCK)
    text = "\n".join(estimate.warnings)
    assert "near status changes" not in text, text
    (steady,) = [w for w in estimate.warnings if "steady tractions" in w]
    (held,) = [w for w in estimate.warnings if "enforced gaps" in w]
    assert steady.startswith("G:tN, G:tT:") and held.startswith("G:gN, G:gT:"), (steady, held)
    assert {"G:tN", "G:tT", "G:gN", "G:gT"} <= estimate.unsettled


def test_three_runs_leave_a_gamma_that_switched_only_in_its_history_to_the_order_line():
    """fix38: efgm P1 on the inclined crack in slip from three runs (h =
    0.1, 0.05, 0.025): Γ switched only in its history, so every sample of
    G's t_N, t_T took the far order (observed 0.50, clipped; 3.31 times
    the error over the kept samples against fe P2 at h = 0.0125).  The old
    code named them as "an exact Γ traction that theory allows order 1,
    from three runs" besides the order line; now the order line alone (and
    the stencil's) names them."""
    estimate = _estimate(CRACK, "efgm", 3)
    text = "\n".join(estimate.warnings)
    assert "exact tractions" not in text, text
    (order,) = [w for w in estimate.warnings if w.startswith("G:tN:")]
    assert "clipped" in order and "(docs/error-estimates.md: order)" in order, order
    assert {"G:tN", "G:tT"} <= estimate.unsettled


def _runs(share: float) -> list[list[ProfileData]]:
    """Two runs of one profile on Γ whose t_N differ by ``share`` of its scale."""
    x = np.linspace(0.0, 1.0, 11)
    base = {"s": x, "x": x, "y": np.zeros_like(x), "tN": -1e6 * (1 + x)}
    moved = dict(base, tN=base["tN"] * (1 + share))
    return [[ProfileData("G", "arclength", base)], [ProfileData("G", "arclength", moved)]]


def test_round_off_is_told_from_a_difference_by_the_quantitys_scale():
    """roundoff_runs: 1e-14 of scale is round-off, 1e-4 is not; the
    exact tractions line then names only the second."""
    scene = load_scene("tests/scenes/tilt_unil_exact.toml")
    noise, signal = (est.caveats.roundoff_runs(scene, _runs(s)) for s in (tol.HELD_GAMMA_NOISE, tol.HELD_GAMMA_SIGNAL))
    assert noise == {"G:tN"} and signal == set()
    profiles = {"G": {"tN": est.QuantityEstimate(np.ones(11), 1.0, (1, 1))}}
    assert est.exact_tractions(scene, profiles, roundoff=noise) == []
    assert est.exact_tractions(scene, profiles, roundoff=signal) == ["G:tN"]


def test_three_runs_without_an_observed_order_do_not_say_two():
    """A three-run estimate's unobserved traction (one difference at
    round-off) is not "from two runs"."""
    (line,) = est.exact_traction_warning(["G:tN"], three=True)
    assert "two runs" not in line and "three runs" in line
