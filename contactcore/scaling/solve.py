"""The one ``solve`` of every method, made to solve the dimensionless scene.

Contract: :func:`dimensionless` decorates ``solve(scene, discretisation,
h=None, **options) -> Result`` (:mod:`contactcore.discretisation`) so that
the method sees the scene, its options and ``h`` made dimensionless
(:func:`dimensionless_inputs`, by :class:`contactcore.scaling.scales.Scales`)
and its caller gets the Result in the user's units; a ``scene`` that is no
Scene or an ``h`` that is no number is refused by name before any scaling.
"""
from __future__ import annotations

import dataclasses
import decimal
import functools
import numbers
from dataclasses import replace

import numpy as np

from ..errors import ContactError, DiscretisationError
from ..result import gamma_reach
from ..scene import Scene, check_resolution
from .fields import ScaledFields
from .scales import Scales


def _option_in(name: str, value, scales: Scales):
    """A method's keyword option made dimensionless: ``nodes`` (points) and a
    ``grading``'s distance (a length); every other option is a count or a
    choice."""
    if value is None:
        return value
    if name == "nodes":
        x = np.asarray(value, float)
        return scales.to_dimensionless(x) if x.ndim == 2 and x.shape[1] == 2 else value
    if name == "grading":
        return replace(value, distance=value.distance / scales.length)
    return value


def dimensionless_inputs(scene: Scene, discretisation, h: float | None):
    """``(scales, scene, discretisation, h)``: the scales of the user's
    ``scene`` and the scene, the discretisation's options and ``h`` a solve
    sees, made dimensionless.  An ``h`` that is not > 0 is passed on
    unchanged, for the method to refuse in the user's numbers; a
    ``scene`` that is no Scene, or an ``h`` that is no number, is refused
    here by name (a ContactError, not the AttributeError it would meet)."""
    _check_kinds(scene, h)
    scales = Scales.of(scene)
    if h is not None and h > 0:  # in the user's numbers, whatever the driver (run checks it too)
        check_resolution(scene, h, "h")
    h_in = decimal_quotient(h, scales.length) if h is not None and h > 0 else h
    given = {f.name: getattr(discretisation, f.name) for f in dataclasses.fields(discretisation)}
    inner = replace(discretisation, **{k: _option_in(k, v, scales) for k, v in given.items()})
    return scales, scales.scene(scene), inner, h_in


#: Digits of :func:`decimal_quotient`'s exact decimal division, more than
#: twice a double's 17, so that its one rounding to a double is the only one.
DECIMAL_DIGITS = 40


def decimal_quotient(a: float, b: float) -> float:
    """``a / b`` as the quotient of the two numbers as written (their
    shortest decimals), rounded once: the same scene in m and in mm then
    divides to the same bits (5/200 and 0.005/0.2 are both 0.025, where
    float division gives 0.024999999999999998 for the second, and fe's
    mesher, deciding at an exact multiple of h, made 2296 and 2302 cells
    of one held-out layered block; 2026-11-29).  For the spacings
    0.4 · 2⁻ᵏ (k = 0..9) and sizes 1, 1.5, 2, 2.5, 3, 4, 5, 6, 10, 20, 100,
    200, 1000, 0.5, 0.2 and 0.001 it is float division's own quotient, bit
    for bit (not for a size of 1.2)."""
    with decimal.localcontext() as ctx:
        ctx.prec = DECIMAL_DIGITS
        return float(decimal.Decimal(repr(float(a))) / decimal.Decimal(repr(float(b))))


def _check_kinds(scene, h) -> None:
    """Refuse a ``scene`` that is no :class:`Scene` (a scene's name, a
    path: :func:`contactcore.load_scene` reads them) and an ``h`` that is
    no real number (a string, a bool), naming the argument."""
    if not isinstance(scene, Scene):
        raise ContactError(f"scene: must be a Scene (contactcore.load_scene(NAME or PATH) reads one), got "
                           f"{type(scene).__name__} {scene!r}"[:200])
    if h is not None and (isinstance(h, bool) or not isinstance(h, numbers.Real)):
        raise DiscretisationError(f"h: must be a number, the cell size or node spacing in the scene's length "
                                  f"unit, got {type(h).__name__} {h!r}"[:200])


def dimensionless(solve):
    """Decorate the one ``solve(scene, discretisation, h=None, **options)
    -> Result`` (:mod:`contactcore.discretisation`) so that it solves the
    dimensionless scene, with the discretisation's options made
    dimensionless too, and returns the Result (and the steps it reports to
    a ``progress`` callback) in the user's units:
    ``scene`` the user's, ``fields`` a :class:`ScaledFields`
    (``fields.inner`` the method's own, ``fields.scales``), ``interface``
    and ``discretisation`` mapped back.  An ``h`` that is not > 0 is passed
    on unchanged, for the method to refuse in the user's numbers.
    """
    @functools.wraps(solve)
    def solve_dimensionless(scene: Scene, discretisation, h: float | None = None, **options):
        scales, scaled, inner, h_in = dimensionless_inputs(scene, discretisation, h)
        progress = options.get("progress")
        if progress is not None:
            options = {**options, "progress": lambda n, total, st: progress(n, total, scales.step(st))}
        result = solve(scaled, inner, h_in, **options)
        path = scales.path(result.interface)
        return replace(result, scene=scene, fields=ScaledFields(result.fields, scales, scene, gamma_reach(scene, path)),
                       interface=path,
                       discretisation=scales.discretisation(result.discretisation))
    return solve_dimensionless
