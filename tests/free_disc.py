"""A stiff disc held by nothing but its interface with a plate (scene C's
plate and circular Γ, the disc 100 times stiffer): the plate pulled away
from it on three sides, where Γ opens all round and the disc's position is
not determined, or pressed onto it, where Γ closes all round and holds it
(tests/test_free_body.py, tests/roundoff.py).
"""
from __future__ import annotations

from contactcore import Material, Pressure, load_scene, make_law

#: The interface laws of the disc: unilateral, exact or on springs stiffer
#: than the plate (k = 1e13 Pa/m against E/h = 2e12 Pa/m at h = 0.1).
LAWS = {"exact": {"type": "unilateral", "enforcement": "exact"},
        "penalty": {"type": "unilateral", "kN": 1e13, "kT": 1e13},
        "linear": {"type": "linear", "kN": 1e13, "kT": 1e13}}

#: The pressure on the plate's left, right and top sides (Pa): negative pulls.
PRESSURE = 2e5


def disc(pulled: bool, law: str = "exact"):
    """Scene C with a disc 100 times stiffer than its plate, the law
    ``LAWS[law]``, and the plate's free sides pulled (``pulled``) or
    pressed by PRESSURE, in one increment."""
    sign = -1.0 if pulled else 1.0
    return load_scene("C").with_changes(
        name=f"disc-{'pulled' if pulled else 'pressed'}-{law}", increments=1,
        materials={"minus": Material(E=2e13, nu=0.3), "plus": Material(E=2e11, nu=0.3)},
        law=make_law(LAWS[law]), loads=tuple(Pressure(side, sign * PRESSURE) for side in ("left", "right", "top")))
