"""``python -m verification run``: the files, and only what the scene needs."""
import csv
import json
import sys

import pytest

import tolerances as tol
from contactcore import load_scene
from verification import files
from verification.__main__ import main


@pytest.fixture(scope="module")
def run_a(tmp_path_factory):
    out = tmp_path_factory.mktemp("runA")
    assert main(["run", "A", "--method", "all", "--h", "0.1", "--out", str(out)]) == 0
    return out


@pytest.mark.parametrize("method", ["fe", "xfem", "efgm"])
def test_profiles_follow_scenes_md(run_a, method):
    scene = load_scene("A")
    written = sorted(p.stem for p in (run_a / method / "profiles").iterdir())
    assert written == sorted(p.id for p in scene.profiles)  # exactly the scene's profiles
    for prof in scene.profiles:
        with open(run_a / method / "profiles" / f"{prof.id}.csv") as fh:
            rows = list(csv.reader(fh))
        assert rows[0] == ["s", "x", "y", *prof.quantities]
        assert len(rows) == 102
        assert float(rows[1][0]) == pytest.approx(1e-9) and float(rows[-1][0]) == pytest.approx(1.0 - 1e-9)


def test_summary_and_provenance(run_a):
    summary = json.loads((run_a / "fe" / "summary.json").read_text())
    assert summary["dofs"] > 0 and summary["degree"] == 1
    assert set(summary["timings"]) == {"mesh", "assembly", "solve", "total"}
    assert summary["timings"]["total"] >= summary["timings"]["solve"] > 0
    solver = summary["solver"]
    assert solver["increments"] == 1 and solver["iterations"] == [1] and solver["residual"] < tol.CONVERGED_RUN_RESIDUAL
    run = json.loads((run_a / "run.json").read_text())
    assert run["command"] == "python -m verification run A --method all --h 0.1 --out " + str(run_a)
    assert run["python"] == sys.executable  # the interpreter the command's "python" was
    assert {"python", "numpy", "dolfinx", "petsc4py", "gmsh"} <= set(run["versions"])
    assert (run_a / "scene.toml").read_text().startswith("# Scene A")
    table = (run_a / "summary.md").read_text()
    assert "| fe | 1 |" in table and "| xfem | 1 |" in table and "| efgm | 1 |" in table
    efgm = json.loads((run_a / "efgm" / "summary.json").read_text())
    assert efgm["discretisation"]["nodes"] == 121 and efgm["discretisation"]["enriched_nodes"] > 0


def test_plots_and_no_fields_unless_asked(run_a):
    assert sorted(p.stem for p in (run_a / "plots").iterdir()) == ["A1", "A2", "A3", "A4", "A5"]
    assert (run_a / "plots" / "A1.png").read_bytes()[:4] == b"\x89PNG"
    assert not (run_a / "fe" / "fields").exists()
    assert not [p for p in run_a.rglob(".*")]  # no temporary file left behind


def test_interrupted_write_leaves_nothing_under_the_final_name(tmp_path):
    target = tmp_path / "result.csv"
    with pytest.raises(RuntimeError):
        with files.atomic_path(target) as tmp:
            tmp.write_text("half")
            raise RuntimeError("interrupted")
    assert list(tmp_path.iterdir()) == []
    files.write_text(target, "whole")
    with pytest.raises(RuntimeError):
        with files.atomic_path(target) as tmp:
            tmp.write_text("half")
            raise RuntimeError("interrupted")
    assert target.read_text() == "whole" and list(tmp_path.iterdir()) == [target]


def test_efficiency_refuses_a_reference_coarser_than_its_ladder(tmp_path, capsys):
    assert main(["efficiency", "A", "--method", "fe", "--h", "0.2", "0.1", "--ref-h", "0.5",
                 "--out", str(tmp_path / "eff")]) == 2
    assert capsys.readouterr().err.strip() == ("error: --ref-h: 0.5 is coarser than the ladder's finest h, 0.1: the "
                                               "reference stands for the exact answer, so it must be at least as "
                                               "fine as every rung")
    assert not (tmp_path / "eff").exists()


def test_efficiency_table_and_plot(tmp_path):
    """Error against run time: one row per run; the error of the reference's
    own discretisation is round-off, a coarser one's is not."""
    assert main(["efficiency", "A", "--method", "fe", "--h", "0.2", "0.1", "--ref-h", "0.1",
                 "--out", str(tmp_path)]) == 0
    with open(tmp_path / "efficiency.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["h"] for r in rows] == ["0.2", "0.1"] and all(float(r["total"]) > 0 for r in rows)
    coarse, same = float(rows[0]["error"]), float(rows[1]["error"])
    assert coarse > tol.COARSE_ERROR_FLOOR and same > 0  # P1 at h = 0.1 against P2 at h = 0.1: not zero, but smaller
    assert same < coarse
    assert (tmp_path / "efficiency.png").read_bytes()[:4] == b"\x89PNG"
    assert "worst at" in (tmp_path / "efficiency.md").read_text()


def test_shapes_benchmark_reports_rates_of_right_shape_functions(tmp_path, capsys):
    """The shape-function benchmark: one row per basis, a rate, and the
    evaluation's own partition-of-unity and reproduction defects at
    round-off; sizes it cannot use are one-line errors."""

    assert main(["shapes", "--grid", "11", "--points", "3000", "--repeats", "1", "--out", str(tmp_path)]) == 0
    with open(tmp_path / "shapes.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["basis"] for r in rows] == ["linear", "quadratic"]
    for row in rows:
        assert row["points"] == "3000" and float(row["points_per_s"]) > 0 and int(row["threads"]) >= 1
        assert max(float(row[k]) for k in ("unity", "reproduction")) <= tol.SHAPE_ROUNDOFF
        assert max(float(row[k]) for k in ("gradient_unity", "gradient_reproduction")) <= tol.SHAPE_GRADIENT_ROUNDOFF
    for bad in (["--grid", "2"], ["--points", "0"], ["--repeats", "0"]):
        assert main(["shapes", *bad, "--out", str(tmp_path / "bad")]) == 2
        assert capsys.readouterr().err.strip().splitlines()[-1].startswith(f"error: {bad[0]}: must be at least")
    assert not (tmp_path / "bad").exists()


def test_efgm_nodes_from_a_file(tmp_path, capsys):
    """Any point set, read from a file: here the vertices of a perturbed grid."""
    import numpy as np

    g = np.linspace(0.0, 1.0, 11)
    X, Y = np.meshgrid(g, g)
    nodes = np.column_stack([X.ravel(), Y.ravel()])
    inner = np.all((nodes > 0) & (nodes < 1), axis=1)
    nodes[inner] += np.random.default_rng(5).uniform(-0.02, 0.02, (inner.sum(), 2))
    path = tmp_path / "nodes.csv"
    np.savetxt(path, nodes, delimiter=",")
    assert main(["run", "A", "--method", "efgm", "--nodes", str(path), "--out", str(tmp_path / "out")]) == 0
    summary = json.loads((tmp_path / "out" / "efgm" / "summary.json").read_text())
    assert summary["discretisation"]["nodes"] == 121
    path.write_text("0 0 0\n1 1 1\n")
    capsys.readouterr()
    assert main(["run", "A", "--method", "efgm", "--nodes", str(path), "--out", str(tmp_path / "bad")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: --nodes:") and "line 1: a row holds two columns (x y), this one 3" in err


def test_the_advisor_picks_the_fastest_rung_that_reaches_each_target():
    from verification.efficiency import advisor
    rows = [{"method": "fe", "degree": 1, "h": 0.1, "dofs": 100, "total": 0.5, "error": 5e-3},
            {"method": "xfem", "degree": 2, "h": 0.1, "dofs": 300, "total": 0.8, "error": 5e-4},
            {"method": "fe", "degree": 1, "h": 0.05, "dofs": 400, "total": 0.9, "error": 8e-4}]
    lines = advisor(rows).splitlines()
    assert lines[2].startswith("| 1e-02 | fe | 1 | 0.1 |")  # both fe rungs reach 1e-2: the faster one
    assert lines[3].startswith("| 1e-03 | xfem | 2 | 0.1 |")  # fe at 0.05 reaches it too, but later
    assert "not reached" in lines[4]


def test_a_scene_built_in_python_goes_through_run(tmp_path):
    """run takes a Scene as well as a name: it writes the scene as TOML,
    which reads back equal, and returns its section (summary.md's text)."""
    from verification.run import run
    scene = load_scene("A").with_changes(name="A-python", increments=1)
    text = run(scene, ["efgm"], tmp_path / "out", h=0.2, draw=False)
    assert load_scene(tmp_path / "out" / "scene.toml") == scene
    assert text == (tmp_path / "out" / "summary.md").read_text()
    assert json.loads((tmp_path / "out" / "run.json").read_text())["scene"] == "A-python"


def test_a_method_that_does_not_spread_over_the_ranks_is_refused_under_mpirun(monkeypatch):
    """Each method states whether its solve spreads over mpirun's ranks
    (``Discretisation.distributed``); one that does not would be solved
    whole on every rank, so a run under mpirun refuses it before any work."""
    from contactcore import ContactError
    from verification import methods
    from xdolfinx.options import XFEM
    methods.check_launch(["fe", "xfem", "efgm"], distributed=True)
    monkeypatch.setattr(XFEM, "distributed", False)
    methods.check_launch(["fe", "xfem"], distributed=False)
    with pytest.raises(ContactError, match="^mpirun: xfem does not spread over mpirun's ranks"):
        methods.check_launch(["fe", "xfem"], distributed=True)


def test_a_failed_solve_among_several_methods_is_named():
    """Where several methods run, a failed solve names its method first
    (``run --method all``: which one failed is the first thing to know),
    keeping its details; alone, or a refused option (the input's fault),
    it is raised as it is."""
    from contactcore.errors import SolverError, SolverOptionError
    from verification import run_solve

    def fails(exc):
        exc.details = "history"
        raise exc

    with pytest.raises(SolverError, match=r"^efgm: scene wedge: increment 1 of 10 failed$") as named:
        run_solve.named(["fe", "xfem", "efgm"], "efgm", fails, SolverError("scene wedge: increment 1 of 10 failed"))
    assert named.value.details == "history"
    with pytest.raises(SolverError, match=r"^scene wedge"):
        run_solve.named(["efgm"], "efgm", fails, SolverError("scene wedge: increment 1 of 10 failed"))
    with pytest.raises(SolverOptionError, match=r"^petsc option"):
        run_solve.named(["fe", "efgm"], "fe", fails, SolverOptionError("petsc option x: unknown"))
