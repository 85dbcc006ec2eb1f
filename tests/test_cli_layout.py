"""The command line's parts stay with the command line: ``verification.cli``
is imported by ``verification.__main__`` and by its own modules only, and
a module of the project that imports argparse is one of them or a command
of its own (``if __name__ == "__main__"``), never a driver or the numerics
(docs/architecture.md, the verification table)."""
import ast
from pathlib import Path

from test_layout import imported_names

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("contactcore", "meshes", "xdolfinx", "efgm", "verification")


def _dotted(path: Path) -> str:
    rel = path.relative_to(ROOT)
    parts = rel.parent.parts if rel.name == "__init__.py" else rel.with_suffix("").parts
    return ".".join(parts)


def _imported(path: Path) -> set[str]:
    """The absolute names ``path`` imports anywhere in its body (relative
    imports resolved, as :func:`test_layout.imported_names` reads them)."""
    found = set()
    for base, names in imported_names(_dotted(path), path, path.name == "__init__.py"):
        found |= set(names) if base is None else {base} | {f"{base}.{n}" for n in names}
    return found


def _runs_as_a_command(path: Path) -> bool:
    return any(isinstance(n, ast.If) and "__name__" in ast.unparse(n.test) and "__main__" in ast.unparse(n.test)
               for n in ast.parse(path.read_text()).body)


def _sources():
    return [p for package in PACKAGES for p in sorted((ROOT / package).rglob("*.py"))]


def _in_cli(path: Path) -> bool:
    return _dotted(path) == "verification.__main__" or _dotted(path).startswith("verification.cli")


def test_only_the_entry_point_imports_the_command_lines_parts():
    outside = [_dotted(p) for p in _sources() if not _in_cli(p)
               and any(n == "verification.cli" or n.startswith("verification.cli.") for n in _imported(p))]
    assert outside == []


def test_argparse_is_the_command_lines_alone():
    found = {_dotted(p): p for p in _sources() if "argparse" in _imported(p)}
    assert "verification.cli.parser" in found  # the check sees what it looks for
    assert [m for m, p in found.items() if not _in_cli(p) and not _runs_as_a_command(p)] == []
