"""XFEM with Γ through mesh nodes or within round-off of them (issue 19).

A body's points that fall in a sliver of a cut cell (Γ passes a node at
1e-6 h) are evaluated in the neighbouring cell that resolves that body
(``EnrichedFunctionSpace.cells_resolving``); every sample of every profile,
on Γ and off it, must then agree with fe P2 at h/2.  Scene A with a straight
Γ along a node row (and so along the cells' edges) and 1e-12 h, 1e-6 h off
it is checked too on quads, P2: 0.020 on the row, 0.045 at 1e-6 h below it
(0.12-0.16 with a sliver's points evaluated in the sliver's own cell; P1
quads give 0.23-0.26 and triangles 0.08-0.67 in σxx on y = 1, away from Γ:
the coarse cells' own error at h = 0.05).  The pressurised rod's
rate with nodes on Γ is checked by tests/test_xfem.py (R = 0.4 is a multiple
of every h of its ladder)."""
from functools import lru_cache

import pytest

import tolerances as tol
from contactcore import sample_profiles
from placements import circle_C, inclined_A, worst_sample
from xdolfinx import conforming, xfem

H = 0.05
#: Radii on a node row (6 h) and just off it, in units of h.
OFFSETS = [0.0, 1e-12, -1e-12, 1e-6, -1e-6]


@lru_cache(maxsize=None)
def _reference(kind: str, offset: float):
    scene = circle_C((1.0, 1.5), 0.3 + offset * H) if kind == "C" else inclined_A(0.0, 0.5 + offset * H)
    return scene, {p.id: p for p in sample_profiles(scene, conforming.solve(scene, H / 2, degree=2).fields)}


def _case(kind, offset, cell, degree, marks=()):
    return pytest.param(kind, offset, cell, degree, marks=marks, id=f"{kind}{offset:+g}h-{cell}-P{degree}")


FAST = [_case("C", 1e-6, "quad", 1), _case("C", 1e-6, "quad", 2), _case("C", -1e-6, "quad", 2),
        _case("C", 1e-6, "triangle", 2), _case("A", 0.0, "quad", 2)]
SLOW = [_case("C", off, cell, deg, marks=pytest.mark.slow) for off in OFFSETS for cell in ("quad", "triangle", "gmsh")
        for deg in (1, 2) if _case("C", off, cell, deg).id not in {c.id for c in FAST}]
SLOW += [_case("A", off, "quad", 2, marks=pytest.mark.slow) for off in OFFSETS[1:]]


@pytest.mark.parametrize("kind, offset, cell, degree", FAST + SLOW)
def test_gamma_through_nodes_agrees_with_fe(kind, offset, cell, degree):
    scene, ref = _reference(kind, offset)
    got = {p.id: p for p in sample_profiles(scene, xfem.solve(scene, H, degree=degree, cell=cell).fields)}
    worst, pid, q = worst_sample(scene, got, ref)
    assert worst <= tol.XFEM_NODE_AGREE[degree], (worst, pid, q)
