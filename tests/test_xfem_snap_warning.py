"""XFEM says when it moved Γ onto mesh nodes (grader24's F5,
2026-11-28): a bonded Γ at 45° passing 1e-6 off a node diagonal was
snapped onto it, t_N of a uniform σ = −pI moving by 2.5e-5 p, unwarned."""
import tomllib

import pytest

from contactcore.scene_files import scene_from_dict
from contactcore.tolerances import XFEM_SNAP_WARN
from verification import methods

SCENE = "tests/scenes/diagonal_near_nodes.toml"
#: The scene's grid: Γ's offsets below are in y, a cell's diameter √2·H.
H = 0.1
#: Γ's offsets in y on either side of the bound: 1e-6 moves it 5e-6 of a
#: cell's diameter (dy/√2 over √2·H), 1e-9 moves it 5e-9, below XFEM_SNAP_WARN.
WARNED_OFFSET, SILENT_OFFSET = 1e-6, 1e-9


def _offset(dy: float):
    data = tomllib.loads(open(SCENE).read())
    data["interface"]["point"] = [0.0, 0.5 + dy]
    return scene_from_dict(data)


def _snap_warnings(dy: float, degree: int = 1) -> list[str]:
    result = methods.solver("xfem")(_offset(dy), H, degree=degree)
    return [w for w in result.solver.warnings if "XFEM moved it" in w]


@pytest.mark.parametrize("degree", [1, 2])
def test_a_gamma_snapped_onto_nodes_is_warned(degree):
    warned = _snap_warnings(WARNED_OFFSET, degree)
    assert len(warned) == 1 and "5.0e-06 of a cell's diameter" in warned[0], warned


def test_gamma_on_the_nodes_or_closer_than_the_bound_is_not_warned():
    assert SILENT_OFFSET / (2 * H) < XFEM_SNAP_WARN < WARNED_OFFSET / (2 * H)
    assert not _snap_warnings(0.0) and not _snap_warnings(SILENT_OFFSET)
