"""The facts about a method that the shared core keeps by name
(contactcore.estimate.orders: ``RECOVERED_STRESS``, ``MESHFREE``; docs/
architecture.md, "A new method") against what each method's run does:
a table that drifted from its method would estimate the wrong error
(one recovery against two, a cell's stencil against a support's) with
no other test failing."""
from __future__ import annotations

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore.estimate import energy
from contactcore.estimate.orders import MESHFREE, RECOVERED_STRESS
from verification import methods

#: Coarse: the facts do not depend on the size.
H = 0.2


@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("method", list(methods.METHODS))  # a new method is held to the tables too
def test_the_core_tables_say_what_each_method_does(method, degree):
    """A (method, degree) is in RECOVERED_STRESS exactly when its reported
    stress differs from the stress of its own displacement (its
    ``direct_stress``) by more than round-off; a method is in MESHFREE
    exactly when its run records a support (``dmax``) and no cells."""
    scene = load_scene("A")
    result = methods.solver(method)(scene, H, degree=degree)
    x = np.linspace(0.05, 0.95, 7)
    points = np.array([(a, b) for a in x for b in (0.2, 0.3, 0.7, 0.8)])
    bodies = (points[:, 1] > 0.5).astype(int)
    reported = result.fields.stress(points, bodies)
    direct = energy.direct_stress(result.fields, points, bodies)
    apart = float(np.max(np.abs(reported - direct)) / np.max(np.abs(direct)))
    assert (apart > tol.FACT_STRESS_ROUNDOFF) == ((method, degree) in RECOVERED_STRESS), apart
    assert ("dmax" in result.discretisation) == (method in MESHFREE)
