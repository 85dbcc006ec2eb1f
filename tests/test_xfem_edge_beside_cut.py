"""review2 (2026-11-27): Γ along a node line between a whole cell and a
cut cell across it was integrated nowhere.  The level set
φ = (x − 1.2)(1.25 − x) on the nodeline bar (3 × 0.5 m, h = 0.1) has Γ at
x = 1.2 (a node line) and x = 1.25 (inside the next column of cells): the
cells left of x = 1.2 are whole −, those right of it are cut by x = 1.25.
Since snapfix, _edge_rules gives the on-Γ edge's rule to the whole − cell
only where the cell across is whole +; the cut cell's own rule covers
x = 1.25 alone, so Γ's rule sums to 0.5 m of its 1.0 m (at 7be9590: 1.0).
The mirror φ = −(x − 1.2)(1.25 − x) (whole + beside a cut cell) lost the
edge before snapfix too, and still does (docs/methods/xfem.md, "Limits"):
its case is marked xfail, strict, so that a fix shows."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import tolerances as tol  # noqa: E402


def _strip(sign: float):
    from contactcore import LevelSetInterface
    return LevelSetInterface(lambda p: sign * (p[:, 0] - 1.2) * (1.25 - p[:, 0]),
                             lambda p: sign * np.column_stack([2.45 - 2 * p[:, 0], 0 * p[:, 0]]))


@pytest.mark.parametrize("cell", ["quad", "triangle"])
@pytest.mark.parametrize("sign", [1.0, pytest.param(-1.0, marks=pytest.mark.xfail(strict=True, reason="a whole + cell beside a cut cell holds no edge rule"))])
def test_gamma_along_a_node_line_beside_a_cut_cell_is_integrated_once(cell, sign):
    from contactcore import load_scene
    from xdolfinx.xfem.cells import CellBasis, background_mesh
    from xdolfinx.xfem.cut import CutIntegration
    scene = load_scene(str(HERE / "scenes" / "nodeline_bar.toml")).with_changes(interface=_strip(sign))
    cut = CutIntegration(CellBasis(background_mesh(scene, 0.1, cell), 1, scene), scene, 3)
    length = sum(float(np.sum(w)) for _, w, _ in cut.gamma_rules.values())
    assert length == pytest.approx(2 * 0.5, rel=tol.NODELINE_ROUNDOFF)
