"""Field files (``run --fields``, issue 18): every file opens with meshio,
and what it holds is the run's own fields and interface state."""
import json
import re
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

from contactcore import BODIES, ProfileData, evaluate_quantities, load_scene, scene_text
from contactcore.labels import reference_text, run_label
from contactcore.scene import Units
from contactcore.tolerances import PLOT_MIN_Y_SPAN
from tests.tolerances import FIELD_FILE_RTOL, SAMPLE_ROUNDING_RTOL
from verification import fields_out, interface, methods, plots
from verification.__main__ import main
from xdolfinx.output import body_mesh, signed_areas
import tolerances as tol

INCREMENTS = 3
H = 0.2


@pytest.fixture(scope="module")
def coulomb_toml(tmp_path_factory):
    """Scene C-coulomb in a few increments (the load path is the same)."""
    text = re.sub(r"(?m)^increments = \d+", f"increments = {INCREMENTS}", scene_text("C-coulomb"))
    path = tmp_path_factory.mktemp("scene") / "C-coulomb-3.toml"
    path.write_text(text)
    return path


def _close(read, expected, rtol=FIELD_FILE_RTOL):
    """``read`` equals ``expected`` to ``rtol`` of the quantity's scale."""
    scale = max(np.abs(expected).max(), np.finfo(float).tiny)
    assert np.abs(np.asarray(read) - expected).max() <= rtol * scale


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
        # an XFEM cut cell's centroid may lie beyond Γ: the body's polynomial extended there, as written
        sig = result.fields.extended.stress(pts[cells].mean(axis=1), np.full(len(cells), b))
        for i, c in enumerate(("xx", "yy", "xy")):
            assert mesh.cell_data[f"sigma_{c}_cell"][0].shape == (len(cells),)  # cell data, one per cell
            _close(mesh.cell_data[f"sigma_{c}_cell"][0], sig[:, i])
    if method == "fe":  # the bodies tile the rectangle 2 x 3 (XFEM's cut cells are in both)
        assert area == pytest.approx(6.0, rel=tol.MESH_SUMS)
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
    final = evaluate_quantities(scene, result.fields, result.interface.points, ["gN", "gT", "tN", "tT"],
                                path=result.interface)
    for k, col in final.items():  # the last step is what the profiles sample on Γ
        _close(meshio.read(tmp_path / entries[-1][1]).point_data[k], col, SAMPLE_ROUNDING_RTOL)


class _Units:
    """A units wrapper as :func:`contactcore.result.method_fields` reads one:
    the inner problem in lengths / L and stresses / S, moved by ``origin``."""

    def __init__(self, base, origin, length_scale, stress_scale):
        self.base, self.origin, self.length_scale, self.stress_scale = base, origin, length_scale, stress_scale

    def _inner(self, points):
        return (np.asarray(points) - self.origin) / self.length_scale

    def displacement(self, points, bodies):
        return self.length_scale * self.base.displacement(self._inner(points), bodies)

    def stress(self, points, bodies):
        return self.stress_scale * self.base.stress(self._inner(points), bodies)


def test_body_meshes_through_wrappers_are_in_the_users_frame(coulomb_toml):
    """Through the history wrapper and a units wrapper: the mesh is placed
    by origin + L x, u is scaled by L and σ by S."""
    result = methods.solver("fe")(load_scene(coulomb_toml), H)
    origin, L, S = np.array([1e3, -7e2]), 2.0, 1e6  # lengths over the domain's size, as a units wrapper does
    wrapped = _Units(result.fields, origin, L, S)
    for b in range(2):
        plain, moved = body_mesh(result.fields, b), body_mesh(wrapped, b)
        _close(moved.points, origin + L * plain.points)
        assert np.array_equal(moved.cells, plain.cells)
        _close(moved.u, L * plain.u)
        _close(moved.sigma, S * plain.sigma)


def test_cli_fields_for_a_nonlinear_law(tmp_path, coulomb_toml):
    """``--fields`` on a Coulomb law: each body's mesh where the method has
    one, Γ at every step for every method."""
    assert main(["run", str(coulomb_toml), "--method", "fe", "efgm", "--h", str(H), "--fields",
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


# --- Figures (issue 18, item 6) ---------------------------------------------

def _profile(pid, s, **quantities):
    return ProfileData(pid, "arclength", {"s": s, "x": s, "y": 0 * s, **quantities})


def _inside(inner, outer):
    return (inner.x0 >= outer.x0 - 0.5 and inner.y0 >= outer.y0 - 0.5 and inner.x1 <= outer.x1 + 0.5
            and inner.y1 <= outer.y1 + 0.5)


def test_every_method_and_degree_has_its_own_style():
    looks = {(m, d): (st["color"], st["linestyle"], st["marker"])
             for m in plots.METHOD_STYLE for d in (1, 2) for st in [plots.style(run_label(m, d))]}
    assert len(set(looks.values())) == len(looks)  # no two curves look alike
    assert len({look[2] for look in looks.values()}) == len(looks)  # not even by marker alone
    for m in plots.METHOD_STYLE:  # a method's two degrees differ by more than their markers
        assert plots.style(run_label(m, 1))["lw"] != plots.style(run_label(m, 2))["lw"]
    assert plots.variant("reference: fe P2, h = 0.025 (3000 DOFs)") == ("fe", 2)
    assert plots.reference_label(["xfem P2", "fe P1", "fe P2", "efgm P1"]) == "fe P2"
    assert plots.reference_label(["xfem P1", "efgm P1"]) == "xfem P1"


def test_profile_figure_differences_span_and_layout():
    """A 24 kPa t_T with a ±3 Pa wobble (scene B5 in the issue): no offset
    labels, no zoom onto the wobble, the overlay in kPa, the difference
    panel method minus reference over the size it is given (the agreement
    table's: here a |t| of 30 kPa), in percent, the size named in its y
    label; the reference's curve named as the reference; legend and title
    inside the figure and off the axes."""
    s = np.linspace(0.0, 1.0, 101)
    ref = -24000.0 + 3.0 * np.sin(20 * s)
    runs = {"fe P2": _profile("B5", s, tT=ref), "xfem P1": _profile("B5", s, tT=ref + 1.0 + s),
            "efgm P1": _profile("B5", s, tT=ref - 2.0)}
    ref_size = 30000.0
    fig = plots.profile_figure("tangential traction on Γ", runs, sizes={"tT": (ref_size, "|(tN, tT)|")})
    fig.canvas.draw()
    overlay, diff = fig.axes[0], fig.axes[1]
    scale = max(np.abs(p.columns["tT"]).max() for p in runs.values())
    kpa, percent = 1e3, 100.0
    assert [overlay.get_ylabel(), diff.get_ylabel()] == ["t_T (kPa)", "Δt_T / max|t| (%)"]
    assert [line.get_label() for line in overlay.get_lines()] == [reference_text("fe P2"), "xfem P1", "efgm P1"]
    for ax, span in ((overlay, scale / kpa), (diff, percent)):
        assert ax.yaxis.get_major_formatter().get_offset() == ""
        low, high = ax.get_ylim()
        assert high - low >= PLOT_MIN_Y_SPAN * span * (1 - tol.PLOT_SPAN_ROUNDOFF)
    lines = {line.get_label(): line.get_ydata() for line in diff.get_lines() if not line.get_label().startswith("_")}
    assert set(lines) == {"xfem P1", "efgm P1"}
    assert np.allclose(lines["xfem P1"], percent * (1.0 + s) / ref_size)
    assert np.allclose(lines["efgm P1"], percent * -2.0 / ref_size)
    figure_box = fig.bbox
    legend = overlay.get_legend().get_window_extent()
    assert legend.x0 >= overlay.get_window_extent().x1  # outside the axes, to their right
    assert _inside(legend, figure_box) and _inside(overlay.title.get_window_extent(), figure_box)
    plots.pyplot().close(fig)


def test_response_figure_counts_increments(tmp_path, coulomb_toml):
    scene = load_scene(coulomb_toml)
    result = methods.solver("efgm")(scene, H)
    fig = interface.response_figure(scene, {"efgm P1": result.interface})
    fig.canvas.draw()
    by_label = {ax.get_ylabel(): ax for ax in fig.axes}
    assert "mean t_T on Γ (Pa)" not in by_label  # Γ is a circle: its mean t_T is the (zero) net torque
    rms = interface.increment_rows(result.interface)[-1]["rms_tT"]
    assert rms > 1.0  # Pa, where the mean is ~1e-4 Pa
    for ax in fig.axes:
        assert all(float(t).is_integer() for t in ax.get_xticks())  # increments are counted
    plots.pyplot().close(fig)


@pytest.mark.parametrize("title, shown", [
    ("", "gamma"),
    ("  ", "gamma"),
    ("tangential traction on Γ", "gamma: tangential traction on Γ"),
    (("", "fe P1, penalty against exact"), "gamma: fe P1, penalty against exact"),
    (("traction on Γ", "fe P1, penalty against exact"), "gamma: traction on Γ; fe P1, penalty against exact"),
])
def test_a_profile_figure_is_titled_by_its_id_without_dangling_separators(title, shown):
    """A profile without a title is titled by its id alone, not "gamma: "
    nor "gamma: ; ..." (run's penalty-against-exact figures add a part)."""
    s = np.linspace(0.0, 1.0, 5)
    fig = plots.profile_figure(title, {"fe P1": _profile("gamma", s, tT=s)})
    assert fig.axes[0].get_title() == shown
    plots.pyplot().close(fig)


def test_a_table_cell_with_a_pipe_or_a_line_break_keeps_its_row():
    """A failed point's two-line solver message in study.md's table."""
    from verification.files import markdown_table
    table = markdown_table([{"status": "failed", "message": "residual 1e-2 | too large\n  either the load"}],
                           ["status", "message"])
    assert table.splitlines()[2] == "| failed | residual 1e-2 \\| too large either the load |"


#: A scene's own units (docs/scenes.md, "Units"): labels only.
MM_MPA = Units(length="mm", stress="MPa")


@pytest.fixture(scope="module")
def a_in_mpa(tmp_path_factory):
    """Scene A's numbers labelled mm and MPa (never converted: its
    stresses, about 1e5, read as MPa), its path followed in two increments."""
    text = re.sub(r"(?m)^increments = \d+", "increments = 2\nfollow_path = true", scene_text("A"))  # a history
    text = text.replace("[domain]", '[units]\nlength = "mm"\nstress = "MPa"\n\n[domain]', 1)
    path = tmp_path_factory.mktemp("scene") / "A-mpa.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("scale", [500.0, 1.75e5, 2e6, 3e9])
def test_a_scene_not_in_pa_is_drawn_as_given_in_its_units(scale):
    """The k/M/G prefixes are an SI scene's only: a stress in MPa is shown
    unscaled and labelled MPa at any size, a length in the scene's unit."""
    assert plots.axis_unit("sxx", scale, MM_MPA) == (1.0, "σxx (MPa)")
    assert plots.axis_unit("gN", scale, MM_MPA) == (1.0, "g_N (mm)")
    assert plots.axis_unit("sxx", 2e6) == (1e6, "σxx (MPa)")  # an SI scene's, as before
    s = np.linspace(0.0, 1.0, 11)
    fig = plots.profile_figure("t_T", {"fe P2": _profile("G", s, tT=scale * (1 + s)),
                                       "xfem P1": _profile("G", s, tT=scale * (1 + s) + 1.0)}, units=MM_MPA)
    overlay, diff = fig.axes[0], fig.axes[1]
    assert [overlay.get_ylabel(), diff.get_ylabel(), diff.get_xlabel()] == [
        "t_T (MPa)", "Δt_T (MPa)", "s (mm)"]  # no sizes given: the differences in the quantity's unit
    assert np.array_equal(overlay.get_lines()[0].get_ydata(), scale * (1 + s))
    plots.pyplot().close(fig)


def test_a_run_in_mm_and_mpa_names_its_units_in_every_file(tmp_path, a_in_mpa):
    """units.json, summary.md's floors and the agreement's message name the
    scene's mm and MPa, never m or Pa."""
    from verification import agreement, files
    out = tmp_path / "run"
    assert main(["run", str(a_in_mpa), "--method", "fe", "xfem", "--h", "0.2", "--no-plots", "-q",
                 "--floor", "sxx=0.01", "--out", str(out)]) == 0
    units = json.loads((out / files.UNITS_FILE).read_text())
    assert units["fe/profiles/A2.csv"] == {"s": "mm", "x": "mm", "y": "mm", "syy": "MPa"}
    assert units["fe/profiles/A5.csv"]["gN"] == "mm" and units["fe/interface.csv"]["tN"] == "MPa"
    assert units["fe/increments.csv"]["rms_tT"] == "MPa" and units["fe/interface.csv"]["gT"] == "mm"
    assert not [(f, c) for f, cols in units.items() for c, u in cols.items() if u in ("m", "Pa", "Pa/m")]
    summary = (out / "summary.md").read_text()
    assert "sxx is measured against sqrt(sxx² + (0.01 MPa)²) (a floor given)" in summary
    row = agreement.Agreement("xfem P1", "A1", "sxx", "stress", 0.1, 0.2, 0.5, 0.5, 0.5, 1.0, 2.0, 5, 5,
                              floor=0.01, units=MM_MPA)
    assert "largest sqrt(sxx² + (0.01 MPa)²) (floored)" in row.describe()


def test_the_interface_and_study_plots_name_the_scenes_units(a_in_mpa):
    """The response figure (a straight Γ: with its loop), the status plot
    and a study's labels in the scene's units; the study's help in any
    scene's words."""
    from verification import study_parameters, study_table
    scene = load_scene(a_in_mpa)
    result = methods.solver("fe")(scene, 0.25)
    fig = interface.response_figure(scene, {"fe P1": result.interface})
    labels = {ax.get_ylabel(): ax.get_xlabel() for ax in fig.axes}
    assert labels["mean t_T on Γ (MPa)"] == "mean slip g_T on Γ (mm)" and "RMS t_N on Γ (MPa)" in labels
    plots.pyplot().close(fig)
    status = []
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(interface, "save", lambda fig, out: status.append(fig))
        interface.plot_status(None, scene, "fe P1", result.interface)
    assert status[0].axes[0].get_xlabel() == "position along Γ (mm)"
    plots.pyplot().close("all")
    assert study_parameters.described("kN", MM_MPA) == "normal spring k_N (MPa/mm)"
    assert study_parameters.described("radius", MM_MPA) == "radius of a circular Γ (mm)"
    assert study_parameters.PARAMETERS["kN"][0] == "normal spring k_N (stress/length)"
    assert "h (cell size or node spacing (mm))" in study_table.markdown("A", ["h"], [], MM_MPA)


def test_efficiency_names_a_mm_scenes_units(tmp_path, a_in_mpa):
    """efficiency on a scene in mm: units.json gives h in mm (from the
    scene's copy beside efficiency.csv), efficiency.md its exclusion in mm;
    an SI scene's sentence still says m."""
    from verification import efficiency, files
    out = tmp_path / "eff"
    assert main(["efficiency", str(a_in_mpa), "--method", "fe", "--degree", "1", "--h", "0.5", "0.25", "-q",
                 "--out", str(out)]) == 0
    assert json.loads((out / files.UNITS_FILE).read_text())["efficiency.csv"]["h"] == "mm"
    text = (out / "efficiency.md").read_text()
    assert "samples within 0.141 mm of corners" in text and " m of corners" not in text
    assert "gets there soonest, in " in text and "then ." not in text  # one variant: no empty "then"
    assert "| target error | method | degree | h (mm) |" in text and "| method | degree | h (mm) | DOFs |" in text
    assert "samples within 0.141 m of corners" in efficiency._error_sentence(None, None, 0.141)


def test_effectivity_gives_each_estimate_its_quantitys_unit(tmp_path, a_in_mpa):
    """effectivity on a scene in mm and MPa: units.json gives h in mm, and
    every row of effectivity.csv and .md names its quantity's unit (the
    estimate column mixes stresses and gaps)."""
    import csv
    from verification import files
    out = tmp_path / "effectivity"
    assert main(["effectivity", "--scene", str(a_in_mpa), "--h", "0.25", "--ref-h", "0.1", "-q",
                 "--out", str(out)]) == 0
    assert json.loads((out / files.UNITS_FILE).read_text())["effectivity.csv"]["h"] == "mm"
    with open(out / "effectivity.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert {r["unit"] for r in rows} == {"MPa", "mm"}
    assert all(r["unit"] == files.column_unit(r["quantity"], MM_MPA) for r in rows)
    text = (out / "effectivity.md").read_text()
    assert "Truth: fe P2 at h = 0.1 mm; runs at 0.25, 0.125 mm" in text
    assert "| estimate | unit | effectivity |" in text and "| gN | " in text and " | mm | " in text


def test_summary_and_estimate_warnings_give_lengths_in_the_scenes_unit(a_in_mpa):
    """summary.md's exclusion sentence and the estimate's unsettled-run
    warnings name the scene's length unit (m for an SI scene), each length
    followed by its unit (newuser32: "within 6 of a singular point …
    (lengths in mm)" split a number from its unit)."""
    from contactcore import estimate as est
    from verification.agreement import AgreementTable, default_exclusion
    corners = (("corners", ((0.0, 0.0), (1.0, 0.0))),)
    assert AgreementTable("A", "fe P2", 0.141, corners, (), units=MM_MPA).excluded().startswith(
        "samples within 0.141 mm of these singular points were left out: corners (0, 0), (1, 0)")
    assert "within 0.141 m of these" in AgreementTable("A", "fe P2", 0.141, corners, ()).excluded()
    scene = load_scene(a_in_mpa)
    runs = [methods.solver("fe")(scene, h) for h in (0.25, 0.125)]  # stencils reaching Γ's ends: unsettled
    warnings = est.estimate_runs(scene, runs, default_exclusion(scene), energy=False).warnings
    unsettled = [w for w in warnings if "not asymptotic; start below h = " in w]
    lengths = [m for w in unsettled for m in re.finditer(r"(?:h = |within |stencils of |feature \(|across Γ \()([-+.\de]+)(?![-+.\de])( mm)?", w)]
    assert unsettled and lengths and all(m.group(2) for m in lengths), unsettled


def test_study_headers_and_difference_floors_name_their_units():
    """study.md's outputs and a Δ panel's floor carry the scene's units."""
    from verification import study_table
    header = study_table.markdown("A", ["h"], [], MM_MPA).splitlines()[-2]
    assert "| max \\|g_N\\| (mm) | max \\|g_T\\| (mm) | max \\|t_N\\| (MPa) |" in header
    assert "| mean t_N (MPa) | mean t_T (MPa) |" in header and header.endswith("| message |")
    assert "| stick length (mm) | max \\|t_N\\| away from ends (MPa) |" in header
    estimated = study_table.markdown("A", ["h"], [], MM_MPA, estimate=True)
    assert "| est. error t_N (RMS) (MPa) | est. error t_T (RMS) (MPa) |" in estimated
    assert "| mean t_N (Pa) |" in study_table.markdown("A", ["h"], [])
    s = np.linspace(0.0, 1.0, 11)
    fig = plots.profile_figure("g", {"fe P2": _profile("G", s, gN=s), "xfem P1": _profile("G", s, gN=s + 0.01)},
                               floors={"gN": 0.00476}, units=MM_MPA)
    assert fig.axes[1].get_title(loc="right").endswith("floored at 0.00476 mm")
    plots.pyplot().close(fig)


def test_spring_messages_name_the_scenes_units(a_in_mpa):
    """The springs' refusals and hints in MPa/mm (and the spacing they
    offer in mm) for a scene in mm and MPa."""
    from contactcore import health
    from contactcore.errors import SolverError
    from contactcore.laws import CoulombLaw, LinearLaw
    scene = load_scene(a_in_mpa)
    with pytest.raises(SolverError, match=r"kN: 1e\+300 MPa/mm is too stiff .* use k_N <= \S+ MPa/mm$"):
        health.check_springs(scene.with_changes(law=LinearLaw(1e300, 1.0)), np.array([0.05]))
    assert "kN = 1e-06 MPa/mm is very soft" in health.failure_hint(
        scene.with_changes(law=LinearLaw(1e-6, 1e-6)), np.array([0.05]))
    with pytest.raises(SolverError, match=r"MPa/mm is .* \(h = 0\.1, efgm's spacing\).* MPa/mm, a spacing "
                                          r"h <= \S+ mm, or fe or xfem"):
        k = 1e5 * scene.softer_modulus  # k h / E = 1e4 at h = 0.1, ten times the limit given
        health.check_friction_springs(scene.with_changes(law=CoulombLaw(k, k, 0.3)), 0.1, {"N": 1e3, "T": 1e3},
                                      "efgm")


def test_run_json_records_the_h_that_ran(tmp_path):
    """Without --h a run takes the scene's own h, and run.json recorded
    ``"h": null`` (grader6 #8): it records the h the methods ran at, as
    their summary.json does; with --paper, whose grids set each method's
    own h, null."""
    path = tmp_path / "coarse.toml"
    path.write_text(re.sub(r"(?m)^h = .*$", "h = 0.2", scene_text("A"), count=1))
    out = tmp_path / "out"
    assert main(["run", str(path), "--method", "efgm", "--no-plots", "-q", "--out", str(out)]) == 0
    ran = json.loads((out / "efgm" / "summary.json").read_text())["discretisation"]["h"]
    assert json.loads((out / "run.json").read_text())["h"] == ran == 0.2
    assert main(["run", "A", "--method", "efgm", "--paper", "--no-plots", "-q", "--out", str(out)]) == 0
    assert json.loads((out / "run.json").read_text())["h"] is None


@pytest.mark.parametrize("param, values, unit", [("h", ["0.5", "0.25"], "mm"), ("angle", ["0", "5"], "degree"),
                                                 ("E_minus", ["1e9", "2e9"], "MPa")])
def test_a_one_parameter_studys_column_carries_its_unit(tmp_path, a_in_mpa, param, values, unit):
    """grader11's fault 4: a one-parameter study named its column ``value``,
    with no unit in units.json, and study.md's header was a bare ``h``:
    the column is named after the parameter, units.json and study.md's
    header give its unit."""
    import csv
    from verification import files
    out = tmp_path / "s"
    assert main(["study", str(a_in_mpa), "--param", param, "--values", *values, "--method", "fe", "--h", "0.5", "-q",
                 "--out", str(out)]) == 0
    with open(out / "study.csv") as fh:
        assert next(csv.reader(fh))[0] == param
    assert json.loads((out / files.UNITS_FILE).read_text())["study.csv"][param] == unit
    assert f"| {param} ({unit}) | method |" in (out / "study.md").read_text()


def test_the_agreement_messages_give_the_scenes_units(a_in_mpa):
    """grader11's fault 7: assert_methods_agree's and describe()'s lines
    gave s, x, y and both values without units on an mm/MPa scene."""
    from verification.agreement import assert_methods_agree, compare
    worst = compare(a_in_mpa, ["xfem"], 0.25, reference="fe:1").worst()
    unit = "mm" if worst.quantity in ("ux", "uy", "gN", "gT") else "MPa"
    assert re.search(rf" at s = \S+ mm \(x = \S+ mm, y = \S+ mm\): \S+ {unit} against \S+ {unit}, a difference",
                     worst.describe()), worst.describe()
    with pytest.raises(AssertionError, match=r"at s = \S+ mm \(x = \S+ mm, y = \S+ mm\): \S+ (mm|MPa) against"):
        assert_methods_agree(a_in_mpa, ["xfem"], 0.25, rtol=worst.worst / 2, reference="fe:1")


def test_the_difference_panel_shades_what_the_agreement_leaves_out():
    """The samples left out near singular points (a mask of the
    reference's) are shaded in the difference panels, each run of them one
    span reaching half way to its kept neighbours, and the panel says so."""
    s = np.linspace(0.0, 1.0, 11)
    runs = {"fe P2": _profile("B5", s, tT=1.0 + s), "xfem P1": _profile("B5", s, tT=1.1 + s)}
    left_out = (s < 0.15) | (s > 0.85)  # two samples at each end
    assert np.allclose(plots._left_out_spans(s, left_out), [(0.0, 0.15), (0.85, 1.0)], rtol=0, atol=tol.COORDINATE_ROUNDOFF)
    fig = plots.profile_figure("t_T", runs, left_out=left_out)
    diff = fig.axes[1]
    assert len(diff.patches) == 2 and "grey: left out" in diff.get_title(loc="right")
    plots.pyplot().close(fig)
    fig = plots.profile_figure("t_T", runs)  # nothing left out: no span, no word of it
    assert not fig.axes[1].patches and "grey" not in fig.axes[1].get_title(loc="right")
    plots.pyplot().close(fig)


def test_the_difference_panel_says_the_agreement_tables_figure():
    """newuser32: a plot's Δt_T read ~17 % where summary.md's table said
    0.83 %: the panel divided by the reference's own largest |t_T|, the
    table by |t|.  Now each panel is over the table's size
    (:meth:`AgreementTable.sizes`): its largest |Δ| over the samples the
    table keeps is the table's worst sample, and its y label names the
    size (|g| for g_N).  On scene A at h = 0.2 some size differs from the
    quantity's own largest |value| (the old scale would fail here)."""
    from verification import agreement
    scene = load_scene("A")
    ref_label = run_label("fe", 2)
    runs = {run_label(m, d): agreement.sampled(scene, methods.solver(m)(scene, 0.2, degree=d))
            for m, d in (("fe", 2), ("xfem", 1))}
    table = agreement.table(scene, runs, ref_label)
    differs = []
    for pid, ref in runs[ref_label].items():
        keep = agreement.kept_samples(scene, ref, table.exclude)
        fig = plots.profile_figure(pid, {label: r[pid] for label, r in runs.items()}, ref_label,
                                   sizes=table.sizes(pid))
        for k, q in enumerate(ref.names[3:]):
            row = next(a for a in table.rows if (a.profile, a.quantity) == (pid, q))
            panel = fig.axes[2 * k + 1]
            [line] = [line for line in panel.get_lines() if line.get_label() == run_label("xfem", 1)]
            assert np.max(np.abs(line.get_ydata()[keep])) == pytest.approx(100 * row.worst, rel=tol.PLOT_TABLE_RTOL)
            assert panel.get_ylabel() == f"Δ{plots.SYMBOLS[q]} / max{plots.size_symbol(q, row.against)} (%)"
            assert reference_text(ref_label) in panel.get_title(loc="right")
            if not np.isclose(row.size, np.max(np.abs(ref.columns[q][keep])), rtol=tol.PLOT_TABLE_RTOL):
                differs.append((pid, q, plots.size_symbol(q, row.against)))
        plots.pyplot().close(fig)
    assert ("A5", "gN", "|g|") in differs, differs

