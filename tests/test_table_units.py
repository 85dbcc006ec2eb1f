"""A table over several scenes (timing.csv, effectivity.csv) gives its
``h`` in the unit the scenes share (units.json, from run.json's
``units``), not SI's; scenes in different units are refused before any
solve, naming each scene's (verification.files.shared_units)."""
import json
import re

import pytest

from contactcore import scene_text
from verification import files
from verification.__main__ import main


def _scene_in_mm(folder, name: str, units: str = '[units]\nlength = "mm"\nstress = "MPa"\n\n'):
    """Scene A's numbers labelled ``units`` (mm and MPa by default; never
    converted) under the name ``name``."""
    text = re.sub(r'(?m)^name = ".*"', f'name = "{name}"', scene_text("A"))
    path = folder / f"{name}.toml"
    path.write_text(text.replace("[domain]", units + "[domain]", 1))
    return path


@pytest.fixture
def two_in_mm(tmp_path):
    return [str(_scene_in_mm(tmp_path, name)) for name in ("A-mm", "A-mm-twin")]


def test_timing_over_scenes_in_mm_gives_h_in_mm(tmp_path, two_in_mm):
    out = tmp_path / "timing"
    assert main(["timing", *two_in_mm, "--method", "efgm", "--degree", "1", "--h", "0.5", "-q",
                 "--out", str(out)]) == 0
    assert json.loads((out / files.UNITS_FILE).read_text())["timing.csv"]["h"] == "mm"
    assert "| h (mm) |" in (out / "timing.md").read_text()
    assert json.loads((out / files.MANIFEST).read_text())[files.RUN_UNITS] == {"length": "mm", "stress": "MPa"}


def test_one_si_scene_keeps_h_in_m(tmp_path):
    out = tmp_path / "timing"
    assert main(["timing", "A", "--method", "efgm", "--degree", "1", "--h", "0.5", "-q", "--out", str(out)]) == 0
    assert json.loads((out / files.UNITS_FILE).read_text())["timing.csv"]["h"] == "m"


@pytest.mark.parametrize("command", [["timing", "{mm}", "A", "--method", "efgm", "--degree", "1", "--h", "0.5"],
                                     ["effectivity", "--scene", "{mm}", "A", "--h", "0.5", "--ref-h", "0.2"]])
def test_scenes_in_different_units_are_refused_before_any_solve(tmp_path, capsys, command):
    mm = str(_scene_in_mm(tmp_path, "A-mm"))
    out = tmp_path / "out"
    assert main([c.replace("{mm}", mm) for c in command] + ["-q", "--out", str(out)]) != 0
    said = capsys.readouterr().err
    assert "the scenes are in different units (A-mm in mm and MPa, A in m and Pa)" in said
    assert "Traceback" not in said and not out.exists()


def test_scenes_differing_in_stress_unit_alone_are_refused(tmp_path):
    """One set of units per table: a length shared but a stress not is refused too."""
    scenes = [_scene_in_mm(tmp_path, "A-mm"), _scene_in_mm(tmp_path, "A-mm-pa", '[units]\nlength = "mm"\n\n')]
    from contactcore import SceneError, load_scene
    with pytest.raises(SceneError, match="A-mm-pa in mm and Pa"):
        files.shared_units([load_scene(p) for p in scenes], "scene")


@pytest.mark.slow
def test_effectivity_over_scenes_in_mm_gives_h_in_mm(tmp_path, two_in_mm):
    out = tmp_path / "effectivity"
    assert main(["effectivity", "--scene", *two_in_mm, "--h", "0.25", "--ref-h", "0.1", "-q",
                 "--out", str(out)]) == 0
    assert json.loads((out / files.UNITS_FILE).read_text())["effectivity.csv"]["h"] == "mm"
    assert "Truth: fe P2 at h = 0.1 mm" in (out / "effectivity.md").read_text()
