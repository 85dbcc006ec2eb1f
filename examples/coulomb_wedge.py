"""A Coulomb wedge: stick, slip, and no equilibrium
==================================================

The block of ``wedge.toml`` rests on a plane inclined by about 11°
(normal (−0.2, 1)), pressed by 1 MPa on its top, its sides free.  On the
interface Γ the shear-to-normal ratio |t_T|/|t_N| is close to the slope's
tangent, 0.2.  Coulomb friction lets a point stick while |t_T| ≤ μ p
(p = −t_N, the contact pressure) and slip at |t_T| = μ p otherwise
(docs/scenes.md, "Interface laws").  Lowering μ turns sticking points into
slipping ones; below the ratio no equilibrium exists and the solve is
refused, naming the increment.

Run it with ``.venv/bin/python examples/coulomb_wedge.py``.
"""
from pathlib import Path

import numpy as np

from contactcore import SolverError, load_scene, make_law
from verification import methods

HERE = Path(__file__).resolve().parent
FRICTION = (0.5, 0.25, 0.21, 0.1)


def solve_with(scene, mu, h):
    """The wedge with friction coefficient ``mu``, solved by fe at degree 1."""
    law = make_law({"type": "coulomb", "kN": scene.law.kN, "kT": scene.law.kT, "mu": mu})
    return methods.solver("fe")(scene.with_changes(law=law), h)


def main(h=None, friction=FRICTION):
    scene = load_scene(HERE / "wedge.toml")
    rows = {}
    for mu in friction:
        try:
            result = solve_with(scene, mu, h)
        except SolverError as refused:
            # Its first line names the increment that failed and the check that failed.
            print(f"μ = {mu}: refused: {str(refused).splitlines()[0]}")
            rows[mu] = None
            continue
        # The history on Γ, at fe's quadrature points: the final state.
        final = result.interface.final
        tN, tT = final.traction[:, 0], final.traction[:, 1]
        ratio = float(np.max(np.abs(tT) / -tN))        # Γ is closed here: t_N < 0
        counts = final.counts()
        print(f"μ = {mu}: {counts['stick']} points stick, {counts['slip']} slip, {counts['open']} open; "
              f"largest |t_T|/p = {ratio:.3f}")
        rows[mu] = {"counts": counts, "ratio": ratio, "tN": tN, "tT": tT,
                    "status": final.status, "iterations": result.solver.iterations}
    return rows


if __name__ == "__main__":
    main()
