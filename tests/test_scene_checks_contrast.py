"""A modulus contrast double precision cannot solve is refused when the
scene is read (grader2 item 11: E⁻ = 1e-300 MPa beside E⁺ = 2.1e5 MPa was
solved into "singular to working precision ... soften k_N, k_T")."""
from pathlib import Path

import pytest

from contactcore import SceneError, load_scene
from contactcore.tolerances import MODULUS_CONTRAST_MIN
from verification.__main__ import main

MM_WEDGE = Path(__file__).parent / "scenes" / "mm_wedge.toml"


def _wedge_with(tmp_path, minus_E: float) -> Path:
    text = MM_WEDGE.read_text()
    assert "E = 70000.0" in text
    path = tmp_path / "wedge.toml"
    path.write_text(text.replace("E = 70000.0", f"E = {minus_E!r}"))
    return path


@pytest.mark.parametrize("minus_E", [1e-300, 2.1e5 * MODULUS_CONTRAST_MIN / 2])
def test_a_contrast_below_the_limit_is_refused_naming_the_moduli(tmp_path, minus_E):
    with pytest.raises(SceneError, match=r"^materials\.minus\.E: .* of materials\.plus\.E \(210000\), below the "
                                         r"1e-12 double precision can solve"):
        load_scene(_wedge_with(tmp_path, minus_E))


def test_a_contrast_at_the_limit_is_read(tmp_path):
    assert load_scene(_wedge_with(tmp_path, 2.1e5 * MODULUS_CONTRAST_MIN)).materials["minus"].E > 0


def test_run_refuses_it_in_one_line_before_any_solve(tmp_path, capsys):
    out = tmp_path / "r"
    assert main(["run", str(_wedge_with(tmp_path, 1e-300)), "--method", "efgm", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: materials.minus.E: 1e-300 is") and "singular" in err[0], err
    assert "soften" not in err[0] and not out.exists()
