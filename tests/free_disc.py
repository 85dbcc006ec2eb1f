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


#: The squeezed disc's friction coefficient and loads: the block pulled up
#: on its top (Pa) and pressed on its left and right sides (Pa).
SQUEEZE_MU, SQUEEZE_PULL, SQUEEZE_PRESSURE = 0.5, 2e5, 1e6


def squeezed(enforcement: str = "exact"):
    """A steel disc (E = 2e11 Pa, radius 0.4) held by Γ alone in a 2 × 2
    plane-strain block 20 times softer with ν = 0.45, fixed at its bottom,
    pulled up on its top and squeezed from the sides: the poles open, the
    sides hold the disc by Coulomb friction (μ = 0.5, exact or on springs
    k = 1e12 Pa/m), and Newton's maps pass through ones whose closed points
    all slip, the disc free to turn (docs/contact-enforcement.md, "Known
    limits")."""
    from contactcore.scene_files import scene_from_dict

    law = {"type": "coulomb", "mu": SQUEEZE_MU, "kN": 1e12, "kT": 1e12, "enforcement": enforcement}
    return scene_from_dict({
        "name": f"disc-squeezed-{enforcement}", "plane": "strain", "h": 0.1,
        "domain": {"type": "rectangle", "size": [2.0, 2.0]},
        "interface": {"type": "circle", "centre": [1.0, 1.0], "radius": 0.4, "law": law},
        "materials": {"minus": {"E": 2e11, "nu": 0.3}, "plus": {"E": 1e10, "nu": 0.45}},
        "supports": [{"boundary": "bottom", "fix": "xy"}],
        "loads": [{"type": "traction", "boundary": "top", "value": [0.0, SQUEEZE_PULL]},
                  {"type": "pressure", "boundary": "left", "value": SQUEEZE_PRESSURE},
                  {"type": "pressure", "boundary": "right", "value": SQUEEZE_PRESSURE}]})
