"""Exact enforcement of the interface laws: Nitsche's method.

The penalty laws (:mod:`contactcore.laws`) set the answer by their springs
k_N, k_T.  Enforced exactly, each law is its springs' limit k → ∞:
``unilateral`` is Signorini's condition (``g_N >= 0``, ``t_N <= 0``,
``g_N t_N = 0``) with a closed point tied tangentially (``g_T = 0``, any
``t_T``: the unilateral law's spring has no limit, docs/scenes.md) and an
open one free; ``coulomb`` is Signorini's condition with Coulomb's friction
(``|t_T| <= μ|t_N|``, no slip increment where it holds with ``<``;
frictionless contact is μ = 0); ``bonded`` is perfect bonding (``g = 0``),
the limit of ``linear``.  No spring enters the answer.

Nitsche's method for contact and Coulomb friction (Chouly & Hild, SINUM
2013; Chouly, Hild & Renard, Math. Comp. 2015), with the weighted average
of Annavarapu, Hautefeuille & Dolbow (CMAME 2012, 2014).  In Γ's frame
(``n`` from − to +, ``t = (n_y, −n_x)``) the method's interface operator
gives, at its m points, the jump ``g = G u`` and the consistent traction
``τ = S u = (n·{σ}n, t·{σ}n)``, ``{σ} = w₋ σ(u⁻) + w₊ σ(u⁺)``
(``w₋ + w₊ = 1``): integrating by parts, ``a(u, v) + ∫_Γ σn·[[v]] = ℓ(v)``,
so ``τ`` is the traction ``t`` of the weak form ``a(u, v) + ∫_Γ t·g(v) = ℓ(v)``.
Each law is the penalty law with ``k_N = k_T = γ`` (per point) evaluated at
the augmented jump

    y = g + τ/γ = G̃ u,     G̃ = G + Γ⁻¹ S,

(``Γ = diag(γ)``): unilateral closed where ``y_N <= 0`` with ``t = γ y``
(so ``g = 0`` holds weakly), open with ``t = 0``; coulomb with
``t_N = min(γ y_N, 0)``, the trial ``t_T* = γ (y_T − s)``, stick if
``|t_T*| <= μ p``, else slip, and ``s`` the penalty law's slip at
``k_T = γ``: kept while the point sticks, ``y_T − t_T/γ`` once it slips
or opens: the tie of a sticking point is anchored where its stick began,
one elastic spring over the whole stick, so a proportional load's answer
does not depend on its increments (``s`` = the last increment's jump
``g_T`` made it; docs/contact-enforcement.md, "The slip state").  It is
consistent: at the exact solution ``t = τ``, so ``y_T − t_T/γ = g_T``.
Bonded ``t = γ y``.  With the test side ``G + θ Γ⁻¹ S`` (θ =
:data:`~contactcore.tolerances.NITSCHE_THETA`: −1, the skew-symmetric
variant, well posed for every γ > 0) the residual and tangent are

    R(u) = A u − b + C u + (G + θΓ⁻¹S)ᵀ W t(G̃ u, s),
    J = A + C + (G + θΓ⁻¹S)ᵀ W (∂t/∂y) G̃,      C = −θ Sᵀ W Γ⁻¹ S,

the penalty's on ``G̃`` (tested by ``G + θΓ⁻¹S``) plus a constant bulk
correction ``C``: Newton, its reuse of factorisations and every method's
solver carry it unchanged.  ``γ = β γ₀`` per point,
``γ₀ = 2|Γ^e| / Σ_k (|Ω_k^e|/E_k)`` from the method
(:class:`~contactcore.system.InterfaceOperator`'s ``stabilisation``) and
``β`` the scene's ``stabilisation`` (default
:data:`~contactcore.tolerances.NITSCHE_STABILISATION`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import ClassVar

import numpy as np
import scipy.sparse as sp

from . import tolerances as tol
from .errors import DiscretisationError, SceneError, quoted
from .collective import SERIAL
from .laws import DIMENSIONLESS, STICK, CoulombLaw, Decision, LawResponse, LinearLaw, UnilateralLaw, registry
from .laws.springs import _positive
from .spelling import hint

#: Laws that exist only enforced exactly (no springs).
BONDED = ("bonded",)

#: What every refusal of springs on ``bonded`` says.
NO_SPRINGS = "it has no springs: for springs use type = \"linear\""


def default_enforcement(kind: str) -> str:
    """How a law of type ``kind`` is enforced when the scene does not say."""
    return "exact" if kind in BONDED else "penalty"


def _stabilisation(params: dict, path: str) -> float:
    """The scene's ``stabilisation`` β, or the default."""
    if "stabilisation" not in params:
        return tol.NITSCHE_STABILISATION
    return checked_stabilisation(params["stabilisation"], f"{path}.stabilisation")


#: Why a β outside NITSCHE_STABILISATION_RANGE is refused, above it and below.
_STIFF = ("a larger β locks cut cells like a stiff penalty (xfem's answer 18 % off β = 3's at β = 100 and h = 0.05, "
          "1868 % at 1e6) or fails Newton's first increment")
_SOFT = ("a smaller β leaves the contact a soft spring (C-coulomb's t_T 11-16 % off β = 3's at β = 0.1 and "
         "h = 0.05, 77 % at 1e-9)")
_NONE = "a β of 0 or less gives Nitsche's method no stabilisation, and its problem no unique answer"


def checked_stabilisation(value, field: str) -> float:
    """β as given (dimensionless, a multiple of the method's E/h), or a
    SceneError naming ``field``: a number within
    :data:`~contactcore.tolerances.NITSCHE_STABILISATION_RANGE`, outside
    which an answer at the mesh's h was measured to move with β (a large γ
    locks cut cells like a stiff penalty, a small one is a soft spring).
    The one rule and text of β, for a scene file, a Python scene and
    ``study --param stabilisation``: every refusal reads ``must lie within
    LOW..HIGH``."""
    low, high = tol.NITSCHE_STABILISATION_RANGE
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SceneError(field, f"must lie within {low:g}..{high:g}, a number: a multiple of the method's E/h "
                                f"(got {value!r})")
    if not low <= value <= high:
        why = _STIFF if value > high else _NONE if value <= 0 else _SOFT
        raise SceneError(field, f"must lie within {low:g}..{high:g} (got {quoted(value, low, high)}): {why}")
    return float(value)


@dataclass(frozen=True)
class _ExactLaw:
    """What the exact laws share: β and the reading of their parameters."""

    stabilisation: float
    #: the ``kN``, ``kT`` its file gave (checked, never used by the answer;
    #: a study's penalty point takes them): ``(("kN", ..), ("kT", ..))``
    given_springs: tuple = field(default=(), compare=False, repr=False)
    enforcement: ClassVar[str] = "exact"
    parameters: ClassVar[tuple[str, ...]] = ("stabilisation",)
    #: the law contract (contactcore.laws' module doc): β is a multiple of E/h
    dimensions: ClassVar[dict[str, str]] = {"stabilisation": DIMENSIONLESS}
    #: (``homogeneous``, ``unilateral``, ``frictional``: each subclass
    #: declares its own, as the law contract asks of every law, so a new
    #: exact law cannot inherit a wrong one; review7 #3)
    has_history: ClassVar[bool] = False
    is_linear: ClassVar[bool] = False
    #: the penalty law evaluated with per-point stiffnesses (None: bonded)
    springs: ClassVar[type | None] = None

    #: What the law says of ``kN``, ``kT`` when it refuses an unknown key.
    about_springs: ClassVar[str] = "kN, kT may be given and play no part"

    @classmethod
    def from_params(cls, params: dict, path: str):
        """Build from a TOML table; k_N, k_T may be given (checked, unused).
        The law's parameters besides ``stabilisation`` are its springs'
        (``mu`` for Coulomb), read and checked by the springs' class
        (:meth:`contactcore.laws._Law.extra_parameters`): a new exact law
        names its ``springs`` and declares the same parameters, with no
        edit here (takeover31 #3)."""
        allowed = set(cls.parameters) | {"type", "kN", "kT"}
        unknown = sorted(set(params) - allowed)
        if unknown:
            raise SceneError(f"{path}.{unknown[0]}", f"unknown parameter of the exact '{cls.name}' law (it takes "
                             f"{', '.join(cls.parameters)}; {cls.about_springs}){hint(unknown[0], allowed - {'type'} | {'enforcement'})}")
        given = tuple((k, _positive(params, k, path)) for k in ("kN", "kT") if k in params)
        values = {"stabilisation": _stabilisation(params, path), "given_springs": given}
        if cls.springs is not None:
            values.update(cls.springs.extra_parameters(params, path))
        return cls(**values)

    def initial_state(self, m: int):
        """Its springs' history before the first increment (none for bonded)."""
        return None if self.springs is None else self.at(np.ones(m)).initial_state(m)

    def slip_bound(self, tN: np.ndarray) -> np.ndarray:
        """Its springs' slip bound (:meth:`contactcore.laws._Law.slip_bound`,
        for a frictional law): the bound does not depend on the springs."""
        return self.at(np.ones(1)).slip_bound(tN)

    def slides_off(self, body: str, shear: float, press: float, length: float) -> str:
        """Its springs' refusal (:meth:`contactcore.laws._Law.slides_off`)."""
        return self.at(np.ones(1)).slides_off(body, shear, press, length)

    def at(self, stiffness: np.ndarray):
        """The penalty law with ``k_N = k_T = stiffness`` (per point)."""
        return self.springs(**self._spring_values(np.asarray(stiffness, float)))

    def evaluate(self, y: np.ndarray, state, stiffness: np.ndarray, decision=None) -> LawResponse:
        """The penalty law :meth:`at` ``stiffness`` at the augmented jumps
        ``y`` (module doc), its state included: for Coulomb, the slip
        ``s`` kept while a point sticks, ``y_T − t_T/γ`` once it slips or opens."""
        return self.at(stiffness).evaluate(y, state, decision)

    def _spring_values(self, k: np.ndarray) -> dict:
        """The springs' arguments: ``k_N = k_T = k`` and every other
        parameter of the law as it is (``mu``)."""
        return {"kN": k, "kT": k, **{p: getattr(self, p) for p in self.parameters if p != "stabilisation"}}


@dataclass(frozen=True)
class ExactUnilateral(_ExactLaw):
    """Signorini contact without friction, enforced exactly (module doc)."""

    name: ClassVar[str] = "unilateral"
    springs: ClassVar[type] = UnilateralLaw
    homogeneous: ClassVar[bool] = True  # its springs' law at per-point γ, read at the linear y = G̃ u
    unilateral: ClassVar[bool] = True
    frictional: ClassVar[bool] = False


@dataclass(frozen=True)
class ExactCoulomb(_ExactLaw):
    """Signorini contact with Coulomb friction, enforced exactly: the state
    is the penalty law's slip ``s`` at ``k_T = γ``, read at the augmented
    jump (module doc)."""

    mu: float = 0.0
    name: ClassVar[str] = "coulomb"
    parameters: ClassVar[tuple[str, ...]] = ("mu", "stabilisation")
    dimensions: ClassVar[dict[str, str]] = {"mu": DIMENSIONLESS, "stabilisation": DIMENSIONLESS}
    has_history: ClassVar[bool] = True
    springs: ClassVar[type] = CoulombLaw
    homogeneous: ClassVar[bool] = True  # its springs' law at per-point γ, read at the linear y = G̃ u
    unilateral: ClassVar[bool] = True
    frictional: ClassVar[bool] = True


@dataclass(frozen=True)
class Bonded(_ExactLaw):
    """Perfect bonding, ``g = 0`` (the limit k → ∞ of ``linear``): ``t = γ y``."""

    name: ClassVar[str] = "bonded"
    is_linear: ClassVar[bool] = True
    homogeneous: ClassVar[bool] = True  # linear
    unilateral: ClassVar[bool] = False
    frictional: ClassVar[bool] = False
    about_springs: ClassVar[str] = NO_SPRINGS

    @classmethod
    def from_params(cls, params: dict, path: str):
        """Build from a TOML table: ``stabilisation`` alone; ``kN``, ``kT``
        are refused, in the words of any unknown key (:data:`NO_SPRINGS`)."""
        for k in ("kN", "kT"):
            if k in params:
                raise SceneError(f"{path}.{k}", f"the 'bonded' law takes stabilisation only; {NO_SPRINGS}")
        return super().from_params(params, path)

    def at(self, stiffness: np.ndarray):
        """Linear springs ``k_N = k_T = stiffness`` (per point): no switch to decide."""
        return LinearLaw(np.asarray(stiffness, float), np.asarray(stiffness, float))

    def evaluate(self, y: np.ndarray, state, stiffness: np.ndarray, decision=None) -> LawResponse:
        y = np.asarray(y, float).reshape(-1, 2)
        k = np.asarray(stiffness, float)
        tangent = k[:, None, None] * np.eye(2)
        return LawResponse(k[:, None] * y, tangent, None, np.full(len(y), STICK, dtype=np.int8))


#: Every law enforced exactly, by the name a scene file gives it.
EXACT_LAWS = registry(ExactUnilateral, ExactCoulomb, Bonded)


def make_law(kind: str, enforcement: str, params: dict, path: str):
    """The exactly enforced law ``kind`` (``"unilateral"``, ``"coulomb"`` or
    ``"bonded"``) built from the scene's law table ``params`` (``mu`` for
    Coulomb, ``stabilisation`` β within NITSCHE_STABILISATION_RANGE);
    ``enforcement`` is the value the scene gave and ``path`` the table's
    field name for errors.  Refused with a :class:`SceneError` at
    ``path.enforcement``: ``bonded`` with any enforcement but ``"exact"``
    (it has no springs), and a law with no exact form (``linear``).  Bad
    parameters are refused by the law's ``from_params``, naming their
    field.  Called by :func:`contactcore.enforcement.make_law`, the entry
    point for any law table."""
    if kind in BONDED and enforcement != "exact":
        raise SceneError(f"{path}.enforcement", f"the '{kind}' law is enforced exactly only, as {NO_SPRINGS}")
    if kind not in EXACT_LAWS:
        raise SceneError(f"{path}.enforcement", f"the '{kind}' law is enforced by its springs only (exact "
                         f"enforcement: {', '.join(EXACT_LAWS)}; perfect bonding is type = \"bonded\")")
    return EXACT_LAWS[kind].from_params(params, path)


def is_exact(law) -> bool:
    """Whether ``law`` (any law object: penalty or exact) is enforced
    exactly (its ``enforcement`` is ``"exact"``), so that its tractions
    come from the solve and not from springs evaluated at the jump."""
    return law.enforcement == "exact"


# ----- the interface operator of Nitsche's method ----------------------------

class NitscheInterface:
    """A method's :class:`~contactcore.system.InterfaceOperator` (with its
    ``S`` and ``stabilisation`` γ₀) read by Newton for an exact law of
    stabilisation ``β`` (module doc): ``jumps`` the actual jumps ``G u``,
    the law evaluated at ``G̃ u`` with ``γ = β γ₀``, the forces
    ``G̃ᵀ W t + C u`` and the tangent ``G̃ᵀ W D G̃ + C``.  Under mpirun the
    columns of ``G``, ``S`` are the local numbering of ``exchange``, so
    ``C`` is applied as ``exchange.reverse(Sᵀ (W Γ⁻¹ S exchange.forward(u)))``,
    and added to the tangent where it falls, like ``Gᵀ W D G``."""

    exact = True

    def __init__(self, operator, beta: float):
        self.operator, self.beta = operator, beta
        self.gamma = beta * np.asarray(operator.stabilisation, float)
        inverse = sp.diags(np.repeat(1.0 / self.gamma, 2)) if len(self.gamma) else sp.csr_matrix((0, 0))
        self.augmented = (operator.G + inverse @ operator.S).tocsr()  # G̃
        self._scaled = replace(operator, G=self.augmented)  # forces, stiffness and pattern on G̃
        theta = tol.NITSCHE_THETA
        self.test = (operator.G + theta * (inverse @ operator.S)).tocsr()  # G + θ Γ⁻¹S
        # (G + θ Γ⁻¹S)ᵀ made once (the CSC view scipy's ``.T`` gives, not one
        # per residual): the forces summed as InterfaceOperator.forces sums them
        self._test_transposed = self.test.T
        WS = sp.diags(np.repeat(operator.weights / self.gamma, 2)) @ operator.S if len(self.gamma) else operator.S
        self.correction = (-theta * (operator.S.T @ WS)).tocsr()  # C, local numbering
        self._weighted = WS  # W Γ⁻¹ S, for an affine flux's constant forces
        self._load = None  # an affine flux's ``L b`` (2m,) of the step (:meth:`loaded`)

    def softened(self, factor: float) -> "NitscheInterface":
        """The same interface at ``factor`` times its stabilisation β (told
        its step's loads afresh, :meth:`loaded`)."""
        return NitscheInterface(self.operator, factor * self.beta)

    def __getattr__(self, name):  # points, weights, exchange, size: the method's
        return getattr(self.operator, name)

    def loaded(self, b: np.ndarray) -> None:
        """Told the step's loads ``b`` (owned values): with an affine flux
        ``τ = S u − L b`` (:attr:`~contactcore.system.InterfaceOperator.load_flux`),
        ``s = L b`` is kept for the step: ``y = G̃ u − Γ⁻¹ s`` and the forces
        gain ``θ Sᵀ W Γ⁻¹ s`` (``R = A u − b + Gᵀ W t + θ Sᵀ W Γ⁻¹ (t − τ)``).
        Nothing for a flux linear in ``u`` (every other method's)."""
        if self.operator.load_flux is None:
            return
        local = b if self.exchange is None else self.exchange.forward(b)
        self._load = self.operator.load_flux @ local

    def augmented_jumps(self, u: np.ndarray) -> np.ndarray:
        """``y = G̃ u`` (m, 2), less ``Γ⁻¹ s`` with an affine flux (:meth:`loaded`)."""
        y = self._scaled.jumps(u)
        if self._load is None:
            return y
        return y - self._load.reshape(-1, 2) / self.gamma[:, None]

    def jumps(self, u: np.ndarray) -> np.ndarray:
        return self.operator.jumps(u)

    def respond(self, law, u: np.ndarray, state, previous=None, ranks=SERIAL) -> LawResponse:
        """The law at the augmented jumps ``G̃ u`` with ``γ``, its switches
        decided, and its state updated, as the penalty law's
        (:class:`~contactcore.laws.Decision`; module doc)."""
        y = self.augmented_jumps(u)
        decision = None
        if previous is not None:
            decision = Decision.reduced(law.at(self.gamma), y, state, previous, ranks)
            # the closed/open band in traction: γ times the margin within
            # DECISION_BAND of Γ's largest pressure γ max(−y_N, 0), so that no
            # point is held closed in tension (or open in penetration) by
            # more than that share of p (laws.Decision.in_traction)
            y2 = np.asarray(y, float).reshape(-1, 2)
            pressure = ranks.max(float(np.max(-self.gamma * y2[:, 0], initial=0.0)))
            decision = decision.in_traction(self.gamma, pressure)
        return law.evaluate(y, state, self.gamma, decision)

    def internal(self, u: np.ndarray, traction: np.ndarray) -> np.ndarray:
        """``G̃ᵀ W t + C u`` (owned rows)."""
        local = u if self.exchange is None else self.exchange.forward(u)
        bulk = self.correction @ local
        bulk = bulk if self.exchange is None else self.exchange.reverse(bulk)
        forces = self._test_transposed @ (self.weights[:, None] * traction).ravel()  # Tᵀ W t
        if self._load is not None:
            forces = forces + tol.NITSCHE_THETA * (self._weighted.T @ self._load)  # θ Sᵀ W Γ⁻¹ s
        return (forces if self.exchange is None else self.exchange.reverse(forces)) + bulk

    def stiffness(self, tangent: np.ndarray) -> sp.csr_matrix:
        return (self._scaled.stiffness(tangent, self.test) + self.correction).tocsr()

    def pattern(self) -> sp.csr_matrix:
        return self._scaled.pattern()

    def sides(self) -> tuple[sp.csr_matrix, sp.csr_matrix]:
        """``(G + θΓ⁻¹S, G̃)``: the stiffness is ``(G + θΓ⁻¹S)ᵀ W D G̃ + C``."""
        return self.test, self.augmented


def enforced(law, operator):
    """The interface operator Newton reads for ``law``: the method's own for
    a penalty law, :class:`NitscheInterface` for an exact one."""
    return NitscheInterface(operator, law.stabilisation) if is_exact(law) else operator


def check(law, operator, method: str) -> None:
    """Refuse exact enforcement by a method whose operator lacks ``S`` or γ₀."""
    if is_exact(law) and (operator.S is None or operator.stabilisation is None):
        raise DiscretisationError(f"{method}: exact enforcement (the '{law.name}' law) needs the method's consistent "
                                  "traction on Γ and its stabilisation, which it does not provide yet; use "
                                  "enforcement = \"penalty\"")
