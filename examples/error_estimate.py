"""How far is a run from the exact answer?
========================================

Without a reference: solve the wedge of ``wedge.toml`` with fe P1 at h and
h/2 and let Richardson extrapolation estimate the finer run's error at
every sample of Γ's profile (docs/error-estimates.md).  Then check the
estimate against a run four times finer at degree 2, which stands in for
the exact answer: the ratio of the two (the effectivity) is near 1 when the
estimate can be trusted.

Γ meets the free sides at two points where the stresses of two materials
are singular; the estimate there is only an indicator, so the samples within
0.1 of the domain's size of those points are left out, as the agreement
checks do (``verification.agreement.default_exclusion``).

Run it with ``.venv/bin/python examples/error_estimate.py``.
"""
from pathlib import Path

import numpy as np

from contactcore import load_scene, sample_profiles
from contactcore.estimate import estimate, far_from_singular, rms
from verification import methods
from verification.agreement import default_exclusion
from xdolfinx.options import FE

HERE = Path(__file__).resolve().parent
QUANTITIES = ("gN", "gT", "tN", "tT")


def main(h=None):
    scene = load_scene(HERE / "wedge.toml")
    h = h or scene.h
    exclude = default_exclusion(scene)

    # fe P1 at h and h/2: `result` is the h/2 run, `est` its estimated error.
    result, est = estimate(scene, FE(degree=1), h, levels=2, exclude=exclude)
    [gamma] = sample_profiles(result.scene, result.fields, result.interface)
    errors = est.error_columns("gamma")            # {"gN_err": ..., ...}, per sample, in the quantity's units
    keep = far_from_singular(scene, np.column_stack([gamma.columns["x"], gamma.columns["y"]]), exclude)

    # A stand-in for the exact answer: fe P2 at h/4.
    truth = methods.solver("fe")(scene, h / 4, degree=2)
    [exact] = sample_profiles(truth.scene, truth.fields, truth.interface)

    print(f"fe P1 at h = {h / 2:g}, {keep.sum()} of {len(keep)} samples of Γ away from its ends:")
    out = {}
    for q in QUANTITIES:
        estimated = rms(errors[q + "_err"][keep])
        true = rms((gamma.columns[q] - exact.columns[q])[keep])
        scale = rms(gamma.columns[q][keep])
        print(f"  {q}: estimated RMS error {estimated:.3g} ({estimated / scale:.1e} of {q}), "
              f"against fe P2 at h/4 {true:.3g}: effectivity {estimated / true:.2f}")
        out[q] = {"estimated": estimated, "true": true}
    print(f"  energy (Zienkiewicz–Zhu): {est.energy.relative:.2%} of the energy norm")
    return {"quantities": out, "energy": est.energy.relative, "warnings": est.summary()["warnings"]}


if __name__ == "__main__":
    main()
