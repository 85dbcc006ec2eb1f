"""est2_39 (2026-11-30): two runs whose values share little pattern are
named (contactcore.estimate.caveats.unlike_runs; docs/error-estimates.md,
"The warnings", "unlike runs").

On grader34's lifted block on rollers (tests/scenes/roller_lift_exact.toml)
the exact u_x and g_T are 0; fe P1's values of them are its own error on
gmsh's unstructured meshes, unrelated from h = 0.1 to 0.05 (cosines 0.16,
0.17), so the runs' difference is about the coarse run's error and the
estimate holds only where the unrelated errors happen to fall at the
assumed rate: D:ux read 3.71 times its error, G:gT 2.13, both unwarned."""
import numpy as np

import tolerances as tol
from contactcore import estimate as est
from contactcore import load_scene
from contactcore import tolerances as core_tol
from contactcore.discretisation import solve
from contactcore.profiles import ProfileData, sample_profiles
from test_estimate_warning_lines import _pointed
from verification import methods
from verification.agreement import default_exclusion

SCENE = "tests/scenes/roller_lift_exact.toml"


def _runs():
    """fe P1's two runs of the roller block, their sampled profiles and the estimate."""
    scene = load_scene(SCENE)
    disc = methods.discretisation("fe")(degree=1)
    results = [solve(scene, disc, h) for h in est.levels_of(tol.UNLIKE_RUNS_H, 2)]
    levels = [sample_profiles(scene, r.fields, r.interface) for r in results]
    return levels, est.estimate_runs(scene, results, default_exclusion(scene), energy=False)


def test_exactly_zero_quantities_whose_runs_are_each_their_own_error_are_named():
    """D:ux and G:gT (exact 0) are named with their cosines; the old code
    named neither, though D:ux's estimate lies outside [1/2, 2] of its
    error (the fine run's value itself); the resolved D:uy and G:gN are
    not named, their cosines near 1."""
    levels, estimate = _runs()
    assert {"D:ux", "G:gT"} <= estimate.unsettled, estimate.warnings
    found = est.unlike_runs(levels, estimate.kept)
    assert set(found) == {"D:ux", "G:gT"}, found
    assert all(c <= core_tol.UNLIKE_RUNS_COSINE for c in found.values())
    (line,) = [w for w in estimate.warnings if "unlike runs" in w]
    _pointed(line)
    assert len(line) <= tol.ESTIMATE_WARNING_CHARS and "off either way" in line, line
    fine = {p.id: p for p in levels[-1]}
    keep = estimate.kept["D"]["ux"]
    ratio = est.rms(estimate.profiles["D"]["ux"].error[keep]) / est.rms(fine["D"].columns["ux"][keep])
    assert not 1 / core_tol.ESTIMATE_TRUST <= ratio <= core_tol.ESTIMATE_TRUST, ratio
    resolved = est.cosine(*(lv[1].columns["uy"][estimate.kept["D"]["uy"]] for lv in levels))
    assert resolved > tol.UNLIKE_RUNS_RESOLVED


def _line(values: list[np.ndarray]) -> list[list[ProfileData]]:
    """Runs of one profile ``P`` with quantity ``ux`` at 41 samples."""
    x = np.linspace(0.0, 1.0, 41)
    return [[ProfileData("P", "arclength", {"s": x, "x": x, "y": 0 * x, "ux": v})] for v in values]


def test_three_runs_and_skipped_entries_are_left_to_other_lines():
    """Unrelated values (alternating signs at two periods) are named from
    two runs only, not where skipped (another line names them, or round-off),
    and never from three, which observe the order and compare the
    differences' patterns (unlike differences)."""
    x = np.linspace(0.0, 1.0, 41)
    a, b = np.sign(np.sin(40 * x)) * 1e-8, np.sign(np.sin(13 * x)) * 1e-8
    kept = {"P": {"ux": np.ones(41, bool)}}
    assert est.cosine(a, b) <= core_tol.UNLIKE_RUNS_COSINE
    assert list(est.unlike_runs(_line([a, b]), kept)) == ["P:ux"]
    assert not est.unlike_runs(_line([a, b]), kept, skip={"P:ux"})
    assert not est.unlike_runs(_line([a, b, a]), kept)
    assert not est.unlike_runs_warning({})
