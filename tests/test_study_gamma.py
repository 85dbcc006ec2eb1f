"""study.csv's Γ columns (verification.study_gamma): the share of Γ's length
in each status, the same as run's increments.csv and never outside [0, 1];
``study --estimate``, the same estimate as ``run --h 2h --estimate``; and the
side ``study --param angle`` keeps + (newuser33)."""
from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore.interface_path import Increment, InterfacePath
from contactcore.laws import OPEN, SLIP, STICK
from verification.__main__ import main
from verification.study_parameters import scene_at
from verification.study_gamma import ESTIMATE_COLUMNS, GAMMA, with_gamma

SCENE = "tests/scenes/wedge_held.toml"


def _rows(path) -> list[dict]:
    with open(path) as fh:
        return list(csv.DictReader(fh))


def _shares(row: dict) -> dict[str, float]:
    return {k.removesuffix("_share"): float(v) for k, v in row.items() if k.endswith("_share") and v != ""}


def test_a_path_s_shares_are_sums_of_the_same_weights():
    """The normalised weights' dot product read 1.0000000000000002 for a Γ
    all slipping (a stick share 1 − open − slip of −2.2e-16): weights of
    0.1 (ten of them sum to 0.9999999999999999) made it here too, where
    each share is a correctly rounded sum over the same total."""
    w = np.full(10, 0.1)
    status = np.full(10, SLIP, np.int8)
    path = InterfacePath(np.zeros((10, 2)), w, [Increment(1, (), 1, [0.0], np.zeros((10, 2)), np.zeros((10, 2)),
                                                          status)])
    assert path.status_shares() == {"open": 0.0, "stick": 0.0, "slip": 1.0}
    path.steps[0].status = np.array([OPEN] * 3 + [STICK] * 3 + [SLIP] * 4, np.int8)
    shares = path.status_shares()
    assert all(0.0 <= s <= 1.0 for s in shares.values())
    assert abs(math.fsum(shares.values()) - 1.0) <= tol.STUDYEST_SHARE_SUM
    assert path.status_lengths()["stick"] == math.fsum([0.1] * 3)


@pytest.mark.parametrize("angle, mu", [(20, 0.1), (30, 0.1)])
def test_the_studys_shares_are_increments_csvs_and_sum_to_one(tmp_path, angle, mu, method="xfem"):
    """At 20°, μ = 0.1 Γ slips whole (xfem P1, h = 0.1: the old dot product
    read slip 1.0000000000000002 there, 2026-11-29); at 30° part of it opens.
    Each share lies in [0, 1], they sum to 1, and open and slip are the last
    row of ``run``'s increments.csv on the same point's scene."""
    argv = ["--method", method, "--h", "0.1", "-q"]
    assert main(["study", SCENE, "--param", "angle", "--values", str(angle), "--param", "mu", "--values", str(mu),
                 *argv, "--out", str(tmp_path / "s")]) == 0
    (row,) = _rows(tmp_path / "s" / "study.csv")
    shares = _shares(row)
    assert set(shares) == {"open", "stick", "slip"} and all(0.0 <= s <= 1.0 for s in shares.values())
    assert abs(math.fsum(shares.values()) - 1.0) <= tol.STUDYEST_SHARE_SUM
    point = scene_at(load_scene(SCENE), {"angle": angle, "mu": mu})
    from verification.run import run
    run(point, [method], tmp_path / "r", h=0.1, draw=False)
    last = _rows(tmp_path / "r" / method / "increments.csv")[-1]
    assert float(last["open_fraction"]) == shares["open"] and float(last["slip_fraction"]) == shares["slip"]
    if angle == 20:
        assert shares == {"open": 0.0, "stick": 0.0, "slip": 1.0} and float(row["stick_length"]) == 0.0
    else:
        assert 0.0 < shares["open"] < 1.0
    assert float(row["max_tN_away"]) <= float(row["max_tN"])


def test_study_estimate_is_runs_estimate_of_the_same_point(tmp_path, method="fe"):
    """``study --estimate`` at h = 0.1 solves 0.2 and 0.1, as ``run --h 0.2
    --estimate`` on the point's scene with Γ's profile: the same worst share,
    the same estimated t_N error, warnings and status comparison."""
    angle, mu = 30, 0.1
    assert main(["study", SCENE, "--param", "angle", "--values", str(angle), "--param", "mu", "--values", str(mu),
                 "--method", method, "--h", "0.1", "--estimate", "-q", "--out", str(tmp_path / "s")]) == 0
    (row,) = _rows(tmp_path / "s" / "study.csv")
    assert all(row[c] != "" for c in ESTIMATE_COLUMNS)
    from verification.run import run
    run(with_gamma(scene_at(load_scene(SCENE), {"angle": angle, "mu": mu})), [method], tmp_path / "r", h=0.2,
        estimate=2, draw=False)
    est = json.loads((tmp_path / "r" / method / "summary.json").read_text())["estimate"]
    assert float(row["est_worst"]) == pytest.approx(est["worst"]["relative"], rel=tol.STUDYEST_SAME_RUNS)
    assert row["est_worst_at"] == est["worst"]["at"]
    assert float(row["est_tN"]) == pytest.approx(est[GAMMA.id]["tN"]["kept_rms"], rel=tol.STUDYEST_SAME_RUNS)
    assert int(row["est_warnings"]) == len(est["warnings"])
    assert int(row["status_changed"]) == est["status"]["differ"]
    md = (tmp_path / "s" / "study.md").read_text()
    assert all(w in md for w in est["warnings"])


def test_study_estimate_refuses_a_coarse_run_larger_than_the_domain_before_any_solve(tmp_path, capsys):
    """At --h 0.6 the estimate's run at 2h = 1.2 exceeds the 1 m square:
    refused in one line naming --estimate, nothing written."""
    assert main(["study", SCENE, "--param", "mu", "--values", "0.3", "--method", "fe", "--h", "0.6", "--estimate",
                 "-q", "--out", str(tmp_path / "s")]) == 2
    assert "--estimate" in capsys.readouterr().err and not (tmp_path / "s").exists()


@pytest.mark.parametrize("normal", [(0.0, 1.0), (0.0, -1.0), (1.0, 0.0), (-1.0, 0.0), (-0.6, 0.8)])
@pytest.mark.parametrize("angle", [0.0, 30.0, -65.0, 90.0, 150.0])
def test_angle_turns_gamma_counter_clockwise_and_keeps_the_scenes_plus_side(normal, angle):
    """``--param angle a``: the scene's Γ, at its own angle a₀ in (−90°,
    90°], turned counter-clockwise by a − a₀ about its chord's middle, its
    normal turning with it; so Γ runs along (cos a, sin a) and, for
    |a − a₀| < 90°, the point the scene's normal reached from the middle is
    still on the + side (the normal was (−sin a, cos a) whatever the
    scene's, which swapped the bodies of a scene whose normal pointed down
    or along +x)."""
    base = load_scene(SCENE)
    mid = (0.5, 0.5)
    base = base.with_changes(interface=type(base.interface)(mid, normal), profiles=())
    turned = scene_at(base, {"angle": angle}).interface
    own = math.degrees(math.atan2(-normal[0], normal[1]))
    own = own + 180.0 if own <= -90.0 else own - 180.0 if own > 90.0 else own  # a₀ in (−90°, 90°]
    t = math.radians(angle - own)
    expected = np.array([[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]]) @ np.array(normal)
    assert np.allclose(turned.normal, expected, atol=tol.STUDYEST_ANGLE_ROUNDOFF)
    a = math.radians(angle)
    assert abs(np.dot(turned.normal, [math.cos(a), math.sin(a)])) <= tol.STUDYEST_ANGLE_ROUNDOFF
    assert np.allclose(turned.point, mid, atol=tol.STUDYEST_ANGLE_ROUNDOFF)
    if abs(angle - own) < 90.0:
        assert turned.phi(np.array(mid) + 0.1 * np.array(normal))[0] > 0, (normal, angle, own)
