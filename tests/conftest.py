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


#: The default suite's memory budget (issue 17): the developers' and CI's
#: machines have 24 GB and run the suite beside a study.  With pytest-xdist
#: the workers run at once, so their peaks are added (an upper bound on what
#: the suite holds at one time).
PEAK_RSS_LIMIT_GB = 4.0

_WORKER_PEAKS: list[float] = []


def _peak_rss_gb() -> float:
    """This process's peak resident memory (Linux reports ru_maxrss in kB)."""
    import resource
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024 ** 2


def pytest_testnodedown(node, error):
    """(xdist controller) a worker's peak, reported when it finishes; a
    worker that crashed reports none (xdist then names the test it ran)."""
    _WORKER_PEAKS.append(getattr(node, "workeroutput", {}).get("peak_rss_gb", 0.0))


def pytest_sessionfinish(session, exitstatus):
    """Fail the run when the suite's peak resident memory exceeds the budget."""
    config = session.config
    if hasattr(config, "workerinput"):  # an xdist worker: hand the figure to the controller
        config.workeroutput["peak_rss_gb"] = _peak_rss_gb()
        return
    peak = sum(_WORKER_PEAKS) if _WORKER_PEAKS else _peak_rss_gb()
    how = f"sum over {len(_WORKER_PEAKS)} workers" if _WORKER_PEAKS else "one process"
    reporter = config.pluginmanager.get_plugin("terminalreporter")
    if reporter is not None:
        reporter.write_line(f"peak resident memory: {peak:.2f} GB ({how}; budget {PEAK_RSS_LIMIT_GB:g} GB)")
    if peak > PEAK_RSS_LIMIT_GB and not config.getoption("--runslow"):
        if reporter is not None:
            reporter.write_line(f"error: the suite's peak resident memory {peak:.2f} GB exceeds "
                                f"{PEAK_RSS_LIMIT_GB:g} GB", red=True)
        session.exitstatus = pytest.ExitCode.TESTS_FAILED


@pytest.fixture(autouse=True, scope="module")
def _free_between_files():
    """Free each file's dolfinx/PETSc objects (and their C memory) before the
    next file: petsc4py frees a Mat or KSP only when its last Python
    reference goes, and module fixtures hold results until the file ends."""
    yield
    import gc
    gc.collect()
