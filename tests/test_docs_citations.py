"""The documentation's citations can be followed by whoever takes the
project over: every repository path a page names in backticks exists,
no page names a file by a path outside the repository (a held-out test's
folder, a session's machine), and the few files outside the repository
the dated logs still name by their bare names, for figures measured with
them (held-out tests' scenes and scripts, sessions' scripts), are each
said to be outside where they are named (docs/error-estimates-log.md,
"Held-out citations", 2026-11-28)."""
import glob
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
#: The repository's top-level folders: a cited path starting with one of
#: them names a file (or a glob of files) of the repository.
REPO_FOLDERS = ("contactcore", "xdolfinx", "efgm", "verification", "meshes", "tests", "docs", "examples", ".ci")
REPO_PATH = re.compile(rf"(?<![\w./-])((?:{'|'.join(map(re.escape, REPO_FOLDERS))})/[\w./*-]*)")
#: A path outside the repository: a held-out test's folder or a machine's.
OUTSIDE_PATH = re.compile(r"heldout|(?<![\w-])grader\d+/|/work/")
#: Files not in the repository that the logs name (bare) beside figures
#: measured with them: held-out tests' scenes and scripts, and sessions'
#: throwaway scripts.  The paragraph that names one, or the one before it
#: (a command block's lead-in), must say so, and the log gives the in-repo
#: check where there is one (docs/error-estimates-log.md, "Held-out
#: citations", 2026-11-28).
NOT_IN_REPOSITORY = (
    # held-out tests (grader6, grader7, grader8, grader17)
    "closed.py", "check_pairs.py", "check_estimate.py", "effectivities.csv", "runall.sh", "energy_ref.py",
    "energy.py", "analyse.py", "bar_bodyforce.toml", "disc_bonded_soft.toml", "disc_coulomb_stiff.toml",
    "disc_thin_ring.toml", "s4b.py",
    # sessions' scripts
    "bycause.py", "three_cf.py", "energy_cand.py", "tie.py", "dump.py", "replay.py", "rayorder.py", "rigid.py",
    "rays.py", "budget3.py")
#: How a paragraph says a file is not in the repository.
SAID_OUTSIDE = re.compile(r"held[- ]out|not\s+in\s+the\s+repository|outside\s+the\s+repository", re.IGNORECASE)


def cited(page: Path) -> list[tuple[int, str]]:
    """The code of ``page`` with each piece's first line number: every
    fenced block, every indented code line, and every backticked span of a
    paragraph outside them (paired within its paragraph, so that one stray
    backtick cannot shift the pairs of the rest of the page)."""
    text, spans = page.read_text(), []
    for m in re.finditer(r"^```[^\n]*\n(.*?)^```$", text, re.MULTILINE | re.DOTALL):
        spans.append((text.count("\n", 0, m.start(1)) + 1, m.group(1)))
    prose = re.sub(r"^```[^\n]*\n.*?^```$", lambda m: "\n" * m.group(0).count("\n"), text,
                   flags=re.MULTILINE | re.DOTALL)
    offset = 0
    for paragraph in re.split(r"(\n\s*\n)", prose):
        line = prose.count("\n", 0, offset) + 1
        for k, row in enumerate(paragraph.split("\n")):
            if row.startswith("    ") and not row.lstrip().startswith(("-", "*", "|")):
                spans.append((line + k, row))
        spans += [(line + paragraph.count("\n", 0, m.start()), m.group(1))
                  for m in re.finditer(r"`([^`]+)`", paragraph)]
        offset += len(paragraph)
    return spans


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_repository_path_cited_exists(page):
    missing = [(line, path.rstrip(".")) for line, span in cited(page) for path in REPO_PATH.findall(span)
               if not glob.glob(str(ROOT / path.rstrip(".")))]
    assert not missing, f"{page.relative_to(ROOT)} cites paths that are not in the repository: {missing}"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_path_outside_the_repository_is_named(page):
    text = page.read_text()
    outside = [(text.count("\n", 0, m.start()) + 1, text[m.start():m.end() + 30])
               for m in OUTSIDE_PATH.finditer(text)]
    assert not outside, f"{page.relative_to(ROOT)} cites paths outside the repository: {outside}"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_a_file_outside_the_repository_is_said_to_be_where_it_is_named(page):
    unsaid = unsaid_outside(page.read_text())
    assert not unsaid, f"{page.relative_to(ROOT)} names files outside the repository without saying so: {unsaid}"


def unsaid_outside(text: str) -> list[tuple[list[str], str]]:
    """The paragraphs of ``text`` that name a file of NOT_IN_REPOSITORY
    with no SAID_OUTSIDE in them or in the paragraph before."""
    paragraphs, unsaid = re.split(r"\n\s*\n", text), []
    for k, paragraph in enumerate(paragraphs):
        names = {n for n in NOT_IN_REPOSITORY if re.search(rf"(?<![\w/.-]){re.escape(n)}\b", paragraph)}
        if names and not any(SAID_OUTSIDE.search(p) for p in paragraphs[max(k - 1, 0):k + 1]):
            unsaid.append((sorted(names), paragraph[:80]))
    return unsaid


def test_the_rules_catch_what_they_are_for(tmp_path):
    """The patterns match the citations the logs used to carry."""
    assert OUTSIDE_PATH.search("heldout6/closed.py") and OUTSIDE_PATH.search("run grader17/scenes/x.toml")
    assert not OUTSIDE_PATH.search("grader17's tilt-unil-exact")
    assert REPO_PATH.findall("run tests/scenes/nowhere.toml --h 0.1") == ["tests/scenes/nowhere.toml"]
    assert not glob.glob(str(ROOT / "tests/scenes/nowhere.toml"))
    assert REPO_PATH.findall("verification.effectivity.CASES") == []
    assert unsaid_outside("Measured with `check_estimate.py`.\n\nThe next.") == [
        (["check_estimate.py"], "Measured with `check_estimate.py`.")]
    assert not unsaid_outside("With grader6's held-out `check_estimate.py`.")
    assert not unsaid_outside("Its tools, not in the\nrepository:\n\n    python dump.py cf")
    assert not unsaid_outside("`verification/tie.py.bak`, `contactcore/estimate/closed.pyc`")
    page = tmp_path / "page.md"
    page.write_text("A stray ` here.\n\nRun `a`:\n\n    python -m verification run tests/scenes/nowhere.toml\n\n"
                    "```toml\nname = 'docs/scenes/none.toml'\n```\n\nthen `tests/x.py`.\n")
    assert [(line, REPO_PATH.findall(span)) for line, span in cited(page) if REPO_PATH.findall(span)] == [
        (8, ["docs/scenes/none.toml"]), (5, ["tests/scenes/nowhere.toml"]), (11, ["tests/x.py"])]


def test_the_rebuilt_held_out_scenes_are_the_ones_the_log_describes():
    """docs/scenes/ rebuilds two lost held-out scenes (docs/error-estimates-log.md,
    "Held-out citations"): grader6's disc on the closed form's values, and
    grader17's tilt-coulomb-exact as tilt-unil-exact under exact Coulomb, μ = 0.8."""
    from contactcore import Material, load_scene
    from verification.closed_forms import pressurised_rod
    disc = load_scene(ROOT / "docs" / "scenes" / "disc_stiff_springs.toml")
    case = pressurised_rod(a=0.5, b=1.0, p=1e7, kN=1e12, kT=1e11, rod=Material(2e11, 0.3),
                           matrix=Material(3e10, 0.2))
    assert disc.with_changes(name=case.scene.name, title=case.scene.title, profiles=case.scene.profiles) == case.scene
    coulomb = load_scene(ROOT / "docs" / "scenes" / "tilt_coulomb_exact.toml")
    unilateral = load_scene(ROOT / "tests" / "scenes" / "tilt_unil_exact.toml")
    assert coulomb.law != unilateral.law and coulomb.law.mu == 0.8
    assert coulomb.with_changes(name=unilateral.name, title=unilateral.title, law=unilateral.law) == unilateral
