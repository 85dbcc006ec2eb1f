"""A scene built in Python
=========================

A polymer rod in an aluminium plate squeezed by a pressure on its top edge.
The rod touches the plate through a *unilateral* interface: it carries
pressure, never tension.  The squeezed hole shortens vertically and widens
sideways, so the plate presses the rod at its top and bottom and pulls
away from it at its sides, where Γ opens.
Built from the dataclasses of :mod:`contactcore` (the same fields as a
TOML file, docs/scenes.md), solved by XFEM on a mesh that ignores Γ.

Run it with ``.venv/bin/python examples/scene_in_python.py``.
"""
import numpy as np

from contactcore import (CircleInterface, InterfaceProfile, LineProfile, Material, Rectangle, Scene, Support,
                         Traction, make_law, sample_profiles)
from verification import methods


def build_scene() -> Scene:
    return Scene(
        name="rod-in-plate",
        title="a polymer rod in a squeezed aluminium plate, unilateral contact",
        domain=Rectangle(corner=(0.0, 0.0), size=(1.0, 1.0)),
        # A circle: the disc inside is the − body (the rod), n points out of it.
        interface=CircleInterface(centre=(0.5, 0.5), radius=0.2),
        materials={"minus": Material(E=3e9, nu=0.35), "plus": Material(E=7e10, nu=0.33)},
        law=make_law({"type": "unilateral", "kN": 1e13, "kT": 1e13}),
        # Clamp the bottom edge, push the top edge down with 1 MPa.
        supports=(Support("bottom", fix="xy"),),
        loads=(Traction("top", (0.0, -1e6)),),
        profiles=(InterfaceProfile("gamma", ("gN", "tN"), parameter="angle"),
                  LineProfile("section", start=(0.0, 0.9), end=(1.0, 0.9), quantities=("syy", "uy"))),
        h=0.05,
    ).validated()   # the same checks as a file gets


def main(h=None):
    scene = build_scene()
    result = methods.solver("xfem")(scene, h, degree=2)
    print(f"xfem P2: {result.dofs} unknowns, relative residual {result.solver.residual:.1e}")
    profiles = {p.id: p for p in sample_profiles(scene, result.fields, result.interface)}

    # Along Γ, against the polar angle θ: g_N > 0 where Γ opened, and there
    # the unilateral law gives t_N = 0; where it stays closed t_N ≤ 0.
    gamma = profiles["gamma"].columns
    opened = gamma["gN"] > 0
    side = np.abs(np.cos(gamma["s"])) > np.cos(np.radians(30))     # within 30° of θ = 0 or 180°
    print(f"Γ open on {opened.mean():.0%} of its samples; of the samples at the rod's sides (within 30° of "
          f"θ = 0 or 180°), {opened[side].mean():.0%} are open")
    print(f"largest |t_N| where open: {np.max(np.abs(gamma['tN'][opened])):.3g} Pa; "
          f"largest tension anywhere: {max(gamma['tN'].max(), 0.0):.3g} Pa; "
          f"largest pressure: {-gamma['tN'].min():.3g} Pa")

    # A horizontal section above the rod carries the whole load: the
    # integral of σyy across it balances the top's −1e6 Pa times its 1 m.
    section = profiles["section"].columns
    resultant = float(np.trapz(section["syy"], section["s"]))
    print(f"∫σyy dx across y = 0.9: {resultant:.6g} N/m (the applied −1e6 N/m)")
    return {"gN": gamma["gN"], "tN": gamma["tN"], "theta": gamma["s"], "side": side, "resultant": resultant}


if __name__ == "__main__":
    main()
