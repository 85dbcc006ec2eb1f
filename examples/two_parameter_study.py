"""A two-parameter study
=======================

How does the contact on scene C-coulomb (a rod in a block, Coulomb
friction with μ = 0.2) change with the rod's radius and the friction
coefficient?  Each point of the product is a new scene, made with
``Scene.with_changes`` (checked like a file), solved by xfem, and read on
Γ.  A point that has no answer (a refused solve) is kept as a row with its
reason, and the study goes on.

The command line does the same, with plots and a CSV:
``.venv/bin/python -m verification study C-coulomb --param radius --values
0.3 0.45 --param mu --values 0.1 0.4 --method xfem --out DIR``.

Run it with ``.venv/bin/python examples/two_parameter_study.py``.
"""
import itertools

import numpy as np

from contactcore import CircleInterface, ContactError, load_scene, make_law
from verification import methods

RADII = (0.3, 0.45)
FRICTION = (0.1, 0.4)


def scene_at(base, radius, mu):
    """Scene C-coulomb with another radius and friction coefficient."""
    law = make_law({"type": "coulomb", "kN": base.law.kN, "kT": base.law.kT, "mu": mu})
    return base.with_changes(interface=CircleInterface(base.interface.centre, radius), law=law)


def main(h=None, radii=RADII, friction=FRICTION):
    base = load_scene("C-coulomb")
    rows = []
    print(f"{'radius (m)':>10} {'mu':>5} {'open':>6} {'stick':>6} {'slip':>6} {'max p (Pa)':>11} {'max |tT| (Pa)':>14}")
    for radius, mu in itertools.product(radii, friction):
        try:
            result = methods.solver("xfem")(scene_at(base, radius, mu), h)
        except ContactError as why:
            rows.append({"radius": radius, "mu": mu, "failed": str(why)})
            print(f"{radius:>10} {mu:>5}  failed: {why}")
            continue
        final = result.interface.final
        tN, tT = final.traction[:, 0], final.traction[:, 1]
        row = {"radius": radius, "mu": mu, **final.counts(), "max_p": float(np.max(-tN)),
               "max_tT": float(np.max(np.abs(tT))), "tN": tN, "tT": tT}
        rows.append(row)
        print(f"{radius:>10} {mu:>5} {row['open']:>6} {row['stick']:>6} {row['slip']:>6} {row['max_p']:>11.4g} "
              f"{row['max_tT']:>14.4g}")
    return rows


if __name__ == "__main__":
    main()
