"""grader28 F2 (2026-11-29): a penalty Γ stiff at the mesh's scale ends
like a bonded one.

At scales above its compliance length ``ℓ = E/k`` a spring Γ is stiff
against the bodies, so that a mesh whose cells are not small against ℓ
sees its end on a free side as a bimaterial edge, whose exponent the
pollution order does not take
(contactcore.estimate.singular.stiff_spring_ends): a bulk displacement
whose orders pollution widened then takes the lower end of the range from
two runs (contactcore.estimate.orders.lower_end), as where Γ is exact.
On grader28's tilted block (tests/scenes/tilt_springs.toml, ℓ = 0.4) fe
P2's bulk displacements read 0.44-0.48 of their error at the balanced
order, 0.84-0.94 at the lower end (docs/error-estimates-log.md, "A
penalty Γ's ends at the scale of its springs")."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import estimate as est
from contactcore import tolerances as core_tol
from contactcore import load_scene
from contactcore.estimate import singular

TILT = "tests/scenes/tilt_springs.toml"
TILT_MM = "tests/scenes/tilt_springs_mm.toml"


def _fires(scene, h):
    return len(singular.stiff_spring_ends(scene, h)) > 0


def test_a_spring_gammas_ends_count_from_cells_of_a_few_hundredths_of_its_compliance_length():
    """ℓ = 0.4 (the stiffer E, 2e11, over the larger k, 5e11): cells of
    0.05 are 0.125 ℓ, above SPRING_BONDED_CELLS; cells of 0.025 are
    0.0625 ℓ, below it.  The same in mm and MPa.  Neither end is taken
    with springs 100 times softer, between equal materials, or under an
    exact law (exact_interface_ends takes that one)."""
    tilt, mm = load_scene(TILT), load_scene(TILT_MM)
    assert singular.compliance_length(tilt) == pytest.approx(0.4, rel=tol.STIFF_SPRINGS_ARITHMETIC)
    assert singular.compliance_length(mm) == pytest.approx(singular.compliance_length(tilt), rel=tol.STIFF_SPRINGS_ARITHMETIC)
    ell, c = singular.compliance_length(tilt), core_tol.SPRING_BONDED_CELLS
    fine, coarse = 0.025, 0.05
    assert fine / ell < c <= coarse / ell
    assert _fires(tilt, coarse) and not _fires(tilt, fine)
    assert _fires(mm, 1000 * coarse) and not _fires(mm, 1000 * fine)
    assert len(singular.stiff_spring_ends(tilt, 0.05)) == 2
    soft = tilt.with_changes(law=type(tilt.law)(kN=tilt.law.kN / 100, kT=tilt.law.kT / 100))
    assert not _fires(soft, 0.1)
    same = tilt.with_changes(materials={"minus": tilt.materials["minus"], "plus": tilt.materials["minus"]})
    assert not _fires(same, 0.1)
    assert not _fires(load_scene("tests/scenes/tilt_bonded.toml"), 0.1)


@pytest.mark.parametrize("path, h, low", [(TILT, 0.2, True), (TILT, 0.025, False), (TILT_MM, 200.0, True)])
def test_the_tilted_blocks_bulk_displacement_takes_the_lower_end_only_on_cells_not_small_against_l(path, h, low):
    """fe P1 at h → h/2: u_x, u_y on the vertical line take 2λ = 1.52 of
    the clamped corners from cells of 0.5 ℓ (in m and in mm), the balanced
    order of [1.52, 2] from cells of 0.0625 ℓ."""
    from contactcore.discretisation import solve
    from verification import methods
    from verification.agreement import default_exclusion
    scene = load_scene(path)
    disc = methods.discretisation("fe")(degree=1)
    results = [solve(scene, disc, hh) for hh in (h, h / 2)]
    e = est.estimate_runs(scene, results, default_exclusion(scene), energy=False)
    for q in ("ux", "uy"):
        qe = e.profiles["vert"][q]
        assert qe.theory[0] == est.pollution_order(scene) < qe.theory[1]
        expected = qe.theory[0] if low else est.balanced_order(*qe.theory)
        assert qe.order == pytest.approx(expected, rel=tol.STIFF_SPRINGS_ARITHMETIC), (q, qe.order, qe.theory)
        assert np.isfinite(qe.rms)
