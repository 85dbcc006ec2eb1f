"""A profile's ``side = "mean"``: on Γ the mean of the two sides'
limits, {σ} = (σ⁺ + σ⁻)/2 and {u} (docs/scenes.md, "Profiles"), the stress
a tied Γ carries where the enforcement leaves a jump; off Γ the one body's
field, as either side reads it.  Parametrized over the three methods:
each samples its own fields through the one evaluation."""
import pathlib
from dataclasses import replace

import numpy as np
import pytest

import tolerances as tol
from contactcore import SceneError, discretisation, load_scene, make_law
from contactcore.profiles import sample_profile
from contactcore.scene import LineProfile
from efgm.options import EFGM
from xdolfinx.options import FE, XFEM

METHODS = {"fe": FE(degree=1), "xfem": XFEM(degree=1), "efgm": EFGM(degree=1)}
H = 0.1
#: Along Γ (A3's segment) and along the top edge (A4's), where no point is on Γ.
ON_GAMMA = LineProfile(id="on", start=(0.0, 0.5), end=(1.0, 0.5), quantities=("sxx", "syy", "sxy", "ux", "uy"))
OFF_GAMMA = replace(ON_GAMMA, id="off", start=(0.0, 1.0), end=(1.0, 1.0))


def _scene():
    """Scene A with the unilateral law enforced exactly: Γ tied, its stress
    jump the enforcement's residue (docs/contact-enforcement.md)."""
    return load_scene("A").with_changes(law=make_law({"type": "unilateral", "enforcement": "exact"}))


@pytest.mark.parametrize("method", list(METHODS))
def test_the_mean_side_is_the_two_sides_mean_on_gamma_and_the_body_off_it(method):
    scene = _scene()
    result = discretisation.solve(scene, METHODS[method], H)

    def sides(profile):
        return {side: sample_profile(scene, result.fields, replace(profile, side=side), result.interface).columns
                for side in ("plus", "minus", "mean")}

    on, off = sides(ON_GAMMA), sides(OFF_GAMMA)
    jumps = 0.0
    for q in ON_GAMMA.quantities:
        scale = np.max(np.abs(on["plus"][q]))
        assert np.max(np.abs(on["mean"][q] - 0.5 * (on["plus"][q] + on["minus"][q]))) <= tol.MEAN_SIDE_ROUNDOFF * scale
        assert np.array_equal(off["mean"][q], off["plus"][q]) and np.array_equal(off["minus"][q], off["plus"][q])
        jumps = max(jumps, np.max(np.abs(on["plus"][q] - on["minus"][q])) / scale)
    assert jumps > tol.MEAN_SIDE_ROUNDOFF  # the two sides differ on Γ: the mean is no copy of one


def test_an_unknown_side_is_refused_naming_the_three():
    with pytest.raises(SceneError, match=r"profiles\[0\]\.side.*'minus' or 'plus', or 'mean'"):
        _scene().with_changes(profiles=(replace(ON_GAMMA, side="middle"),))


def test_a_scene_file_takes_the_mean_side(tmp_path):
    text = (pathlib.Path(__file__).parents[1] / "contactcore" / "scenes" / "A.toml").read_text()
    path = tmp_path / "a_mean.toml"
    path.write_text(text.replace('quantities = ["sxx"]\n', 'quantities = ["sxx"]\nside = "mean"\n', 1))
    profiles = {p.id: p for p in load_scene(path).profiles}
    assert profiles["A3"].side == "mean" and profiles["A1"].side == "plus" and profiles["A4"].side == "plus"
