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
    imports included), a submodule's import of its own package left out."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = name.split(".") if package else name.split(".")[:-1]
                parts = parts[:len(parts) - node.level + 1]
                base = ".".join(parts + ([node.module] if node.module else []))
            targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base for a in node.names]
        else:
            continue
        for target in targets:
            while target and target not in modules:
                target = target.rpartition(".")[0]
            if target and target != name and not name.startswith(target + "."):
                found.add(target)
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

    circles = sorted(m for m in graph if m in reachable(m))
    assert circles == []


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

