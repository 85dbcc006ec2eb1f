"""Geometry kept between Newton's questions (costexact, 2026-11-29): the
restraint's supports and Γ's modal jumps (contactcore.health.restraint
._geometry) and xfem's edges with both ends on Γ
(EnrichedFunctionSpace.edge_neighbours).  Kept, they must give what a
fresh computation gives, for the scene and Γ asked about and no other."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from contactcore import LineInterface, load_scene, make_law  # noqa: E402
from contactcore.health import restraint  # noqa: E402
from contactcore.laws import OPEN, SLIP, STICK  # noqa: E402


def _circle_points(scene, m: int):
    """``m`` points on C's circle and their weights."""
    itf = scene.interface
    a = np.linspace(0.0, 2 * np.pi, m, endpoint=False)
    pts = np.column_stack([itf.centre[0] + itf.radius * np.cos(a), itf.centre[1] + itf.radius * np.sin(a)])
    return pts, np.full(m, 2 * np.pi * itf.radius / m)


def _fresh(scene, pts, w, holding=None, gripping=None):
    """``_restraint`` with nothing kept."""
    restraint._geometry_kept.clear()
    return restraint._restraint(scene, pts, w, holding, gripping)


def test_kept_restraint_is_the_fresh_one_for_each_scene_and_gamma():
    """Asked in turn about two scenes (C, and C held at its top instead of
    its bottom) and two sets of Γ points, each answer is the one computed
    afresh, bit for bit: no scene or Γ reads another's supports or jumps."""
    c = load_scene("C-coulomb")
    support = c.supports[0]
    top = c.with_changes(supports=(type(support)(**{**support.__dict__, "boundary": "top"}),))
    (p1, w1), (p2, w2) = _circle_points(c, 40), _circle_points(c, 41)
    status = np.array([(OPEN, STICK, SLIP)[i % 3] for i in range(40)], np.int8)
    cases = [(c, p1, w1), (top, p1, w1), (c, p2, w2), (top, p2, w2)]
    fresh = [_fresh(s, p, w, status[:len(w)] != OPEN if len(w) == 40 else None) for s, p, w in cases]
    restraint._geometry_kept.clear()
    for _ in range(2):  # the second round from what the first kept
        for (s, p, w), want in zip(cases, fresh):
            got = restraint._restraint(s, p, w, status[:len(w)] != OPEN if len(w) == 40 else None)
            for a, b in zip(got, want):
                assert np.array_equal(a, b)
    assert not np.array_equal(fresh[0][0], fresh[1][0])  # the two scenes' supports do differ
    assert len(restraint._geometry_kept) <= restraint._GEOMETRY_KEPT


def test_kept_restraint_decides_as_before():
    """lets_go and slips_free on C from what is kept: every point open lets
    the rod go, every point slipping leaves it free to turn in its hole
    (the disc in the plate), a sticking map holds it."""
    c = load_scene("C-coulomb")
    pts, w = _circle_points(c, 60)
    restraint._geometry_kept.clear()
    for _ in range(2):
        assert restraint.lets_go(c, pts, w, np.full(60, OPEN, np.int8))
        assert restraint.slips_free(c, pts, w, np.full(60, SLIP, np.int8))
        assert not restraint.slips_free(c, pts, w, np.full(60, STICK, np.int8))


@pytest.mark.parametrize("a", [1.2, 1.23])
def test_xfem_edges_on_gamma_are_every_such_edge_with_its_cells(a):
    """The kept edges are exactly the cells' edges whose two ends lie on Γ,
    each with every cell holding it in cell order (a brute force over the
    mesh); none where Γ runs between node lines."""
    from mpi4py import MPI

    from xdolfinx import xfem
    scene = load_scene(str(HERE / "scenes" / "nodeline_bar.toml"))
    scene = scene.with_changes(interface=LineInterface((a, 0.0), (1.0, 0.0)),
                               law=make_law({"type": "coulomb", "mu": 0.3, "enforcement": "exact"})).validated()
    space = xfem.enriched_space(xfem.background_mesh(scene, 0.1, "quad", comm=MPI.COMM_SELF), 1, scene, 3)
    nodes, on = space.cells.corner_nodes, space.cells.node_on
    want: dict = {}
    for c in range(len(nodes)):
        for i in range(nodes.shape[1]):
            p, q = int(nodes[c, i]), int(nodes[c, (i + 1) % nodes.shape[1]])
            if on[p] and on[q]:
                want.setdefault((min(p, q), max(p, q)), []).append(c)
    got = space.edge_neighbours()
    assert got == want and list(got) == list(want)
    assert space.edge_neighbours() is got  # made once per space
    assert (len(got) > 0) == (a == 1.2)  # Γ on the node line x = 12 h has such edges; between lines none
