"""The rules of the bodies' materials: each body has one, with E > 0 and
ν in (-1, 0.5) (:func:`check_material`), and moduli close enough for
double precision to solve (:func:`check_contrast`)."""
from __future__ import annotations

from .. import tolerances as tol
from ..errors import SceneError
from .materials import Material
from .values import finite
from .vocabulary import BODIES


def check_materials(scene: "Scene") -> None:
    """Every body's material present and valid, then their contrast."""
    for body in BODIES:
        if body not in scene.materials:
            raise SceneError(f"materials.{body}", "missing")
        check_material(scene.materials[body], scene.plane, f"materials.{body}")
    check_contrast(scene.materials)


def check_material(mat: Material, plane: str, path: str) -> None:
    """E finite and > 0, ν finite in (-1, 0.5)."""
    if finite(mat.E, f"{path}.E") <= 0:
        raise SceneError(f"{path}.E", f"Young's modulus must be > 0 (got {mat.E!r})")
    nu = finite(mat.nu, f"{path}.nu")
    if not -1.0 < nu < 0.5:
        raise SceneError(f"{path}.nu", f"Poisson's ratio must lie in (-1, 0.5) for plane {plane} (got {nu!r})")


def check_contrast(materials: dict) -> None:
    """Refuse moduli so far apart (softer/stiffer below
    :data:`~contactcore.tolerances.MODULUS_CONTRAST_MIN`) that the softer
    body's stiffness is lost in the round-off of the stiffer's: the system
    is singular at double precision, whatever the springs or the method."""
    (soft, Es), (stiff, Eh) = sorted(((b, materials[b].E) for b in BODIES), key=lambda item: item[1])
    if Es / Eh < tol.MODULUS_CONTRAST_MIN:  # finite and > 0 both: check_material
        raise SceneError(f"materials.{soft}.E", f"{Es:g} is {Es / Eh:.2g} of materials.{stiff}.E ({Eh:g}), below "
                         f"the {tol.MODULUS_CONTRAST_MIN:g} double precision can solve: the softer body's "
                         "stiffness is lost in the round-off of the stiffer's (every method's system is singular "
                         "or fails its residual check); bring the moduli closer, e.g. treat the stiffer body as "
                         "rigid with supports on Γ, or the softer as absent")
