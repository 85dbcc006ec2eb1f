"""GetFEM's contact bricks as a peer of our exact contact
(verification/peer_getfem_contact/, docs/peer-contact.md).

The default stage needs no GetFEM: the module imports without it, a scene
outside its reach is refused by name before GetFEM is asked for, a missing
GetFEM is one clear error, and its numerics that do not call GetFEM (Γ's
facet quadrature, the status test, the comparison) are checked by hand.
The slow stage solves scenes A and C-coulomb with GetFEM and with fe P2
and asserts the agreement measured in docs/peer-contact.md."""
import re
import subprocess
import sys

import numpy as np
import pytest

from contactcore import DiscretisationError, ProfileData, SceneError, load_scene
from contactcore.enforcement import make_law
from contactcore.laws import OPEN, SLIP, STICK
from contactcore.scene import Pin, Pressure, Traction
from verification import peer_getfem_contact as peer
from verification.closed_forms import layered_slip, pressurised_rod

import tolerances as tol


def test_the_module_imports_without_getfem():
    code = ("import sys; sys.modules['getfem'] = None; import verification.peer_getfem_contact as p; "
            "print(p.METHOD)")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == peer.METHOD


def _exact(name: str, law: dict):
    return load_scene(name).with_changes(law=make_law(law))


@pytest.mark.parametrize("scene,problem", [
    (load_scene("C-coulomb"), 'the interface law must be unilateral or coulomb with enforcement = "exact" '
                              "\\(got penalty 'coulomb'\\)"),
    (load_scene("A"), "the interface law must be unilateral or coulomb .* \\(got penalty 'linear'\\)"),
    (_exact("A", {"type": "bonded"}), "the interface law must be unilateral or coulomb .* \\(got exact 'bonded'\\)"),
    (pressurised_rod().scene, "the domain must be a rectangle"),
    (load_scene("B").with_changes(law=make_law({"type": "coulomb", "mu": 0.2, "enforcement": "exact"})),
     "loads must be edge tractions or pressures"),
    (_exact("A", {"type": "unilateral", "enforcement": "exact"}).with_changes(pins=(Pin((0.2, 0.8)),)),
     "supports must hold whole edges \\(no pins\\)"),
])
def test_a_scene_outside_its_reach_is_refused_by_name(scene, problem, monkeypatch):
    monkeypatch.setitem(sys.modules, "getfem", None)  # refused before GetFEM is asked for
    with pytest.raises(DiscretisationError, match=f"scene {scene.name} is outside the peer's reach: .*{problem}"):
        peer.solve(scene, 0.1)


@pytest.mark.parametrize("options,problem", [({"degree": 3}, "degree must be 1 or 2 \\(got 3\\)"),
                                             ({"paper": True}, "the paper's grids are structured")])
def test_a_bad_resolution_is_refused(options, problem):
    with pytest.raises(DiscretisationError, match=problem):
        peer.solve(peer.exact_scene("A"), 0.1, **options)


@pytest.mark.parametrize("h,problem", [(0.0, "h: must be a finite number > 0 \\(got 0.0\\)"),
                                       (2.0, "h: 2 m exceeds the domain's smallest dimension 1 m")])
def test_a_bad_h_is_refused_not_replaced_by_the_scenes(h, problem, monkeypatch):
    monkeypatch.setitem(sys.modules, "getfem", None)  # refused before GetFEM is asked for
    with pytest.raises(SceneError, match=problem):
        peer.solve(peer.exact_scene("A"), h)


@pytest.mark.parametrize("h,problem", [
    ("0", "--h: must be a finite number > 0 \\(got 0.0\\)"),
    ("1e-9", "--h 1e-09 with fe \\(degree 2, 20 increments\\): about .* GB usable on this machine"),
    ("0.001", "--h 0.001 with getfem-contact \\(degree 2, 20 increments\\)")])
def test_the_study_refuses_an_h_before_any_mesh(h, problem, capsys, monkeypatch):
    """The study checks every h before any solve: one line, exit 2 (an h
    of 1e-9 meshed until the machine killed it); the peer's own size
    (efgm's run at h = 0.001 fits, GetFEM's P2 meshes do not)."""
    monkeypatch.setattr(peer.solver, "_Bodies", None)  # no mesh is made
    methods = ["efgm"] if h == "0.001" else ["fe"]
    assert peer.main(["A", "--h", "0.1", h, "--methods", *methods]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and re.match(f"error: {problem}", err[0]), err


def test_a_missing_getfem_is_one_clear_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "getfem", None)
    with pytest.raises(DiscretisationError, match="GetFEM is not installed"):
        peer.solve(peer.exact_scene("C-coulomb"), 0.1)


def test_a_scene_outside_the_study_is_refused():
    with pytest.raises(DiscretisationError, match="no study scene 'B'"):
        peer.exact_scene("B")


def test_the_studys_scenes_are_exact_and_within_reach(monkeypatch):
    """Every scene of the study has an exact unilateral or Coulomb law and
    passes the peer's check; the inclined A's Γ is turned as named, the
    slipping wedge carries its own μ and top traction."""
    monkeypatch.setitem(sys.modules, "getfem", None)
    for name in peer.STUDIES:
        scene = peer.exact_scene(name)
        assert scene.law.enforcement == "exact" and scene.law.name in ("unilateral", "coulomb")
        peer._check(scene, 2, False)
    normal = peer.exact_scene("A-inclined").interface.normal
    assert np.degrees(np.arctan2(-normal[0], normal[1])) == pytest.approx(peer.INCLINED_A[0])
    slipping = peer.exact_scene("wedge-slip")
    assert (slipping.law.mu, slipping.loads[0].value) == peer.WEDGE_SLIP


def test_a_pressure_is_the_traction_against_its_edges_outward_normal():
    assert list(peer._edge_traction(Pressure("top", 2.0))) == [0.0, -2.0]
    assert list(peer._edge_traction(Pressure("left", 2.0))) == [2.0, 0.0]
    assert list(peer._edge_traction(Traction("right", (1.0, -3.0)))) == [1.0, -3.0]


def test_a_straight_facet_has_its_length_and_its_points_on_it():
    a, b = np.array([0.0, 0.5]), np.array([0.3, 0.9])
    for facet, degree in ((np.array([[a, b]]), 1), (np.array([[a, b, (a + b) / 2]]), 2)):
        pts, w, sizes = peer._facet_points(facet, degree)
        assert list(sizes) == [peer.FACET_POINTS]
        assert abs(w.sum() - 0.5) <= tol.PATCH_ROUNDOFF
        cross = (pts[:, 0] - a[0]) * (b[1] - a[1]) - (pts[:, 1] - a[1]) * (b[0] - a[0])
        assert np.abs(cross).max() <= tol.PATCH_ROUNDOFF


def test_a_curved_facet_follows_the_circle():
    """Three points of a circle's arc of angle h/R: the quadratic facet's
    length is the arc's to O((h/R)⁴) and its Gauss points lie on the circle
    to O((h/R)⁴) of R."""
    R, angle = 0.45, 0.1
    ends = R * np.array([[np.cos(0), np.sin(0)], [np.cos(angle), np.sin(angle)], [np.cos(angle / 2), np.sin(angle / 2)]])
    pts, w, _ = peer._facet_points(ends[None], 2)
    assert abs(w.sum() - R * angle) <= tol.PEER_CONTACT_CURVED_FACET * R * angle
    assert np.abs(np.linalg.norm(pts, axis=1) - R).max() <= tol.PEER_CONTACT_CURVED_FACET * R


def test_the_status_is_getfems_augmented_test():
    """Open where λ_N + r g_N ≥ 0; closed points stick while
    |λ_T + r Δg_T| ≤ μ(−λ_N − r g_N), else slip."""
    r, mu = 10.0, 0.5
    t = np.array([[0.0, 0.0], [-10.0, 4.0], [-10.0, 6.0], [-10.0, 4.0], [-1.0, 0.0]])
    g = np.array([[1.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.2, 0.0]])
    dg = np.array([[0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.2], [0.0, 0.0]])
    assert list(peer._Gamma.status(t, g, dg, r, mu)) == [OPEN, STICK, SLIP, SLIP, OPEN]


def _profiles(values: dict) -> dict:
    s = np.linspace(0.0, 2.0, 5)
    return {pid: ProfileData(pid, "arclength", {"s": s, "x": s, "y": np.full(5, 1.5), **cols})
            for pid, cols in values.items()}


def test_differences_are_shares_of_our_largest_value_away_from_corners():
    scene = peer.exact_scene("C-coulomb")
    ours = _profiles({"C3": {"syy": np.array([9.0, -4.0, 2.0, 0.0, -1.0])}})
    got = _profiles({"C3": {"syy": np.array([9.0, -3.0, 2.0, 0.0, -1.0])}})
    (row,) = peer.differences(scene, got, ours)
    assert (row.profile, row.quantity, row.at) == ("C3", "syy", 0.5)
    assert row.worst == pytest.approx(1 / 9) and row.rms == pytest.approx(np.sqrt(1 / 5) / 9)


# ----- with GetFEM ------------------------------------------------------------------

def _ours_and_peer(name: str, h: float):
    pytest.importorskip("getfem", reason="GetFEM is not installed (sudo apt-get install python3-getfem)")
    from contactcore import sample_profiles
    from verification import methods
    scene = peer.exact_scene(name)
    runs = [methods.solver("fe")(scene, h, degree=2), peer.solve(scene, h, degree=2)]
    profiles = [{p.id: p for p in sample_profiles(scene, r.fields, r.interface)} for r in runs]
    return scene, runs, profiles


@pytest.mark.slow
@pytest.mark.parametrize("name,h,bounds", [("A", 0.025, tol.PEER_CONTACT_A), ("C-coulomb", 0.025, tol.PEER_CONTACT_C)],
                         ids=["A", "C-coulomb"])
def test_getfems_contact_agrees_with_our_exact_answer(name, h, bounds):
    """Every profile quantity within the RMS share measured at h = 0.025
    (docs/peer-contact.md), and Γ's open share within its bound."""
    scene, runs, (ours, theirs) = _ours_and_peer(name, h)
    for row in peer.differences(scene, theirs, ours):
        assert row.rms <= bounds["rms"][(row.profile, row.quantity)], row
    split = [peer.status_split(r) for r in runs]
    assert abs(split[0]["open"] - split[1]["open"]) <= bounds["open"]


@pytest.mark.slow
@pytest.mark.parametrize("degree", [1, 2])
def test_getfem_follows_the_layered_closed_form_through_stick_slip_and_reversal(degree):
    """The layered-slip closed form with exact Coulomb: at every increment
    Γ's mean traction is (−p, τ) and its jump (0, s), and every point
    sticks or slips as the closed form does, but where a stick's |τ|
    reaches μp (the last stick step before a slip, decided by round-off)."""
    pytest.importorskip("getfem", reason="GetFEM is not installed (sudo apt-get install python3-getfem)")
    case = layered_slip(exact=True)
    result = peer.solve(case.scene, case.scene.h, degree=degree)
    p = -case.scene.loads[0].value[1]
    limit = case.mu * p
    for state, means, step in zip(case.history(), peer.path_means(result), result.interface.steps):
        exact = np.array([-state.p, state.tau, 0.0, state.slip])
        assert np.abs(means[:2] - exact[:2]).max() <= tol.PEER_CONTACT_LAYERED * p, (step.step, means)
        stick_limit = limit * case.compliance
        assert np.abs(means[2:] - exact[2:]).max() <= tol.PEER_CONTACT_LAYERED * stick_limit, (step.step, means)
        if state.status == "slip" or abs(state.tau) < limit * (1 - tol.EXACT_LIMIT_BAND):
            assert np.all(step.status == (STICK if state.status == "stick" else SLIP)), step.step


@pytest.mark.slow
@pytest.mark.parametrize("name,bounds", [("A-inclined", tol.PEER_CONTACT_INCLINED_A),
                                         ("wedge-slip", tol.PEER_CONTACT_WEDGE_SLIP)])
def test_getfems_contact_and_ours_converge_to_one_answer(name, bounds):
    """fe P2 against GetFEM P2 at h = 0.05 and 0.025: every RMS difference
    falls by PEER_CONTACT_FALL or more and ends within its bound
    (docs/peer-contact.md)."""
    pytest.importorskip("getfem", reason="GetFEM is not installed (sudo apt-get install python3-getfem)")
    rows, _, _ = peer.study(name, (0.05, 0.025))
    for coarse, fine in zip(rows["fe", 0.05], rows["fe", 0.025]):
        assert fine.rms <= coarse.rms / tol.PEER_CONTACT_FALL, (coarse, fine)
        assert fine.rms <= bounds[(fine.profile, fine.quantity)], fine
