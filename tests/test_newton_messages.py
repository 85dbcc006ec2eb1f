"""What Newton's failure says: the figure its convergence test judges, and
the threshold it is judged against (grader1 item 8: the message printed a
residual normalised otherwise, "relative residual history [..., 1.03e-09]",
then "did not converge" against a threshold of 1e-8)."""
import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

import roundoff  # noqa: E402
import tolerances as tol  # noqa: E402


def test_a_failed_step_prints_the_figure_its_convergence_test_judges(monkeypatch):
    """The tie of tests/scenes/shearslide.toml (efgm P1 at h = 0.1, six
    iterations at its fourth increment) given one iteration: every step
    fails, and each failure prints the equilibrium rows' residual over their
    forces, which must then lie above the threshold it names."""
    from contactcore import SolverError
    from contactcore import tolerances as core_tol
    from verification import methods

    monkeypatch.setattr(core_tol, "NEWTON_MAX_ITERATIONS", 1)
    monkeypatch.setattr(core_tol, "NEWTON_PROGRESS_ITERATIONS", 0, raising=False)
    factory = roundoff.CASES["tie-exact"][0]
    with pytest.raises(SolverError) as failed:
        methods.solver("efgm")(factory(), tol.MESSAGE_TIE_H, estimate_condition=False)
    details = getattr(failed.value, "details", "") or str(failed.value)
    found = re.findall(r"relative residual of the equilibrium rows over their forces \[([^\]]*)\], "
                       r"converged at <= ([0-9.e+\-]+)", details)
    assert found, f"no judged figure and threshold in the failure: {details[:600]}"
    for figures, threshold in found:
        last = float(figures.split(", ")[-1])
        assert last > float(threshold), f"printed {last:.2e} as not converged against {threshold}"
