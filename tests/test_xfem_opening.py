"""Where Γ opens, xfem with an exact law on a Γ along a node row
(grader16 F2, docs/methods/xfem.md "Γ along a node row, exact laws").

grader16's `uni`: a unit block on a foundation of the same material, Γ
at y = 0.5 (a node row of every h that halves 0.5), the exact
unilateral law, the top pushed down and sideways, so Γ opens on its left
part.  When xfem read Γ's traction from the − cells alone, the opening
held at the node s = 0.325 at h = 0.05, 0.025 and 0.0125 (P1 and P2)
against 0.3156, and the far-field gap did not converge; read from both
cells, as fe reads a facet, it follows h.
"""
import pathlib

import numpy as np
import pytest

from contactcore import discretisation, load_scene
from contactcore.laws import OPEN

from tolerances import UNI_OPENING, UNI_OPENING_REFERENCE

UNI = (pathlib.Path(__file__).parent / "scenes" / "uni_opening.toml").read_text()


def _opening(tmp_path, h):
    """Where Γ's points change from open to closed (between the last open
    and the first closed point along x), and how many times they change."""
    from xdolfinx.options import XFEM
    path = tmp_path / "uni.toml"
    path.write_text(UNI)
    interface = discretisation.solve(load_scene(path), XFEM(degree=1), h).interface
    order = np.argsort(interface.points[:, 0], kind="stable")
    x, status = interface.points[order, 0], interface.final.status[order]
    change = np.flatnonzero((status[:-1] == OPEN) != (status[1:] == OPEN))
    return 0.5 * (x[change] + x[change + 1]), len(change)


def test_xfem_opening_follows_h_on_a_node_row(tmp_path):
    """xfem P1 at h = 0.025 and 0.0125: one opening point, within
    UNI_OPENING of the reference, closer at the finer h."""
    errors = []
    for h in (0.025, 0.0125):
        where, changes = _opening(tmp_path, h)
        assert changes == 1, (h, where)
        errors.append(abs(where[0] - UNI_OPENING_REFERENCE))
    assert max(errors) <= UNI_OPENING and errors[1] < errors[0], errors


@pytest.mark.parametrize("increments", [1, 5])
def test_the_unilateral_refusal_names_the_step_solved_and_no_order_in_h(tmp_path, increments):
    """grader16 F1: a law without history is solved once at its last
    increment and its path followed only when that fails, so a refusal
    at increment 1 of 5 says so (at 1 of 1 there is nothing to add); the
    message claims no order in h or degree (on `uni`, xfem P1 fails at
    h = 0.05 and 1/60 and solves at 0.025, 0.0125; on the docs' tilted
    block, finer h and degree 2 failed more often)."""
    from contactcore.newton import _no_equilibrium
    path = tmp_path / "uni.toml"
    path.write_text(UNI.replace("increments = 5", f"increments = {increments}"))
    failure = "step 0 → 0.5: Newton did not converge in 25 iterations"
    first, _ = str(_no_equilibrium(load_scene(path), 1, 6, [failure], from_rest=True)).splitlines()
    followed = " (followed once the one step to increment 5 failed)" if increments == 5 else ""
    assert first.startswith(f"scene g16-uni: increment 1 of {increments}{followed}: Newton found no open/closed "
                            "map of the unilateral law"), first
    assert "finer h" not in first and "fails more often" not in first
    assert "another h or degree may settle it or not" in first
