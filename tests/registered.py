"""The methods the cross-method tests run: those of the one registry the
drivers use (``verification.methods.METHODS``), so that a registered method
is picked up by every such test (takeover33's ``tri`` was left out of the
tests that kept their own lists).  A test on a scene a method refuses by its
documented check (``Discretisation.check``, ``check_spacing``: a disc, a
curved Γ, a level set) skips it by name and reason, never passes silently."""
from __future__ import annotations

import pytest

from contactcore import ContactError
from contactcore.discretisation import check_solvable, make
from contactcore.scaling import dimensionless_inputs
from verification import methods

#: The degrees every method takes (contactcore.discretisation.check_degree).
DEGREES = (1, 2)

#: The shipped methods, which solve a disc and a circular Γ (docs/
#: architecture.md, "A new method"): a refusal of theirs is no skip but a
#: failure, so these tests never shrink for them.
SOLVE_EVERY_SHAPE = ("fe", "xfem", "efgm")


def names() -> list[str]:
    """Every registered method, in the registry's order."""
    return list(methods.METHODS)


def keys(degrees=DEGREES) -> list[tuple[str, int]]:
    """``(method, degree)`` for every registered method and degree."""
    return [(name, degree) for name in names() for degree in degrees]


def key_id(key) -> str:
    """A ``(method, degree)``'s test id: ``fe-P1``."""
    return f"{key[0]}-P{key[1]}"


def options(name: str, degree: int = 1, **given):
    """Method ``name``'s options at ``degree``."""
    return make(methods.discretisation(name), degree=degree, **given)


def refusal(scene, disc, h=None, *, paper: bool = False) -> str | None:
    """What ``disc``'s documented check says of ``scene`` at ``h`` before
    anything is built (its message), or None if it takes it."""
    try:
        if h is None and scene.h is None and not paper:  # no spacing to check: the geometry alone
            _, scene, disc, _ = dimensionless_inputs(scene, disc, None)
            disc.check(scene)
        else:
            check_solvable(scene, disc, h, paper=paper)
    except ContactError as error:
        return str(error)
    return None


def skip_unless_solvable(scene, disc, h=None, *, paper: bool = False, what: str = "") -> None:
    """Skip the running test for ``disc`` if its check refuses ``scene``,
    naming the method and its reason; a method of SOLVE_EVERY_SHAPE is
    never skipped (its solve then fails, naming the refusal)."""
    why = None if disc.name in SOLVE_EVERY_SHAPE else refusal(scene, disc, h, paper=paper)
    if why is not None:
        pytest.skip(f"{disc.name} refuses {what or scene.name}: {why}")


def built_fitted(scene, name: str, h: float, degree: int = 1) -> bool:
    """Whether method ``name``'s build of ``scene`` at ``h`` says its mesh
    follows Γ (``Built.fitted``): built, read, released."""
    from contactcore.discretisation import _refused
    from contactcore.result import Timings
    _, scene, disc, h = dimensionless_inputs(scene, options(name, degree), h)
    built = disc.build(scene, _refused(scene, disc, h, False), Timings())
    built.system.close()
    return bool(built.fitted)
