"""The documentation: docs/api.md's examples run as doctests, and the user
documentation names no issue numbers and no path outside the repository."""
import doctest
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
USER_DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]


def test_the_api_pages_examples_run():
    failed, attempted = doctest.testfile(str(ROOT / "docs" / "api.md"), module_relative=False,
                                         optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert attempted > 0 and failed == 0


@pytest.mark.parametrize("page", USER_DOCS, ids=lambda p: str(p.relative_to(ROOT)))
def test_user_docs_name_no_issue_and_no_outside_path(page):
    text = page.read_text()
    assert not re.search(r"\bissue \d+", text, re.IGNORECASE)
    assert "SCENES.md" not in text and "/work/" not in text
