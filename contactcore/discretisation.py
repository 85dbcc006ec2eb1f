"""The method contract: one :func:`solve` for every method.

A method is a :class:`Discretisation`: a frozen dataclass of its typed
options (``FE(degree=2)``, ``XFEM(degree=1, cell="quad")``,
``EFGM(basis="quadratic")``) that knows how to :meth:`~Discretisation.build`
the algebraic :class:`~contactcore.system.ContactSystem` of a scene at a
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
import hashlib
import importlib
import pickle
import time
from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Any, Callable, ClassVar

import numpy as np

from . import exact, health
from .labels import run_label
from .collective import Collective
from . import tolerances as tol
from .errors import DiscretisationError
from .geometry import LevelSetInterface, Rectangle
from .newton import solve_increments
from .newton import guess as newton_guess
from .newton.guess import coarse_guess
from .newton.iteration import STICKING
from .system import ContactSystem, check_points_on_gamma
from .result import MethodFacts, Result, Timings
from .scaling import Scales, dimensionless, dimensionless_inputs, softer_stress


#: The size rule of a method (or degree) that measured none
#: (:attr:`Discretisation.coarse_map_min_unknowns`): the middle of the
#: break-even sizes measured on exact C-coulomb (fe, xfem, efgm: 4 000 to
#: 18 000 unknowns) and scene A made exact (about 5 000).
NEW_METHOD_COARSE_MAP_FROM = 10_000


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
    """What a method's ``build`` hands back (docs/architecture.md, "A new
    method"): the system to solve (its interface's points on Γ:
    :func:`contactcore.system.check_points_on_gamma`), the fields of its
    solution vector, the number of unknowns, a JSON-ready record of the
    discretisation, and the spacing and fitting that the interface's
    warnings depend on; ``warnings`` the method's own."""

    system: ContactSystem
    fields: Callable[[np.ndarray], Any]
    #: The displacement unknowns of the whole system (over every rank, the
    #: same on each), the prescribed ones included and multipliers
    #: (``constraint_rows``) left out: fe's active unknowns, xfem's every
    #: unknown, efgm's every displacement unknown (``approx.ndofs``).  The Result's DOFs, and
    #: what :attr:`Discretisation.coarse_map_min_unknowns` is compared with.
    dofs: int
    #: JSON-ready; holds ``"h"`` (:meth:`Discretisation.label` reads it).
    record: dict
    #: The spacing built (the interface's warnings read it).
    h: float
    #: Whether the mesh follows Γ (cells' edges on Γ, each cell in one
    #: body: fe), not cut by it (xfem, efgm): an unfitted method is warned
    #: of penalty locking on a curved Γ and of tractions amplified on a
    #: cut straight Γ (:func:`contactcore.scene.caveats.interface_warnings`).
    fitted: bool = False
    warnings: list[str] = field(default_factory=list)


class Discretisation:
    """Base of the method option classes (module doc), and the one place
    each method's facts are stated, as class attributes:

    * ``name``: the method's name in results and on the command line;
    * ``module``: the module that implements it, imported by :meth:`build`
      only (so the options import no numerics): its
      ``build(scene, options, resolution, timings)`` and ``solve``;
    * ``paper_grid``: the key of the paper's grid in ``scene.paper``;
    * ``level_set``: whether a general level-set Γ can be solved;
    * ``field_output``: what its field files hold, ``"mesh"`` (each
      body's mesh with u and σ, and Γ) or ``"interface"`` (Γ only);
    * ``distributed``: whether one solve spreads over mpirun's ranks;
    * ``needs_mpi``: whether it starts MPI even outside a launcher (a
      driver hands a method that does not a communicator only under one).

    and the facts the shared core reads of an instance (the degree's, where
    they depend on it), never of a method's name: the memory budget's
    (:mod:`contactcore.budget`, before the solve, from the options) and
    the error estimate's (:mod:`contactcore.estimate`, from the
    :class:`~contactcore.result.Result`, which carries :meth:`facts`):

    * ``field_copies``: the displacement fields it keeps over the domain
      (the budget counts ``2 · field_copies`` unknowns a node): 1 here;
    * :attr:`nodes_per_cell`: the nodes a cell of size ``h`` holds
      (the budget's ``A / h²`` cells): ``degree²`` here;
    * ``meshfree``: its stencil is a support, not a cell, and its error
      at the scale of its cells includes its quadrature's: False here;
    * :attr:`recovered_stress`, :attr:`quadrature_energy`,
      :attr:`fast_gamma`: the estimate's rules of its degree (each
      property's doc): False here.

    A subclass overrides only the facts where it differs, with the
    measurement that set it.  Subclasses are frozen dataclasses; they
    validate their options in ``__post_init__``.
    """

    name: ClassVar[str]
    module: ClassVar[str]
    paper_grid: ClassVar[str]
    level_set: ClassVar[bool] = False
    field_output: ClassVar[str] = "interface"
    distributed: ClassVar[bool] = False
    needs_mpi: ClassVar[bool] = True
    field_copies: ClassVar[int] = 1
    meshfree: ClassVar[bool] = False
    #: one line for a report's reader: what the method is, and what its
    #: stress at degree 1 is (summary.md's legend under its table)
    about: ClassVar[str] = ""
    #: degree -> the least unknowns of a system whose exact, nonlinear law
    #: takes a coarser solve's first map (:attr:`coarse_map_min_unknowns`)
    coarse_map_from: ClassVar[dict[int, int]] = {}
    degree: int

    @property
    def coarse_map_min_unknowns(self) -> int:
        """The least unknowns (the whole system's, the same on every rank
        and under any numbering: a decision no round-off moves) of a
        system whose exact, nonlinear law starts its first status search
        from a coarser solve's map (:mod:`contactcore.newton.guess`).
        Below it the coarser build and search cost more than the fine
        iterations they save.  Where they break even depends on the
        method's build and iteration costs and on the scene (how many
        iterations the map saves: on scene A made exact at about 5 000
        unknowns in fe and xfem P1, on exact C-coulomb at 9 000 in xfem
        and 18 000 in fe P1), so each method gives its own, measured on
        C-coulomb (:attr:`coarse_map_from`; :data:`NEW_METHOD_COARSE_MAP_FROM`
        for a degree it does not give; docs/newton.md, "A first map from
        a coarser solve").  Speed only: either start reaches the same
        status map, and the answer within Newton's tolerance."""
        return self.coarse_map_from.get(self.degree, NEW_METHOD_COARSE_MAP_FROM)

    @property
    def nodes_per_cell(self) -> int:
        """Nodes per cell of size ``h`` (:mod:`contactcore.budget`): a
        degree-k mesh has vertices, and edge and cell nodes for k = 2,
        about ``k²`` a cell."""
        return self.degree ** 2

    @property
    def recovered_stress(self) -> bool:
        """Whether the stress it reports at this degree is recovered (a
        patch recovery, :mod:`contactcore.recovery`), not its
        displacement's own: it converges one order faster, as the
        displacement (:func:`~contactcore.estimate.orders.theoretical_order`),
        its stencil is the recovery patch
        (:func:`~contactcore.estimate.caveats.stencil_radius`), it converges
        slower in a layer along a curved Γ
        (:func:`~contactcore.estimate.caveats.curved_layer`), and the
        Zienkiewicz–Zhu estimate takes it as σ* (its fields then also have
        ``direct_stress``: :class:`contactcore.result.Fields`)."""
        return False

    @property
    def quadrature_energy(self) -> bool:
        """Whether, at this degree, its Zienkiewicz–Zhu estimate below
        :data:`~contactcore.tolerances.QUADRATURE_ENERGY_SHARE` of the
        run's energy is named as possibly too small: its quadrature's
        error, which a recovery does not see, may then be most of the
        error (:func:`~contactcore.estimate.caveats.quadrature_energy`)."""
        return False

    @property
    def fast_gamma(self) -> bool:
        """Whether, at this degree, its gaps and tractions on Γ are named
        as converging faster than the order the estimate takes, though
        where its quadrature sets their error they do not
        (:func:`~contactcore.estimate.caveats.fast_gamma`)."""
        return False

    def facts(self) -> MethodFacts:
        """The estimate's facts of these options (:class:`~contactcore.result.MethodFacts`),
        which :func:`solve` puts in the Result."""
        return MethodFacts(recovered_stress=self.recovered_stress, meshfree=self.meshfree,
                           quadrature_energy=self.quadrature_energy, fast_gamma=self.fast_gamma)

    def check(self, scene) -> None:
        """Refuse a scene this method cannot solve."""
        if isinstance(scene.interface, LevelSetInterface) and not self.level_set:
            raise DiscretisationError(f"{self.name}: a general level set Γ is supported by xfem only "
                                      "(its mesh ignores Γ)")

    def check_spacing(self, scene, resolution: Resolution) -> None:
        """Refuse a scene that this method cannot carry at ``resolution``
        (what :meth:`check` cannot know before the spacing), before anything
        is built: nothing here."""

    def spacing_warnings(self, scene, h: float) -> list[str]:
        """This method's warnings of ``scene`` at the spacing ``h`` it
        built (its laws' and materials' numbers, which a reused system
        (:class:`Reuse`) does not carry): none here."""
        return []

    def resolution(self, scene, h: float | None, paper: bool) -> Resolution:
        """This discretisation's resolution of ``scene`` by the one rule
        (:func:`resolution`)."""
        return resolution(scene, h, paper, self.paper_grid)

    def build(self, scene, resolution: Resolution, timings: Timings) -> Built:
        """The method's system of ``scene`` (its :attr:`module`'s ``build``)."""
        return importlib.import_module(self.module).build(scene, self, resolution, timings)

    @classmethod
    def label(cls, result: Result) -> str:
        """A short name of the discretisation that gave ``result``, for legends."""
        return f"{run_label(cls.name, result.degree)} (h = {result.discretisation['h']:.3g})"


def check_degree(name: str, degree) -> None:
    """Refuse a polynomial ``degree`` other than 1 or 2 (the int values; for
    efgm 1 is the linear basis, 2 the quadratic) with a
    :class:`DiscretisationError` naming the method ``name`` and the value
    given.  Returns nothing; called by each options class on construction."""
    if degree not in (1, 2):
        raise DiscretisationError(f"{name}: degree must be 1 or 2 (got {degree})")


def check_choice(name: str, option: str, value, choices) -> None:
    """Refuse an option ``value`` not among ``choices`` (compared with
    ``in``: exact values, no case folding) with a
    :class:`DiscretisationError` naming the method ``name``, the
    ``option``, every allowed choice and the value given."""
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
        raise DiscretisationError(f"the resolution h must be > 0 (got {h})" if h is not None else
                                  "no resolution h: give one, the scene gives no default")
    return Resolution(float(h))


class Reuse:
    """Built systems kept between solves that differ only in what a system
    does not depend on: the interface law and its parameters (not how it
    is enforced: an exact law's system holds Nitsche's operators), the load path
    (increments, ``follow_path``), the profiles and the names.  A study of
    k_N, k_T or μ then meshes, evaluates shape functions and assembles once
    per discretisation.

    Keyed by a digest of everything else — the (dimensionless) scene
    without those, the discretisation's options but its communicator, and
    the resolution — so a change of h, geometry, material or load builds
    afresh.  At most :data:`~contactcore.tolerances.SYSTEMS_KEPT` are kept,
    the one used longest ago released first, and before the new one is
    built (never ``size`` kept beside the one building); :meth:`close`
    releases all.  With :attr:`keep` False, the caller's next solve is its
    system's last use (no later case shares it: a study of h, review6's
    fault 1): a kept system is taken out of the store and a new one not
    put in, so the solve closes it.  A scene that cannot be pickled (a
    general level set of Python callables) is never reused.
    """

    def __init__(self, size: int | None = None):
        self.size = tol.SYSTEMS_KEPT if size is None else size
        self._kept: OrderedDict[bytes, Built] = OrderedDict()
        self.keep = True

    def __len__(self) -> int:
        """The systems kept now."""
        return len(self._kept)

    @staticmethod
    def key(scene, discretisation: Discretisation, resolution: Resolution) -> bytes | None:
        """The digest of what a built system depends on, or None."""
        bare = dataclasses.replace(scene, law=None, increments=1, follow_path=False, profiles=(), name="",
                                   title="", source=None)
        options = {f.name: getattr(discretisation, f.name) for f in dataclasses.fields(discretisation)
                   if f.name != "comm"}
        try:
            blob = pickle.dumps((type(discretisation).__name__, options, bare, resolution,
                                 scene.law.enforcement))
        except (pickle.PicklingError, TypeError, AttributeError):
            return None
        return hashlib.sha256(blob).digest()

    def build(self, scene, discretisation: Discretisation, resolution: Resolution, timings: Timings) -> Built:
        """A kept system for this key, or a new one (kept)."""
        key = self.key(scene, discretisation, resolution)
        if key is not None and key in self._kept:
            self._kept.move_to_end(key)
            built = self._kept[key] if self.keep else self._kept.pop(key)
            return dataclasses.replace(built, record={**built.record, "reused": True})
        keep = key is not None and self.keep and self.size > 0
        while keep and len(self._kept) >= self.size:
            self._kept.popitem(last=False)[1].system.close()  # room made before the new one is built
        built = discretisation.build(scene, resolution, timings)
        if keep:
            self._kept[key] = built
        return built

    def owns(self, built: Built) -> bool:
        return any(b.system is built.system for b in self._kept.values())

    def close(self) -> None:
        while self._kept:
            self._kept.popitem()[1].system.close()


def _refused(scene, discretisation: Discretisation, h: float | None, paper: bool) -> Resolution:
    """The ``discretisation``'s resolution of the dimensionless ``scene``,
    after its refusals of it there (:meth:`Discretisation.check`,
    :meth:`Discretisation.check_spacing`): what a solve refuses before
    anything is built."""
    discretisation.check(scene)
    resolution = discretisation.resolution(scene, h, paper)
    discretisation.check_spacing(scene, resolution)
    return resolution


def check_solvable(scene, discretisation: Discretisation, h: float | None = None, *, paper: bool = False) -> None:
    """Refuse the user's ``scene`` as :func:`solve` with these arguments
    would before building anything, in the same words: its checks taken on
    the dimensionless scene, options and ``h`` the solve sees
    (:func:`contactcore.scaling.dimensionless_inputs`)."""
    _, scene, discretisation, h = dimensionless_inputs(scene, discretisation, h)
    _refused(scene, discretisation, h, paper)


#: Why an exact, nonlinear law's run took no coarser map (``SolverReport.first_map``).
NO_COARSER_MAP = "no coarser map (a given grid or node set, or the coarser spacing refused or its solve failed)"

#: ... and where its system is too small for one to pay (:attr:`Discretisation.coarse_map_min_unknowns`).
SMALL_FOR_COARSER_MAP = "no coarser map (fewer than {} unknowns: a coarser solve costs more than it saves)"


def _coarsens(scene, resolution: Resolution) -> bool:
    """Whether an exact, nonlinear law at a spacing ``h`` (not a given grid
    or node set) may take a coarser solve's map: the size rule aside."""
    return (newton_guess.COARSER is not None and exact.is_exact(scene.law) and not scene.law.is_linear
            and resolution.h is not None and resolution.counts is None)


def _coarse_guess(scene, discretisation: Discretisation, resolution: Resolution, ranks: Collective):
    """An exact, nonlinear law's first status map from the same scene and
    method at twice the spacing (:mod:`contactcore.newton.guess`), or None:
    not for a penalty or linear law, a given grid or node set (no ``h`` to
    coarsen), or a coarser spacing the method refuses.  The size rule
    (:attr:`Discretisation.coarse_map_min_unknowns`) is :func:`solve`'s."""
    if not _coarsens(scene, resolution):
        return None
    coarse, kept = Resolution(newton_guess.COARSER * resolution.h), []

    def build():
        discretisation.check_spacing(scene, coarse)
        built = discretisation.build(scene, coarse, Timings())
        kept.append(built)  # its mesh, whose communicator the system's reductions use, lives as long
        try:
            exact.check(scene.law, built.system.interface, discretisation.name)
        except Exception:
            built.system.close()
            raise
        return built.system

    return coarse_guess(scene, build, ranks)


def _user_length(scene):
    """(point, length) of the dimensionless ``scene`` -> the user's, for a message."""
    if scene.source is None:
        return None
    scales = Scales.of(scene.user)
    return lambda point, length: (tuple(scales.to_user(np.asarray([point]))[0]), scales.length * length)


@dimensionless
def solve(scene, discretisation: Discretisation, h: float | None = None, *, paper: bool = False,
          progress=None, reuse: Reuse | None = None) -> Result:
    """Solve ``scene`` with ``discretisation`` at the spacing ``h`` (the
    cell size or node spacing, in the scene's length unit; None: the
    scene's own) or on the paper's grid: the one entry point of every
    method (module doc); ``progress`` as for
    :func:`contactcore.newton.solve_increments`; ``reuse`` a :class:`Reuse`
    that may hold this system already (the record then says ``"reused":
    true`` and the mesh and assembly times are zero: nothing was built).
    Refused before anything is built: a scene or ``h`` that cannot be
    discretised (:class:`~contactcore.errors.SceneError`), options the
    method cannot use (:class:`~contactcore.errors.DiscretisationError`);
    a solve that fails (no equilibrium, a singular system) raises
    :class:`~contactcore.errors.SolverError`.  Each is a
    :class:`~contactcore.errors.ContactError` whose message names the problem."""
    start, timings = time.perf_counter(), Timings()
    resolution = _refused(scene, discretisation, h, paper)
    built = (reuse.build(scene, discretisation, resolution, timings) if reuse is not None
             else discretisation.build(scene, resolution, timings))
    try:
        exact.check(scene.law, built.system.interface, discretisation.name)
        check_points_on_gamma(built.system.interface, scene, discretisation.name, built.system.collective,
                              _user_length(scene))
        least = discretisation.coarse_map_min_unknowns  # the size rule: a whole system's count, on every rank
        small = _coarsens(scene, resolution) and built.dofs < least
        with timings.measure("solve"):
            guess = None if small else _coarse_guess(scene, discretisation, resolution, built.system.collective)
            x, path, report = solve_increments(scene, built.system, progress, guess)
        if guess is None and exact.is_exact(scene.law) and not scene.law.is_linear:
            report.first_map = STICKING + (SMALL_FOR_COARSER_MAP.format(least) if small else NO_COARSER_MAP)
    finally:
        if reuse is None or not reuse.owns(built):
            built.system.close()
    report.warnings += (scene.interface_warnings(built.h, fitted=built.fitted) + scene.ligament_warnings(built.h)
                        + built.warnings + discretisation.spacing_warnings(scene, built.h))
    path = path.gathered(built.system.collective, scene.interface)
    stress_size = softer_stress(scene, built.h)  # the round-off of a traction on a Γ no load reaches
    report.warnings += health.friction_excess_warnings(scene, path, stress_size, built.h)
    report.warnings += health.closed_tension_warnings(scene, path, stress_size)
    report.warnings += health.hinge_warnings(scene, path, stress_size, built.h)
    report.warnings += health.grazing_warnings(scene, path, stress_size)
    fields = built.fields(x)
    strain_unit = Scales.of(scene.user).strain if scene.source is not None else 1.0  # ε = (U/L) σ'/E'
    report.warnings += health.large_slip_warnings(scene, path, strain_unit)  # a jump U/L of a length
    report.warnings += scene.small_strain_warnings(fields, built.h, strain_unit)
    timings.total = time.perf_counter() - start
    return Result(method=discretisation.name, scene=scene, degree=discretisation.degree, dofs=built.dofs,
                  timings=timings, solver=report, fields=fields, interface=path, discretisation=built.record,
                  facts=discretisation.facts())
