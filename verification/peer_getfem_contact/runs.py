"""The study: one scene, our methods and GetFEM at each h, and each code's own move with h.

A difference from GetFEM means little without the size of each code's
own discretisation error: at each h the study solves the scene with each
of our methods and with GetFEM, measures ours against GetFEM's
(:func:`~.comparison.differences`), and measures each code's answer at
the coarser h against its answer at the finer, the move that a
difference from GetFEM is judged by (docs/peer-contact.md).  Every h is
checked before any mesh: a resolution of the scene, and runs that fit
this machine (:func:`contactcore.budget.check_budget`).

Contract: :func:`study` returns ``(rows, splits, moves)`` keyed as its
docstring says, the input of :func:`~.tables.markdown`;
:func:`check_sizes` returns nothing or raises a
:class:`~contactcore.ContactError` naming the first h refused.
"""
from __future__ import annotations

from contactcore import Scene
from contactcore.budget import check_budget
from contactcore.scene import check_resolution

from .comparison import differences, status_split
from .reach import METHOD
from .scenes import exact_scene
from .solver import solve


def study(name: str, hs, degree: int = 2, methods=("fe",), allow_large: bool = False) -> tuple[dict, dict, dict]:
    """Scene ``name`` of :data:`STUDIES`, each of our ``methods`` and GetFEM
    at each h: the :func:`differences` from GetFEM (``(method, h) ->
    rows``); each run's :func:`status_split` with its time in seconds
    (``(h, method | "peer") -> split``); and each code's own move from one
    h to the next, its answer at the coarser h against the finer
    (``(method | "peer", finer h) -> rows``), the measure of its own
    discretisation error that a difference from GetFEM is judged by.
    Every h is checked first (:func:`check_sizes`; its memory unless
    ``allow_large``)."""
    from contactcore import sample_profiles
    from verification import methods as ours
    scene = exact_scene(name)
    check_sizes(scene, hs, degree, methods, allow_large)
    rows, splits, moves, profiles = {}, {}, {}, {}
    for h in hs:
        for label, solver in (*((m, ours.solver(m)) for m in methods), ("peer", solve)):
            result = solver(scene, h, degree=degree)
            profiles[label, h] = {p.id: p for p in sample_profiles(scene, result.fields, result.interface)}
            splits[h, label] = {**status_split(result), "seconds": result.timings.total}
        for m in methods:
            rows[m, h] = differences(scene, profiles["peer", h], profiles[m, h])
    for coarse, fine in zip(hs, hs[1:]):
        for label in (*methods, "peer"):
            moves[label, fine] = differences(scene, profiles[label, coarse], profiles[label, fine])
    return rows, splits, moves


def check_sizes(scene: Scene, hs, degree: int, methods, allow_large: bool = False) -> None:
    """Every h a resolution of ``scene`` (:func:`contactcore.scene.check_resolution`)
    whose runs fit this machine (:func:`contactcore.budget.check_budget`,
    GetFEM's two bodies' meshes one field over the domain; not checked if
    ``allow_large``), before any mesh: a ContactError naming the first
    that is not."""
    from verification.methods import budgeted
    for h in hs:
        check_resolution(scene, h)
        for method in () if allow_large else (*methods, METHOD):
            check_budget(scene, h, budgeted(method, degree))
