"""The method contract: one :func:`solve` for every method.

A method is a :class:`Discretisation`: a frozen dataclass of its typed
options (``FE(degree=2)``, ``XFEM(degree=1, cell="quad")``,
``EFGM(basis="quadratic")``) that knows how to :meth:`~Discretisation.build`
the algebraic :class:`~contactcore.newton.ContactSystem` of a scene at a
:class:`Resolution`, and the fields of a solution of it (a :class:`Built`).
Everything else is the same for all of them and lives here, once:

* the resolution, by one rule (:func:`resolution`): ``h``, else the scene's
  default, or with ``paper=True`` the grid the paper used (its
  ``scene.paper[discretisation.paper_grid]`` counts per direction);
* the timings of the stages (the method measures ``mesh`` and ``assembly``
  inside ``build``; ``solve`` and ``total`` are measured here);
* the increments and Newton (:func:`contactcore.newton.solve_increments`),
  the system released after them, the health report with the interface's
  warnings and the method's own;
* the :class:`~contactcore.result.Result`, in the user's units
  (:func:`contactcore.scaling.dimensionless`).

The option classes live beside their methods in modules that import no
numerics (``xdolfinx.options``, ``efgm.options``), so a driver can check
options without importing dolfinx.  Building one with an option it does
not take is a :class:`~contactcore.errors.DiscretisationError` naming it
(:func:`make`).
"""
from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass, field
from typing import Any, Callable, ClassVar

import numpy as np

from .errors import DiscretisationError
from .geometry import LevelSetInterface, Rectangle
from .newton import ContactSystem, solve_increments
from .result import Result, Timings
from .scaling import dimensionless


@dataclass(frozen=True)
class Resolution:
    """How fine a method discretises a scene: the cell or node spacing
    ``h``, and, for the paper's discretisations, the grid's ``counts``
    per direction (cells for fe and xfem, nodes for efgm); ``h`` None where
    the discretisation fixes it itself (EFGM on given nodes)."""

    h: float | None
    counts: tuple[int, int] | None = None


@dataclass
class Built:
    """What a method's ``build`` hands back: the system to solve, the fields
    of its solution vector, the number of unknowns, a JSON-ready record of
    the discretisation, and the spacing and fitting that the interface's
    warnings depend on; ``warnings`` the method's own."""

    system: ContactSystem
    fields: Callable[[np.ndarray], Any]
    dofs: int
    record: dict
    h: float
    fitted: bool = False
    warnings: list[str] = field(default_factory=list)


class Discretisation:
    """Base of the method option classes (module doc).

    Subclasses are frozen dataclasses and set ``name`` (the method's name
    in results and on the command line), ``paper_grid`` (the key of the
    paper's grid in ``scene.paper``) and ``level_set`` (whether a general
    level-set Γ can be solved); they validate their options in
    ``__post_init__`` and implement :meth:`build`.
    """

    name: ClassVar[str]
    paper_grid: ClassVar[str]
    level_set: ClassVar[bool] = False
    degree: int

    def check(self, scene) -> None:
        """Refuse a scene this method cannot solve."""
        if isinstance(scene.interface, LevelSetInterface) and not self.level_set:
            raise DiscretisationError(f"{self.name}: a general level set Γ is supported by xfem only "
                                      "(its mesh ignores Γ)")

    def resolution(self, scene, h: float | None, paper: bool) -> Resolution:
        """This discretisation's resolution of ``scene`` by the one rule
        (:func:`resolution`)."""
        return resolution(scene, h, paper, self.paper_grid)

    def build(self, scene, resolution: Resolution, timings: Timings) -> Built:
        raise NotImplementedError

    @classmethod
    def label(cls, result: Result) -> str:
        """A short name of the discretisation that gave ``result``, for legends."""
        return f"{cls.name} P{result.degree} (h = {result.discretisation['h']:.3g})"


def check_degree(name: str, degree) -> None:
    if degree not in (1, 2):
        raise DiscretisationError(f"{name}: degree must be 1 or 2 (got {degree})")


def check_choice(name: str, option: str, value, choices) -> None:
    if value not in choices:
        raise DiscretisationError(f"{name}: {option} must be one of {', '.join(map(str, choices))} (got {value!r})")


def make(cls: type[Discretisation], **options) -> Discretisation:
    """``cls(**options)``, an option ``cls`` does not take refused by name."""
    taken = {f.name for f in dataclasses.fields(cls)}
    for key in options:
        if key not in taken:
            raise DiscretisationError(f"{cls.name}: takes no option {key!r} (it takes {', '.join(sorted(taken))})")
    return cls(**options)


def option_names(cls: type[Discretisation]) -> tuple[str, ...]:
    """The options a method takes."""
    return tuple(f.name for f in dataclasses.fields(cls))


def resolution(scene, h: float | None, paper: bool, grid: str) -> Resolution:
    """The one rule (module doc).  ``grid`` names the paper's counts in
    ``scene.paper``: ``"xfem_cells"`` (cells per direction, h = side/cells)
    or ``"efgm_nodes"`` (nodes per direction, h = side/(nodes − 1))."""
    if paper:
        counts = scene.paper.get(grid)
        if counts is None or not isinstance(scene.domain, Rectangle):
            raise DiscretisationError(f"scene {scene.name} gives no paper discretisation")
        size = scene.domain.size
        if grid == "efgm_nodes":
            return Resolution(max(s / (n - 1) for s, n in zip(size, counts)), tuple(counts))
        return Resolution(min(s / n for s, n in zip(size, counts)), tuple(counts))
    h = scene.h if h is None else h
    if h is None or not h > 0:
        raise DiscretisationError(f"the resolution h must be > 0 (got {h}); the scene gives no default")
    return Resolution(float(h))


@dimensionless
def solve(scene, discretisation: Discretisation, h: float | None = None, *, paper: bool = False,
          progress=None) -> Result:
    """Solve ``scene`` with ``discretisation`` at the spacing ``h`` (or the
    paper's grid): the one entry point of every method (module doc);
    ``progress`` as for :func:`contactcore.newton.solve_increments`."""
    discretisation.check(scene)
    start, timings = time.perf_counter(), Timings()
    built = discretisation.build(scene, discretisation.resolution(scene, h, paper), timings)
    try:
        with timings.measure("solve"):
            x, path, report = solve_increments(scene, built.system, progress)
    finally:
        built.system.close()
    report.warnings += scene.interface_warnings(built.h, fitted=built.fitted) + built.warnings
    fields = built.fields(x)
    timings.total = time.perf_counter() - start
    return Result(method=discretisation.name, scene=scene, degree=discretisation.degree, dofs=built.dofs,
                  timings=timings, solver=report, fields=fields, interface=path, discretisation=built.record)
