"""What the stabilisation β moves on scene A (docs/contact-enforcement.md,
"What β moves, re-measured at three h").

Scene A with the unilateral law enforced exactly: Γ closed and tied, both
blocks of one material, so the exact σxx is continuous across Γ.  A3 is
σxx on Γ read on the + side (docs/scenes.md).  β/10 and 10β each move fe P2's A3
more than halving h moves it, and efgm P2's β/10 and 10β answers lie
further apart than h and h/2 (the acceptance that β 10× either way moves
a profile less than h → h/2 fails there, measured 2026-11-27).  What β moves is the jump σxx⁺ − σxx⁻
across Γ, the weak tie's residue (∂g_T/∂x at a small β, the elements' own
stress jump at a large one): its two sides move by about equal and opposite
amounts, and their mean moves with β less than with h.  The tests pin that
cause; where it stops holding the docs' explanation is wrong.

The acceptance's own criterion, read literally (β/10 against β, and 10β against
β, each against h against h/2 at β, at the largest sample), holds for
every stress profile of scene A in fe P1, efgm P1 and xfem P2 read on the
+ side and in fe P2 read as the two sides' mean (measured 2026-11-29);
the last test checks it."""
import functools
from dataclasses import replace

import numpy as np
import pytest

import tolerances as tol
from contactcore import discretisation, load_scene, make_law
from contactcore.estimate.singular import far_from_singular
from contactcore.profiles import sample_profile
from contactcore.scene import STRESS_QUANTITIES
from contactcore.tolerances import NITSCHE_STABILISATION
from efgm.options import EFGM
from verification.agreement import default_exclusion
from xdolfinx.options import FE, XFEM

#: The variants whose A3 β moves more than h/2 does while Γ's two sides of it
#: stay apart (xfem P1's − side at Γ on a row of nodes is a sliver's and is
#: not in the average: its β move is the + side's own, docs).
VARIANTS = {("fe", 2): FE(degree=2), ("efgm", 2): EFGM(degree=2)}
IDS = lambda k: f"{k[0]}-P{k[1]}"  # noqa: E731


@functools.lru_cache(maxsize=None)
def _solved(key, h, beta):
    """Scene A exact unilateral at stabilisation ``beta``: the scene and its result."""
    scene = load_scene("A").with_changes(
        law=make_law({"type": "unilateral", "enforcement": "exact", "stabilisation": beta}))
    return scene, discretisation.solve(scene, VARIANTS[key], h)


def _sides(key, h, beta, profile_id="A3"):
    """A profile on Γ (A1-A3: its one stress) read from the + and the − side,
    at the samples away from singular points, for scene A exact unilateral
    at stabilisation ``beta``."""
    scene, result = _solved(key, h, beta)
    profile = next(p for p in scene.profiles if p.id == profile_id)
    sides = {side: sample_profile(scene, result.fields, replace(profile, side=side), result.interface).columns
             for side in ("plus", "minus")}
    base = load_scene("A")
    keep = far_from_singular(base, np.column_stack([sides["plus"]["x"], sides["plus"]["y"]]), default_exclusion(base))
    (q,) = profile.quantities
    return sides["plus"][q][keep], sides["minus"][q][keep]


def _rms(a, b):
    return float(np.sqrt(np.mean((a - b) ** 2)))


@pytest.mark.slow
@pytest.mark.parametrize("key", list(VARIANTS), ids=IDS)
def test_the_stabilisation_moves_the_stress_jump_across_gamma_not_its_mean(key):
    """At h = BETA_H, β/10 and 10β move A3 by the jump across Γ: the mean of
    the two sides moves with β by less than BETA_MEAN_SHARE of h → h/2's move
    of it, and half the change of σxx⁺ − σxx⁻ is at least BETA_JUMP_SHARE of
    the + side's move (RMS over the samples away from singular points)."""
    beta, h = NITSCHE_STABILISATION, tol.BETA_H
    plus, minus = _sides(key, h, beta)
    fine_plus, fine_minus = _sides(key, h / 2, beta)
    mean, jump = 0.5 * (plus + minus), plus - minus
    halved = _rms(mean, 0.5 * (fine_plus + fine_minus))
    for factor in (0.1, 10.0):
        p, m = _sides(key, h, factor * beta)
        assert _rms(0.5 * (p + m), mean) < tol.BETA_MEAN_SHARE * halved, (factor, _rms(0.5 * (p + m), mean), halved)
        half_jump = 0.5 * ((p - m) - jump)
        assert _rms(half_jump, 0) >= tol.BETA_JUMP_SHARE * _rms(p, plus), (factor, _rms(half_jump, 0), _rms(p, plus))


#: The variants (and the side A1-A3 are read on) where β 10× either way
#: moves every stress profile of scene A less than halving h does; the
#: ratio's largest, measured 2026-11-29 at h = BETA_H (and at h/2): fe P1
#: 0.42 (0.20), efgm P1 0.21 (0.03), xfem P2 0.84 (0.83), fe P2's mean of
#: Γ's two sides 0.38 (0.44; its + side's A3 2.09).  0.8-2.1 s each.
LITERAL = {("fe", 1, "plus"): FE(degree=1), ("efgm", 1, "plus"): EFGM(degree=1),
           ("xfem", 2, "plus"): XFEM(degree=2), ("fe", 2, "mean"): FE(degree=2)}


@functools.lru_cache(maxsize=None)
def _stresses(key, h, beta):
    """Scene A exact unilateral at ``beta``: each stress profile's kept
    samples (away from singular points), A1-A3 read on the side ``key[2]``."""
    base = load_scene("A")
    scene = base.with_changes(law=make_law({"type": "unilateral", "enforcement": "exact", "stabilisation": beta}))
    result = discretisation.solve(scene, LITERAL[key], h)
    out = {}
    for profile in scene.profiles:
        for q in set(profile.quantities) & set(STRESS_QUANTITIES):
            read = replace(profile, side=key[2]) if profile.id in ("A1", "A2", "A3") else profile
            columns = sample_profile(scene, result.fields, read, result.interface).columns
            keep = far_from_singular(base, np.column_stack([columns["x"], columns["y"]]), default_exclusion(base))
            out[profile.id, q] = columns[q][keep]
    return out


@pytest.mark.parametrize("key", list(LITERAL), ids=lambda k: f"{k[0]}-P{k[1]}-{k[2]}")
def test_beta_ten_times_either_way_moves_each_stress_less_than_halving_h(key):
    """The acceptance's criterion, each way and each stress profile (A1-A4) of
    scene A, exact unilateral, at h = BETA_H: with p_b the profile at
    stabilisation b, max|p_{β/10} − p_β| and max|p_{10β} − p_β| are each
    below max|p_β(h/2) − p_β(h)| over the samples away from singular
    points.  (The gaps A5, whose exact value is 0, are left out: β sets
    their size at every h, docs/contact-enforcement.md.)"""
    beta, h = NITSCHE_STABILISATION, tol.BETA_H
    ref, fine = _stresses(key, h, beta), _stresses(key, h / 2, beta)
    for factor in (0.1, 10.0):
        moved = _stresses(key, h, factor * beta)
        for name, values in ref.items():
            by_beta, by_h = np.max(np.abs(moved[name] - values)), np.max(np.abs(fine[name] - values))
            assert by_beta < by_h, (factor, name, by_beta, by_h)


def test_efgm_p2_stiffer_tie_moves_sigma_yy_near_gamma_not_its_jump():
    """efgm P2's A2 (σyy on Γ, exact unilateral) at 10β moves as σyy itself
    near Γ, alike on Γ's two sides, not as the jump σyy⁺ − σyy⁻ that moves
    A3 (docs/contact-enforcement.md, "What β moves, re-measured at three
    h"): at h = BETA_H, half the change of the jump from β to 10β is below
    EFGM_BETA_JUMP_SHARE of the change of the two sides' mean, at the
    largest kept sample.  Measured 0.19 (h = 0.05), 0.09, 0.06, 0.03 (h =
    0.00625); A3 reads 1.74 (its move is the jump's)."""
    beta, h = NITSCHE_STABILISATION, tol.BETA_H
    plus, minus = _sides(("efgm", 2), h, beta, "A2")
    stiff_plus, stiff_minus = _sides(("efgm", 2), h, 10 * beta, "A2")
    jump = 0.5 * np.max(np.abs((stiff_plus - stiff_minus) - (plus - minus)))
    mean = 0.5 * np.max(np.abs((stiff_plus + stiff_minus) - (plus + minus)))
    assert jump < tol.EFGM_BETA_JUMP_SHARE * mean, (jump, mean)
