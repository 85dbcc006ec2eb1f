"""The result type every method returns, so comparisons compare like with like.

A method's ``solve(scene, h=None, *, degree=1, paper=False, ...)`` returns a
:class:`Result`.  Its ``fields`` answer two questions at arbitrary points for
a given body (0 = −, 1 = +): the displacement and the stress.  Everything
else (gaps, slips, interface tractions, profiles) is derived from those by
:mod:`contactcore.profiles`, once for all methods.
"""
from __future__ import annotations

import time
from contextlib import contextmanager
from dataclasses import asdict, dataclass, field
from typing import Protocol

import numpy as np


class Fields(Protocol):
    """Point evaluation of a solution, body by body."""

    def displacement(self, points: np.ndarray, bodies: np.ndarray) -> np.ndarray:
        """``u`` (m, 2) of body ``bodies[i]`` at ``points[i]`` (m, 2)."""

    def stress(self, points: np.ndarray, bodies: np.ndarray) -> np.ndarray:
        """``(σxx, σyy, σxy)`` (m, 3) of body ``bodies[i]`` at ``points[i]``."""


@dataclass(frozen=True)
class Placement:
    """Where a method's own (inner) coordinates sit in the user's frame:
    ``x_user = origin + length_scale · x_inner``."""

    origin: tuple = (0.0, 0.0)
    length_scale: float = 1.0

    def to_user(self, x: np.ndarray) -> np.ndarray:
        """Inner coordinates (m, 2) mapped to the user's frame."""
        return np.asarray(self.origin, float) + self.length_scale * np.asarray(x, float)[:, :2]


def method_fields(fields) -> tuple[object, Placement]:
    """The method's own fields behind any wrappers, and their placement.

    The one protocol for wrappers of :class:`Fields` (history, units): a
    wrapper names what it wraps ``base``, and may map coordinates with
    ``origin`` and ``length_scale`` (``x_outer = origin + length_scale ·
    x_inner``; defaults 0 and 1).  The chain is followed to the first object
    without ``base``; the placements compose outermost last.
    """
    origin, scale = np.zeros(2), 1.0
    while hasattr(fields, "base"):
        length = float(getattr(fields, "length_scale", 1.0))
        origin = origin + scale * np.asarray(getattr(fields, "origin", (0.0, 0.0)), float)
        scale *= length
        fields = fields.base
    return fields, Placement(tuple(origin), scale)


@dataclass
class Timings:
    """Wall times in seconds of the stages of one run."""

    mesh: float = 0.0
    assembly: float = 0.0
    solve: float = 0.0
    total: float = 0.0

    @contextmanager
    def measure(self, stage: str):
        """Add the wall time of the ``with`` block to ``stage``."""
        start = time.perf_counter()
        try:
            yield
        finally:
            setattr(self, stage, getattr(self, stage) + time.perf_counter() - start)


@dataclass
class SolverReport:
    """Health of the solve: what ran, how well, and what to distrust.

    ``residual`` is the relative residual ``‖b − A x‖/max(‖b‖, F)`` of the
    equations actually solved (F the internal forces of a Newton step; after
    Newton, its last relative residual): the criterion of success
    (:mod:`contactcore.health`); ``backward_error`` is
    ``‖b − A x‖/(‖A‖‖x‖ + ‖b‖)``, reported beside it, never instead;
    ``condition`` the solver's condition estimate when it was asked for;
    ``solves`` the linear solves and ``factorisations`` the matrices
    factorised for them (a solve with an unchanged tangent reuses the last).
    """

    solver: str
    residual: float = float("nan")
    backward_error: float = float("nan")
    iterations: list[int] = field(default_factory=list)
    increments: int = 1
    solves: int = 1
    factorisations: int = 0
    condition: float | None = None
    warnings: list[str] = field(default_factory=list)
    options: dict = field(default_factory=dict)


@dataclass
class Result:
    """One method's solution of one scene at the full load."""

    method: str
    scene: object
    degree: int
    dofs: int
    timings: Timings
    solver: SolverReport
    fields: Fields
    discretisation: dict = field(default_factory=dict)
    interface: object = None  # contactcore.interface_path.InterfacePath: every increment on Γ

    def summary(self) -> dict:
        """A JSON-ready record of the run (no field values)."""
        return {
            "method": self.method,
            "scene": self.scene.name,
            "degree": self.degree,
            "dofs": int(self.dofs),
            "discretisation": self.discretisation,
            "timings": asdict(self.timings),
            "solver": asdict(self.solver),
        }
