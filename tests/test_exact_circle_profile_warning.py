"""grader15 #6: an exactly enforced law on a circle of radius comparable to
h reads its profile tractions between pieces (5-15 % off): warned, as the
penalty law on the same Γ is; a circle of R > 2h is not."""
from pathlib import Path

from contactcore import load_scene
from contactcore import tolerances as lib_tol

SCENE = Path(__file__).parent / "scenes" / "circle_hydrostatic.toml"


def _profile_warned(scene, h) -> bool:
    return any("read between the pieces' centres" in w for w in scene.interface_warnings(h))


def test_exact_law_on_a_circle_comparable_to_h_is_warned():
    scene = load_scene(SCENE)
    assert not hasattr(scene.law, "kN")  # enforced exactly
    radius = scene.interface.radius
    assert _profile_warned(scene, radius * lib_tol.EXACT_PROFILE_WARN * 1.5)
    assert _profile_warned(scene, radius)
    assert not _profile_warned(scene, radius * lib_tol.EXACT_PROFILE_WARN / 1.5)
