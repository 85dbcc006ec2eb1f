"""A body thinner than a method can resolve is refused before anything is
built, by a message that says so (grader9 #5): a 2 × t strip under a
horizontal Γ passed validation, then fe failed inside gmsh ("gmsh curve 6
could not be assigned to one outer boundary" at t = 3e-6; "body + can slide
along Γ" at 1e-7, Γ's facets lost) and xfem said "Γ crosses no cell of the
mesh" at t ≤ 1e-6 (its nodes snapped onto Γ)."""
from pathlib import Path

import pytest

from contactcore import DiscretisationError, LineInterface, load_scene
from contactcore import tolerances as ctol
from contactcore.discretisation import check_solvable
from xdolfinx.options import FE, XFEM

THIN = Path(__file__).resolve().parent / "scenes" / "thin_layer.toml"  # 2 × 1, Γ at y = 1e-6, h = 0.1


def _at(t: float):
    scene = load_scene(THIN)
    return scene.with_changes(interface=LineInterface((0.0, t), (0.0, 1.0)))


def test_a_straight_gammas_bodies_are_as_thick_as_their_farthest_corner():
    assert _at(0.25).body_thickness() == {"minus": 0.25, "plus": 0.75}
    tilted = load_scene(THIN).with_changes(interface=LineInterface((1.0, 0.5), (1.0, 1.0)))
    assert tilted.body_thickness()["minus"] == pytest.approx(1.5 / 2 ** 0.5)
    assert load_scene("B").body_thickness() is None  # a circle


@pytest.mark.parametrize("t", [1e-7, 1e-6, 3e-6])
def test_fe_refuses_a_layer_no_fitted_mesh_can_hold_by_its_thickness(t):
    floor = ctol.THINNEST_FITTED_BODY * load_scene(THIN).length_scale
    with pytest.raises(DiscretisationError, match=rf"^body − is at most {t:.3g} m thick across Γ, not above "
                                                  rf"2e-06 of the domain's diameter \({floor:.3g} m\): a fitted "
                                                  r"mesh cannot tell its edges apart"):
        check_solvable(_at(t), FE(), 0.1)


def test_fe_takes_a_layer_just_thicker_than_that():
    """4.6e-6 meshes and solves (measured; module doc of THINNEST_FITTED_BODY)."""
    check_solvable(_at(1.03 * ctol.THINNEST_FITTED_BODY * load_scene(THIN).length_scale), FE(), 0.1)


@pytest.mark.parametrize("t", [1e-7, 1e-6])
def test_xfem_refuses_a_layer_its_snap_moves_onto_gamma_by_its_thickness(t):
    with pytest.raises(DiscretisationError, match=r"^xfem: no cell resolves body −: it reaches at most "
                                                  r"[0-9.e+-]+ of a cell's diameter from Γ, within xfem's snap "
                                                  r"distance .*; divide h by about [0-9.e+]+ or more$"):
        check_solvable(_at(t), XFEM(), 0.1)
    check_solvable(_at(3e-6), XFEM(), 0.1)  # beyond the snap: the cut's own refusal names it (test below)


@pytest.mark.slow
def test_xfem_beyond_the_snap_is_refused_by_the_cuts_own_check(tmp_path, capsys):
    from verification.__main__ import main
    scene = tmp_path / "thin.toml"
    scene.write_text(THIN.read_text().replace("point = [0.0, 1e-6]", "point = [0.0, 3e-6]"))
    assert main(["run", str(scene), "--method", "xfem", "--no-plots", "-q", "--reference", "none",
                 "--out", str(tmp_path / "o")]) == 2
    assert "xfem: no cell resolves body −: wherever Γ cuts it" in capsys.readouterr().err


def test_the_command_line_refuses_it_in_one_line_before_any_method_runs(tmp_path, capsys, monkeypatch):
    from verification import methods
    from verification.__main__ import main
    monkeypatch.setattr(methods, "solver", lambda name: pytest.fail(f"{name} was solved"))
    assert main(["run", str(THIN), "--method", "all", "--no-plots", "--reference", "none",
                 "--out", str(tmp_path / "o")]) == 2
    errors = [line for line in capsys.readouterr().err.splitlines() if line.startswith("error:")]
    assert len(errors) == 1 and "body − is at most 1e-06 m thick across Γ" in errors[0], errors
