"""The sizes below which a quantity's difference does not count: round-off
of the scene's own scale (:func:`roundoff`) or of the runs' values
(:func:`negligible`), an exactly enforced law's gap floor
(:func:`gap_floor`, :func:`measured_against`), and the user's floors
(:func:`user_floors`, one rule for ``floors={...}`` and ``--floor``:
:func:`floor_problem`)."""
from __future__ import annotations

import numpy as np

from contactcore import ContactError, Scene
from contactcore.exact import is_exact
from contactcore.scaling import Sizes, softer_displacement
from contactcore.scene import DISPLACEMENT_QUANTITIES, QUANTITIES, STRESS_QUANTITIES
from contactcore.tolerances import EXACT_GAP_FLOOR, NEGLIGIBLE_SHARE


#: The kinds whose largest value floors a quantity's scale (:func:`negligible`).
KINDS = (STRESS_QUANTITIES + ("tN", "tT"), DISPLACEMENT_QUANTITIES + ("gN", "gT"))


def roundoff(scene: Scene | None, quantity: str) -> float:
    """:data:`NEGLIGIBLE_SHARE` of ``scene``'s own size of ``quantity``'s
    kind (:class:`contactcore.scaling.Sizes`: the stress Σ of its largest
    load or prescribed displacement for a stress or traction, the
    displacement U they cause in the softer body for a displacement or
    gap); 0 without a scene.  A run whose values are all round-off (a Γ
    pulled open and stress-free: σ ~ 1e-14 MPa where Σ = 200 MPa) has no
    scale of its own: measured against it, round-off read as 60 % errors."""
    if scene is None:
        return 0.0
    sizes = Sizes.of(scene)
    return NEGLIGIBLE_SHARE * (sizes.stress if quantity in KINDS[0] else sizes.displacement)


def negligible(profiles: dict, quantity: str, scene: Scene | None = None) -> float:
    """:data:`NEGLIGIBLE_SHARE` of the largest |value| that any quantity of
    ``quantity``'s kind (:data:`KINDS`) takes on ``profiles`` (id ->
    ProfileData), or of ``scene``'s own size of that kind
    (:func:`roundoff`), the larger: the size below which its error is
    round-off."""
    kind = next(k for k in KINDS if quantity in k)
    sizes = [np.max(np.abs(p.columns[q])) for p in profiles.values() for q in p.names[3:] if q in kind
             and len(p.columns[q])]
    return max(NEGLIGIBLE_SHARE * max(sizes, default=0.0), roundoff(scene, quantity))


def size_floor(quantity: str, given: dict, *runs: dict, scene: Scene | None = None) -> float:
    """The size below which ``quantity`` does not count: the user's floor
    in ``given`` (checked, :func:`user_floors`) or round-off of its kind
    on any of ``runs`` (id -> ProfileData) or of ``scene``'s own scale
    (:func:`negligible`), the largest."""
    return max([given.get(quantity, 0.0), roundoff(scene, quantity),
                *(negligible(run, quantity) for run in runs)])


def displacement_scale(scene: Scene) -> float:
    """``U`` (m) of the loads at full value, in the softer body
    (:func:`contactcore.scaling.softer_displacement`)."""
    return softer_displacement(scene)


def gap_floor(scene: Scene) -> float:
    """The floor of an exactly enforced law's gaps on ``scene``:
    :data:`EXACT_GAP_FLOOR` times the displacement scale of its loads (m,
    :func:`displacement_scale`)."""
    return EXACT_GAP_FLOOR * displacement_scale(scene)


def gap_floors(scene: Scene) -> dict[str, float]:
    """``{"gN": f, "gT": f}``, ``f`` = :func:`gap_floor` of ``scene``: the
    floors of its law's gaps enforced exactly (``run --against-exact``
    measures a penalty run against that)."""
    return dict.fromkeys(("gN", "gT"), gap_floor(scene))


def floors(scene: Scene, given: dict | None = None) -> dict[str, float]:
    """Quantity -> the floor its values are measured against on ``scene``
    (:func:`measured_against`): the gaps of an exactly enforced law, none
    otherwise; with ``given`` (quantity -> value in its unit,
    :func:`user_floors`) the larger of the two where both name one."""
    own, user = (gap_floors(scene) if is_exact(scene.law) else {}), user_floors(given)
    return {q: max(own.get(q, 0.0), user.get(q, 0.0)) for q in {**own, **user}}


def measured_floor(scene: Scene, quantity: str) -> float:
    """The floor :func:`measured_against` gives ``quantity`` on ``scene`` (0 if none)."""
    return floors(scene).get(quantity, 0.0)


def measured_against(scene: Scene, quantity: str, values: np.ndarray) -> np.ndarray:
    """The per-sample values a profile quantity is measured against: its
    own ``values``, but an exactly enforced law's gap ``sqrt(g² + f²)``,
    ``f`` = :func:`gap_floor` (see :data:`EXACT_GAP_FLOOR`)."""
    floor = measured_floor(scene, quantity)
    return np.hypot(values, floor) if floor else np.asarray(values, float)


def floor_problem(q: str, value) -> str | None:
    """What is wrong with ``value`` as quantity ``q``'s floor, or None: the
    one rule and text of a floor, for ``floors={...}`` in Python and
    ``--floor Q=VALUE`` on the command line: a finite number > 0 in ``q``'s
    unit (a floor of 0 is no floor: leave the quantity out)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value) or value <= 0:
        shown = f"{value:g}" if isinstance(value, (int, float)) and not isinstance(value, bool) else repr(value)
        return f"{q}: the floor must be a finite number > 0 in {q}'s unit (got {shown})"
    return None


def user_floors(floors: dict | None) -> dict[str, float]:
    """``floors`` (quantity -> a value in its unit, > 0: :func:`floor_problem`)
    checked: a ContactError names a quantity that does not exist or a bad value."""
    checked = {}
    for q, value in (floors or {}).items():
        if q not in QUANTITIES:
            raise ContactError(f"floors: unknown quantity {q!r} (known: {', '.join(QUANTITIES)})")
        problem = floor_problem(q, value)
        if problem:
            raise ContactError(f"floors: {problem}")
        checked[q] = float(value)
    return checked
