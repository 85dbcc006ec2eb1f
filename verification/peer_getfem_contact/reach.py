"""What the GetFEM contact peer covers: the scenes it refuses, by name.

The peer (:mod:`verification.peer_getfem_contact`) models exact
unilateral or Coulomb contact (``enforcement = "exact"``) between two
bodies on a rectangle, with a straight or circular Γ, edges held in x, y
or both (at zero or a prescribed displacement) and edge tractions or
pressures: what GetFEM's integral contact brick between two meshes
(Renard, CMAME 256, 2013) and its Dirichlet and source-term bricks hold.
Anything else is refused before GetFEM is asked for, every problem of
the scene named in one :class:`~contactcore.DiscretisationError`.

Contract: :data:`METHOD` names the peer in results and messages;
:func:`_check` returns nothing or raises.
"""
from __future__ import annotations

from contactcore import DiscretisationError, Scene
from contactcore.exact import is_exact
from contactcore.scene import Pressure, Traction
from verification.peer_getfem import geometry_problems

METHOD = "getfem-contact"


def _check(scene: Scene, degree: int, paper: bool) -> None:
    """The peer covers exact unilateral or Coulomb contact on a rectangle
    with a straight or circular Γ, edges held in x, y or both (at zero or a
    prescribed displacement) and edge tractions or pressures."""
    if degree not in (1, 2):
        raise DiscretisationError(f"{METHOD}: degree must be 1 or 2 (got {degree})")
    if paper:
        raise DiscretisationError(f"{METHOD}: the paper's grids are structured; this peer meshes Γ: give h")
    problems = geometry_problems(scene)
    if not is_exact(scene.law) or scene.law.name not in ("unilateral", "coulomb"):
        problems.append(f"the interface law must be unilateral or coulomb with enforcement = \"exact\" (got "
                        f"{scene.law.enforcement} '{scene.law.name}')")
    if scene.pins:
        problems.append("supports must hold whole edges (no pins)")
    if any(not isinstance(ld, (Traction, Pressure)) for ld in scene.loads):
        problems.append("loads must be edge tractions or pressures")
    if problems:
        raise DiscretisationError(f"{METHOD}: scene {scene.name} is outside the peer's reach: "
                                  + "; ".join(problems))
