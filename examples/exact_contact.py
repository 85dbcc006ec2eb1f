"""Exact contact: an answer that no spring decides
================================================

The wedge of ``wedge.toml`` (a block pressed onto a plane inclined by about
11°) with Coulomb friction μ = 0.21, just above the slope's shear-to-normal
ratio of about 0.2, so that most of Γ slips.  It is solved twice per
spring stiffness k = k_N = k_T:

* with the penalty law (the default, ``enforcement = "penalty"``): Γ's
  tractions are springs, ``t = k g``, so the answer depends on k.  Soft
  springs let the blocks overlap and slide by ``t/k``, and keep all of Γ
  sticking;
* with ``enforcement = "exact"`` (Nitsche's method,
  docs/contact-enforcement.md): Signorini's condition and Coulomb's law
  hold without springs.  k_N and k_T are read and play no part: every k
  gives the same answer, to round-off.

Run it with ``.venv/bin/python examples/exact_contact.py``.
"""
from pathlib import Path

import numpy as np

from contactcore import load_scene, make_law, sample_profiles
from verification import methods

HERE = Path(__file__).resolve().parent
#: Friction coefficient: above the slope's ratio, so the wedge holds, but only just.
MU = 0.21
#: Spring stiffnesses k_N = k_T tried (Pa/m), from soft (about E/200 per metre) to stiff.
SPRINGS = (1e9, 1e12)


def solve_with(scene, enforcement, k, h):
    """The wedge with Coulomb friction at springs ``k``, enforced as
    ``enforcement`` says, solved by fe at degree 1: Γ's profile."""
    law = make_law({"type": "coulomb", "kN": k, "kT": k, "mu": MU, "enforcement": enforcement})
    result = methods.solver("fe")(scene.with_changes(law=law), h)
    # Sample the run's own scene: the tractions are its law's response to the jump.
    [gamma] = sample_profiles(result.scene, result.fields, result.interface)
    return gamma.columns, result.interface.final.counts()


def spread(runs, q):
    """The largest difference of quantity ``q`` between the runs, as a share
    of its largest value."""
    values = np.array([columns[q] for columns, _ in runs])
    return float(np.ptp(values, axis=0).max() / np.abs(values).max())


def main(h=None, springs=SPRINGS):
    scene = load_scene(HERE / "wedge.toml")
    out = {}
    for enforcement in ("penalty", "exact"):
        runs = [solve_with(scene, enforcement, k, h) for k in springs]
        for k, (columns, counts) in zip(springs, runs):
            print(f"{enforcement:7s} k = {k:.0e} Pa/m: {counts['stick']} points stick, {counts['slip']} slip, "
                  f"{counts['open']} open; largest |g_N| {np.abs(columns['gN']).max():.2e} m, "
                  f"largest pressure {-columns['tN'].min():.4g} Pa")
        moved = {q: spread(runs, q) for q in ("tN", "tT")}
        print(f"{enforcement}: t_N moves by {moved['tN']:.1e}, t_T by {moved['tT']:.1e} of their largest values "
              "over the springs")
        out[enforcement] = {"runs": runs, "moved": moved}
    return out


if __name__ == "__main__":
    main()
