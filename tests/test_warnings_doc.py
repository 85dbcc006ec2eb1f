"""docs/warnings.md lists every warning a run can print: a function that
makes warnings (named ``*_warnings``) in the health checks, the scene's
caveats, the methods or the mesher is named on the page, a module that
appends to a report's ``warnings`` is named too, and each entry's quoted
beginning is still the code's (each piece between its ``…`` is in one of
the code's strings, with ``…`` where the code puts a value).  So the
page cannot fall behind the code, nor quote words the code no longer
writes."""
import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "warnings.md"
#: Where the solver's warnings are made (the estimate's, contactcore/estimate/,
#: have their own table: docs/error-estimates.md, "The warnings").
SOURCES = sorted({*(ROOT / "contactcore" / "health").glob("*.py"), ROOT / "contactcore" / "scene" / "caveats.py",
                  *(p for p in (ROOT / "contactcore").rglob("*.py") if "estimate" not in p.parts),
                  *(ROOT / "xdolfinx").rglob("*.py"), *(ROOT / "efgm").rglob("*.py"), *(ROOT / "meshes").rglob("*.py")})
#: A value the code puts into a warning, as the page writes it.
VALUE = "…"


def _tree(path: Path) -> ast.Module:
    return ast.parse(path.read_text(), filename=str(path))


def warning_functions(paths=SOURCES) -> set[str]:
    """The functions and methods named ``*_warnings`` that ``paths`` define."""
    return {node.name for path in paths for node in ast.walk(_tree(path))
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.name.endswith("_warnings")}


def appending_modules(paths=SOURCES) -> set[str]:
    """The files of ``paths`` that append to a ``….warnings`` list (a
    report's or a build's), as paths from the repository's root."""
    found = set()
    for path in paths:
        for node in ast.walk(_tree(path)):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "append"
                    and isinstance(node.func.value, ast.Attribute) and node.func.value.attr == "warnings"):
                found.add(str(path.relative_to(ROOT)))
    return found


def _rendered(node) -> str:
    """A string node as its text, ``…`` for each value an f-string puts in."""
    if isinstance(node, ast.Constant):
        return node.value
    return "".join(v.value if isinstance(v, ast.Constant) else VALUE for v in node.values)


def code_strings(paths=SOURCES) -> str:
    """Every string literal of ``paths``, rendered, one a line."""
    return "\n".join(_rendered(node) for path in paths for node in ast.walk(_tree(path))
                     if isinstance(node, ast.JoinedStr)
                     or (isinstance(node, ast.Constant) and isinstance(node.value, str)))


def quoted_beginnings(text: str) -> list[str]:
    """The first backticked span of each entry (a line ``- `…```) of the page."""
    return re.findall(r"^- `([^`]+)`", text, re.MULTILINE)


def missing(text: str) -> list[str]:
    """What ``text`` (the page) leaves out: a warning function's name or a
    module that appends warnings, each as written in the code."""
    names = [f"`{name}`" for name in sorted(warning_functions())] + [f"`{m}`" for m in sorted(appending_modules())]
    return [n for n in names if n not in text]


def stale(text: str) -> list[str]:
    """The page's quoted beginnings that some piece of is in no string of the code."""
    strings = code_strings()
    return [q for q in quoted_beginnings(text)
            if not all(piece.strip() in strings for piece in q.split(VALUE) if piece.strip())]


def test_every_warning_function_and_module_is_named_on_the_page():
    text = PAGE.read_text()
    assert warning_functions() >= {"material_warnings", "friction_excess_warnings", "small_strain_warnings",
                                   "interface_warnings", "polygon_warnings", "snap_warnings"}
    assert not missing(text), f"docs/warnings.md does not name {missing(text)}"


def test_every_quoted_beginning_is_the_codes():
    text = PAGE.read_text()
    assert len(quoted_beginnings(text)) >= len(warning_functions())
    assert not stale(text), f"docs/warnings.md quotes words the code does not write: {stale(text)}"


def test_the_checks_catch_a_deleted_entry_and_a_changed_quote():
    text = PAGE.read_text()
    entry = re.search(r"^- `Γ is pressed[^\n]*$|^- `from increment[^\n]*\n(?:  [^\n]*\n)*", text, re.MULTILINE)
    assert entry and "`hinge_warnings`" in missing(text.replace(entry.group(0), ""))
    assert stale(text.replace("Γ grazes: no load presses it", "Γ grazes: no load pushes it"))
