"""The rules of one value of a scene's field, each refused with a
:class:`~contactcore.errors.SceneError` at the field's dotted path: a
finite number (:func:`finite`), a file-safe name (:func:`check_file_name`),
a body's name (:func:`check_body`), a point inside the domain
(:func:`check_point_inside`).  The rules of a scene's parts that use them
are the ``check_*`` modules beside this one."""
from __future__ import annotations

import math
import re

from .. import tolerances as tol
from ..errors import SceneError
from .vocabulary import BODIES


def finite(value, path: str) -> float:
    """``value`` as a float when it is a finite int or float; a bool, a
    string, None, NaN or ±inf is refused with a :class:`SceneError` at the
    scene field ``path`` (e.g. ``materials.minus.E``).  No unit is
    checked or converted: the value stays in the scene's own units."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SceneError(path, f"must be a finite number (got {value!r})")
    return float(value)


#: A name that becomes a file name (a scene's, a profile's id): letters,
#: digits, '-', '_' and '.', starting with a letter, a digit or '_' —
#: nothing that can leave the result folder ('/', '..'), hide a file
#: ('.') or read as a command's option ('-').
FILE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]*")


def check_file_name(value, field: str) -> None:
    """Raise :class:`SceneError` unless ``value`` is a safe file name."""
    if not isinstance(value, str) or not FILE_NAME.fullmatch(value):
        raise SceneError(field, f"must be a file-safe name: letters, digits, '-', '_', '.', starting with a "
                         f"letter, a digit or '_' (got {value!r})")


def check_body(name: str, path: str) -> None:
    """``name`` one of :data:`~contactcore.scene.vocabulary.BODIES`."""
    if name not in BODIES:
        raise SceneError(path, f"unknown body {name!r} (bodies are 'minus' and 'plus')")


def check_point_inside(scene: "Scene", point, path: str) -> None:
    """``point`` of finite coordinates, inside ``scene``'s domain (to the
    geometric tolerance)."""
    for k, v in zip("xy", point):
        finite(v, f"{path}.{k}")
    if not scene.domain.contains([point], tol.GEOMETRY * scene.length_scale)[0]:
        raise SceneError(path, f"the point {list(point)} lies outside the domain")
