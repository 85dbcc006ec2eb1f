"""XFEM with a straight Γ turned off the node rows in scene A (issue 22).

Where Γ cuts a corner or a thin strip off a cell, the body's polynomial in
that cell is fitted to the sliver alone; such points are evaluated in the
nearest cell that resolves the body (tol.SLIVER_EVAL_DEPTH), and a node is
enriched when its stiffness, not its value, reaches across Γ
(xfem.MIN_CUT_FRACTION).  At degree 1 a body's stress is recovered from
its cells' stresses at their parts' centroids (contactcore.recovery): a cut
part's centroid lies up to 0.7 h off Γ, where σ varies steeply across it.
Every sample of every profile, away from corners and Γ's ends, must agree
with fe P2 at h/2 within XFEM_INCLINED_AGREE (the issue's 2 % and 15 %)."""
from functools import lru_cache

import pytest

import tolerances as tol
from contactcore import sample_profiles
from placements import circle_C, inclined_A, one_sided_gaps, seeded_inclined, worst_sample
from xdolfinx import conforming, xfem

H = 0.025
#: the issue's geometry, then 23 seeded draws (the EFGM tests' list)
PLACEMENTS = [(20.0, 0.4)] + seeded_inclined(23)
#: by default: the issue's geometry, and the draws that are hardest for the
#: enrichment and sliver rules (index 3: P2 quads 2.5 %; 21: P2 triangles 71x; 12: P2
#: triangles 85 %, a node whose gradient reached across a corner h/2500 deep;
#: 16: P1 quads 0.75), and the worst P1 draws with the stress recovered (9:
#: triangles 0.124; 5: quads 0.076) and read from the cell's own field
#: (18: quads 0.29, triangles 0.31)
DEFAULT = {(0, "quad", 2), (16, "quad", 1), (3, "quad", 2), (21, "triangle", 2), (12, "triangle", 2),
           (9, "triangle", 1), (5, "quad", 1), (18, "triangle", 1)}


@lru_cache(maxsize=None)
def _reference(angle, height):
    scene = inclined_A(angle, height)
    return scene, {p.id: p for p in sample_profiles(scene, conforming.solve(scene, H / 2, degree=2).fields)}


def _cases():
    return [pytest.param(k, cell, degree, marks=[] if (k, cell, degree) in DEFAULT else [pytest.mark.slow],
                         id=f"{PLACEMENTS[k][0]:+.1f}deg-{PLACEMENTS[k][1]:.3f}-{cell}-P{degree}")
            for k in range(len(PLACEMENTS)) for cell in ("quad", "triangle") for degree in (1, 2)]


@pytest.mark.parametrize("k, cell, degree", _cases())
def test_inclined_gamma_agrees_with_fe(k, cell, degree):
    scene, ref = _reference(*PLACEMENTS[k])
    got = {p.id: p for p in sample_profiles(scene, xfem.solve(scene, H, degree=degree, cell=cell).fields)}
    worst, pid, q = worst_sample(scene, got, ref)
    assert worst <= tol.XFEM_INCLINED_AGREE[cell, degree], (worst, pid, q)


@pytest.mark.parametrize("k, cell, x", [(0, "quad", 0.8325), (21, "triangle", 0.75), (12, "triangle", 0.2)])
def test_stress_on_gamma_is_its_one_sided_limit(k, cell, x):
    """P2: σ of the + body at a point of Γ equals σ 1e-6 off Γ and the
    quadratic extrapolation to Γ of σ at h/8, h/4 and 3h/8 off Γ; the last
    two points are within h/2500 of a node, where a sliver's polynomial
    gave 71x (21) and 2x (12) before."""
    angle, height = PLACEMENTS[k]
    scene = inclined_A(angle, height)
    fields = xfem.solve(scene, H, degree=2, cell=cell).fields
    gaps = one_sided_gaps(fields, scene, x, angle, H)
    assert max(gaps) <= tol.XFEM_ONE_SIDED, gaps


#: off-centre rods (centre, radius) of scene C (the EFGM tests' list)
CIRCLES = [((0.93, 1.43), 0.45), ((1.063, 1.581), 0.421)]


@lru_cache(maxsize=None)
def _rod_reference(centre, radius):
    scene = circle_C(centre, radius)
    return scene, {p.id: p for p in sample_profiles(scene, conforming.solve(scene, H / 2, degree=2).fields)}


@pytest.mark.slow
@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("cell", ["quad", "triangle"])
@pytest.mark.parametrize("centre,radius", CIRCLES)
def test_off_centre_rod_agrees_with_fe(centre, radius, cell, degree):
    """Scene C with its rod moved off the node rows, at the issue's h (the
    inclined Γ's), against fe P2 at h/2 (tests/tolerances.py::XFEM_ROD_AGREE)."""
    scene, ref = _rod_reference(centre, radius)
    got = {p.id: p for p in sample_profiles(scene, xfem.solve(scene, H, degree=degree, cell=cell).fields)}
    worst, pid, q = worst_sample(scene, got, ref)
    assert worst <= tol.XFEM_ROD_AGREE[cell, degree], (worst, pid, q)
