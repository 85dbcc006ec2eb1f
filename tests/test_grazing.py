"""A `unilateral` answer whose open zone is the mesh's is warned of
(contactcore.health.grazing; docs/contact-enforcement.md, "No normal load:
Γ grazes everywhere").  grader17's `shear-unilateral` (no load across Γ;
closed form g_N = 0, t_N = 0, t_T = 0.047 on all of Γ) answered in fe P1 at
h = 0.05 with 9 points open and t_T 31 % above the closed form, and in
efgm P2 at h = 0.1 pressed by 0.02 of the shear with 76 of 80 open and
t_T 16 times above it on the other 4: their closed points carry shear on
a pressure of at most 0.024 of the loads' stress.  The legitimate
openings of every unilateral scene of the tests press their closed points
by 1.15 of it or more, or carry no shear there, and are not warned."""
from __future__ import annotations

import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from contactcore import discretisation, load_scene
from contactcore.enforcement import make_law
from contactcore.health.grazing import grazing_warnings, grazing_zone
from contactcore.scaling import Scales
from contactcore.tolerances import GRAZING_PRESSURE, GRAZING_SHEAR, LIMIT_ROUNDOFF
from contactcore.laws import OPEN, STICK

from test_unilateral_partial import SHEAR_UNILATERAL
from tolerances import PRINTED_2G
from test_xfem_opening import UNI

SCENES = Path(__file__).parent / "scenes"
#: the closed form's t_T of `shear-unilateral`: the + layer's body force
#: times its height, 0.1 × 0.47 (the − layer's ends on Γ with it)
SHEAR_CLOSED_FORM = 0.1 * 0.47
GRAZED = "Γ grazes: no load presses it where it carries shear"


def _pressed(share):
    """`shear-unilateral` pressed on its top by ``share`` of its shear."""
    return SHEAR_UNILATERAL + ('[[loads]]\ntype = "traction"\nboundary = "top"\n'
                               f'value = [0.0, {-share * SHEAR_CLOSED_FORM!r}]\n')


def _grazing_lines(result):
    return [w for w in result.solver.warnings if GRAZED in w]


NUMBER = r"([\d.e+-]+)"
#: the warning's figures: open points, points, opening and scale (length
#: unit), U, shear, Σ, pressure (stress unit) and the pressure's share
FIGURES = re.compile(
    rf"Γ opens at (\d+) of (\d+) points \(increment 1\) by at most {NUMBER} (\w+) \({NUMBER} of "
    rf"max\(U, max\|g\|\) = {NUMBER} \w+, U = {NUMBER} \w+ from the loads\), while its "
    rf"closed points carry a shear of up to {NUMBER} (\w+) \({NUMBER} of the loads' stress Σ = {NUMBER} \w+\) on a "
    rf"pressure of at most {NUMBER} \w+ \({NUMBER} of Σ, below")


def _figures(result):
    """The one grazing warning of ``result``, checked against its answer's
    final increment (in the user's units): the open points, the largest
    opening and Γ's largest jump (the scale, as max(U, max|g|)), the closed
    points' largest |t_T| and −t_N, each printed to 2 digits; returns the
    printed shares and units."""
    lines = _grazing_lines(result)
    assert len(lines) == 1, result.solver.warnings
    (count, points, opening, length, share, scale, unit, shear, stress, shear_share, sigma, pressure,
     pressure_share) = FIGURES.search(lines[0]).groups()
    final = result.interface.final
    opened = final.status == OPEN
    assert int(count) == np.count_nonzero(opened) > 0 and int(points) == len(final.status)
    U = Scales.of(result.scene).displacement
    assert length == result.scene.units.length and stress == result.scene.units.stress
    for printed, value in ((opening, final.jump[opened, 0].max()), (unit, U),
                           (scale, max(U, np.abs(final.jump).max())),
                           (shear, np.abs(final.traction[~opened, 1]).max()),
                           (pressure, (-final.traction[~opened, 0]).max(initial=0.0))):
        assert float(printed) == pytest.approx(value, rel=PRINTED_2G)
    assert float(share) == pytest.approx(float(opening) / float(scale), rel=2 * PRINTED_2G)
    assert float(pressure_share) == pytest.approx(float(pressure) / float(sigma), rel=2 * PRINTED_2G)
    assert float(pressure_share) < GRAZING_PRESSURE and float(shear_share) > GRAZING_SHEAR
    for part in ("the discretisation's error in g_N", "the open/closed map and the tractions are the mesh's, not the load's",
                 'type = "linear"', "h/2", "No normal load: Γ grazes everywhere"):
        assert part in lines[0], part
    return {"share": float(share), "shear": float(shear_share), "pressure": float(pressure_share),
            "opening": float(opening), "scale": float(scale), "U": float(unit), "Σ": float(sigma),
            "t_T": float(shear), "t_N": float(pressure)}


def _shear_unilateral(tmp_path, pressed, options, h):
    path = tmp_path / "shear.toml"
    path.write_text(SHEAR_UNILATERAL if pressed is None else _pressed(pressed))
    result = discretisation.solve(load_scene(path), options, h)
    assert np.max(np.abs(result.interface.final.traction[:, 1])) > SHEAR_CLOSED_FORM  # the answer is off
    return result


@pytest.mark.parametrize("pressed", [None, 0.02, 0.1])
def test_shear_unilateral_fe_p1_warns_that_its_open_zone_is_the_meshs(tmp_path, pressed):
    """fe P1 at h = 0.05, unpressed and pressed by 0.02 and 0.1 of the shear
    (docs: 9, 8 and 6 points open, t_T 22-31 % above the closed form; the
    closed points pressed by 0.013-0.018 of the loads' stress): one warning
    naming the open points (as many as the answer's), their opening in the
    scene's length unit and as a share of max(U, max|g|), the closed
    points' shear and pressure (below GRAZING_PRESSURE), the mesh's map and
    what to compare with."""
    from xdolfinx.options import FE
    _figures(_shear_unilateral(tmp_path, pressed, FE(degree=1), 0.05))


def test_shear_unilateral_efgm_p2_pressed_warns_too(tmp_path):
    """efgm P2 at h = 0.1 pressed by 0.02 of the shear: 76 of 80 points
    open by 0.0135 of max(U, max|g|), above the 2026-11-28 opening bound
    (5e-3), which missed it; its 4 closed points carry t_T up to 16 times
    the closed form on a pressure of 0.024 of the loads' stress, and it is
    warned of as grazing."""
    from efgm.options import EFGM
    figures = _figures(_shear_unilateral(tmp_path, 0.02, EFGM(degree=2), 0.1))
    assert figures["t_T"] > 10 * SHEAR_CLOSED_FORM


def test_the_warning_prints_the_scenes_units(tmp_path):
    """The same scene in mm and MPa (tests/scenes/shear_unilateral_mm.toml,
    review9 #10): the same shares, lengths 1e3 and stresses 1e-6 times the
    m/Pa warning's (each within its 2 printed digits)."""
    from xdolfinx.options import FE
    metres = _figures(_shear_unilateral(tmp_path, None, FE(degree=1), 0.05))
    millimetres = _figures(discretisation.solve(load_scene(SCENES / "shear_unilateral_mm.toml"), FE(degree=1), 50.0))
    for name, factor in (("share", 1.0), ("shear", 1.0), ("pressure", 1.0), ("opening", 1e3), ("scale", 1e3),
                         ("U", 1e3), ("Σ", 1e-6), ("t_T", 1e-6), ("t_N", 1e-6)):
        assert millimetres[name] == pytest.approx(factor * metres[name], rel=2 * PRINTED_2G), name


def _text(tmp_path, name, text):
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    return path


def _tilt_on_springs(tmp_path):
    """grader17's `tilt-unil-exact` on soft springs (k_N = 1000, k_T = 40,
    `shear-unilateral`'s): the smallest legitimate opening measured
    (0.031 of max(U, max|g|), the tie's g_T setting that scale), its
    closed points pressed by 1.97 of the loads' stress."""
    text = (SCENES / "tilt_unil_exact.toml").read_text().replace('enforcement = "exact"', "kN = 1000.0\nkT = 40.0")
    return _text(tmp_path, "tiltpen", text)


# (scene, method, degree, h); measured 2026-11-28, the closed points'
# largest pressure and shear over the loads' stress: tilt 1.97 and 1.74, on
# springs 1.97 and 0.59, partial 1.15 and 8.0, presspull all open, hung at
# h = 0.2 0.0017 and 0.003 (below GRAZING_PRESSURE: its shear is what keeps
# it silent; review9 #1), scene C on springs 0.104 and 9e-4 (the same);
# uni 2.6, scene C exact 1.35
LEGITIMATE = [
    (lambda tmp: SCENES / "tilt_unil_exact.toml", "fe", 1, 0.05),
    (_tilt_on_springs, "fe", 1, 0.05),
    (lambda tmp: SCENES / "hung_on_gamma.toml", "fe", 1, 0.2),
    (lambda tmp: SCENES / "partial_unilateral.toml", "fe", 1, 0.05),
    (lambda tmp: SCENES / "presspull.toml", "fe", 1, 0.1),
    ("C springs", "fe", 1, 0.1),
]
SLOW = [
    (lambda tmp: _text(tmp, "uni", UNI), "fe", 1, 0.05),
    (lambda tmp: _text(tmp, "uni", UNI), "efgm", 1, 0.1),
    (lambda tmp: SCENES / "tilt_unil_exact.toml", "xfem", 1, 0.05),
    (lambda tmp: SCENES / "tilt_unil_exact.toml", "efgm", 1, 0.05),
    (lambda tmp: SCENES / "partial_unilateral.toml", "xfem", 2, 0.05),
    ("C", "fe", 1, 0.1),
    ("C", "xfem", 2, 0.1),
    ("C", "efgm", 1, 0.1),
    (lambda tmp: SCENES / "hung_on_gamma.toml", "efgm", 1, 0.1),
]


def _options(method, degree):
    if method == "efgm":
        from efgm.options import EFGM
        return EFGM(degree=degree)
    from xdolfinx.options import FE, XFEM
    return {"fe": FE, "xfem": XFEM}[method](degree=degree)


def _legitimate(tmp_path, source, method, degree, h):
    if source == "C":
        scene = load_scene("C").with_changes(law=make_law({"type": "unilateral", "enforcement": "exact"}))
    elif source == "C springs":
        scene = load_scene("C").with_changes(law=make_law({"type": "unilateral", "kN": 1e10, "kT": 1e8}))
    else:
        scene = load_scene(source(tmp_path))
    result = discretisation.solve(scene, _options(method, degree), h)
    assert np.any(result.interface.final.status == OPEN)  # Γ does open: the case asks something
    assert not _grazing_lines(result), result.solver.warnings


@pytest.mark.parametrize("case", range(len(LEGITIMATE)))
def test_a_legitimate_opening_is_not_warned(tmp_path, case):
    """Openings the loads make (a tilted block, exact and on soft springs,
    a block lifted at its end, a layer pulled off), each pressing what
    stays closed, or carrying no shear there (scene C on springs), and a
    Γ opened by the discretisation's g_N whose tractions are all the
    discretisation's (the hung body, t = 0 open or closed): no grazing
    warning."""
    _legitimate(tmp_path, *LEGITIMATE[case])


@pytest.mark.slow
@pytest.mark.parametrize("case", range(len(SLOW)))
def test_a_legitimate_opening_is_not_warned_in_other_methods(tmp_path, case):
    """grader16's `uni` (fe P1 at h = 0.05 with its partial point), the
    tilted block and grader7's partial contact in xfem and efgm, scene C
    made unilateral (exact), the hung body in efgm: no grazing warning."""
    _legitimate(tmp_path, *SLOW[case])


def _path(shear, pressure, opening=1e-3):
    """Two points: one open by ``opening`` beside one closed carrying the
    shear ``shear`` on the pressure ``pressure``."""
    step = SimpleNamespace(step=1.0, status=np.array([OPEN, STICK]),
                           jump=np.array([[opening, 1.0], [0.0, 1.0]]),
                           traction=np.array([[0.0, 0.0], [-pressure, shear]]))
    return SimpleNamespace(steps=[step])


def test_the_two_conditions_and_the_law():
    """Grazing needs a closed shear above GRAZING_SHEAR and a closed
    pressure below GRAZING_PRESSURE of the loads' stress, whatever the
    opening; at either bound within round-off it is silent (review9 #7);
    the unilateral law alone (not Coulomb, whose shear vanishes with the
    pressure, nor linear)."""
    unilateral = SimpleNamespace(law=make_law({"type": "unilateral", "kN": 1e3, "kT": 40.0}))
    shear, pressure = 2 * GRAZING_SHEAR, 0.5 * GRAZING_PRESSURE
    found = grazing_zone(unilateral, _path(shear, pressure), 1.0)
    assert found[:3] == (1.0, 1, 2) and (found.opening, found.shear, found.pressure) == (1e-3, shear, pressure)
    assert grazing_zone(unilateral, _path(shear, pressure, opening=0.5), 1.0) is not None  # a wide opening too
    assert grazing_zone(unilateral, _path(0.5 * GRAZING_SHEAR, pressure), 1.0) is None  # the map moves no traction
    assert grazing_zone(unilateral, _path(shear, 2 * GRAZING_PRESSURE), 1.0) is None  # the loads press Γ
    assert grazing_zone(unilateral, _path(shear, pressure), 10.0) is None  # both are shares of the loads' stress
    near = 0.1 * LIMIT_ROUNDOFF  # at a bound within round-off: silent, either bound
    assert grazing_zone(unilateral, _path(GRAZING_SHEAR * (1 + near), pressure), 1.0) is None
    assert grazing_zone(unilateral, _path(shear, GRAZING_PRESSURE * (1 - near)), 1.0) is None
    assert grazing_zone(unilateral, _path(shear, pressure), 0.0) is None  # no loads' stress: no shear above it
    for law in ({"type": "coulomb", "kN": 1e3, "kT": 40.0, "mu": 0.3}, {"type": "linear", "kN": 1e3, "kT": 40.0}):
        assert grazing_zone(SimpleNamespace(law=make_law(law)), _path(shear, pressure), 1.0) is None
    assert grazing_warnings(unilateral, None, 1.0) == [] and grazing_zone(unilateral, None, 1.0) is None
