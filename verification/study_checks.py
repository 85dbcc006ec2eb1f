"""What ``study`` checks before any solve: each value given once, every
point's scene buildable (:func:`check_points`), every point's 2h within
the domain under ``--estimate`` (:func:`check_coarse`) and every point's
solve within this machine's memory (:func:`check_sizes`).

Contract: each check returns nothing (or what it built: the scenes, the
memory estimates) or refuses with one line naming the option and, where
it is one, the point (``--param kN = 1e+09, radius = 0.2``): a
:class:`~contactcore.SceneError`, or :class:`~contactcore.budget.TooLargeError`
for a solve beyond the memory.  No mesh, no solve; the check of several
cases at once, which reads the systems they share, is
:func:`verification.study.check_memory`'s.
"""
from __future__ import annotations

from contactcore import SceneError
from contactcore.budget import check_budget
from contactcore.scene import check_resolution

from . import methods
from .study_parameters import scene_at
from .study_plots import _shown


def check_given_once(field: str, values, name: str = "") -> None:
    """Refuse with a :class:`SceneError` naming ``field`` (and ``name``, the
    parameter the values belong to, if any) a value given more than once: a
    repeated value ran the same case twice and wrote its row twice (the
    one check of ``study --values`` and ``efficiency --method/--degree/--h``)."""
    values = list(values)
    twice = sorted({f"{v:g}" if isinstance(v, float) else str(v) for v in values if values.count(v) > 1})
    if twice:
        raise SceneError(field, f"{name + ': ' if name else ''}each value may be given once "
                                f"({', '.join(twice)} given twice)")


def check_points(base, names: list[str], points: list[tuple]) -> list:
    """Every point's scene built and validated (:func:`scene_at`; no
    mesh, no solve), in study order: the first that cannot be ends the
    study with a SceneError naming it, by the parameter and value where
    the message does not already (a scene's own field, such as
    ``interface``, names neither).  Returns the scenes."""
    scenes = []
    for point in points:
        try:
            scenes.append(scene_at(base, dict(zip(names, point))))
        except SceneError as exc:
            if exc.field.startswith("--param"):
                raise
            raise SceneError(f"--param {_where(names, point)}", str(exc)) from None
    return scenes


def check_coarse(scenes: list, names: list[str], points: list[tuple], h) -> None:
    """``study --estimate``: every point's 2h (its ``h`` parameter, else
    ``h``, else its scene's) fits the domain
    (:func:`contactcore.scene.check_resolution`), before any solve."""
    for scene, point in zip(scenes, points):
        at = dict(zip(names, point)).get("h", h if h is not None else scene.h)
        if at is None:
            raise SceneError("--estimate", f"scene {scene.name} gives no default h; give --h")
        given = (f"h = {_shown(at)}" if "h" in names else f"--h {_shown(at)}" if h is not None
                 else f"the scene's h {_shown(at)}")
        check_resolution(scene, 2 * at, f"--estimate: {given}, the coarse run at 2h")


def check_sizes(scenes: list, names: list[str], points: list[tuple], method_names: list[str], degree: int,
                h, every: bool = False) -> list:
    """Every point's solve (its scene of :func:`check_points`), with every
    method, within this machine's memory
    (:func:`contactcore.budget.check_budget`), before any solve: the first
    that is not ends the study with a TooLargeError naming it (``--param h
    --values 1e-9`` would otherwise mesh until the system stops the
    process).  Returns each case's estimated memory in bytes, for the
    check of several at once (with ``every``, one per case in study
    order, None for a case without h)."""
    memories = []
    for scene, point in zip(scenes, points):
        at = dict(zip(names, point)).get("h", h if h is not None else scene.h)
        if at is None:
            memories += [None] * len(method_names) if every else []
            continue  # refused by the solve itself, as a failed row, naming the missing h
        for name in method_names:
            memories.append(check_budget(scene, at, methods.budgeted(name, degree), field=f"--param {_where(names, point)}: h").memory)
    return memories


def _where(names: list[str], point: tuple) -> str:
    """A point as the messages name it: ``kN = 1e+09, radius = 0.2``."""
    return ", ".join(f"{p} = {_shown(v)}" for p, v in zip(names, point))
