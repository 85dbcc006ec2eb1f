"""Coulomb's law at μ = 0 (frictionless): the cone is t_T = 0, so stick
and slip are one state, and which of the two Newton gives a closed point
is its trial traction's round-off (grader24 F1: fe P2 40 stick / 0 slip
under OPENBLAS_CORETYPE=Haswell, 39 / 1 under Nehalem, xfem P1 two points
apart between serial and 2 ranks; the tractions alike to 1e-14).  Outputs
report every closed point ``slip`` (``Increment.frictionless``), so the
reported statuses follow no round-off."""
from pathlib import Path

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore.discretisation import solve
from contactcore.interface_path import Increment
from contactcore.laws import OPEN, PARTIAL, SLIP, STICK
from xdolfinx.options import FE, XFEM

SCENE = Path(__file__).parent / "scenes" / "frictionless_body.toml"


def test_a_frictionless_closed_point_is_reported_slipping_whatever_newton_chose():
    """``reported_status`` maps STICK to SLIP where the law is
    frictionless, leaves OPEN and a partial point alone, and changes
    nothing otherwise."""
    status = np.array([STICK, SLIP, OPEN, STICK], np.int8)
    theta = np.array([np.nan, np.nan, np.nan, 0.5])
    step = Increment(1.0, (1.0,), 1, [0.0], np.zeros((4, 2)), np.zeros((4, 2)), status, theta, frictionless=True)
    assert step.reported_status().tolist() == [SLIP, SLIP, OPEN, PARTIAL]
    assert step.counts() == {"open": 1, "stick": 0, "slip": 2, "partial": 1}
    plain = Increment(1.0, (1.0,), 1, [0.0], np.zeros((4, 2)), np.zeros((4, 2)), status)
    assert plain.reported_status().tolist() == status.tolist()


@pytest.mark.parametrize("options", [FE(degree=2), XFEM(degree=1)], ids=["fe-P2", "xfem-P1"])
def test_the_frictionless_body_slips_at_every_point_with_no_shear(options):
    """grader24's body pressed by its weight onto a frictionless Γ: every
    point closed and reported slipping, t_N the weight's pressure and t_T
    zero, both to a patch test's round-off of it (PATCH_ROUNDOFF)."""
    scene = load_scene(SCENE)
    result = solve(scene, options, 0.1)
    final = result.interface.final
    assert final.counts() == {"open": 0, "stick": 0, "slip": len(final.status)}
    p = 2e6 * 0.5  # the + body's weight per length: body force 2e6 N/m³ over its 0.5 m height
    assert np.max(np.abs(final.traction[:, 0] + p)) <= tol.PATCH_ROUNDOFF * p
    assert np.max(np.abs(final.traction[:, 1])) <= tol.PATCH_ROUNDOFF * p
