"""A scene's effectivity rows leave out true errors at round-off
(verification.effectivity.scene_rows): on an answer a method represents
exactly, estimate and true error are both round-off, and their ratio says
nothing of the estimate (docs/error-estimates.md, "Final figures")."""
from __future__ import annotations

from pathlib import Path

import tolerances as tol

CRACK = Path(__file__).parent / "scenes" / "tilted_crack_slip_exact.toml"


def test_an_answer_fe_p1_represents_exactly_has_no_effectivity_and_efgm_keeps_its_own():
    """fe P1 solves the crack in slip (σ uniform, u affine on each side)
    exactly, as does the truth (fe P2): every fe P1 row's true error is
    at round-off and has no effectivity; EFGM P1, whose quadrature misses
    even a uniform stress, keeps a true error and an effectivity on Γ."""
    from contactcore import load_scene
    from verification.effectivity import scene_rows, scene_truth
    scene = load_scene(CRACK)
    truth = scene_truth(scene, tol.ROUNDOFF_SCENE_TRUTH_H)
    fe = scene_rows(scene, ("fe", 1), tol.ROUNDOFF_SCENE_H, truth)
    assert fe and all(r["effectivity"] is None for r in fe), [(r["profile"], r["quantity"], r["effectivity"])
                                                             for r in fe if r["effectivity"] is not None]
    efgm = scene_rows(scene, ("efgm", 1), tol.ROUNDOFF_SCENE_H, truth)
    assert any(r["effectivity"] is not None for r in efgm if r["profile"] == "G")
