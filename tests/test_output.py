"""Field files (``run --fields``, issue 18): every file opens with meshio,
and what it holds is the run's own fields and interface state."""
import re
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

from contactcore import BODIES, evaluate_quantities, load_scene, scene_text
from tests.tolerances import FIELD_FILE_RTOL
from verification import fields_out, methods
from verification.__main__ import main
from xdolfinx.output import signed_areas

INCREMENTS = 3
H = 0.2


@pytest.fixture(scope="module")
def coulomb_toml(tmp_path_factory):
    """Scene C-coulomb in a few increments (the load path is the same)."""
    text = re.sub(r"(?m)^increments = \d+", f"increments = {INCREMENTS}", scene_text("C-coulomb"))
    path = tmp_path_factory.mktemp("scene") / "C-coulomb-3.toml"
    path.write_text(text)
    return path


def _close(read, expected):
    """``read`` equals ``expected`` to round-off of the quantity's scale."""
    scale = max(np.abs(expected).max(), np.finfo(float).tiny)
    assert np.abs(np.asarray(read) - expected).max() <= FIELD_FILE_RTOL * scale


def _pvd_entries(path):
    return [(float(d.get("timestep")), d.get("file")) for d in ET.parse(path).getroot().iter("DataSet")]


@pytest.mark.parametrize("method", ["fe", "xfem"])
def test_field_files_hold_the_run(tmp_path, coulomb_toml, method):
    scene = load_scene(coulomb_toml)
    result = methods.solver(method)(scene, H)
    written = fields_out.write_fields(tmp_path, result, mesh=True)
    steps = result.interface.steps
    assert len(steps) >= INCREMENTS
    assert sorted(written) == sorted(["minus.vtu", "plus.vtu", "interface.pvd"]
                                     + [f"interface_{n:04d}.vtu" for n in range(len(steps))])
    area = 0.0
    for b, body in enumerate(BODIES):
        mesh = meshio.read(tmp_path / f"{body}.vtu")
        pts, cells = mesh.points[:, :2], mesh.cells[0].data
        assert signed_areas(pts, cells).min() > 0  # every cell counter-clockwise, none degenerate
        area += signed_areas(pts, cells).sum()
        inside = scene.body_of(pts, body) == b  # vertices of XFEM cut cells may lie in the other body
        assert inside.sum() > 10
        u = evaluate_quantities(scene, result.fields, pts[inside], ["ux", "uy"], side=body)
        _close(mesh.point_data["u"][inside, :2], np.column_stack([u["ux"], u["uy"]]))
        sig = result.fields.stress(pts[cells].mean(axis=1), np.full(len(cells), b))
        for i, c in enumerate(("xx", "yy", "xy")):
            assert mesh.cell_data[f"sigma_{c}_cell"][0].shape == (len(cells),)  # cell data, one per cell
            _close(mesh.cell_data[f"sigma_{c}_cell"][0], sig[:, i])
    if method == "fe":  # the bodies tile the rectangle 2 x 3 (XFEM's cut cells are in both)
        assert area == pytest.approx(6.0, rel=1e-12)
    else:
        assert area > 6.0
    entries = _pvd_entries(tmp_path / "interface.pvd")
    assert [t for t, _ in entries] == [s.step for s in steps]
    for (_, name), step in zip(entries, steps):
        cloud = meshio.read(tmp_path / name)
        _close(cloud.points[:, :2], result.interface.points)
        assert np.array_equal(cloud.point_data["status"], step.status)
        for k, col in (("gN", step.jump[:, 0]), ("gT", step.jump[:, 1]), ("tN", step.traction[:, 0]),
                       ("tT", step.traction[:, 1])):
            _close(cloud.point_data[k], col)
    final = evaluate_quantities(scene, result.fields, result.interface.points, ["gN", "gT", "tN", "tT"])
    for k, col in final.items():  # the last step is what the profiles sample on Γ
        _close(meshio.read(tmp_path / entries[-1][1]).point_data[k], col)


def test_cli_fields_for_a_nonlinear_law(tmp_path, coulomb_toml):
    """The issue's traceback: ``--xdmf`` (alias of ``--fields``) on Coulomb."""
    assert main(["run", str(coulomb_toml), "--method", "fe", "efgm", "--h", str(H), "--xdmf",
                 "--out", str(tmp_path)]) == 0
    for method, bodies in (("fe", True), ("efgm", False)):
        folder = tmp_path / method / "fields"
        assert (folder / "minus.vtu").exists() == bodies  # efgm has no mesh: Γ only
        for _, name in _pvd_entries(folder / "interface.pvd"):
            assert len(meshio.read(folder / name).points) > 0
    assert not [p for p in tmp_path.rglob(".*")]  # no temporary left behind


@pytest.mark.parametrize("method,cell", [("fe", None), ("xfem", "quad"), ("xfem", "triangle")])
def test_fields_of_a_linear_law_at_degree_2(tmp_path, method, cell):
    args = ["run", "B", "--method", method, "--degree", "2", "--h", str(H), "--fields", "--out", str(tmp_path)]
    assert main(args + (["--cell", cell] if cell else [])) == 0
    folder = tmp_path / method / "fields"
    for body in BODIES:
        mesh = meshio.read(folder / f"{body}.vtu")
        assert mesh.cells[0].type == ("quad" if cell == "quad" else "triangle")
        assert signed_areas(mesh.points[:, :2], mesh.cells[0].data).min() > 0
        assert np.isfinite(mesh.point_data["u"]).all() and np.abs(mesh.point_data["u"]).max() > 0
    assert len(_pvd_entries(folder / "interface.pvd")) == 1  # a linear law: one step
