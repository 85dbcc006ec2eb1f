"""A scene from a TOML file
===========================

Read ``wedge.toml`` (the README's scene: a block pressed onto an inclined
plane), solve it with the conforming reference, and check the normal
traction on the interface Γ against a hand estimate.

Run it with ``.venv/bin/python examples/scene_from_toml.py``.
"""
from pathlib import Path

import numpy as np

from contactcore import load_scene, sample_profiles
from verification import methods

HERE = Path(__file__).resolve().parent


def main(h=None):
    # Every field of the file is checked as it is read: a typo or an
    # impossible value ends in a SceneError naming the field.
    scene = load_scene(HERE / "wedge.toml")
    print(f"scene {scene.name}: {scene.title}")

    # Solve with the conforming finite elements (fe) at degree 2.  h=None
    # takes the scene's own resolution (h = 0.05 in the file).
    result = methods.solver("fe")(scene, h, degree=2)
    print(f"fe P2: {result.dofs} unknowns, relative residual {result.solver.residual:.1e}")

    # The file asks for one profile, "gamma": gN, gT, tN, tT along Γ.
    [gamma] = sample_profiles(scene, result.fields, result.interface)
    tN = gamma.columns["tN"]

    # Estimate: under the top's pressure p the blocks carry σyy ≈ −p, so on
    # Γ, with unit normal n, t_N = n·σn ≈ −p n_y².  The ends of Γ feel the
    # free sides and the clamped bottom, so compare the middle half.
    p = scene.loads[0].value
    n = np.asarray(scene.interface.normal)
    estimate = -p * n[1] ** 2
    middle = slice(len(tN) // 4, 3 * len(tN) // 4)
    mean_tN = float(np.mean(tN[middle]))
    print(f"mean t_N on the middle of Γ: {mean_tN:.4g} Pa (estimate −p n_y² = {estimate:.4g} Pa)")
    # t_N < 0 everywhere: Γ is closed and in compression (t_N > 0 would be tension).
    print(f"Γ closed everywhere: {bool(np.all(gamma.columns['tN'] < 0))}")
    return {"mean_tN": mean_tN, "estimate": estimate, "tN": tN}


if __name__ == "__main__":
    main()
