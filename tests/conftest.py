"""Shared fixtures; long studies run only with ``--runslow``."""
import copy
import tomllib

import pytest

from contactcore import scene_text


def pytest_addoption(parser):
    parser.addoption("--runslow", action="store_true", help="also run the long studies marked 'slow'")


def pytest_collection_modifyitems(config, items):
    if config.getoption("--runslow"):
        return
    marker = pytest.mark.skip(reason="long study: run with --runslow")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(marker)


@pytest.fixture
def scene_dict():
    """A fresh parsed copy of a built-in scene file, to mutate in a test."""
    def make(name="A"):
        return copy.deepcopy(tomllib.loads(scene_text(name)))
    return make
