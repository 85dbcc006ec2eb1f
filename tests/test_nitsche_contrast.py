"""Exact contact across a stiffness contrast (XFEM's Nitsche γ₀ on cut
cells): a stiff disc in a ring 100 times softer under outer pressure
(tests/scenes/cylinder.toml, whose Lamé solution presses Γ by 13.06 MPa at
every point), and the floor of γ₀ where Γ clips a cell's corner
(:func:`xdolfinx.xfem.traction.gamma_floor`)."""
from pathlib import Path

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore.laws import OPEN
from contactcore.tolerances import NITSCHE_DEGENERATE_PIECE, NITSCHE_PIECE_FLOOR
from contactcore.traction import nitsche_weights
from verification import methods
from xdolfinx.xfem.traction import gamma_floor

CYLINDER = Path(__file__).resolve().parent / "scenes" / "cylinder.toml"


@pytest.mark.parametrize("h", [0.1, 0.05])
def test_xfem_p1_keeps_a_uniformly_compressed_circle_closed(h):
    """The Lamé solution presses Γ by 13.06 MPa at every point, so no
    point may open.  With γ₀'s floor taken as a piece of half the cell's
    diameter in the clipped cell itself, a corner clip whose far part is
    the stiff disc got the disc's modulus over h, 10-80 times the γ of the
    cuts beside it, and γ times the ring's jump error opened 6 of 348
    points at h = 0.1 and 2 of 690 at 0.05 (3 of 1386 at 0.025).  The
    soft rod of tests/test_exact.py (test_a_point_open_by_the_gap_is_open)
    checks the other side: a floor too low there keeps open points closed."""
    result = methods.solver("xfem")(load_scene(str(CYLINDER)), h, degree=1)
    status = np.asarray(result.interface.steps[-1].status)
    opened = int(np.sum(status == OPEN))
    assert opened == 0, f"{opened} of {status.size} points of a Γ pressed by 13 MPa everywhere are open"
    assert any("moduli 100 times apart" in w for w in result.solver.warnings), result.solver.warnings


def test_xfem_p1_warns_of_a_contrast_on_a_curved_gamma_only():
    """The warning (XFEM_P1_CONTRAST) is for xfem P1, an exact law, a curved
    Γ and moduli at least that far apart; not degree 2, not equal moduli,
    not a penalty law."""
    import dataclasses
    from contactcore import make_law
    from xdolfinx.xfem.traction import contrast_warnings
    scene = load_scene(str(CYLINDER))
    assert contrast_warnings(scene, 1) and not contrast_warnings(scene, 2)
    equal = {b: dataclasses.replace(m, E=scene.materials["minus"].E) for b, m in scene.materials.items()}
    assert not contrast_warnings(scene.with_changes(materials=equal), 1)
    springs = make_law({"type": "unilateral", "kN": 1e6, "kT": 1e6})
    assert not contrast_warnings(scene.with_changes(law=springs), 1)


def _cells(count=200, seed=7):
    """Random cut cells: parts (count, 2) of a unit cell and moduli (count, 2) up to 1e4 apart."""
    rng = np.random.default_rng(seed)
    share = rng.uniform(0.0, 1.0, count)
    moduli = 10.0 ** rng.uniform(0.0, 4.0, (count, 2))
    return np.column_stack([share, 1.0 - share]), moduli


def test_the_floor_leaves_every_cut_across_the_cell_alone():
    """γ₀ of a piece at least NITSCHE_PIECE_FLOOR of the diameter long is
    never below the floor, whatever the parts and the moduli."""
    areas, moduli = _cells()
    for parts, E in zip(areas, moduli):
        _, gamma = nitsche_weights(parts[None], E, np.array([NITSCHE_PIECE_FLOOR * 1.0]))
        assert gamma_floor(parts, E, 1.0) <= gamma[0] * (1 + tol.GAMMA_FLOOR_ROUNDOFF)


def test_the_floor_is_the_softer_bodys_scale():
    """For equal moduli the floor is γ₀ of a piece NITSCHE_PIECE_FLOOR of the
    diameter long, as before the contrast was measured; where the far part
    is 100 times stiffer it is not the far part's γ₀ at that length (100
    times the softer body's scale) but the larger of the softer body's
    scale and the far part's γ₀ at NITSCHE_DEGENERATE_PIECE."""
    areas, _ = _cells()
    for parts in areas:
        E = np.array([3.0, 3.0])
        _, gamma = nitsche_weights(parts[None], E, np.array([NITSCHE_PIECE_FLOOR]))
        assert gamma_floor(parts, E, 1.0) == pytest.approx(gamma[0], rel=tol.GAMMA_FLOOR_ROUNDOFF)
    clip = np.array([1.0, 0.0])  # all of the cell on the stiff side
    E = np.array([100.0, 1.0])
    _, far = nitsche_weights(clip[None], E, np.array([NITSCHE_PIECE_FLOOR]))
    expected = far[0] * max(E[1] / E[0], NITSCHE_DEGENERATE_PIECE / NITSCHE_PIECE_FLOOR)
    assert gamma_floor(clip, E, 1.0) == pytest.approx(expected, rel=tol.GAMMA_FLOOR_ROUNDOFF)
