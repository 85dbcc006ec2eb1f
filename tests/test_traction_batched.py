"""xfem's Nitsche traction operator, computed for all cells at once
(xdolfinx.xfem.traction.traction_operator), against the cell-by-cell
assembly it replaced (each cell's :func:`cell_traction` rows added to the
COO sink in turn): the same ``S`` — pattern and values, bit for bit — and
the same γ₀.  On a circle (cut cells, the batched path, triangles and
quads) and on Γ along a node line (cells whose rows read the whole cell
across an edge, :func:`_edge_traction`, mixed with the others).
"""
import dataclasses
from pathlib import Path

import numpy as np
import pytest

from contactcore import BODIES, CircleInterface, load_scene
from contactcore.assembly import Triplets
from nitsche_fields import build, exact
from xdolfinx.xfem import traction

#: Coarse enough to be quick; the equality holds on any mesh.
H = 0.1


def _cell_by_cell(space):
    """``(S, γ₀)`` assembled a cell at a time from :func:`cell_traction`."""
    scene = space.scene
    D = scene.voigt_matrices()
    moduli = np.array([scene.materials[b].E for b in BODIES])
    trip = Triplets((0, 2 * space.num_blocks))
    gammas, m = [], 0
    edges = space.edge_neighbours()
    for c in (c for c in space.owned_band if c in space.cut.gamma_rules):
        blocks, rows, gamma = traction.cell_traction(space, c, D, moduli, edges)
        P = len(gamma)
        cols = np.where(blocks[:, None] >= 0, 2 * blocks[:, None] + np.arange(2), -1).ravel()
        trip.add(2 * (m + np.arange(P))[:, None, None] + np.arange(2)[None, :, None], cols[None, None, :], rows)
        gammas.append(gamma)
        m += P
    trip.shape = (2 * m, trip.shape[1])
    return trip.to_csr(), np.concatenate(gammas)


def _circle():
    scene = load_scene("C").with_changes(interface=CircleInterface((1.0, 1.5), 0.45))
    materials = {b: dataclasses.replace(scene.materials[b], E=E) for b, E in zip(BODIES, (2e11, 5e10))}
    return exact(scene.with_changes(materials=materials))


def _node_line():
    return exact(load_scene(Path(__file__).parent / "scenes" / "nodeline_bar.toml"))


@pytest.mark.parametrize("scene, cell", [(_circle, "triangle"), (_circle, "quad"), (_node_line, "quad")],
                         ids=["circle-triangle", "circle-quad", "node-line"])
@pytest.mark.parametrize("degree", [1, 2])
def test_all_cells_at_once_is_the_cell_by_cell_assembly(scene, cell, degree, monkeypatch):
    spaces = []
    made = traction.traction_operator

    def keep(space):
        spaces.append(space)
        return made(space)

    monkeypatch.setattr(traction, "traction_operator", keep)
    built = build("xfem", scene(), degree, H, cell=cell)
    built.system.close()
    (space,) = spaces
    S, gamma = made(space)
    S0, gamma0 = _cell_by_cell(space)
    assert S.shape == S0.shape and len(gamma) > 0
    assert np.array_equal(S.indptr, S0.indptr) and np.array_equal(S.indices, S0.indices)
    assert np.array_equal(S.data, S0.data)
    assert np.array_equal(gamma, gamma0)
