"""A command imports only what its path uses (issue 24)."""
import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEAVY = ("matplotlib", "dolfinx", "gmsh", "efgm", "meshio", "ufl", "basix")


def _loaded(argv: list[str]) -> set[str]:
    """The heavy top-level packages loaded by ``main(argv)`` in a fresh interpreter."""
    code = (f"import json, sys\nsys.path.insert(0, {str(ROOT)!r})\nfrom verification.__main__ import main\n"
            f"try:\n    main({argv!r})\nexcept SystemExit:\n    pass\n"
            f"print(json.dumps(sorted({{m.split('.')[0] for m in sys.modules}} & set({list(HEAVY)!r}))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    return set(json.loads(out.stdout.strip().splitlines()[-1]))


def test_help_imports_no_numerics_and_no_plots():
    assert _loaded(["--help"]) == set()


def test_an_efgm_run_without_plots_loads_no_mesh_package_and_no_matplotlib(tmp_path):
    out = tmp_path / "out"
    loaded = _loaded(["run", "A", "--method", "efgm", "--h", "0.2", "--quiet", "--no-plots", "--out", str(out)])
    assert loaded == {"efgm"}, loaded
    assert (out / "efgm" / "profiles" / "A1.csv").is_file() and not (out / "plots").exists()


def test_an_xfem_run_on_structured_cells_loads_neither_gmsh_nor_efgm(tmp_path):
    loaded = _loaded(["run", "A", "--method", "xfem", "--h", "0.2", "--quiet", "--no-plots",
                      "--out", str(tmp_path / "out")])
    assert loaded == {"dolfinx", "ufl", "basix"}, loaded


def test_an_fe_run_loads_no_efgm(tmp_path):
    loaded = _loaded(["run", "A", "--method", "fe", "--h", "0.2", "--quiet", "--no-plots",
                      "--out", str(tmp_path / "out")])
    assert loaded == {"dolfinx", "ufl", "basix", "gmsh"}, loaded


def test_the_error_norm_depends_on_no_method():
    """One norm measures every method: its quadrature is the core's
    (contactcore.quadrature), so importing it loads no method's package."""
    code = (f"import sys\nsys.path.insert(0, {str(ROOT)!r})\nimport verification.norms\n"
            f"print(sorted({{m.split('.')[0] for m in sys.modules}} & {{'efgm', 'xdolfinx', 'dolfinx', 'gmsh'}}))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert out.stdout.strip().splitlines()[-1] == "[]", out.stdout
