"""What a ``study`` parameter changes in a scene (``python -m verification
study --param NAME --values ...``): the mesh size ``h``, the law's springs
``kN``, ``kT``, friction ``mu`` and any other parameter a registered law
declares, its ``enforcement`` and an exact law's ``stabilisation`` β, a
factor on every ``load``, the number of ``increments``, the materials
``E_minus``, ``nu_minus``, ``E_plus``, ``nu_plus``, and Γ's ``radius``,
``offset`` and ``angle``.

Contract: :data:`PARAMETERS` maps each name to (its description, with its
unit in any scene's words; ``changes(scene, value)`` -> the scene's fields
to replace); :func:`scene_at` gives a scene with a point's values set (the
enforcement first), without profiles, validated, or refuses a bad value
with a one-line :class:`~contactcore.SceneError` naming ``--param NAME``;
:func:`left_aside` names the parameters a point's law, as enforced, leaves
aside (:data:`UNUSED_UNDER`); :func:`described` says what a parameter is
in a scene's units.  No mesh, no solve.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from contactcore import CircleInterface, LineInterface, SceneError
from contactcore.enforcement import ENFORCEMENTS, make_law
from contactcore.exact import BONDED, EXACT_LAWS, checked_stabilisation, is_exact
from contactcore.laws import LAWS
from contactcore.scene import Units, check_resolution
from contactcore.scene.loads import scaled_load

from . import files
from .against_exact import exact_law, penalty_counterpart


def _material(scene, body: str, key: str, value: float):
    mats = dict(scene.materials)
    mats[body] = dataclasses.replace(mats[body], **{key: value})
    return {"materials": mats}


#: The penalty's springs: an exact law has none.
SPRINGS = ("kN", "kT")
#: The parameters that play no part under each enforcement: a penalty law's
#: springs where it is enforced exactly, Nitsche's β where by its springs.
UNUSED_UNDER = {"exact": SPRINGS, "penalty": ("stabilisation",)}


def _law(scene, key: str, value: float):
    if key == "stabilisation" and not is_exact(scene.law):
        how = ("vary it where --param enforcement is exact, or on a scene with enforcement = \"exact\""
               if scene.law.name in EXACT_LAWS else 'its limit k → ∞ is type = "bonded"')
        raise SceneError("--param stabilisation", f"applies to enforcement = \"exact\" only, and the scene's "
                         f"'{scene.law.name}' law is enforced by its springs here ({how})")
    if key == "stabilisation":
        value = checked_stabilisation(value, "--param stabilisation")
    if key in SPRINGS and is_exact(scene.law):
        how = (penalty_counterpart(scene.law) if scene.law.name in BONDED
               else f"vary {key} where --param enforcement is penalty")
        raise SceneError(f"--param {key}", f"plays no part under enforcement = \"exact\" (Nitsche's β is --param "
                         f"stabilisation; {how})")
    if key not in scene.law.parameters:
        raise SceneError(f"--param {key}", f"the '{scene.law.name}' law has no parameter {key}")
    return {"law": dataclasses.replace(scene.law, **{key: value})}


def _enforcement(scene, value):
    """The scene's law enforced ``value``-ly: ``exact`` drops its springs
    (:mod:`contactcore.exact`); ``penalty`` needs the scene's own springs."""
    law = scene.law
    if value not in ENFORCEMENTS:
        raise SceneError("--param enforcement", f"must be {' or '.join(ENFORCEMENTS)} (got {value!r})")
    if value == law.enforcement:
        return {"law": law}
    if value == "penalty":
        springs = dict(getattr(law, "given_springs", ()))
        missing = [k for k in ("kN", "kT") if k not in springs]
        if missing:
            raise SceneError("--param enforcement", f"penalty: the scene's '{law.name}' law is enforced exactly and "
                             f"its file gives no {' or '.join(missing)} to enforce it by: add "
                             f"{' and '.join(missing)} to its [interface.law] ({penalty_counterpart(law)})")
        params = {k: getattr(law, k) for k in law.parameters if k != "stabilisation"}
        return {"law": make_law({"type": law.name, "enforcement": "penalty", **params, **springs},
                                "--param enforcement: interface.law")}
    return {"law": exact_law(law, "--param enforcement: interface.law")}


def _radius(scene, value: float):
    if not isinstance(scene.interface, CircleInterface):
        raise SceneError("--param radius", "needs a circular interface")
    return {"interface": CircleInterface(scene.interface.centre, value)}


def _line(scene, name: str):
    if not isinstance(scene.interface, LineInterface):
        raise SceneError(f"--param {name}", "needs a straight interface")
    return scene.interface


def _finite(name: str, value: float) -> None:
    """Refuse a non-finite ``value`` of ``--param name`` in its own words
    (a load times inf is nan where a component is 0, and a line shifted by
    nan "misses the domain": grader13 #6)."""
    if not math.isfinite(value):
        raise SceneError(f"--param {name}", f"must be a finite number (got {value:g})")


def _offset(scene, value: float):
    itf = _line(scene, "offset")
    _finite("offset", value)
    n = np.asarray(itf.normal, float) / np.linalg.norm(itf.normal)
    return {"interface": LineInterface(tuple(np.asarray(itf.point) + value * n), tuple(n))}


def plus_on_left(normal) -> bool:
    """Whether a straight Γ of unit ``normal`` has its + body on the left
    of its direction at its own angle a₀ in (−90°, 90°] from the x axis:
    where the normal points up (n_y > 0), or along −x on a vertical Γ."""
    return normal[1] > 0 or (normal[1] == 0 and normal[0] < 0)


def _angle(scene, value: float):
    """Γ at ``value`` = a degrees from the x axis, counter-clockwise
    positive, through the middle of its chord: the scene's Γ turned by
    a − a₀ about that point, a₀ its own angle in (−90°, 90°], its normal
    turning with it.  The normal is (−sin a, cos a) where the scene's +
    body lies on the left of Γ's direction at a₀ (:func:`plus_on_left`:
    above a Γ whose normal points up), else (sin a, −cos a): the + body
    stays on the scene's side for |a − a₀| < 90° (the normal was
    (−sin a, cos a) whatever the scene's, which swapped the bodies of a
    scene whose normal pointed down or along +x)."""
    itf = _line(scene, "angle")
    mid = itf.chord(scene.domain).mean(axis=0)
    _finite("angle", value)
    a, side = np.radians(value), 1.0 if plus_on_left(itf.normal) else -1.0
    return {"interface": LineInterface(tuple(mid), (-side * np.sin(a), side * np.cos(a)))}


def _scaled(load, value: float):
    """``load`` times ``value``: each parameter of a magnitude it declares
    (:func:`contactcore.scene.loads.scaled_load`; a point stays put)."""
    return scaled_load(load, value)


def _load(scene, value: float):
    """Every load times ``value``, its path unchanged."""
    _finite("load", value)
    return {"loads": tuple(_scaled(ld, value) for ld in scene.loads)}


def _resolution(scene, value: float):
    """``h`` is the solve's, not the scene's: only checked here."""
    check_resolution(scene, value, "--param h")
    return {}


def _increments(scene, value: float):
    if not math.isfinite(value) or value != int(value) or value < 1:
        raise SceneError("--param increments", f"must be a whole number >= 1 (got {value:g})")
    return {"increments": int(value)}


#: What each parameter is, without its unit, and what it changes in a scene:
#: name -> (description, changes(scene, value) -> dict).
CHANGES = {
    "h": ("cell size or node spacing", _resolution),
    "kN": ("normal spring k_N", lambda s, v: _law(s, "kN", v)),
    "kT": ("tangential spring k_T", lambda s, v: _law(s, "kT", v)),
    "enforcement": ("how the law is enforced: penalty (its springs) or exact (Nitsche)", _enforcement),
    "stabilisation": ("Nitsche's β of an exact law (× the method's E/h)", lambda s, v: _law(s, "stabilisation", v)),
    "mu": ("friction coefficient μ of a coulomb law", lambda s, v: _law(s, "mu", v)),
    "load": ("factor on every load", _load),
    "increments": ("load increments", _increments),
    "E_minus": ("Young's modulus of the − body", lambda s, v: _material(s, "minus", "E", v)),
    "nu_minus": ("Poisson's ratio of the − body", lambda s, v: _material(s, "minus", "nu", v)),
    "E_plus": ("Young's modulus of the + body", lambda s, v: _material(s, "plus", "E", v)),
    "nu_plus": ("Poisson's ratio of the + body", lambda s, v: _material(s, "plus", "nu", v)),
    "radius": ("radius of a circular Γ", _radius),
    "offset": ("shift of a straight Γ along its normal, in the scene's length unit", _offset),
    "angle": ("angle of a straight Γ to the x axis, in degrees, counter-clockwise, Γ turned about the middle of its "
              "chord, its + body on the scene's side", _angle),
}
#: Every other parameter a registered law declares (its ``parameters``,
#: contactcore.laws' contract), so that a new law's is a --param as it is
#: registered: ``_law`` refuses it on a scene whose law lacks it.
for _kind in (*LAWS.values(), *EXACT_LAWS.values()):
    for _key in _kind.parameters:
        if _key not in CHANGES:
            CHANGES[_key] = (f"parameter {_key} of the '{_kind.name}' law ({_kind.dimensions[_key]})",
                             lambda s, v, key=_key: _law(s, key, v))
del _kind, _key
#: The units of a scene as the help names them: any consistent set
#: (docs/scenes.md, "Units"); a study's tables and plots name its scene's.
ANY_UNITS = Units(length="length", stress="stress")


def described(param: str, units: Units = ANY_UNITS) -> str:
    """What ``param`` is, with its unit in the scene's ``units``
    (:func:`verification.files.labelled`) if it has one."""
    return files.labelled(CHANGES[param][0], param, units)


#: What each parameter changes in a scene: name -> (description with its
#: unit in any scene's words, changes(scene, value) -> dict).
PARAMETERS = {param: (described(param), change) for param, (_, change) in CHANGES.items()}


def _check(param: str) -> None:
    if param not in PARAMETERS:
        raise SceneError("--param", f"unknown parameter {param!r} (known: {', '.join(PARAMETERS)})")


def scene_at(scene, point: dict):
    """``scene`` with each parameter of ``point`` (name -> value) set, in
    order but the enforcement first (the law's μ and β are then set on the
    law as enforced), without profiles (the study records Γ's points,
    :func:`verification.study._outputs`), validated.  Each step sees no
    profile already: the scene's own profiles may not fit a moved Γ (an
    angle first, then another parameter, failed on scene A's profiles
    along y = 0.5)."""
    changes = {}
    for param, value in sorted(point.items(), key=lambda item: item[0] != "enforcement"):
        _check(param)
        change = PARAMETERS[param][1]
        if param not in left_aside(point, changes.get("law", scene.law)):
            changes.update(change(scene.with_changes(profiles=(), **changes), value))
    return scene.with_changes(profiles=(), **changes)


def left_aside(point: dict, law) -> list[str]:
    """The parameters ``point`` gives that its ``law``, as enforced, leaves
    aside (:data:`UNUSED_UNDER`): where the point also sets the enforcement,
    k_N and k_T play no part at its exact points and β none at its penalty
    ones; the study's points enforced the other way use them."""
    return [p for p in UNUSED_UNDER[law.enforcement] if p in point] if "enforcement" in point else []
