"""Stability of Nitsche's traction on any cut: scene A with the unilateral
law enforced exactly and Γ inclined, placed anywhere (the placements of the
inclined-Γ tests), xfem's and efgm's t_N at Γ's points agree with fe P2's
at h/2 within NITSCHE_CUT_AGREE, with no point-to-point oscillation.  Slow:
the reference alone takes 4–20 s a placement."""
from functools import lru_cache

import numpy as np
import pytest

import tolerances as tol
from contactcore import discretisation
from contactcore.interface_path import along
from efgm.options import EFGM
from nitsche_fields import exact
from placements import inclined_A, seeded_inclined
from xdolfinx.options import FE, XFEM

H = 0.025
PLACEMENTS = [(20.0, 0.4)] + seeded_inclined(23)
METHODS = {"xfem-quad-P1": XFEM(degree=1, cell="quad"), "xfem-quad-P2": XFEM(degree=2, cell="quad"),
           "xfem-triangle-P1": XFEM(degree=1, cell="triangle"), "xfem-triangle-P2": XFEM(degree=2, cell="triangle"),
           "efgm-P1": EFGM(degree=1), "efgm-P2": EFGM(degree=2)}
#: Placement 0 (Γ at 20° through (0, 0.4)): Γ opens near its left end, and
#: xfem P2's t_N at the first kept point next to the opening is 4.6 % off
#: fe P2's (quads; 4.5 % on triangles), falling to 0.3 % within a tenth of
#: Γ; fe P2 itself moves 0.7 % there from h = 0.025 to 0.0125 (measured
#: 2026-11-26, β = 3): the opening point's location, resolved to a cell,
#: not an oscillation (the second-difference bound holds).
OPENING = pytest.mark.xfail(strict=True, reason="placement 0, xfem P2: 4.6 % at Γ's opening point (OPENING)")


def _marks(k, name):
    return [OPENING] if k == 0 and name in ("xfem-quad-P2", "xfem-triangle-P2") else []


def _profile(scene, result):
    s = along(scene.interface, result.interface.points)
    order = np.argsort(s)
    return s[order], result.interface.final.traction[order, 0]


@lru_cache(maxsize=None)
def _reference(k):
    scene = exact(inclined_A(*PLACEMENTS[k]))
    return scene, _profile(scene, discretisation.solve(scene, FE(degree=2), H / 2))


@pytest.mark.slow
@pytest.mark.parametrize("k, name", [pytest.param(k, n, marks=_marks(k, n)) for k in range(len(PLACEMENTS))
                                     for n in METHODS])
def test_normal_traction_on_any_cut_agrees_with_fe(k, name):
    scene, (s_ref, t_ref) = _reference(k)
    s, t = _profile(scene, discretisation.solve(scene, METHODS[name], H))
    margin = 0.1 * (s_ref.max() - s_ref.min())
    keep = (s > s_ref.min() + margin) & (s < s_ref.max() - margin)
    scale = np.max(np.abs(t_ref))
    error = (t[keep] - np.interp(s[keep], s_ref, t_ref)) / scale
    bound = tol.NITSCHE_CUT_AGREE[METHODS[name].degree]
    assert np.max(np.abs(error)) <= bound
    assert np.max(np.abs(error[2:] - 2 * error[1:-1] + error[:-2])) <= bound
