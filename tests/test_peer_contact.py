"""GetFEM's contact bricks as a peer of our exact contact
(verification/peer_getfem_contact.py, docs/peer-contact.md).

The default stage needs no GetFEM: the module imports without it, a scene
outside its reach is refused by name before GetFEM is asked for, a missing
GetFEM is one clear error, and its numerics that do not call GetFEM (Γ's
facet quadrature, the status test, the comparison) are checked by hand.
The slow stage solves scenes A and C-coulomb with GetFEM and with fe P2
and asserts the agreement measured in docs/peer-contact.md."""
import subprocess
import sys

import numpy as np
import pytest

from contactcore import DiscretisationError, ProfileData, load_scene
from contactcore.enforcement import make_law
from contactcore.laws import OPEN, SLIP, STICK
from verification import peer_getfem_contact as peer
from verification.closed_forms import pressurised_rod

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
     "loads must be edge tractions"),
    (load_scene("A-cyclic").with_changes(law=make_law({"type": "coulomb", "mu": 0.3, "enforcement": "exact"})),
     "supports must clamp whole edges"),
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


def test_a_missing_getfem_is_one_clear_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "getfem", None)
    with pytest.raises(DiscretisationError, match="GetFEM is not installed"):
        peer.solve(peer.exact_scene("C-coulomb"), 0.1)


def test_a_scene_without_a_study_law_is_refused():
    with pytest.raises(DiscretisationError, match="no study law for scene 'B'"):
        peer.exact_scene("B")


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
