"""fe on a user's gmsh mesh (``run --mesh FILE``, ``FE(mesh=...)``,
newuser33): the file of ``python -m meshes`` read back gives fe's own
answer; a graded mesh made with gmsh's API solves and agrees with fe's
own mesh within its discretisation error; each bad mesh and each option
that means nothing beside it ends in one ``error:`` line, exit 2, before
any solve; two ranks give the serial numbers."""
import csv
import json
import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import meshes.__main__ as meshes_cli
import tolerances as tol
from contactcore import ContactError, DiscretisationError, Pin, load_scene, sample_profiles
from meshes.read import H_MEASURE, check_mesh, read_mesh_file
from user_meshes import scene_a_mesh, swap_bodies
from verification.__main__ import main

ROOT = Path(__file__).resolve().parents[1]

#: scene A's spacing in these tests (254 cells: a solve of a fraction of a second)
H = 0.1


def _csv(path) -> dict:
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def _run(tmp_path, name, *args) -> int:
    return main(["run", "A", "--method", "fe", *map(str, args), "--out", str(tmp_path / name), "--no-plots", "-q"])


def _one_error_line(capsys) -> str:
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    return lines[0]


#: Scenes whose mesh from ``python -m meshes`` is read back: A at H, and a
#: 200 × 120 mm block (a domain not square, in mm: L = 200) at its own h.
ROUND_TRIPS = {"A": ["--h", str(H)], str(ROOT / "tests" / "scenes" / "layer_units_mm.toml"): []}


@pytest.mark.parametrize("scene", list(ROUND_TRIPS), ids=lambda s: Path(s).stem)
def test_the_mesh_of_python_m_meshes_gives_fes_own_answer(tmp_path, scene):
    """The file ``python -m meshes SCENE --h H`` writes, read back through
    ``--mesh``, is fe's own mesh: the same DOFs and cells, and the same
    profiles to round-off (the file's coordinates are printed to 16
    digits; TOLERANCE USER_MESH_ROUND_TRIP).  The run records the file,
    its hash and its h (the largest cell diameter)."""
    msh, h = tmp_path / "a.msh", ROUND_TRIPS[scene]
    assert meshes_cli.main([scene, *h, "--out", str(msh)]) == 0
    for name, args in (("own", h), ("file", ["--mesh", msh])):
        assert main(["run", scene, "--method", "fe", *map(str, args), "--out", str(tmp_path / name), "--no-plots",
                     "-q"]) == 0
    own, given = (json.loads((tmp_path / n / "fe" / "summary.json").read_text()) for n in ("own", "file"))
    assert given["dofs"] == own["dofs"] and given["discretisation"]["cells"] == own["discretisation"]["cells"]
    profiles = sorted((tmp_path / "own" / "fe" / "profiles").glob("*.csv"))
    assert profiles
    for f in profiles:
        a, b = _csv(f), _csv(tmp_path / "file" / "fe" / "profiles" / f.name)
        assert a.keys() == b.keys()
        for k in a:
            scale = max(np.max(np.abs(a[k])), np.finfo(float).tiny)
            assert np.max(np.abs(a[k] - b[k])) <= tol.USER_MESH_ROUND_TRIP * scale, (f.name, k)
    record = json.loads((tmp_path / "file" / "run.json").read_text())
    mesh = read_mesh_file(msh)
    assert record["mesh"]["file"] == "a.msh" and record["mesh"]["sha256"] == mesh.sha256
    assert record["mesh"]["h_measure"] == H_MEASURE and record["h"] == pytest.approx(mesh.h)
    assert given["discretisation"]["mesh"]["sha256"] == mesh.sha256
    assert given["discretisation"]["h"] == pytest.approx(mesh.h)
    assert mesh.h > own["discretisation"]["h"]  # gmsh's sides reach past its h
    unit = load_scene(scene).units.length  # summary.md states each run's h and the file (newuser34 #9)
    for name, summary in (("own", own), ("file", given)):
        text = (tmp_path / name / "summary.md").read_text()
        header, _, row = (line for line in text.splitlines() if line.startswith("| ") and "| DOFs |" in line
                          or line.startswith("| fe |") or line.startswith("|---"))
        assert header.startswith(f"| method | degree | h ({unit}) | DOFs |"), header
        assert row.startswith(f"| fe | {summary['degree']} | {summary['discretisation']['h']:.6g} | {summary['dofs']} |")
        assert (f"on the mesh file a.msh ({mesh.cells.shape[0]} cells; h = {mesh.h:.6g} {unit}, its {H_MEASURE})"
                in text) == (name == "file")


#: A profile's columns that place its samples, not a quantity.
PLACES = ("s", "x", "y")


def _profiles(scene, result) -> dict:
    return {(p.id, q): np.asarray(p.columns[q], float) for p in sample_profiles(scene, result.fields, result.interface)
            for q in p.columns if q not in PLACES}


def test_a_graded_mesh_made_in_gmsh_agrees_within_the_discretisation_error(tmp_path):
    """A mesh graded to 0.3 H on Γ, made with gmsh's API (groups by name,
    numbered otherwise), solves through ``FE(mesh=...)``; finer everywhere
    than fe's own mesh at H, its error is no larger, so it differs from
    fe's own by at most twice that mesh's error (measured against fe at
    H/4; TOLERANCE USER_MESH_GRADED_WITHIN)."""
    from xdolfinx import conforming
    scene = load_scene("A")
    graded = conforming.solve(scene, mesh=scene_a_mesh(tmp_path / "g.msh", H, factor=0.3, distance=0.2))
    own, fine = conforming.solve(scene, H), conforming.solve(scene, H / 4)
    assert graded.dofs > own.dofs and graded.discretisation["mesh"]["file"] == "g.msh"
    g, d, r = _profiles(scene, graded), _profiles(scene, own), _profiles(scene, fine)
    assert g.keys() == d.keys()

    def rms(v):
        return float(np.sqrt(np.mean(v ** 2)))

    for k in g:
        error = rms(d[k] - r[k])
        assert rms(g[k] - d[k]) <= tol.USER_MESH_GRADED_WITHIN * error, k
        assert rms(g[k] - d[k]) > 0.0, k  # another mesh, not fe's own again


BAD = {  # name: (the fault, words its line must hold)
    "no interface group": (dict(drop=("interface",)), "no physical group named interface"),
    "no body_plus group": (dict(drop=("body_plus",)), "no physical group named body_plus"),
    "Γ moved off by 1e-3": (dict(shift_gamma=1e-3), "off the scene's Γ"),
    "cells in no body": (dict(untag_top=True, save_all=True), "in no body group"),
    "cells left out at the top": (dict(untag_top=True), "does not cover the scene's domain: its nodes span x 0 to 1, "
                                  "y 0 to 0.75 m, the domain x 0 to 1, y 0 to 1 m"),
    "cells left out inside": (dict(untag=(0.6, 0.8)), "hole inside the domain"),
    "support's boundary missing": (dict(drop=("boundary_bottom",)), "supports[0] acts on boundary 'bottom'"),
}


@pytest.mark.parametrize("name", list(BAD))
def test_a_bad_mesh_is_one_line_before_any_solve(tmp_path, capsys, monkeypatch, name):
    fault, words = BAD[name]
    msh = scene_a_mesh(tmp_path / "bad.msh", 2 * H, **fault)
    from contactcore import discretisation
    monkeypatch.setattr(discretisation, "solve_increments", lambda *a, **k: pytest.fail("solved"))
    assert _run(tmp_path, "o", "--mesh", msh) == 2
    line = _one_error_line(capsys)
    assert line.startswith(f"error: fe: mesh {msh}: ") and words in line, line
    assert not (tmp_path / "o").exists()


def test_gammas_nodes_must_lie_on_gamma_to_round_off(tmp_path):
    """review17 #6: Γ's nodes moved by 1e-10 m (below the mesher's
    NODE_MATCH, 1.4e-6 m on A) were accepted, and a profile sample there
    read the other body (A3 σxx at s = 0.5: −7834 Pa for +7857 Pa).  A move
    above USER_MESH_ON_GAMMA of L is refused; one within it solves."""
    from contactcore import tolerances as ctol
    scene = load_scene("A")
    beyond, within = (f * ctol.USER_MESH_ON_GAMMA * scene.length_scale for f in tol.USER_MESH_GAMMA_MOVES)
    check_mesh(scene, read_mesh_file(scene_a_mesh(tmp_path / "in.msh", 2 * H, shift_gamma=within)), 1)
    with pytest.raises(DiscretisationError, match="off the scene's Γ"):
        check_mesh(scene, read_mesh_file(scene_a_mesh(tmp_path / "out.msh", 2 * H, shift_gamma=beyond)), 1)


def test_a_pin_off_the_meshs_vertices_is_refused(tmp_path):
    scene = load_scene("A")
    mesh = read_mesh_file(scene_a_mesh(tmp_path / "a.msh", 2 * H))
    check_mesh(scene, mesh, 1)
    vertex = mesh.nodes[mesh.cells[0, 0]]
    check_mesh(replace(scene, pins=(Pin(tuple(vertex), "xy"),)), mesh, 1)
    between = tuple(mesh.nodes[mesh.cells[0, :3]].mean(axis=0))
    with pytest.raises(DiscretisationError, match=r"pins\[0\] at .* is no vertex of the mesh"):
        check_mesh(replace(scene, pins=(Pin(between, "xy"),)), mesh, 1)


@pytest.mark.parametrize("args, words", [
    (("--method", "fe", "xfem"), "--mesh: is fe's mesh, and xfem builds its own"),
    (("--h", "0.1"), "--mesh: --h means nothing"),
    (("--estimate",), "--mesh: --estimate means nothing"),
    (("--paper",), "--mesh: --paper means nothing"),
])
def test_options_that_mean_nothing_beside_a_mesh_are_refused_by_name(tmp_path, capsys, args, words):
    msh = tmp_path / "a.msh"
    msh.write_text("not read: refused before")
    assert main(["run", "A", "--method", "fe", "--mesh", str(msh), *args, "--out", str(tmp_path / "o")]) == 2
    assert words in _one_error_line(capsys)


def test_the_python_api_takes_a_mesh_and_refuses_what_means_nothing_beside_it(tmp_path):
    from meshes import Grading
    from xdolfinx import conforming
    from xdolfinx.options import FE
    with pytest.raises(DiscretisationError, match="grading means nothing with mesh="):
        FE(mesh="a.msh", grading=Grading(0.5, 0.1))
    with pytest.raises(DiscretisationError, match="geometry_order means nothing with mesh="):
        FE(mesh="a.msh", geometry_order=2)
    msh = scene_a_mesh(tmp_path / "a.msh", 2 * H)
    with pytest.raises(ContactError, match="fixes the resolution"):
        conforming.solve(load_scene("A"), H, mesh=msh)
    with pytest.raises(ContactError, match="cannot read it"):
        conforming.solve(load_scene("A"), mesh=tmp_path / "none.msh")


def test_two_ranks_on_a_user_mesh_give_the_serial_numbers(tmp_path):
    from test_mpi import _worst, mpirun
    msh = scene_a_mesh(tmp_path / "g.msh", 2 * H, factor=0.5, distance=0.2)
    assert _run(tmp_path, "serial", "--mesh", msh) == 0
    out = mpirun(2, "-m", "verification", "run", "A", "--method", "fe", "--mesh", msh, "--out", tmp_path / "two",
                 "--no-plots", "-q", timeout=120)
    assert out.returncode == 0, out.stderr
    assert json.loads((tmp_path / "two" / "run.json").read_text())["ranks"] == 2
    files = sorted((tmp_path / "serial" / "fe" / "profiles").glob("*.csv"))
    assert files
    for f in files:
        assert _worst(f, tmp_path / "two" / "fe" / "profiles" / f.name) <= tol.PARALLEL_PARITY, f.name


def test_a_mesh_too_large_for_the_machine_is_refused_by_its_vertices(tmp_path, capsys, monkeypatch):
    """The memory budget counts the file's vertices (not the scene's h),
    and the refusal names the file."""
    from contactcore import budget
    msh = scene_a_mesh(tmp_path / "a.msh", 2 * H)
    monkeypatch.setattr(budget, "machine_memory", lambda: 1.0)  # every solve too large
    assert _run(tmp_path, "o", "--mesh", msh) == 2
    line = _one_error_line(capsys)
    vertices = len(np.unique(read_mesh_file(msh).cells[:, :3]))
    assert f"--mesh a.msh: {vertices} vertices, as many as h" in line and "--allow-large" in line, line


# --- usermesh2 (newuser34 #1, #10, #11): bodies swapped, another domain's mesh, a format without names ---

#: Meshes of ``python -m meshes`` whose bodies are read back swapped: a
#: straight Γ (A), a circle (B, C), C curved (geometry order 2).
SWAPPED = {"A": ["--h", "0.2"], "B": ["--h", "0.25"], "C": ["--h", "0.25"], "C order 2": ["--h", "0.25", "--order", "2"]}


@pytest.mark.parametrize("case", list(SWAPPED))
def test_a_mesh_with_its_bodies_swapped_is_refused_and_the_right_one_passes(tmp_path, case):
    """newuser34 #1: body_minus and body_plus exchanged in the file was
    solved (A5 g_N open where it is closed); now every cell's centroid is
    held to its body's side of Γ, and a mesh whose every cell is on the
    other side is asked whether the two are swapped.  The file as written
    passes (a straight-celled circle's + cells on Γ's chords reach inside
    the circle by the chord's sagitta, allowed)."""
    name = case.split()[0]
    msh = tmp_path / "m.msh"
    assert meshes_cli.main([name, *SWAPPED[case], "--out", str(msh)]) == 0
    scene = load_scene(name)
    right = read_mesh_file(msh)
    check_mesh(scene, right, 1)
    wrong = read_mesh_file(swap_bodies(msh, tmp_path / "swapped.msh"))
    minus, plus = (len(right.group(g, 2)) for g in ("body_minus", "body_plus"))
    with pytest.raises(DiscretisationError) as err:
        check_mesh(scene, wrong, 1)
    line = str(err.value)
    assert "\n" not in line and line.endswith("are body_minus and body_plus swapped?"), line
    assert f"all {plus} cells of body_minus lie on Γ's + side and all {minus} of body_plus on its − side" in line


def test_the_swapped_mesh_is_one_line_before_any_solve(tmp_path, capsys, monkeypatch):
    msh = tmp_path / "a.msh"
    assert meshes_cli.main(["A", "--h", "0.2", "--out", str(msh)]) == 0
    swapped = swap_bodies(msh, tmp_path / "swapped.msh")
    from contactcore import discretisation
    monkeypatch.setattr(discretisation, "solve_increments", lambda *a, **k: pytest.fail("solved"))
    assert _run(tmp_path, "o", "--mesh", swapped) == 2
    line = _one_error_line(capsys)
    assert line.startswith(f"error: fe: mesh {swapped}: ") and "swapped?" in line, line


def test_some_cells_of_a_body_on_the_other_side_are_counted_without_asking_for_a_swap(tmp_path):
    """A body_plus holding cells below Γ (the interface check catches such
    a mesh first where the cells touch; the count is the last word): the
    group, how many of its cells, and no swap question."""
    from meshes.read import _check_bodies
    scene = load_scene("A")
    mesh = read_mesh_file(scene_a_mesh(tmp_path / "a.msh", 2 * H))
    minus, plus = mesh.group("body_minus", 2), mesh.group("body_plus", 2)
    moved = replace(mesh, groups={**mesh.groups, (2, "body_plus"): np.concatenate([plus, minus[:3]])})
    with pytest.raises(DiscretisationError, match=rf"3 of the {len(plus) + 3} cells of body_plus lie on Γ's − side") \
            as err:
        _check_bodies(scene, moved, mesh.path, 0.0)
    assert "swapped" not in str(err.value)


@pytest.mark.parametrize("size, words", [
    ((2.0, 1.0), "does not cover the scene's domain: its nodes span x 0 to 1, y 0 to 1 m, the domain x 0 to 2, "
                 "y 0 to 1 m (the mesh of another domain"),
    ((1.0, 0.8), "reaches past the scene's domain: its nodes span x 0 to 1, y 0 to 1 m, the domain x 0 to 1, "
                 "y 0 to 0.8 m"),
])
def test_another_domains_mesh_is_named_so_not_a_hole(tmp_path, size, words):
    """newuser34 #10: scene A's 1 × 1 mesh on a 2 × 1 scene was "a hole
    inside the domain"; the extents are compared first, both ways."""
    from contactcore.geometry import Rectangle
    scene = load_scene("A")
    other = replace(scene, domain=Rectangle((0.0, 0.0), size))  # its profiles unchecked: check_mesh reads none
    mesh = read_mesh_file(scene_a_mesh(tmp_path / "a.msh", 2 * H))
    with pytest.raises(DiscretisationError, match=re.escape(words)):
        check_mesh(other, mesh, 1)


def test_a_format_without_physical_names_is_named(tmp_path, capsys):
    """newuser34 #11: ``python -m meshes --out x.vtk`` writes a file gmsh
    reads back without a physical group; ``--mesh`` says the format keeps
    no names and to write .msh (it said only "no physical group named
    body_minus")."""
    vtk = tmp_path / "x.vtk"
    assert meshes_cli.main(["A", "--h", "0.2", "--out", str(vtk)]) == 0
    assert _run(tmp_path, "o", "--mesh", vtk) == 2
    line = _one_error_line(capsys)
    assert "its format (.vtk) carries no physical names" in line and "write the mesh as .msh" in line, line
