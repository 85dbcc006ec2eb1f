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

from . import tolerances as tol
from .bodies import Body
from .errors import FieldsError


class Fields(Protocol):
    """Point evaluation of a solution, body by body.

    The contract (:func:`check_points`, applied by every Result's fields in
    the user's frame): ``points`` (m, 2) finite, ``bodies`` (m,) of 0 or 1;
    each point inside the domain and inside the body named for it, within
    the scene's geometric tolerance (``GEOMETRY · L``: a point on Γ lies in
    both bodies, a point on the outer boundary in the domain); anything
    else a :class:`~contactcore.errors.FieldsError` naming the first
    offending point, never a value extrapolated from the nearest cell."""

    def displacement(self, points: np.ndarray, bodies: np.ndarray) -> np.ndarray:
        """``u`` (m, 2) of body ``bodies[i]`` at ``points[i]`` (m, 2)."""

    def stress(self, points: np.ndarray, bodies: np.ndarray) -> np.ndarray:
        """``(σxx, σyy, σxy)`` (m, 3) of body ``bodies[i]`` at ``points[i]``."""

    # A method whose ``stress`` is recovered rather than its displacement's
    # own (xfem P1: MethodFacts.recovered_stress) also has
    # ``direct_stress(points, bodies)``, σ(u_h) itself, which the energy
    # norm of the error measures; a Result's fields always have it (the
    # stress where the method has none: :class:`contactcore.scaling.ScaledFields`).


def _coordinate(x) -> str:
    """Six digits where they say the number exactly, else the shortest
    that reads back: a point just outside the domain is never shown on
    its boundary (1 + 1e-6 is ``1.000001``, not ``1``)."""
    short = f"{float(x):.6g}"
    return short if float(short) == float(x) or not np.isfinite(x) else repr(float(x))


def _xy(p, unit: str = "") -> str:
    return f"({_coordinate(p[0])}, {_coordinate(p[1])})" + (f" {unit}" if unit else "")


def _domain_text(domain, unit: str) -> str:
    if hasattr(domain, "corner"):
        (x0, y0), (a, b) = domain.corner, domain.size
        return f"[{x0:.6g}, {x0 + a:.6g}] × [{y0:.6g}, {y0 + b:.6g}]" + (f" {unit}" if unit else "")
    return f"the disc of centre {_xy(domain.centre)} and radius {domain.radius:.6g}" + (f" {unit}" if unit else "")


def gamma_reach(scene, interface) -> float:
    """How far off the exact Γ a method's own Γ lies (the scene's units):
    :data:`~contactcore.tolerances.DISCRETE_GAMMA_REACH` times the largest
    distance of its ``interface`` points (an InterfacePath in the user's
    frame, or None) and their pieces' centres from Γ."""
    if interface is None or not len(interface.points):
        return 0.0
    pts = interface.points if interface.pieces is None else np.vstack([interface.points, interface.pieces])
    with np.errstate(divide="ignore", invalid="ignore"):
        d = np.abs(np.asarray(scene.interface.signed_distance(pts), float))
    d = d[np.isfinite(d)]
    return tol.DISCRETE_GAMMA_REACH * float(d.max()) if len(d) else 0.0


def check_points(points, bodies, scene=None, what: str = "fields",
                 reach: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """``(points (m, 2) float, bodies (m,) int)`` of a call ``what(points,
    bodies)`` of :class:`Fields`, or a FieldsError naming the argument, or
    the first offending point and why.

    Without ``scene``, the arrays alone: ``points`` (m, 2) (or (m, 3)
    with z = 0, as dolfinx pads them) and finite, ``bodies`` m integers 0 or 1.  With
    the user's ``scene``: also each point inside the domain and inside its
    body, both within ``GEOMETRY · L`` (contactcore.tolerances): a point on
    Γ is in both bodies, by Γ's signed distance (a level set's to first
    order), and is named in the scene's own coordinates and length unit.
    ``reach``: how far off the exact Γ the method's own Γ lies
    (:func:`gamma_reach`); a point that close to Γ is on it, too."""
    try:
        pts = np.array(points, dtype=float)
    except (TypeError, ValueError) as exc:
        raise FieldsError(f"{what}: points: not an array of numbers ({exc})") from None
    if pts.ndim != 2 or pts.shape[1] not in (2, 3):
        raise FieldsError(f"{what}: points: must have shape (m, 2), got {pts.shape}")
    if pts.shape[1] == 3 and np.any(pts[:, 2] != 0.0):
        i = int(np.flatnonzero(pts[:, 2] != 0.0)[0])
        raise FieldsError(f"{what}: points[{i}] has z = {float(pts[i, 2])!r}: the problem is plane, give (m, 2) "
                          "points, or (m, 3) with z = 0 as dolfinx pads them")
    pts = pts[:, :2]
    bad = np.flatnonzero(~np.all(np.isfinite(pts), axis=1))
    if len(bad):
        raise FieldsError(f"{what}: points[{bad[0]}] = {_xy(pts[bad[0]])} is not finite")
    raw = np.asarray(bodies)
    if raw.ndim != 1 or len(raw) != len(pts):
        raise FieldsError(f"{what}: bodies: must hold one body per point ({len(pts)}), got shape {raw.shape}")
    if raw.dtype.kind not in "biuf":
        raise FieldsError(f"{what}: bodies: must be 0 (−) or 1 (+), got {raw.dtype} values")
    good = np.isin(raw, (0, 1)) if raw.dtype.kind != "f" else np.isin(np.nan_to_num(raw, nan=-1.0), (0.0, 1.0))
    if not np.all(good):
        i = int(np.flatnonzero(~good)[0])
        raise FieldsError(f"{what}: bodies[{i}] = {raw[i]!r}: a body is 0 (−) or 1 (+)")
    body = raw.astype(int)
    if scene is None or not len(pts):
        return pts, body
    unit = scene.units.length
    slack = tol.GEOMETRY * scene.length_scale
    outside = np.flatnonzero(~scene.domain.contains(pts, slack))
    if len(outside):
        i = int(outside[0])
        raise FieldsError(f"{what}: points[{i}] = {_xy(pts[i], unit)} lies outside the domain "
                          f"{_domain_text(scene.domain, unit)} ({len(outside)} of {len(pts)} points outside)")
    with np.errstate(divide="ignore", invalid="ignore"):
        d = np.asarray(scene.interface.signed_distance(pts), float)
    d = np.where(np.isnan(d), scene.interface.phi(pts), d)  # |∇φ| = 0 on φ = 0: on Γ, by φ's sign
    near = max(slack, reach)
    wrong = np.flatnonzero(np.where(body == 1, d < -near, d > near))
    if len(wrong):
        i = int(wrong[0])
        asked, other = Body(int(body[i])), Body(1 - int(body[i]))
        raise FieldsError(f"{what}: points[{i}] = {_xy(pts[i], unit)} lies in the {other.label} (" + "−+"[other]
                          + f") body, {abs(d[i]):.3g} {unit} from Γ, not in the {asked.label} body that "
                          f"bodies[{i}] = {int(body[i])} names ({len(wrong)} of {len(pts)} points in the other body)")
    return pts, body


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
    factorised for them (a solve with an unchanged tangent reuses the last);
    ``first_map`` where an exact, nonlinear law's first status search
    started (:mod:`contactcore.newton.guess`): :data:`~contactcore.newton.iteration.FROM_COARSER`
    or "every point sticking: " and why no coarser map was taken; empty
    for other laws.
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
    first_map: str = ""


@dataclass(frozen=True)
class MethodFacts:
    """What the error estimate (:mod:`contactcore.estimate`) must know of
    the method and degree that solved a run, as its options declared them
    (:meth:`contactcore.discretisation.Discretisation.facts`, where each
    fact's meaning and measurement are): ``recovered_stress`` (its
    reported stress is recovered, not its displacement's own),
    ``meshfree`` (its stencil is a support of ``dmax · h``, its cells'
    error its quadrature's), ``quadrature_energy`` (its energy estimate
    is named below a share of the run's energy) and ``fast_gamma`` (its
    Γ quantities are named as converging faster than theory allows).
    The defaults, all False, are a mesh method's whose stress is its
    displacement's own.  Plain values: a :class:`Result` carries them
    through pickling (a pool's or mpi4py.futures' workers) unchanged."""

    recovered_stress: bool = False
    meshfree: bool = False
    quadrature_energy: bool = False
    fast_gamma: bool = False


@dataclass
class Result:
    """One method's solution of one scene at the full load, the same type
    from every method (``verification.methods.solver(name)(scene, h)``).

    ``method`` and ``degree`` name the run; ``scene`` is the scene as given
    (the user's units); ``dofs`` its unknowns; ``timings``
    (:class:`Timings`: mesh, assembly, solve, total, in s) and ``solver``
    (:class:`SolverReport`: residual, backward error, Newton iterations per
    increment, factorisations, warnings) say what it cost and how healthy
    the solve was; ``fields`` (:class:`Fields`) evaluates the displacement
    and stress at any points; ``discretisation`` records the mesh or nodes
    (cells, h, quadrature); ``interface``, for a law with history or a
    followed path, holds Γ's jump, traction and status at every increment
    (:class:`~contactcore.interface_path.InterfacePath`); ``facts`` what
    the method's options declared of it at this degree (:class:`MethodFacts`,
    set once by :func:`contactcore.discretisation.solve`; the defaults for
    a peer's run), which the error estimate reads; :meth:`summary` is the
    JSON record ``run`` writes (without ``facts``)."""

    method: str
    scene: object
    degree: int
    dofs: int
    timings: Timings
    solver: SolverReport
    fields: Fields
    discretisation: dict = field(default_factory=dict)
    interface: object = None  # contactcore.interface_path.InterfacePath: every increment on Γ
    facts: MethodFacts = field(default_factory=MethodFacts)

    def summary(self) -> dict:
        """A JSON-ready record of the run (no field values); with an
        interface history, ``status``: the final increment's counts of
        open, sticking and slipping points of Γ
        (:meth:`~contactcore.interface_path.Increment.counts`), and where
        the unilateral law's partial answer has partial points
        (:mod:`contactcore.newton.partial`) their count too and
        ``partial``: each one's ``x``, ``y`` and share ``theta`` of the
        tie's shear, in Γ's order."""
        record = {
            "method": self.method,
            "scene": self.scene.name,
            "degree": self.degree,
            "dofs": int(self.dofs),
            "discretisation": self.discretisation,
            "timings": asdict(self.timings),
            "solver": asdict(self.solver),
        }
        if self.interface is not None and self.interface.steps:
            final = self.interface.final
            record["status"] = final.counts()
            where = np.flatnonzero(final.partial)
            if len(where):
                record["partial"] = [{"x": float(self.interface.points[i, 0]), "y": float(self.interface.points[i, 1]),
                                      "theta": float(final.theta[i])} for i in where]
        return record
