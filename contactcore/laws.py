"""Interface laws: jumps (and state) in, tractions and tangents out.

A law works in the local frame of Γ.  For ``m`` interface points it takes the
jumps ``g = [g_N, g_T]`` (shape ``(m, 2)``, ``g_N = [[u]]·n``,
``g_T = [[u]]·t``) and returns the tractions ``[t_N, t_T]`` (Pa) and the
tangent ``∂t/∂g`` (shape ``(m, 2, 2)``, Pa/m).  The traction acting on the +
body is ``τ⁺ = −(t_N n + t_T t)``; the − body receives ``−τ⁺`` (docs/scenes.md).

In a weak form the law contributes ``∫_Γ t(g(u)) · g(δu) dΓ`` to the
internal virtual work.  Laws are looked up by name in :data:`LAWS`; every
method calls the same code.

The contract of a law class (:class:`_Law`), checked when it is registered
(:func:`registry`) and again when a scene is made dimensionless
(:func:`law_contract`), so that a law missing a declaration is refused by
name rather than answered wrongly:

* ``parameters``: the names of its parameters, and ``dimensions``: the
  dimension of each (:data:`DIMENSIONS`).  :mod:`contactcore.scaling`
  makes every parameter dimensionless by its declared dimension and by
  nothing else: a gap ``g0`` (m) compared with a jump is a
  :data:`DISPLACEMENT`, scaled as the jumps are; undeclared, it would
  reach every method in the user's metres against dimensionless jumps.
  The response must be dimensionally consistent (the same formula in any
  consistent units), which every physical law is.
* ``homogeneous``: whether ``t(c·g) = c·t(g)`` for every ``c > 0`` at an
  untouched history (positively homogeneous of degree one), as
  ``linear``, ``unilateral`` and ``coulomb`` are and a law with a gap, a
  threshold or a cohesive strength is not.  Newton's cut-backs rely on it
  only where it is declared (:meth:`contactcore.newton.increments._Newton._from_rest`:
  from rest a smaller step is then the same problem scaled).
* ``unilateral`` (the law can open: no tension, ``t_N <= 0``) and
  ``frictional`` (a closed point may slip: its ``|t_T|`` is bounded by the
  law's :meth:`slip_bound`, Coulomb's ``μ max(−t_N, 0)`` or any other):
  the capabilities the health checks and refusals read
  (:mod:`contactcore.health`), never the law's name.
* a frictional law's ``slip_bound(t_N)``: the largest ``|t_T|`` a closed
  point carries at the normal traction ``t_N`` (an array in the scene's
  stress unit, made dimensionless as the law is), non-decreasing and
  concave in the pressure ``p = −t_N`` (so that Γ's resultant obeys
  ``|F_T| <= |Γ| slip_bound(−F_N/|Γ|)``, Jensen).  Everything that needs
  the bound asks the law for it, never for a parameter by name: the
  refusal before Newton of a load Γ cannot hold (:meth:`_Law.slides_off`,
  :func:`contactcore.health.beyond_cone`), the traction scale of
  :class:`Decision` (:meth:`_Law.decision_scales`), the rigid slide
  (:mod:`contactcore.slide`), a profile's slipping samples
  (:mod:`contactcore.profiles`), the exact form (:mod:`contactcore.exact`)
  and the layered closed form (verification/closed_forms.py).
* parameters beyond ``kN``, ``kT`` are read and checked by the class's
  :meth:`_Law.extra_parameters` (its exact form reads them through it too).

A new law is one class declaring these, registered in :data:`LAWS`
(:func:`register` for a law from outside the package), its row in
docs/scenes.md and a closed-form test: the checklist is docs/architecture.md,
"A new law".
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np

from . import tolerances as tol
from .errors import ContactError, SceneError
from .registry import add, declared_dimensions, registered
from .spelling import hint


@dataclass(frozen=True)
class LawResponse:
    """Tractions ``[t_N, t_T]`` (m, 2), tangent (m, 2, 2), the new state and
    the status of each point."""

    traction: np.ndarray
    tangent: np.ndarray
    state: np.ndarray | None
    status: np.ndarray  # (m,) OPEN, STICK or SLIP
    #: (m,) the secant tangential stiffness ``|t_T| / |g_T − s|`` of the
    #: slipping points (0 elsewhere), a stiffness their tangent lacks
    #: (:func:`contactcore.laws.secant_tangent`); None for a
    #: law without slip
    secant: np.ndarray | None = None


def _positive(params: dict, key: str, path: str) -> float:
    if key not in params:
        raise SceneError(f"{path}.{key}", "missing (a penalty stiffness, in the scene's stress unit per length unit: "
                         "Pa/m in SI, MPa/mm in a scene of mm and MPa)")
    value = params[key]
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(f"{path}.{key}", f"must be a number (got {value!r})")
    if not math.isfinite(value) or value <= 0:
        raise SceneError(f"{path}.{key}", f"must be a finite penalty > 0 (got {value!r})")
    return float(value)


#: Status of an interface point (``LawResponse.status``).
OPEN, STICK, SLIP = 0, 1, 2
STATUS_NAMES = ("open", "stick", "slip")
#: A point of the unilateral law's partial answer (:mod:`contactcore.newton.partial`:
#: ``y_N = 0`` with a share θ of the tie's shear), as outputs report it
#: (:meth:`contactcore.interface_path.Increment.reported_status`).  No law
#: and no Newton status arithmetic ever sees it: there the point is ``STICK``.
PARTIAL = 3
REPORTED_STATUS_NAMES = STATUS_NAMES + ("partial",)


@dataclass(frozen=True)
class Decision:
    """What Newton hands a law so that no status follows round-off.

    ``previous`` is each point's status at the previous iterate (at a
    step's first iterate, the last converged one).  A switch whose margin —
    ``−g_N`` for closed/open, ``μp − |t*|`` for stick/slip — lies within
    ``DECISION_BAND`` of its scale keeps the previous status (the scale
    never below ``DECISION_FLOOR`` of the scene's units: with no load every
    gap is round-off, and so would its largest be): the traction
    of either branch differs there by at most that band, far above the
    round-off that a BLAS kernel, a MUMPS ordering or a renumbering leaves
    in the margin, so every machine takes the same decision.  The scales
    are Γ-wide (reduced over every rank by Newton): ``gap`` the largest
    ``|g_N|``, ``traction`` the largest slip limit of a closed point, the
    law's ``slip_bound`` (Coulomb's ``μp``; :meth:`_Law.decision_scales`).
    A margin within REST_ROUNDOFF of ``size`` (the larger of the scene's
    displacement unit and Γ's largest jump or slip history; a traction
    margin over the point's stiffness) is a point at rest, decided
    as a zero margin is (closed, sticking) whatever it was before: a load
    back to exactly zero leaves every margin round-off, and the band
    relative to round-off scales is round-off too.

    Γ is at rest for the stick/slip decision where its largest pressure
    ``pressure`` is at DECISION_FLOOR too, not only its largest slip limit
    ``μp``: a small μ puts μp below the floor under any load (the layered
    cycle at μ = 1e-6, p = 5e-5 of E), and the rest window held every
    point at stick there.  Under load the traction scale is
    ``max(μp, TRACTION_ROUNDOFF · p)``, with no absolute floor: the band
    then lets a sticking ``|t_T|`` past ``μp`` by at most ``1e-5 μp`` or the
    traction's round-off (μ below MU_SMALLEST is refused, where that
    round-off would be a tenth of μp or more).
    """

    previous: np.ndarray
    gap: float
    traction: float
    #: the size of Γ's jumps and slip history (their largest, at least the
    #: displacement unit): the round-off of a margin ``g − s`` is relative to it
    size: float = 1.0
    #: Γ's largest pressure ``p = −t_N`` (reduced over ranks); at or below
    #: DECISION_FLOOR Γ is at rest for the stick/slip decision
    pressure: float = 0.0
    #: the closed/open band's scale per point where it is narrower than
    #: ``gap`` (None: ``gap``): an exact law's ``p/γ`` (:meth:`in_traction`),
    #: so that a point the band holds closed carries a tension (or one it
    #: holds open a penetration) of at most DECISION_BAND of Γ's pressure
    normal: np.ndarray | None = None

    @classmethod
    def reduced(cls, law, g: np.ndarray, state, previous: np.ndarray, ranks) -> "Decision":
        """The decision of ``law`` at the jumps ``g``, its scales reduced
        over ``ranks`` (a :class:`~contactcore.collective.Collective`)."""
        scales = [ranks.max(float(v)) for v in law.decision_scales(g, state)]
        gap, limit = scales[0], scales[1]
        pressure = scales[2] if len(scales) > 2 else 0.0
        if pressure > tol.DECISION_FLOOR:  # Γ loaded: the band follows μp and the traction's round-off
            traction = max(limit, tol.TRACTION_ROUNDOFF * pressure)
        else:
            traction = max(limit, tol.DECISION_FLOOR)
        history = 0.0 if state is None else float(np.max(np.abs(state), initial=0.0))
        size = max(1.0, ranks.max(max(float(np.max(np.abs(g), initial=0.0)), history)))
        return cls(previous, max(gap, tol.DECISION_FLOOR), traction, size, pressure)

    def in_traction(self, stiffness: np.ndarray, pressure: float) -> "Decision":
        """This decision with its closed/open band narrowed, point by point,
        to ``pressure / stiffness`` where that is below ``gap``: the band
        then holds a point's status while ``stiffness × margin``, the
        traction its other branch would carry, lies within DECISION_BAND of
        Γ's largest ``pressure`` (reduced over ranks).  ``gap``, the largest
        jump, is an open gap's where Γ opens, and held a closed point with
        a tension of 2.4e-3 of p (xfem P2, grader7's partial contact).
        Unchanged where Γ carries no pressure above DECISION_FLOOR."""
        if not pressure > tol.DECISION_FLOOR:
            return self
        k = np.asarray(stiffness, float)
        return replace(self, normal=np.minimum(self.gap, pressure / k))

    def switch(self, margin: np.ndarray, scale: float, was: np.ndarray, stiffness=1.0,
               rest: bool | None = None) -> np.ndarray:
        """``margin > 0`` where it is beyond the band, ``True`` (a zero
        margin's side: closed, sticking) where Γ is at rest (``rest``; by
        default where Γ's ``scale`` is at DECISION_FLOOR) and ``|margin|``
        within REST_ROUNDOFF (times the ``stiffness`` that makes a gap of
        it, for a traction margin), else ``was``."""
        band = tol.DECISION_BAND * scale
        # at rest only where Γ as a whole is (a load back to zero); under
        # load the band decides, and a stiff spring's window would
        # otherwise hold a point past μp
        if rest is None:
            rest = scale <= tol.DECISION_FLOOR
        rest = rest & (np.abs(margin) <= tol.REST_ROUNDOFF * self.size * np.asarray(stiffness, float))
        return np.where(rest | (margin > band), True, np.where(margin < -band, False, was))


#: The dimensions a law's parameter may declare (:attr:`_Law.dimensions`),
#: each made dimensionless by :mod:`contactcore.scaling` with the scene's
#: units (``L`` length, ``S`` modulus, ``U`` displacement, ``Σ = S U/L``):
STIFFNESS = "stress per length"  #: a spring, Pa/m in SI: × L/S
STRESS = "stress"  #: a traction or strength, Pa: / Σ
DISPLACEMENT = "displacement"  #: compared with a jump (a gap, a slip), m: / U
LENGTH = "length"  #: a distance in the geometry, m: / L
DIMENSIONLESS = "dimensionless"  #: μ, β: unchanged
DIMENSIONS = (STIFFNESS, STRESS, DISPLACEMENT, LENGTH, DIMENSIONLESS)

#: The capabilities every law class declares (module doc), each a bool.
CAPABILITIES = ("homogeneous", "unilateral", "frictional")


def frictionless(law) -> bool:
    """Whether ``law`` is frictional with a slip bound of zero (Coulomb's
    μ = 0): its closed points carry no shear, so a sticking one is
    reported as slipping (:attr:`contactcore.interface_path.Increment.frictionless`).
    Asked of the bound at a unit pressure, not of a parameter's name."""
    return bool(law.frictional) and not np.any(law.slip_bound(np.array([-1.0])))


def law_contract(cls) -> dict[str, str]:
    """The declared dimension of each parameter of the law class ``cls``
    (module doc), or a ContactError naming what ``cls`` fails to declare: a
    parameter without a dimension in :data:`DIMENSIONS`, a dimension for
    no parameter, a capability of :data:`CAPABILITIES` that is not a bool,
    ``frictional`` without a ``slip_bound`` method."""
    name = getattr(cls, "name", cls.__name__)
    where = f"the '{name}' law ({cls.__module__}.{cls.__qualname__})"
    dims = declared_dimensions(cls, where, DIMENSIONS)
    for cap in CAPABILITIES:
        if not isinstance(getattr(cls, cap, None), bool):
            raise ContactError(f"{where}: declares no '{cap}' (True or False; contactcore.laws' module doc): the "
                               "health checks and Newton's cut-backs read it")
    if cls.frictional and not callable(getattr(cls, "slip_bound", None)):
        raise ContactError(f"{where}: is frictional but has no method 'slip_bound(t_N)', the largest |t_T| of a "
                           "closed point, which the health checks, Newton's decisions and the profiles read")
    return dims


def registry(*classes) -> dict:
    """``{name: class}`` of law classes, each held to :func:`law_contract`
    (at import: a law that declares too little is refused before any scene
    uses it), no name twice (:func:`contactcore.registry.registered`)."""
    return registered("law", law_contract, classes)


def register(cls, laws: dict | None = None):
    """Register the law class ``cls`` (held to :func:`law_contract`) in
    ``laws`` (default :data:`LAWS`, the penalty laws; an exact form goes
    into :data:`contactcore.exact.EXACT_LAWS`) under its ``name``, so that
    a scene file's ``type = "<name>"`` builds it
    (:func:`contactcore.enforcement.make_law`): a law from outside the
    package, as a plugin (or a test) adds it.  Refused like the built-in
    ones: a class that declares too little, a name already registered.
    Returns ``cls`` (usable as a decorator); :func:`unregister` undoes it."""
    add("law", law_contract, LAWS if laws is None else laws, cls)
    return cls


def unregister(name: str, laws: dict | None = None) -> None:
    """Remove the law ``name`` that :func:`register` added (nothing if absent)."""
    (LAWS if laws is None else laws).pop(name, None)


class _Law:
    """What every law shares: reading its parameters, its spring scale.

    A law class declares (module doc; :func:`law_contract` refuses one that
    does not): ``name``; ``parameters`` and the ``dimensions`` of each;
    ``homogeneous``, whether ``t(c·g) = c·t(g)`` for ``c > 0`` from an
    untouched history; ``unilateral``, whether it can open (no tension);
    ``frictional``, whether a closed point may slip, with its
    ``slip_bound(t_N)`` then.  The capabilities are deliberately not given
    here, so that a new law cannot inherit a wrong one."""

    parameters: ClassVar[tuple[str, ...]] = ("kN", "kT")
    dimensions: ClassVar[dict[str, str]] = {"kN": STIFFNESS, "kT": STIFFNESS}
    homogeneous: ClassVar[bool]
    unilateral: ClassVar[bool]
    frictional: ClassVar[bool]
    has_history: ClassVar[bool] = False
    #: how the law is enforced: by its springs (here) or exactly
    #: (:mod:`contactcore.exact`, which evaluates these laws with per-point
    #: stiffness arrays in place of k_N, k_T)
    enforcement: ClassVar[str] = "penalty"

    @classmethod
    def from_params(cls, params: dict, path: str):
        """Build from a TOML table, naming the field of any bad value."""
        unknown = sorted(set(params) - set(cls.parameters) - {"type"})
        if unknown:
            raise SceneError(f"{path}.{unknown[0]}", f"unknown parameter of the '{cls.name}' law "
                             f"(it takes {', '.join(cls.parameters)}, and enforcement = \"penalty\" or \"exact\")"
                             f"{hint(unknown[0], (*cls.parameters, 'enforcement'))}")
        values = {k: _positive(params, k, path) for k in ("kN", "kT")}
        values.update(cls.extra_parameters(params, path))
        return cls(**values)

    @classmethod
    def extra_parameters(cls, params: dict, path: str) -> dict:
        """``{name: value}`` of the law's parameters beyond ``kN``, ``kT``,
        read from the TOML table ``params`` and checked (a bad one a
        SceneError naming ``path.name``): none here.  A law with more
        parameters gives its own (CoulombLaw: ``mu``); its exact form reads
        them through it (:meth:`contactcore.exact._ExactLaw.from_params`)."""
        extra = [p for p in cls.parameters if p not in ("kN", "kT")]
        if extra:
            raise ContactError(f"the '{cls.name}' law ({cls.__qualname__}) declares the parameters "
                               f"{', '.join(extra)} but no extra_parameters(params, path) to read and check them")
        return {}

    def initial_state(self, m: int):
        """The history of ``m`` points before the first increment (none)."""
        return None

    @property
    def stiffness_scale(self) -> float:
        """The largest spring stiffness, used in conditioning diagnostics."""
        return max(self.kN, self.kT)

    def decision_scales(self, g: np.ndarray, state=None) -> np.ndarray:
        """This rank's scales of :class:`Decision`: ``[gap, traction]``, the
        largest ``|g_N|`` and ``|k_N g_N|``; for a frictional law ``[gap,
        traction, pressure]``: the largest ``|g_N|``, the largest slip limit
        ``slip_bound(t_N)`` of a closed point (not the trial, which a
        far-off iterate can make arbitrarily large; Coulomb's ``μp``) and
        the largest pressure ``p``."""
        if not self.frictional:
            g = np.asarray(g, dtype=float).reshape(-1, 2)
            return np.array([float(np.max(np.abs(g[:, 0]), initial=0.0)),
                             float(np.max(np.abs(self.kN * g[:, 0]), initial=0.0))])
        g, closed, tN = self._springs(g)
        return np.array([float(np.max(np.abs(g[:, 0]), initial=0.0)),
                         float(np.max(self.slip_bound(tN[closed]), initial=0.0)),
                         float(np.max(-tN, initial=0.0))])

    def slides_off(self, body: str, shear: float, press: float, length: float) -> str:
        """Why a body held by Γ alone (a straight Γ of ``length``) slides
        off under loads whose resultant presses Γ with ``press`` > 0 and
        shears it with ``shear`` >= 0, or "" where Γ's slip bound may hold
        them: by the concavity of :meth:`slip_bound` (module doc) Γ carries
        at most ``|Γ| slip_bound(−press/|Γ|)``, taken beyond
        DEMAND_ROUNDOFF of it (the scene's data, no BLAS: the same on every
        machine).  A frictional law's; CoulombLaw words it by μ."""
        bound = length * float(np.asarray(self.slip_bound(np.array([-press / length])), float).reshape(-1)[0])
        if not shear > bound * (1.0 + tol.DEMAND_ROUNDOFF):  # (a zero bound: any shear slides)
            return ""
        ratio, digits = shear / bound if bound > 0 else math.inf, 3  # unit-free: the scene may be dimensionless here
        while digits < 17 and float(f"{ratio:.{digits}g}") <= 1.0:
            digits += 1
        return (f"on Γ the loads ask for {ratio:.{digits}g} times the shear the '{self.name}' law's slip bound "
                f"carries over Γ at their pressure (body {body}): it slides off (no equilibrium); lower the shear "
                "load or raise the bound")

    def _springs(self, g: np.ndarray, decision: Decision | None = None):
        """``g`` as (m, 2), the closed points (``g_N <= 0``, or by
        ``decision`` within its band) and ``t_N``."""
        g = np.asarray(g, dtype=float).reshape(-1, 2)
        if decision is None:
            closed = g[:, 0] <= 0.0
        else:
            was = decision.previous != OPEN
            if decision.normal is None:
                closed = decision.switch(-g[:, 0], decision.gap, was)
            else:  # the band in traction; at rest as the gap scale says
                closed = decision.switch(-g[:, 0], decision.normal, was, rest=decision.gap <= tol.DECISION_FLOOR)
        return g, closed, np.where(closed, self.kN * g[:, 0], 0.0)


def _friction(params: dict, path: str) -> float:
    if "mu" not in params:
        raise SceneError(f"{path}.mu", "missing (the friction coefficient, >= 0)")
    value = params["mu"]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
        raise SceneError(f"{path}.mu", f"must be a finite friction coefficient >= 0 (got {value!r})")
    if 0 < value < tol.MU_SMALLEST:
        raise SceneError(f"{path}.mu", f"{value:g} is below {tol.MU_SMALLEST:g}: a traction carries round-off up to "
                         f"{tol.TRACTION_ROUNDOFF:g} of the pressure p, a tenth or more of such a μp, so whether a "
                         f"point sticks or slips cannot be decided; give mu = 0 (frictionless) or mu >= "
                         f"{tol.MU_SMALLEST:g}")
    if value > tol.MU_LARGEST:
        raise SceneError(f"{path}.mu", f"{value:g} is above {tol.MU_LARGEST:g}: a μ of that size already makes "
                         "every closed point stick; give one at most that large")
    return float(value)


@dataclass(frozen=True)
class LinearLaw(_Law):
    """The paper's Eq. (6): bonded springs ``t_N = k_N g_N``, ``t_T = k_T g_T``.

    Tension is allowed; the tangent is constant, so a scene with this law is
    one linear solve whatever its number of increments.
    """

    kN: float
    kT: float

    name: ClassVar[str] = "linear"
    is_linear: ClassVar[bool] = True
    homogeneous: ClassVar[bool] = True
    unilateral: ClassVar[bool] = False
    frictional: ClassVar[bool] = False

    def constant_tangent(self) -> np.ndarray:
        """``∂t/∂g = diag(k_N, k_T)``: the same at every point."""
        return np.diag([self.kN, self.kT])

    def evaluate(self, g: np.ndarray, state=None, decision: Decision | None = None) -> LawResponse:
        """The springs' response to the jumps ``g`` ((m, 2) or flat, ``[g_N,
        g_T]`` in the scene's length unit; tractions in its stress unit, k in
        stress per length): ``t = diag(k_N, k_T) g`` at every point, in
        tension too; the constant tangent; no state (``state`` and
        ``decision`` are ignored); every point ``STICK``.  Nothing is
        refused: a non-finite jump gives a non-finite traction, which the
        health checks refuse."""
        g = np.asarray(g, dtype=float).reshape(-1, 2)
        D = self.constant_tangent()
        return LawResponse(g @ D.T, np.broadcast_to(D, (len(g), 2, 2)).copy(), None,
                           np.full(len(g), STICK, dtype=np.int8))


@dataclass(frozen=True)
class UnilateralLaw(_Law):
    """Penalty contact without tension (docs/scenes.md): ``t_N = k_N min(g_N, 0)``;
    where closed (``g_N <= 0``) ``t_T = k_T g_T``, where open ``t_T = 0``.

    History-free but piecewise linear: the tangent is ``diag(k_N, k_T)`` on
    closed points and zero on open ones (status STICK or OPEN).
    """

    kN: float
    kT: float

    name: ClassVar[str] = "unilateral"
    is_linear: ClassVar[bool] = False
    homogeneous: ClassVar[bool] = True
    unilateral: ClassVar[bool] = True
    frictional: ClassVar[bool] = False

    def evaluate(self, g: np.ndarray, state=None, decision: Decision | None = None) -> LawResponse:
        """The response to the jumps ``g`` ((m, 2) or flat, ``[g_N, g_T]`` in
        the scene's length unit): where closed, ``t = diag(k_N, k_T) g``
        (``STICK``), where open ``t = 0`` (``OPEN``), with the tangent of
        each.  A point is closed where ``g_N <= 0``; with a Newton
        ``decision`` (:class:`Decision`), by its band, so that round-off
        cannot flip a point.  No state (``state`` is ignored); nothing is
        refused."""
        g, closed, tN = self._springs(g, decision)
        tT = np.where(closed, self.kT * g[:, 1], 0.0)
        tangent = np.zeros((len(g), 2, 2))
        tangent[:, 0, 0] = np.where(closed, self.kN, 0.0)
        tangent[:, 1, 1] = np.where(closed, self.kT, 0.0)
        return LawResponse(np.column_stack([tN, tT]), tangent, None,
                           np.where(closed, STICK, OPEN).astype(np.int8))


@dataclass(frozen=True)
class CoulombLaw(_Law):
    """Unilateral penalty contact with Coulomb friction (docs/scenes.md), the
    elastic-predictor / return-map of Wriggers, *Computational Contact
    Mechanics* (2006), §5.2, in one dimension of slip.

    State: the accumulated slip ``s`` of each point.  With ``p = −t_N`` and
    the trial ``t* = k_T (g_T − s)``:

    * open (``g_N > 0``): ``t = 0``, ``s ← g_T`` (closes with no shear), tangent 0;
    * stick (``|t*| <= μ p (1 + STICK_ROUNDOFF)``): ``t_T = t*``, tangent ``diag(k_N, k_T)``;
    * slip: ``t_T = μ p sign(t*)``, ``s ← g_T − t_T / k_T``; tangent
      ``∂t_T/∂g_N = −μ k_N sign(t*)``, ``∂t_T/∂g_T = 0`` — not symmetric.
    """

    kN: float
    kT: float
    mu: float

    name: ClassVar[str] = "coulomb"
    parameters: ClassVar[tuple[str, ...]] = ("kN", "kT", "mu")
    dimensions: ClassVar[dict[str, str]] = {"kN": STIFFNESS, "kT": STIFFNESS, "mu": DIMENSIONLESS}
    is_linear: ClassVar[bool] = False
    has_history: ClassVar[bool] = True
    homogeneous: ClassVar[bool] = True  # the cone μp scales with p, the slip s with g
    unilateral: ClassVar[bool] = True
    frictional: ClassVar[bool] = True

    @classmethod
    def extra_parameters(cls, params: dict, path: str) -> dict:
        """``mu``, checked (:func:`_friction`)."""
        return {"mu": _friction(params, path)}

    def initial_state(self, m: int) -> np.ndarray:
        """No slip before the first increment."""
        return np.zeros(m)

    def slip_bound(self, tN: np.ndarray) -> np.ndarray:
        """Coulomb's cone: ``μ max(−t_N, 0)``."""
        return self.mu * np.maximum(-np.asarray(tN, dtype=float), 0.0)

    def slides_off(self, body: str, shear: float, press: float, length: float) -> str:
        """:meth:`_Law.slides_off` in Coulomb's words: the loads' shear/normal
        beyond μ (by DEMAND_ROUNDOFF; Wriggers 2006, §2.3), the demand to 3
        digits and μ to 6, or both to as many digits as tell them apart
        (0.25 against μ = 0.2499999975)."""
        mu = self.mu
        if not shear > mu * press * (1.0 + tol.DEMAND_ROUNDOFF):
            return ""
        ratio, digits = shear / press, 3
        while digits < 17 and float(f"{ratio:.{digits}g}") <= float(f"{mu:.{max(digits, 6)}g}"):
            digits += 1
        return (f"on Γ the loads ask for shear/normal = {ratio:.{digits}g} of body {body}, above μ = "
                f"{mu:.{max(digits, 6)}g}: it slides off (no equilibrium); lower the shear load or raise μ")

    def evaluate(self, g: np.ndarray, state=None, decision: Decision | None = None) -> LawResponse:
        """The return map (class doc) at the jumps ``g`` ((m, 2) or flat,
        ``[g_N, g_T]`` in the scene's length unit) from the slip ``state``
        ((m,), same unit; None: no slip yet): tractions (stress unit),
        the tangent (not symmetric where a point slips), the new slip
        state, each point's ``OPEN``/``STICK``/``SLIP``, and the slipping
        points' secant stiffness.  Open/closed and stick/slip are decided
        at ``g_N <= 0`` and ``|t*| <= μp (1 + STICK_ROUNDOFF)``, or, with a
        Newton ``decision``, by its bands (round-off cannot flip a
        point).  Nothing is refused: ``state`` must have one entry per
        point (numpy broadcasting rules otherwise)."""
        g, closed, tN = self._springs(g, decision)
        limit = self.slip_bound(tN)
        s = np.zeros(len(g)) if state is None else np.asarray(state, dtype=float)
        trial = self.kT * (g[:, 1] - s)
        if decision is None:
            stick = closed & (np.abs(trial) <= limit * (1.0 + tol.STICK_ROUNDOFF))
        else:
            stick = closed & decision.switch(limit - np.abs(trial), decision.traction, decision.previous == STICK,
                                             self.kT, rest=decision.traction <= tol.DECISION_FLOOR
                                             and decision.pressure <= tol.DECISION_FLOOR)
        slip = closed & ~stick
        direction = np.sign(trial)
        tT = np.where(stick, trial, np.where(slip, limit * direction, 0.0))
        tangent = np.zeros((len(g), 2, 2))
        tangent[:, 0, 0] = np.where(closed, self.kN, 0.0)
        tangent[:, 1, 1] = np.where(stick, self.kT, 0.0)
        tangent[:, 1, 0] = np.where(slip, -self.mu * self.kN * direction, 0.0)
        new_state = np.where(stick, s, g[:, 1] - tT / self.kT)
        status = np.where(stick, STICK, np.where(slip, SLIP, OPEN)).astype(np.int8)
        # a slipping point's |t*| exceeds μp >= 0, so it is never 0 there
        secant = np.divide(np.broadcast_to(self.kT * limit, limit.shape), np.abs(trial),
                           out=np.zeros(len(g)), where=slip)
        return LawResponse(np.column_stack([tN, tT]), tangent, new_state, status, secant)


def secant_tangent(tangent: np.ndarray, secant: np.ndarray) -> np.ndarray:
    """``tangent`` (m, 2, 2) with each slipping point's ``secant``
    stiffness ``|t_T| / |g_T − s|`` (:attr:`LawResponse.secant`, 0 where
    the point does not slip) in place of its ``∂t_T/∂g_T = 0``: where every
    closed point of a body held by Γ alone slips, the slip tangent leaves
    the body free to turn (or slide): its moment is flat in the rotation
    until a point's trial re-enters the stick window.  This step (Kačanov's
    iteration for a monotone law), exact or penalty (for Nitsche, ``g``
    is the augmented jump ``y``), moves the rotation towards that window by
    as much as the slipping tractions ask, where the stick stiffness, far
    steeper, crept; Newton goes on with the law's tangent once a point
    sticks."""
    out = np.array(tangent, float, copy=True)
    slipping = secant > 0
    out[slipping, 1, 1] = secant[slipping]
    return out


#: Every penalty law by the name a scene file gives it.
LAWS = registry(LinearLaw, UnilateralLaw, CoulombLaw)

#: The type of a scene's penalty law: any law class (a union of the shipped
#: ones would leave out a law :func:`register` adds; takeover31 #5).  An
#: exactly enforced law is a :class:`contactcore.exact._ExactLaw`.
InterfaceLaw = _Law
