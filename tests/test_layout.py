"""The code's layout as a newcomer meets it: the import map points down
(verification -> xdolfinx, efgm, meshes -> contactcore) with no circle, each
file of xdolfinx holds one idea in a size one can read, and the shared
core reads what a ContactSystem declares (that every command-line option
has a help line is tests/test_glance.py's)."""
import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

#: Each package's layer: a module imports only from its own layer or below.
LAYER = {"contactcore": 0, "meshes": 1, "xdolfinx": 1, "efgm": 1, "verification": 2}

#: The readable sizes of xdolfinx's files and classes (lines): one idea each,
#: as XFEM's split after GetFEM's MeshFem / MeshIm keeps them.
FILE_LINES, CLASS_LINES = 500, 200


def _modules() -> dict[str, tuple[Path, bool]]:
    """Dotted name -> (file, whether it is a package's __init__)."""
    out = {}
    for path in ROOT.rglob("*.py"):
        rel = path.relative_to(ROOT)
        if rel.parts[0] in LAYER:
            package = rel.name == "__init__.py"
            parts = rel.parent.parts if package else rel.with_suffix("").parts
            out[".".join(parts)] = (path, package)
    return out


def _imports(name: str, path: Path, package: bool, modules) -> set[str]:
    """The project's modules that ``name`` imports anywhere in its body (lazy
    imports included).  ``from PKG import X`` imports ``PKG.X`` where that
    is a module, else ``PKG`` itself, its ``__init__``: a submodule's import
    of a name from its own package counts too (left out, it hid the circle
    scene -> quadrature -> contactcore -> scene, grader9 #9)."""
    found = set()
    for base, names in imported_names(name, path, package):
        targets = names if base is None else [f"{base}.{n}" if f"{base}.{n}" in modules else base for n in names]
        for target in targets:
            while target and target not in modules:
                target = target.rpartition(".")[0]
            if target and target != name:
                found.add(target)
    return found


def imported_names(name: str, path: Path, package: bool) -> list[tuple[str | None, list[str]]]:
    """Every import statement of module ``name`` (file ``path``, a
    package's ``__init__`` if ``package``) anywhere in its body, relative
    ones resolved: ``(None, modules)`` for ``import a, b``, ``(base,
    names)`` for ``from base import names``."""
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found.append((None, [a.name for a in node.names]))
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = name.split(".") if package else name.split(".")[:-1]
                parts = parts[:len(parts) - node.level + 1]
                base = ".".join(parts + ([node.module] if node.module else []))
            found.append((base, [a.name for a in node.names]))
    return found


def _graph():
    modules = _modules()
    return {name: _imports(name, path, package, modules) for name, (path, package) in modules.items()}


def test_every_import_points_down_or_across():
    up = [(a, b) for a, targets in _graph().items() for b in targets
          if LAYER[b.split(".")[0]] > LAYER[a.split(".")[0]]]
    assert up == []


def test_the_import_map_has_no_circle():
    graph = _graph()
    reach = {}

    def reachable(start):
        if start not in reach:
            seen, todo = set(), list(graph[start])
            while todo:
                m = todo.pop()
                if m not in seen:
                    seen.add(m)
                    todo += graph[m]
            reach[start] = seen
        return reach[start]

    circles = {m: sorted(graph[m] & {n for n in graph if m in reachable(n)})
               for m in sorted(graph) if m in reachable(m)}
    assert circles == {}, f"each module on a circle, with its arrows along it: {circles}"


def test_a_submodules_import_from_its_own_package_is_an_arrow(tmp_path):
    """``from contactcore import Scene`` inside contactcore.quadrature is an
    arrow to the package's ``__init__``, which imports contactcore.scene:
    the check left it out and missed that circle (grader9 #9)."""
    source = tmp_path / "quadrature.py"
    source.write_text("from contactcore import Scene, tolerances\n\ndef f():\n    from . import Scene\n")
    assert _imports("contactcore.quadrature", source, False, _modules()) == {"contactcore", "contactcore.tolerances"}


@pytest.mark.parametrize("path", sorted((ROOT / "xdolfinx").rglob("*.py")), ids=lambda p: p.name)
def test_an_xdolfinx_file_holds_one_readable_idea(path):
    text = path.read_text()
    assert len(text.splitlines()) <= FILE_LINES
    classes = [n for n in ast.walk(ast.parse(text)) if isinstance(n, ast.ClassDef)]
    assert [c.name for c in classes if c.end_lineno - c.lineno + 1 > CLASS_LINES] == []


def test_the_core_reads_what_a_contact_system_declares():
    """No ``getattr(system, name, default)``: the attributes Newton reads are
    ContactSystem's, with its defaults."""
    found = [f"{p.name}:{m.group(0)}" for p in (ROOT / "contactcore").glob("*.py")
             for m in re.finditer(r"getattr\((built\.)?system\b[^)]*\)", p.read_text())]
    assert found == []



#: The keywords that carry a tolerance in pytest.approx, numpy's allclose /
#: isclose / assert_allclose and math.isclose, and the calls that take them.
TOLERANCE_KEYWORDS = {"rel", "abs", "atol", "rtol", "rel_tol", "abs_tol"}
CLOSENESS_CALLS = {"approx", "allclose", "isclose", "assert_allclose"}
ORDERINGS = (ast.Lt, ast.LtE, ast.Gt, ast.GtE)


def _bare_float(node) -> bool:
    """Whether ``node``'s arithmetic holds a float literal that is neither 0
    nor a whole number (``1e-9``, ``-0.25``, ``bound * x + 1e-9``); a call's
    arguments are not looked into."""
    if isinstance(node, ast.Constant) and isinstance(node.value, float):
        return node.value != int(node.value)
    if isinstance(node, ast.UnaryOp):
        return _bare_float(node.operand)
    if isinstance(node, ast.BinOp):
        return _bare_float(node.left) or _bare_float(node.right)
    return False


def _call_name(call: ast.Call) -> str:
    return call.func.attr if isinstance(call.func, ast.Attribute) else getattr(call.func, "id", "")


def _inline_tolerances(tree) -> list[int]:
    """Lines where an assert orders against a bare float, or a closeness
    call gets one as its tolerance (keyword, or allclose's 3rd/4th argument)."""
    lines = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Assert):
            lines += [o.lineno for c in ast.walk(node.test)
                      if isinstance(c, ast.Compare) and any(isinstance(op, ORDERINGS) for op in c.ops)
                      for o in (c.left, *c.comparators) if _bare_float(o)]
        elif isinstance(node, ast.Call) and _call_name(node) in CLOSENESS_CALLS:
            given = [k.value for k in node.keywords if k.arg in TOLERANCE_KEYWORDS]
            given += node.args[2:4] if _call_name(node) != "approx" else []
            lines += [v.lineno for v in given if _bare_float(v)]
    return sorted(set(lines))


def test_the_inline_tolerance_check_sees_each_form():
    src = ("assert err <= 1e-9\nassert abs(a - b) < bound * x + 1e-9\nassert a == pytest.approx(b, rel=0.25)\n"
           "assert np.allclose(a, b, atol=1e-15)\nassert np.allclose(a, b, 1e-8)\n"
           "assert err <= tol.X\nassert n >= 2\nassert a == pytest.approx(0.3)\nassert np.allclose(a, b, atol=0.0)\n")
    assert _inline_tolerances(ast.parse(src)) == [1, 2, 3, 4, 5]


@pytest.mark.parametrize("path", sorted(p for p in (ROOT / "tests").glob("*.py") if p.name != "tolerances.py"),
                         ids=lambda p: p.name)
def test_every_test_tolerance_is_named_in_tests_tolerances(path):
    """A bound a test compares against is a constant of tests/tolerances.py
    with its reason, not a literal in the test."""
    assert _inline_tolerances(ast.parse(path.read_text())) == []


def _assigned(path: Path) -> set[str]:
    """The names a module assigns at its top level."""
    return {x.id for n in ast.parse(path.read_text()).body if isinstance(n, (ast.Assign, ast.AnnAssign))
            for t in (n.targets if isinstance(n, ast.Assign) else [n.target]) for x in ast.walk(t)
            if isinstance(x, ast.Name)}


def test_a_library_tolerance_is_defined_once_in_contactcore_tolerances():
    """The comparison's tolerances are contactcore.tolerances' (with their
    reasons), still importable from verification.agreement, and no other
    module of the project or helper of the tests assigns a name that
    contactcore/tolerances.py defines (a second copy drifts apart)."""
    import contactcore.tolerances as lib
    from verification import agreement

    names = ("EXCLUDE_FRACTION", "EXACT_GAP_FLOOR", "NEGLIGIBLE_SHARE", "WORST_TIE")
    assert set(names) <= _assigned(ROOT / "contactcore" / "tolerances.py")
    assert [n for n in names if getattr(agreement, n) is not getattr(lib, n)] == []
    defined = _assigned(ROOT / "contactcore" / "tolerances.py")
    copies = sorted(f"{p.relative_to(ROOT)}:{name}" for package in (*LAYER, "tests")
                    for p in (ROOT / package).rglob("*.py") if p.name != "tolerances.py"
                    for name in _assigned(p) & defined)
    assert copies == []


def test_the_architecture_pages_largest_xdolfinx_file_is_the_largest():
    """docs/architecture.md's "Sizes" names the largest file of xdolfinx/ and
    its lines: it said 388 where the file had grown to 408 (grader9 #9)."""
    text = (ROOT / "docs" / "architecture.md").read_text()
    name, lines = re.search(r"the largest, `([\w/]+\.py)`, (\d+)\)", text).groups()
    sizes = {p.relative_to(ROOT / "xdolfinx").as_posix(): len(p.read_text().splitlines())
             for p in (ROOT / "xdolfinx").rglob("*.py")}
    largest = max(sizes, key=sizes.get)
    assert (name, int(lines)) == (largest, sizes[largest]), "update docs/architecture.md's Sizes"


def test_every_package_is_in_the_wheel():
    """setuptools lists packages by name (pyproject.toml's
    ``[tool.setuptools] packages``): a package left out is missing from an
    installed wheel though an editable install still finds it (the split of
    verification/__main__.py left out ``verification.cli``)."""
    import tomllib
    listed = set(tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = {name for name, (_, package) in _modules().items() if package}
    assert found == listed, f"in the tree, not listed: {sorted(found - listed)}; listed, not in the tree: {sorted(listed - found)}"


def top_level_packages(root: Path) -> set[str]:
    """The repository's top-level packages: each folder beside xdolfinx/
    and efgm/ holding an ``__init__.py``, and each package (its first
    dotted part) that pyproject.toml's ``[tool.setuptools] packages`` lists."""
    import tomllib
    found = {p.parent.name for p in root.glob("*/__init__.py") if not p.parent.name.startswith(".")}
    pyproject = root / "pyproject.toml"
    if pyproject.exists():
        listed = tomllib.loads(pyproject.read_text()).get("tool", {}).get("setuptools", {}).get("packages", [])
        found |= {name.split(".")[0] for name in listed}
    return found


def test_every_package_has_a_layer():
    """Every layout check here walks only the packages of ``LAYER``: a
    package left out of it (takeover33's ``trife``) escaped the import
    direction, the tolerance and the method-name checks with no warning."""
    missing = sorted(top_level_packages(ROOT) - set(LAYER))
    assert missing == [], (f"package(s) {missing} not in tests/test_layout.py's LAYER: give each its layer "
                           "(0 core, 1 method or meshes, 2 drivers), docs/architecture.md \"A new method\"")


def test_the_layer_check_sees_a_package_folder_and_a_listed_one(tmp_path):
    (tmp_path / "efgm").mkdir()
    (tmp_path / "efgm" / "__init__.py").write_text("")
    (tmp_path / "trife").mkdir()
    (tmp_path / "trife" / "__init__.py").write_text("")
    (tmp_path / "docs").mkdir()
    (tmp_path / "pyproject.toml").write_text('[tool.setuptools]\npackages = ["efgm", "quadfe", "quadfe.shape"]\n')
    assert top_level_packages(tmp_path) == {"efgm", "trife", "quadfe"}
    assert sorted(top_level_packages(tmp_path) - set(LAYER)) == ["quadfe", "trife"]


def test_every_source_file_compiles_without_a_warning():
    """An invalid escape in a docstring is a DeprecationWarning today (shown in
    a user's own pytest run, which does not filter the project's warnings)
    and a SyntaxError under ``-W error``: no file of the project has one."""
    import subprocess
    import warnings
    listed = subprocess.run(["git", "ls-files", "*.py"], cwd=ROOT, capture_output=True, text=True)
    paths = [ROOT / p for p in listed.stdout.split()] or sorted(ROOT.glob("[!.]*/**/*.py"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for path in paths:
            compile(path.read_text(), str(path), "exec")



def _docstrings(tree) -> set[int]:
    """The ids of the docstring constants of ``tree``'s module, classes and functions."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str):
                found.add(id(first.value))
    return found


def method_names_in(text: str, names) -> list[tuple[int, str]]:
    """``(line, name)`` of each string constant of the source ``text`` equal
    to one of the method ``names``, docstrings left out (they may name a
    method as an example); an f-string's literal parts count too."""
    tree = ast.parse(text)
    docs = _docstrings(tree)
    return sorted((node.lineno, node.value) for node in ast.walk(tree)
                  if isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value in names
                  and id(node) not in docs)


def test_the_core_names_no_method():
    """contactcore imports no method and names none: a fact about a method
    is declared by its options class (contactcore.discretisation.Discretisation)
    and read from the options or the Result, never looked up by the
    method's name (docs/architecture.md, "A new method")."""
    from verification.methods import METHODS
    found = [f"{path.relative_to(ROOT)}:{line}: {name!r}" for path in sorted((ROOT / "contactcore").rglob("*.py"))
             for line, name in method_names_in(path.read_text(), METHODS)]
    assert found == []


def test_the_method_name_check_sees_a_name_but_not_a_docstring():
    source = ('"""fe and xfem."""\nFIELDS = {"fe": 2}\n\n\ndef f(m):\n    """efgm"""\n'
              '    return m != "efgm" or f"{m}" == "xfem"\n')
    assert method_names_in(source, ("fe", "xfem", "efgm")) == [(2, "fe"), (7, "efgm"), (7, "xfem")]
