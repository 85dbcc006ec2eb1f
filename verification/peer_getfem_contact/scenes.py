"""The study's scenes, each with an exact law: the shipped ones and three made here.

GetFEM's contact checks our exact laws (Nitsche's method,
docs/contact-enforcement.md) on scenes that exercise them: scene A tied
where closed, C-coulomb (μ = 0.2), the layered-slip closed form (stick,
slip, stick, reversed slip; :func:`verification.closed_forms.layered_slip`),
scene A with Γ inclined (:data:`INCLINED_A`: Γ opens over part of its
length), the README's wedge sticking, and its slipping variant
(:data:`WEDGE_SLIP`).  Scene B is not among them: under its torque alone Γ
carries no pressure, so Coulomb's friction holds nothing and the rod has
no equilibrium (docs/peer-contact.md).

Contract: :data:`STUDIES` maps a name to a function that builds the scene;
:func:`exact_scene` builds one by name or refuses an unknown name.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from contactcore import DiscretisationError, Scene
from contactcore.enforcement import make_law
from contactcore.geometry import LineInterface
from contactcore.scene import InterfaceProfile, Traction

from .reach import METHOD

#: The README's wedge (a block pressed onto a plane inclined at 11.3°).
WEDGE = Path(__file__).resolve().parents[2] / "examples" / "wedge.toml"

#: Scene A's Γ turned this many degrees through (0.5, this height): the tied
#: unilateral law opens it over part of its length (tests/test_exact.py's
#: placement, rounded).
INCLINED_A = (17.8, 0.52)

#: The wedge's slipping variant: μ and the top's traction (Pa).  Its mean
#: shear on Γ is 0.094 of the pressure, below μ, so the block holds; Γ
#: slips from x ≈ 0.04 to 0.75 and sticks at its right end (fe P2, h =
#: 0.0125: 73 % of Γ slipping).
WEDGE_SLIP = (0.15, (3e5, -1e6))

#: Γ sampled on the scenes whose own profiles do not follow it.
_GAMMA_PROFILE = InterfaceProfile("gamma", ("gN", "gT", "tN", "tT"), parameter="arclength")


def _shipped(name: str, law: dict):
    def build() -> Scene:
        from contactcore import load_scene
        return load_scene(name).with_changes(law=make_law(law))
    return build


def _layered_slip() -> Scene:
    """The layered-slip closed form with its law exact (stick, slip, stick,
    reversed slip; :func:`verification.closed_forms.layered_slip`)."""
    from verification.closed_forms import layered_slip
    return layered_slip(exact=True).scene


def _inclined_A() -> Scene:
    """Scene A, tied unilateral, Γ turned :data:`INCLINED_A`: profiles along
    Γ (t, g) and A4 (σxx along y = 1, as shipped)."""
    from contactcore import load_scene
    angle, height = np.radians(INCLINED_A[0]), INCLINED_A[1]
    base = load_scene("A")
    itf = LineInterface((0.5, height), (-float(np.sin(angle)), float(np.cos(angle))))
    profiles = (_GAMMA_PROFILE, *(p for p in base.profiles if p.id == "A4"))
    return base.with_changes(name=f"A-inclined{INCLINED_A[0]:g}", interface=itf, profiles=profiles,
                             law=make_law({"type": "unilateral", "enforcement": "exact"}))


def _wedge(slipping: bool) -> Scene:
    """The README's wedge with its Coulomb law exact; ``slipping``: with μ and
    the top's traction of :data:`WEDGE_SLIP`."""
    from contactcore import load_scene
    wedge = load_scene(WEDGE)
    if not slipping:
        return wedge.with_changes(law=make_law({"type": "coulomb", "mu": wedge.law.mu, "enforcement": "exact"}))
    mu, top = WEDGE_SLIP
    return wedge.with_changes(name="wedge-slip", law=make_law({"type": "coulomb", "mu": mu, "enforcement": "exact"}),
                              loads=(Traction("top", top),))


#: The study's scenes, each with an exact law: scene A and its inclined Γ
#: tied where closed (``unilateral``), C-coulomb with its own μ = 0.2, the
#: layered-slip closed form, the README's wedge (μ = 0.5, sticking) and its
#: slipping variant.  Scene B is not among them: under its torque alone Γ
#: carries no pressure, so Coulomb's friction holds nothing and the rod has
#: no equilibrium (docs/peer-contact.md).
STUDIES = {"A": _shipped("A", {"type": "unilateral", "enforcement": "exact"}),
           "C-coulomb": _shipped("C-coulomb", {"type": "coulomb", "mu": 0.2, "enforcement": "exact"}),
           "layered-slip": _layered_slip,
           "A-inclined": _inclined_A,
           "wedge": lambda: _wedge(False),
           "wedge-slip": lambda: _wedge(True)}


def exact_scene(name: str) -> Scene:
    """A scene of the study (:data:`STUDIES`), its law exact."""
    if name not in STUDIES:
        raise DiscretisationError(f"{METHOD}: no study scene {name!r} (known: {', '.join(STUDIES)})")
    return STUDIES[name]()
