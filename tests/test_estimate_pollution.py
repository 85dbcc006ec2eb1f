"""grader17 F1 (2026-11-28): silent underestimates of degree-2 bulk
displacements where a straight Γ under an exact law ends on free sides.

Γ's ends are then singular points whose exponent the pollution order does
not take (a bimaterial or contact edge:
contactcore.estimate.singular.exact_interface_ends); a bulk displacement
whose orders pollution widened takes the lower end of the range from two
runs, not the balanced order (contactcore.estimate.orders.lower_end), and
an exact law's traction estimated at order 1 is named by a warning
(contactcore.estimate.caveats.exact_tractions)."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import estimate as est
from contactcore import load_scene, sample_profiles
from contactcore.estimate import extrapolation
from verification.effectivity import CASES

TILT = "tests/scenes/tilt_bonded.toml"


def test_only_an_exact_gammas_ends_on_a_rectangle_are_taken():
    """The closed forms of the effectivity table and scenes A, B, C have
    no such end (their tables are unchanged by the rule); the tilted
    block has two; a bonded Γ between equal materials is no interface."""
    tilt = load_scene(TILT)
    assert len(est.exact_interface_ends(tilt)) == 2
    same = tilt.with_changes(materials={"minus": tilt.materials["minus"], "plus": tilt.materials["minus"]})
    assert len(est.exact_interface_ends(same)) == 0
    for scene in [CASES[k]().scene for k in CASES] + [load_scene(n) for n in ("A", "B", "C", "C-coulomb")]:
        assert len(est.exact_interface_ends(scene)) == 0


def test_the_lower_end_is_for_bulk_displacements_of_a_widened_range():
    assert est.lower_end("ux", (1.42, 3), True) and est.lower_end("uy", (1.42, 2), True)
    assert not est.lower_end("ux", (1.42, 3), False)
    assert not est.lower_end("gN", (1.42, 2), True) and not est.lower_end("sxx", (1, 2), True)
    assert not est.lower_end("ux", (3, 3), True)
    s = np.linspace(0.0, 1.0, 11)
    runs = [np.cos(s) + (1 + s ** 2) * h ** 1.42 for h in (0.1, 0.05)]
    assert est.richardson(runs, (1.42, 3), low=True).order == 1.42
    assert est.richardson(runs, (1.42, 3)).order == pytest.approx(est.balanced_order(1.42, 3))
    three = [np.cos(s) + (1 + s ** 2) * h ** 3 for h in (0.1, 0.05, 0.025)]
    assert est.richardson(three, (1.42, 3), low=True).order == pytest.approx(est.balanced_order(1.42, 3))


def _effectivities(scene, results, truth):
    from verification.agreement import default_exclusion
    e = est.estimate_runs(scene, results, default_exclusion(scene), energy=False)
    return {q: e.profiles["H"][q].rms / est.rms(e.sampled[0].columns[q] - truth.columns[q]) for q in ("ux", "uy")}, e


def test_the_tilted_blocks_bulk_displacements_are_not_underestimated(monkeypatch):
    """fe P2 at h = 0.1 → 0.05 against fe P2 at 0.0125: u_x, u_y within
    EFFECTIVITY at the lower end 2λ = 1.42 of the clamped corners; at the
    balanced order 2.15 (the rule switched off) u_y read below it,
    unwarned, as grader17 found."""
    from contactcore.discretisation import solve
    from verification import methods
    scene = load_scene(TILT)
    disc = methods.discretisation("fe")(degree=2)
    results = [solve(scene, disc, h) for h in (0.1, 0.05)]
    ref = solve(scene, disc, 0.0125)
    truth = sample_profiles(scene, ref.fields, ref.interface)[0]
    eff, e = _effectivities(scene, results, truth)
    for q in ("ux", "uy"):
        theory = e.profiles["H"][q].theory
        assert e.profiles["H"][q].order == theory[0] == est.pollution_order(scene)
        assert tol.EFFECTIVITY[0] <= eff[q] <= tol.EFFECTIVITY[1], (q, eff[q])
        assert eff[q] == pytest.approx(tol.TILT_BONDED_EFFECTIVITY[q], rel=tol.EFFECTIVITY_OUTSIDE_DRIFT)
    monkeypatch.setattr(extrapolation, "unknown_ends", lambda scene, h: False)
    before, e = _effectivities(scene, results, truth)
    assert before["uy"] < tol.EFFECTIVITY[0] and not e.unsettled
    for q in ("ux", "uy"):
        assert before[q] == pytest.approx(tol.TILT_BONDED_EFFECTIVITY_BALANCED[q], rel=tol.EFFECTIVITY_OUTSIDE_DRIFT)


def test_an_exact_laws_traction_at_order_one_is_named():
    """grader17 F3: Nitsche's multiplier estimated at order 1 overestimated
    up to 13.7 times, unwarned; now named (and counted as warned)."""
    from contactcore.estimate.extrapolation import QuantityEstimate
    s = np.ones(3)
    profiles = {"G": {"tN": QuantityEstimate(s, 1.0, (1, 1)), "gN": QuantityEstimate(s, 1.7, (1.42, 2)),
                      "tT": QuantityEstimate(s, 2.0, (2, 2))}}
    tilt = load_scene(TILT)
    assert est.exact_tractions(tilt, profiles) == ["G:tN"]
    (line,) = est.exact_traction_warning(["G:tN"])
    assert "G:tN" in line and "13.7" in line
    assert est.exact_tractions(load_scene("A"), profiles) == []


LAYERED = "tests/scenes/layered_press_exact.toml"


def _layered_warnings(method: str, levels: int) -> list[str]:
    from contactcore.discretisation import solve
    from verification import methods
    from verification.agreement import default_exclusion
    scene = load_scene(LAYERED)
    runs = [solve(scene, methods.discretisation(method)(degree=2), h) for h in est.levels_of(tol.LAYERED_EXACT_H, levels)]
    return [w for w in est.estimate_runs(scene, runs, default_exclusion(scene), energy=False).warnings
            if "(docs/error-estimates.md: pollution)" in w]


@pytest.mark.parametrize("method", ["fe", "xfem"])
@pytest.mark.parametrize("levels", [2, 3])
def test_runs_at_round_off_are_not_told_of_pollution(method, levels):
    """grader34 F3: on a layered block whose answer is piecewise quadratic
    fe and xfem P2 are exact and their runs differ at round-off, so no
    order is observed; the pollution line named G:gN, G:gT, V:uy, D:ux,
    D:uy "estimated at order 3 from two runs ... try --estimate 3", also
    after three runs.  Now it names no round-off runs, and nothing after
    three."""
    assert _layered_warnings(method, levels) == []


def test_runs_above_round_off_are_still_told_of_pollution():
    """EFGM P2's runs on the same block differ above round-off: two runs
    are named as before, three are not (their order is observed, or a
    difference is at round-off)."""
    (line,) = _layered_warnings("efgm", 2)
    assert line.startswith("G:gN, G:gT, V:uy, D:ux, D:uy: estimated at order 3 from two runs"), line
    assert _layered_warnings("efgm", 3) == []
