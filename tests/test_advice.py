"""The advice of an increment that does not converge names only remedies
that apply to the law and its enforcement: springs (k_N, k_T) only where
the law is enforced by them, Nitsche's β only where it is enforced exactly,
more increments only for a nonlinear law, the friction limit (μ times the pressure) only for friction."""
import pytest

from contactcore import load_scene
from contactcore.enforcement import make_law
from contactcore.newton import _no_equilibrium

FAILURE = ["step 0 → 1: Newton did not converge in 25 iterations; relative residual of the equilibrium rows over their forces [1.0e+00, 5.0e-01], converged at <= 1e-08"]
#: law -> (phrases its advice holds, phrases it must not hold)
CASES = {
    "coulomb penalty": ({"type": "coulomb", "kN": 1e10, "kT": 1e8, "mu": 0.2},
                        ["soften k_N, k_T", "use more increments", "μ times its pressure"], ["stabilisation"]),
    "coulomb exact": ({"type": "coulomb", "mu": 0.2, "enforcement": "exact"},
                      ["another stabilisation", "use more increments", "μ times its pressure"], ["k_N", "k_T", "springs"]),
    # Newton out of iterations under the unilateral law: its tie is named first (health.tie_cause)
    "unilateral penalty": ({"type": "unilateral", "kN": 1e10, "kT": 1e8},
                           ["soften k_N, k_T", "more increments help only where a consistent map exists"],
                           ["stabilisation", "μ times its pressure", "stick/slip"]),
    "unilateral exact": ({"type": "unilateral", "enforcement": "exact"},
                         ["another stabilisation", "more increments help only where a consistent map exists"],
                         ["k_N", "springs", "μ times its pressure"]),
    "linear penalty": ({"type": "linear", "kN": 1e10, "kT": 1e8},
                       ["k_N, k_T", "more increments do not help"],
                       ["use more increments", "stabilisation", "μ times its pressure", "open points", "stick"]),
    "bonded exact": ({"type": "bonded"},
                     ["another stabilisation", "more increments do not help"],
                     ["use more increments", "k_N", "springs", "μ times its pressure", "open points", "stick"]),
}


@pytest.mark.parametrize("name", CASES)
def test_a_failed_first_increment_advises_what_applies_to_its_law(name):
    law, holds, lacks = CASES[name]
    scene = load_scene("C").with_changes(law=make_law(law), follow_path=True)
    advice = str(_no_equilibrium(scene, 1, 6, FAILURE))  # the unilateral law's on its first line
    assert [p for p in holds if p not in advice] == [] and [p for p in lacks if p in advice] == [], advice
