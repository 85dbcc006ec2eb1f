"""The block under its own weight on an exact Coulomb Γ
(docs/scenes/self_weight_beta.toml) and what the reaction-flux tests read
of it (tests/test_nodal_reaction.py, tests/test_reaction_flux.py): its
closed form, a solved scene's profiles, and each quantity's scale.

The closed form: a block of height ``HEIGHT`` on Γ inclined by 10°, top
pressure ``S0``, shear ``T``, body force ``B`` (per volume, along y):
``σyy = S0 + B (HEIGHT − y)``, ``σxy = T``, no jump across Γ.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from contactcore import discretisation, load_scene, make_law
from contactcore.profiles import sample_profile

SCENE = str(Path(__file__).resolve().parent.parent / "docs" / "scenes" / "self_weight_beta.toml")
#: the block's E, HEIGHT, S0 (top pressure), T (shear), B (body force)
E, HEIGHT, S0, T, B = 1e9, 1.0, -1e6, 4e5, -2e6
DISPLACEMENTS = ("ux", "uy", "gN", "gT")


def closed(q: str, x, y):
    """The block's closed form of quantity ``q`` at (x, y)."""
    n = np.array([-np.sin(np.radians(10)), np.cos(np.radians(10))])
    syy = S0 + B * (HEIGHT - y)
    tx, ty = T * n[1] + 0 * x, T * n[0] + syy * n[1]
    return {"ux": 2 * T / E * y, "uy": (S0 * y + B * (HEIGHT * y - y * y / 2)) / E, "syy": syy, "sxy": T + 0 * y,
            "gN": 0 * y, "gT": 0 * y, "tN": n[0] * tx + n[1] * ty, "tT": n[1] * tx - n[0] * ty}[q]


def exact_profiles(path: str, options, beta: float, h: float) -> dict:
    """(profile id, quantity) -> (x, y, values) of the scene at ``path``
    with its Coulomb law exact at ``beta``, solved with ``options`` at ``h``."""
    base = load_scene(path)
    scene = base.with_changes(law=make_law({"type": "coulomb", "mu": base.law.mu, "enforcement": "exact",
                                            "stabilisation": beta}))
    result = discretisation.solve(scene, options, h)
    out = {}
    for p in scene.profiles:
        c = sample_profile(scene, result.fields, p, result.interface).columns
        out.update({(p.id, q): (np.asarray(c["x"]), np.asarray(c["y"]), np.asarray(c[q], float))
                    for q in p.quantities})
    return out


def scales(profiles: dict) -> dict:
    """Each quantity's family scale: the largest |u| for displacements and
    gaps, the largest |σ|, |t| for stresses and tractions."""
    largest = {fam: max(np.max(np.abs(v)) for (_, q), (_, _, v) in profiles.items()
                        if (q in DISPLACEMENTS) == fam) for fam in (True, False)}
    return {k: largest[k[1] in DISPLACEMENTS] for k in profiles}


def closed_error(got: dict) -> float:
    """The largest error of any profile value of ``got`` against the
    closed form, as a share of its family's largest exact value."""
    exact = {k: closed(k[1], x, y) for k, (x, y, _) in got.items()}
    scale = scales({k: (None, None, v) for k, v in exact.items()})
    return max(np.max(np.abs(got[k][2] - exact[k])) / scale[k] for k in got)
