"""A point of the unilateral law's partial answer (contactcore.newton.partial:
y_N = 0 with a share θ of the tie's shear) is reported as ``partial``, with
its θ, in the Result and interface.csv; Newton's status there stays STICK.

grader16's `uni` (tests/test_xfem_opening.py), fe P1 at h = 0.05, has one
partial point, at s = 0.325 (the run's warning names it and its θ); a run
without a partial point reports what its law's status says."""
import csv
import pathlib
import re

import numpy as np
import pytest

from contactcore import discretisation, load_scene
from contactcore.laws import PARTIAL, STICK
from contactcore.profiles import interface_response
from verification.interface import write_history

import tolerances as tol

#: shear_unilateral's closed-form t_T, 0.1 × 0.47 (test_grazing.SHEAR_CLOSED_FORM,
#: not imported: test_grazing imports this module through test_xfem_opening)
SHEAR_T_T = 0.1 * 0.47


def _rows(folder):
    with open(folder / "interface.csv", newline="") as f:
        return list(csv.DictReader(f))


def check_partial_reported(tmp_path, scene, result):
    """``result``: `uni` fe P1 at h = 0.05 (solved once, in
    tests/test_unilateral_partial.py): its one partial point is reported
    ``partial`` with its θ in the Result, its summary and interface.csv."""
    final = result.interface.final
    where = np.flatnonzero(final.partial)
    assert len(where) == 1, where
    # Newton's status is untouched: the point is closed (STICK); outputs say partial
    assert final.status[where[0]] == STICK and final.reported_status()[where[0]] == PARTIAL
    assert final.status_names()[where[0]] == "partial"
    assert np.isnan(np.delete(final.theta, where)).all()
    # θ is the warning's (printed to 3 digits there)
    warned = [w for w in result.solver.warnings if "share θ of the tie's shear" in w]
    assert len(warned) == 1, result.solver.warnings
    theta = float(re.search(r"θ = ([0-9.e+-]+)", warned[0]).group(1))
    assert f"{final.theta[where[0]]:.3g}" == f"{theta:.3g}", (final.theta, warned)
    assert 0 < final.theta[where[0]] < 1
    # summary(): counts with partial apart from stick, and the point
    summary = result.summary()
    assert summary["status"]["partial"] == 1
    assert sum(summary["status"].values()) == len(final.status)
    assert summary["status"]["stick"] == int(np.sum(final.status == STICK)) - 1
    assert summary["partial"] == [{"x": float(result.interface.points[where[0], 0]),
                                   "y": float(result.interface.points[where[0], 1]),
                                   "theta": float(final.theta[where[0]])}]
    # interface.csv: status partial and θ at that point of the last step, θ empty elsewhere
    write_history(tmp_path, scene, result.interface)
    rows = _rows(tmp_path)
    last = [r for r in rows if r["step"] == rows[-1]["step"]]
    partial = [r for r in last if r["status"] == "partial"]
    assert len(partial) == 1 and float(partial[0]["theta"]) == final.theta[where[0]]
    assert all(r["theta"] == "" for r in rows if r["status"] != "partial")
    assert [r["status"] for r in last] == final.status_names()


def test_without_a_partial_point_statuses_are_the_laws(tmp_path):
    """C-coulomb (penalty), fe P1 at its coarse h: open, stick and slip
    as the law says, no theta column, no partial count."""
    from xdolfinx.options import FE
    scene = load_scene("C-coulomb")
    result = discretisation.solve(scene, FE(degree=1), 0.1)
    path = result.interface
    assert all(s.theta is None and not s.partial.any() for s in path.steps)
    assert all(np.array_equal(s.reported_status(), s.status) for s in path.steps)
    assert "partial" not in result.summary() and "partial" not in result.summary()["status"]
    write_history(tmp_path, scene, path)
    rows = _rows(tmp_path)
    assert "theta" not in rows[0]
    names = {"open", "stick", "slip"}
    assert {r["status"] for r in rows} <= names and len({r["status"] for r in rows}) > 1
    with open(tmp_path / "increments.csv", newline="") as f:
        assert "partial" not in next(csv.reader(f))


def test_summary_md_lists_partial_points_only_where_a_run_has_them():
    """summary.md's note under the table: each run with partial points, its
    counts and each point with θ (summary.json's `status` and `partial`);
    nothing for a run without."""
    from verification.run_summary import _partial_note
    plain = {"method": "fe", "status": {"open": 1, "stick": 2, "slip": 0}}
    partial = {"method": "xfem", "status": {"open": 19, "stick": 40, "slip": 0, "partial": 1},
               "partial": [{"x": 0.325, "y": 0.5, "theta": 0.0587}]}
    assert _partial_note([plain]) == []
    note = _partial_note([plain, partial])
    assert len(note) == 3 and note[2].startswith("- xfem: ") and "1 partial" in note[2]
    assert "(0.325, 0.5) θ = 0.0587" in note[2]


def _path(status, theta=None):
    """One increment on Γ: y = 0.5 at len(status) evenly spaced points."""
    from contactcore.interface_path import Increment, InterfacePath
    m = len(status)
    points = np.column_stack([np.linspace(0.05, 0.95, m), np.full(m, 0.5)])
    step = Increment(1.0, (1.0,), 1, [0.0], np.zeros((m, 2)), np.zeros((m, 2)), np.asarray(status, np.int8),
                     None if theta is None else np.asarray(theta, float))
    return InterfacePath(points, np.full(m, 1.0 / m), [step])


def test_the_estimate_compares_a_partial_point_as_its_own_status(tmp_path):
    """status_change: a point partial in one run and sticking in the other
    differs there; `partial` among the shares only where a run has one.
    switches: a partial point beside sticking ones is a change of status."""
    from contactcore.estimate.status import status_change, switches
    from test_xfem_opening import UNI
    (tmp_path / "uni.toml").write_text(UNI)
    scene = load_scene(tmp_path / "uni.toml")  # Γ the line y = 0.5 of the paths
    from types import SimpleNamespace
    # an exact law's statuses are its quadrature points': no field is read
    stick = SimpleNamespace(interface=_path([STICK] * 5), fields=None)
    mixed = SimpleNamespace(interface=_path([STICK] * 5, theta=[np.nan, np.nan, 0.5, np.nan, np.nan]), fields=None)
    same = status_change(scene, stick, stick)
    assert same["differ"] == 0 and "partial" not in same["fine"]
    change = status_change(scene, stick, mixed)
    assert change["differ"] > 0 and change["fine"]["partial"] > 0 and change["coarse"]["partial"] == 0
    assert not switches([stick.interface]) and switches([mixed.interface])


def test_the_status_compared_is_the_one_the_profiles_tractions_follow():
    """grader25b H1 (tests/scenes/unil_partopen.toml, penalty unilateral,
    fe P1 at h = 0.05 and 0.025): at one sample of Γ the coarser run's
    interpolated gap opens (its profile reads t = 0) while the nearest
    quadrature point sticks, and the finer run's closes.  The status the
    estimate compares is the law's at the profile's own jumps, so the two
    runs differ there and the estimate is warned (it read `differ 0`,
    the quadrature points' statuses, and t_T's effectivity was 5.3
    unwarned).  Each differing sample's t_T is zero in exactly one run."""
    from contactcore.estimate import status_along, status_change
    from contactcore.laws import OPEN
    from contactcore.profiles import sample_points
    from contactcore.scene import InterfaceProfile
    from xdolfinx.options import FE
    scene = load_scene(pathlib.Path(__file__).parent / "scenes" / "unil_partopen.toml")
    runs = [discretisation.solve(scene, FE(degree=1), h) for h in (0.05, 0.025)]
    change = status_change(scene, *runs, (0.05, 0.025))
    assert change["differ"] >= 1
    _, points, _ = sample_points(scene, InterfaceProfile("gamma", ("gN",)))
    statuses = [status_along(scene, r) for r in runs]
    tT = [interface_response(scene, r.fields, points, r.interface)["tT"] for r in runs]
    for i in np.flatnonzero(statuses[0] != statuses[1]):
        assert [s[i] == OPEN for s in statuses] == [t[i] == 0.0 for t in tT]
        assert (tT[0][i] == 0.0) != (tT[1][i] == 0.0)
    # the moved split moves the whole answer: every estimate is named, the bulk u_x
    # (its rigid shift, 0.087 of its error) with Γ's
    from contactcore.estimate import estimate_runs
    estimate = estimate_runs(scene, runs, exclude=0.0)
    named = {f"{pid}:{q}" for pid, qs in estimate.profiles.items() for q in qs}
    assert "H:ux" in named and named <= estimate.unsettled
    assert any("no estimate of this run is asymptotic" in w for w in estimate.warnings)


def test_a_change_in_the_solves_own_map_is_a_status_change_where_the_profile_shows_none():
    """unil_partopen in fe P2 at h = 0.05 -> 0.025: the status each
    profile's tractions follow (the law's at the profile's jump) is the
    same in both runs at every sample, but the nearest quadrature point's
    (contactcore.profiles.nearest_status, the solve's map) differs at
    some: the open/closed split moved, and status_change counts it (it
    read differ 0 with the profile's status alone, while g_T's and t_T's
    estimates were 0.37 and 0.32 of their error, 2026-11-29)."""
    from contactcore.estimate import status_along, status_change
    from contactcore.profiles import nearest_status, sample_points
    from contactcore.scene import InterfaceProfile
    from xdolfinx.options import FE
    scene = load_scene(pathlib.Path(__file__).parent / "scenes" / "unil_partopen.toml")
    runs = [discretisation.solve(scene, FE(degree=2), h) for h in (0.05, 0.025)]
    _, points, _ = sample_points(scene, InterfaceProfile("gamma", ("gN",)))
    profile = [status_along(scene, r) for r in runs]
    nearest = [nearest_status(scene, points, r.interface) for r in runs]
    assert np.array_equal(profile[0], profile[1])
    moved = int(np.sum(nearest[0] != nearest[1]))
    change = status_change(scene, *runs, (0.05, 0.025))
    assert moved >= 1 and change["differ"] == moved
    s, _, parameter = sample_points(scene, InterfaceProfile("gamma", ("gN",)))
    at = np.isin(s, [a for stretch in change["at"] for a in stretch])  # each stretch's ends are samples of Γ
    within = np.any([(s >= a) & (s <= b) for a, b in change["at"]], axis=0)
    assert change["parameter"] == parameter and np.array_equal(within, nearest[0] != nearest[1]) and at.any()


def test_stretches_of_differing_samples_run_from_first_to_last():
    """newuser35: summary.json's ``estimate.status`` says where Γ's status
    differs, as runs of consecutive samples."""
    from contactcore.estimate.status import stretches
    s = np.linspace(0.0, 1.0, 11)
    differ = np.array([0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1], bool)
    assert stretches(s, differ) == [[0.1, 0.2], [0.5, 0.5], [0.9, 1.0]]
    assert stretches(s, np.zeros(11, bool)) == []


def test_a_penalty_coulomb_gamma_that_slips_everywhere_reads_slip_at_every_sample():
    """grader28 F1 (tests/scenes/slide_everywhere.toml, penalty Coulomb
    μ = 0.6, dragged along Γ): every quadrature point slips in fe P1 at
    h = 0.1 and 0.05, and so does every profile sample; the runs' status
    does not differ.  Re-evaluated against the final slip, the law puts a
    point that slipped on its limit, where it reads stick: the estimate
    had read 82 % stick and warned of a moved split at 21 of 101 samples."""
    from contactcore.estimate import status_along, status_change
    from contactcore.laws import SLIP
    from contactcore.profiles import sample_points
    from contactcore.scene import InterfaceProfile
    from xdolfinx.options import FE
    scene = load_scene(pathlib.Path(__file__).parent / "scenes" / "slide_everywhere.toml")
    runs = [discretisation.solve(scene, FE(degree=1), h) for h in (0.1, 0.05)]
    _, points, _ = sample_points(scene, InterfaceProfile("gamma", ("gN",)))
    for r in runs:
        assert np.all(r.interface.final.reported_status() == SLIP)
        assert np.all(status_along(scene, r) == SLIP)
        # and the tractions those statuses say: on the cone (review12 #1: 13 of 101 samples at
        # down to 0.884 of it, the stick branch's, in fe P1), in the slip's direction
        t = interface_response(scene, r.fields, points, r.interface)
        assert np.array_equal(np.abs(t["tT"]), scene.law.mu * np.abs(t["tN"]))
        assert np.all(np.sign(t["tT"]) == np.sign(r.interface.final.traction[0, 1]))
    assert status_change(scene, *runs, (0.1, 0.05))["differ"] == 0


def test_a_grazing_gamma_reads_the_solves_tie_at_every_sample_whatever_the_round_off():
    """review11 #2: shear_unilateral (no load across Γ; closed form t_T =
    0.047, g_N = 0) in fe P2 at h = 0.1 and 0.05: every quadrature point
    sticks, and every profile sample's g_N is round-off (|g_N| <= 6.4e-18
    against g_T 1.2e-3).  Decided as the solve decided (the law's band,
    each sample's previous status its nearest point's), every sample is
    closed with the closed form's t_T, and the runs do not differ; decided
    by the sign of g_N's round-off, 100 or 101 of 101 samples read open
    (t_T = 0), as the BLAS kernel chose, and 34 or 39 differed."""
    from contactcore.estimate import status_along, status_change
    from contactcore.laws import OPEN
    from contactcore.profiles import sample_points
    from contactcore.scene import InterfaceProfile
    from xdolfinx.options import FE
    scene = load_scene(pathlib.Path(__file__).parent / "scenes" / "shear_unilateral.toml")
    runs = [discretisation.solve(scene, FE(degree=2), h) for h in (0.1, 0.05)]
    _, points, _ = sample_points(scene, InterfaceProfile("gamma", ("gN",)))
    for r in runs:
        assert not np.any(r.interface.final.reported_status() == OPEN)
        assert not np.any(status_along(scene, r) == OPEN)
        tT = interface_response(scene, r.fields, points, r.interface)["tT"]
        assert tT == pytest.approx(np.full(len(points), SHEAR_T_T), rel=tol.SHEAR_UNILATERAL_TRACTION)
    assert status_change(scene, *runs, (0.1, 0.05))["differ"] == 0


def test_a_sample_within_the_band_keeps_its_nearest_points_status_open_or_closed():
    """review12 #4: a penalty sample whose g_N lies within the law's band
    (DECISION_BAND of Γ's largest |g_N|) keeps its nearest quadrature
    point's status, the solve's previous one (contactcore.profiles._law_at's
    Decision): on unil_partopen fe P1 at h = 0.05 (37 of 101 samples
    nearest an open point), every sample given g_N = ±band/2 is open
    exactly where its nearest point is, with t = 0 there; beyond the band
    (±2 band) the sign decides.  A previous status taken as STICK whatever
    the map passed every other test."""
    from contactcore.laws import OPEN
    from contactcore.profiles import _jumps_at, _penalty_at, nearest_status, sample_points
    from contactcore.scene import InterfaceProfile
    from contactcore.tolerances import DECISION_BAND
    from xdolfinx.options import FE
    scene = load_scene(pathlib.Path(__file__).parent / "scenes" / "unil_partopen.toml")
    run = discretisation.solve(scene, FE(degree=1), 0.05)
    _, points, _ = sample_points(scene, InterfaceProfile("gamma", ("gN",)))
    path = run.interface
    near_open = nearest_status(scene, points, path) == OPEN
    assert 0 < near_open.sum() < len(points)
    band = DECISION_BAND * np.max(np.abs(path.final.jump[:, 0]))
    g = _jumps_at(scene, run.fields, points)
    for share, opened in ((0.5, near_open), (-0.5, near_open), (2.0, True), (-2.0, False)):
        g[:, 0] = share * band
        t, status = _penalty_at(scene, g, points, path)
        assert np.array_equal(status == OPEN, np.broadcast_to(opened, near_open.shape)), share
        assert np.all(t[status == OPEN] == 0.0)


def test_a_penalty_sample_nearest_a_partial_point_carries_its_share_of_the_tie(tmp_path):
    """review11 #7: a penalty sample whose nearest quadrature point is of
    the partial answer is reported partial and carries that point's
    traction, y_N = 0 with the share θ of its tie's shear, (0, θ k_T g_T);
    it carried the whole tie, k g (t_N -7.2e5 to -7.7e5 Pa, t_T 2.4e5 to
    3.9e5 below).  No penalty run measured has a partial point (`uni` on
    springs of 1e12-1e14, every method and degree, h = 0.1 and 0.05), so
    the run's map is given one: `uni` on springs kN = 1e13, kT = 3e12, fe
    P1 at h = 0.1, its third closed point made partial with θ = 0.4.  A
    sample there whose gap opens reads open with t = 0, as any other
    (review13 #3)."""
    from dataclasses import replace
    from contactcore.laws import OPEN
    from contactcore.profiles import nearest_status, sample_points
    from contactcore.scene import InterfaceProfile
    from xdolfinx.options import FE
    text = (pathlib.Path(__file__).parent / "scenes" / "uni_opening.toml").read_text()
    path = tmp_path / "uni_springs.toml"
    path.write_text(text.replace('enforcement = "exact"', "kN = 1e13\nkT = 3e12"))
    scene = load_scene(path)
    run = discretisation.solve(scene, FE(degree=1), 0.1)
    final = run.interface.final
    theta = np.full(len(final.status), np.nan)
    theta[np.flatnonzero(final.status != OPEN)[2]] = 0.4
    given = replace(run.interface, steps=run.interface.steps[:-1] + [replace(final, theta=theta)])
    _, points, _ = sample_points(scene, InterfaceProfile("G", ("gN",)))
    near = np.flatnonzero(nearest_status(scene, points, given) == PARTIAL)
    assert len(near) >= 1
    t = interface_response(scene, run.fields, points, given)
    assert np.all(t["tN"][near] == 0.0)
    assert np.array_equal(t["tT"][near], 0.4 * scene.law.kT * t["gT"][near])
    plain = interface_response(scene, run.fields, points, run.interface)
    others = np.setdiff1d(np.arange(len(points)), near)
    assert np.array_equal(t["tT"][others], plain["tT"][others]) and np.all(plain["tN"][near] < 0)
    # the same samples with their gaps opened beyond the band read open with t = 0, as any other
    from contactcore.profiles import _jumps_at, _penalty_at
    g = _jumps_at(scene, run.fields, points)
    g[near, 0] = np.max(np.abs(final.jump[:, 0]))
    opened, status = _penalty_at(scene, g, points, given)
    assert np.all(status[near] == OPEN) and np.all(opened[near] == 0.0)


def test_a_sample_midway_between_two_quadrature_points_takes_the_first_along_gamma_whatever_the_round_off():
    """contactcore.profiles.nearest_status (review12 #5): a sample at
    x = 0.1 on A's Γ, between points at 0 (open) and 0.2 (stick), and the
    same sample 1e-17 either side (round-off of a distance), take the
    status of the point first along Γ; a sample clearly nearer 0.2 takes
    its status."""
    from types import SimpleNamespace
    from contactcore.laws import OPEN
    from contactcore.profiles import nearest_status
    scene = load_scene("A")
    status = np.array([OPEN, STICK], np.int8)
    path = SimpleNamespace(points=np.array([[0.2, 0.5], [0.0, 0.5]])[::-1].copy(),
                           final=SimpleNamespace(reported_status=lambda: status))
    samples = np.array([[0.1, 0.5], [0.1 + 1e-17, 0.5], [0.1 - 1e-17, 0.5], [0.1 + 2.8e-17, 0.5], [0.15, 0.5]])
    assert nearest_status(scene, samples, path).tolist() == [OPEN, OPEN, OPEN, OPEN, STICK]
    path.points = path.points[::-1].copy()  # the points' order plays no part
    status = status[::-1].copy()
    path.final = SimpleNamespace(reported_status=lambda: status)
    assert nearest_status(scene, samples, path).tolist() == [OPEN, OPEN, OPEN, OPEN, STICK]
