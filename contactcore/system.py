"""The contract between a method and the shared Newton: what every method
hands to :func:`contactcore.newton.solve_increments`.

A discretisation reduces to an algebraic :class:`ContactSystem`: a bulk
operator ``A`` (elasticity, and for EFGM its constraint rows), load vectors
``b(λ)``, prescribed unknowns, and the :class:`InterfaceOperator` that maps
the unknowns to the jumps ``g = [g_N, g_T]`` at Γ's quadrature points.
Newton's residual and tangent are then the same for every method:

    R(u) = A u − b(λ) + Gᵀ W t(G u, s),      J = A + Gᵀ W (∂t/∂g) G.

fe and xfem implement the system with PETSc (:mod:`xdolfinx.contact_system`),
EFGM with scipy or PETSc (:mod:`efgm.method`, :mod:`efgm.distributed`).
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import scipy.sparse as sp

from . import tolerances as tol
from .collective import SERIAL, Collective
from .errors import DiscretisationError
from .exchange import Exchange
from .laws import Decision
from .result import SolverReport


@dataclass
class InterfaceOperator:
    """The interface as a method discretises it: ``m`` quadrature points on
    Γ, their weights, and ``G`` (2m × n) with rows ``2p, 2p+1`` giving
    ``g_N, g_T`` of point p from the unknowns."""

    #: whether Newton reads it for an exact law (contactcore.exact.NitscheInterface)
    exact: ClassVar[bool] = False
    G: sp.csr_matrix
    weights: np.ndarray
    points: np.ndarray
    #: Under mpirun, this rank's points only, ``G``'s columns in the local
    #: numbering of the unknowns it touches (owned, then ghosts), and
    #: ``exchange`` the system's ghost exchange (:class:`~contactcore.exchange.Exchange`);
    #: None in serial (local = owned = all).
    exchange: Exchange | None = None
    #: For exact enforcement (:mod:`contactcore.exact`), None where the
    #: method gives none: ``S`` (2m × n, ``G``'s shape and columns) with
    #: rows ``2p, 2p+1`` the consistent traction ``τ = (n·{σ}n, t·{σ}n)``
    #: of point p, ``{σ}`` the weighted average of the two sides' stresses
    #: (Annavarapu et al. 2012: ``w_k ∝ |Ω_k^e|/E_k``), and
    #: ``stabilisation`` γ₀ (m,) in Pa/m, ``2|Γ^e| / Σ_k (|Ω_k^e|/E_k)``
    #: over the two sides' parts ``Ω_k^e`` of the cell(s) at the point's
    #: piece ``Γ^e`` of Γ; the scene's β multiplies it.
    S: sp.csr_matrix | None = None
    stabilisation: np.ndarray | None = None
    #: Each point's piece of Γ (m, 2), named by its centre
    #: (:func:`~contactcore.interface_path.piece_centres`), or None: an
    #: exact law's traction is reported as its mean over each piece
    #: (:meth:`~contactcore.interface_path.InterfacePath.piece_means`).
    pieces: np.ndarray | None = None
    #: For a flux affine in the loads (fe's nodal reaction,
    #: :mod:`xdolfinx.nodal`), None otherwise: ``L`` (2m × n, ``S``'s shape
    #: and columns) with ``τ = S u − L b``, ``b`` the step's loads
    #: (:meth:`ContactSystem.external`); ``S = L A``.
    load_flux: sp.csr_matrix | None = None

    @property
    def size(self) -> int:
        return len(self.weights)

    def loaded(self, b: np.ndarray) -> None:
        """Told each step's loads ``b`` (owned values) before the step:
        nothing here (a penalty law's jumps do not read them;
        :meth:`contactcore.exact.NitscheInterface.loaded`)."""

    def respond(self, law, u: np.ndarray, state, previous=None, ranks=SERIAL):
        """The law's response to the jumps of ``u`` (penalty enforcement),
        each switch within its round-off band keeping the ``previous``
        status (:class:`~contactcore.laws.Decision`, its scales Γ-wide over
        ``ranks``); every switch by its sign where ``previous`` is None."""
        g = self.jumps(u)
        decision = None if previous is None else Decision.reduced(law, g, state, previous, ranks)
        return law.evaluate(g, state, decision)

    def internal(self, u: np.ndarray, traction: np.ndarray) -> np.ndarray:
        """The interface's forces at ``u`` with the tractions ``t``: ``Gᵀ W t``."""
        return self.forces(traction)

    def sides(self) -> tuple[sp.csr_matrix, sp.csr_matrix]:
        """``(T, G)`` with the interface's stiffness ``Tᵀ W D G``: here ``(G, G)``."""
        return self.G, self.G

    def jumps(self, u: np.ndarray) -> np.ndarray:
        """``[g_N, g_T]`` (m, 2) of the unknowns ``u`` (owned values)."""
        local = u if self.exchange is None else self.exchange.forward(u)
        return (self.G @ local).reshape(-1, 2)

    def forces(self, traction: np.ndarray) -> np.ndarray:
        """Nodal forces ``Gᵀ W t`` of the tractions ``t`` (m, 2), owned rows."""
        local = self.G.T @ (self.weights[:, None] * traction).ravel()
        return local if self.exchange is None else self.exchange.reverse(local)

    def stiffness(self, tangent: np.ndarray, test: sp.csr_matrix | None = None) -> sp.csr_matrix:
        """``Gᵀ W D G`` for the tangents ``D`` (m, 2, 2) of the points
        (``Tᵀ W D G`` with another ``test`` operator ``T``)."""
        m = self.size
        rows = 2 * np.arange(m)[:, None, None] + np.arange(2)[None, :, None]
        cols = 2 * np.arange(m)[:, None, None] + np.arange(2)[None, None, :]
        WD = sp.csr_matrix(((self.weights[:, None, None] * tangent).ravel(),
                            (np.broadcast_to(rows, tangent.shape).ravel(),
                             np.broadcast_to(cols, tangent.shape).ravel())), shape=(2 * m, 2 * m))
        return ((self.G if test is None else test).T @ WD @ self.G).tocsr()

    def pattern(self) -> sp.csr_matrix:
        """Every entry any ``Gᵀ W D G`` can reach (values meaningless):
        both jumps of a point couple through a full 2 × 2 ``D``; with ``S``,
        every unknown either reaches (Nitsche's ``G + Γ⁻¹S`` and ``SᵀWΓ⁻¹S``)."""
        A = abs(self.G) if self.S is None else abs(self.G) + abs(self.S)
        pairs = sp.kron(sp.identity(self.size), np.ones((2, 2)), format="csr")
        return (A.T @ pairs @ A).tocsr()


def check_points_on_gamma(interface: InterfaceOperator, scene, method: str, collective: Collective = SERIAL,
                          to_user=None) -> None:
    """Refuse a method's Γ points that are not on the scene's Γ: each of
    ``interface.points`` within :data:`~contactcore.tolerances.GAMMA_POINT_OFFSET`
    of the domain's length scale of ``scene.interface`` (its own
    ``signed_distance``), over every rank's points (``collective``), else
    a :class:`~contactcore.errors.DiscretisationError` naming the
    ``method``, the worst point and its distance (in the user's length,
    ``to_user`` the map of a dimensionless point and length: (point,
    distance) -> (point, distance); None: as given).  A Γ point off Γ
    solves without complaint (takeover33's sign bug put every point
    0.17 m off a tilted Γ, and ``gamma_reach`` widened the fields' "on
    Γ" tolerance to match)."""
    points = np.asarray(interface.points, dtype=float).reshape(-1, 2)
    distance = np.abs(np.asarray(scene.interface.signed_distance(points), dtype=float)) if len(points) else np.zeros(0)
    distance = np.where(np.isnan(distance), np.inf, distance)  # a NaN is no distance: off Γ
    worst = np.zeros((0, 3))
    if len(points):
        k = int(np.argmax(distance))
        worst = np.array([[distance[k], *points[k]]])
    worst = collective.gather(worst)
    if not len(worst):
        return
    d, x, y = worst[int(np.argmax(worst[:, 0]))]
    allowed = tol.GAMMA_POINT_OFFSET * scene.domain.length_scale
    if d <= allowed:
        return
    point, d, allowed = ((x, y), d, allowed) if to_user is None else (*to_user((x, y), d), to_user((x, y), allowed)[1])
    raise DiscretisationError(
        f"{method}: a method's Γ points must lie on Γ: its Γ point ({point[0]:.6g}, {point[1]:.6g}) is {d:.3g} "
        f"from the scene's Γ, beyond {tol.GAMMA_POINT_OFFSET:g} of the domain's size ({allowed:.3g}): "
        "its interface operator is not on this scene's Γ")


class ContactSystem(ABC):
    """What a method hands to :func:`solve_increments`: every method's
    system subclasses it.  Vectors are this rank's owned values (all of
    them in serial).

    Newton reads the attributes below and calls the methods; a subclass
    sets ``size``, ``interface`` and ``fixed`` and implements the abstract
    methods; ``constraint_rows`` and ``collective`` have real defaults."""

    size: int
    interface: InterfaceOperator
    #: indices of the prescribed unknowns
    fixed: np.ndarray
    #: the rows that prescribe values rather than balance forces (EFGM's
    #: multiplier rows, ``s (C u − ū)``): judged as data, not as forces
    constraint_rows: np.ndarray = np.zeros(0, dtype=int)
    #: the reductions over the ranks the system is distributed on: every
    #: decision of Newton is taken on values reduced by it (serial: none)
    collective: Collective = SERIAL

    @abstractmethod
    def fixed_values(self, support_factors) -> np.ndarray:
        """Values of the prescribed unknowns for the supports' factors."""

    @abstractmethod
    def external(self, load_factors, support_factors) -> np.ndarray:
        """``b(λ)``: loads (and, for multipliers, prescribed values)."""

    @abstractmethod
    def internal(self, u: np.ndarray) -> np.ndarray:
        """``A u``: the bulk forces of the unknowns."""

    @abstractmethod
    def solve(self, interface_tangent: sp.csr_matrix | None, rhs: np.ndarray,
              force_scale: float = 0.0, slot: int = 0) -> tuple[np.ndarray, SolverReport]:
        """``δu`` with ``(A + K_Γ)[free, free] δu = rhs[free]``, zero on the
        fixed unknowns; raise SolverError if the solve fails, by the health
        policy with the residual relative to ``max(‖rhs‖, force_scale)``.
        The matrix is factorised into ``slot`` (one of
        :data:`~contactcore.tolerances.FACTORISATIONS_KEPT`); with
        ``interface_tangent`` None, the slot's last factorisation is used."""

    def column_budget(self, slot: int) -> int | None:
        """How many columns of ``slot``'s factorisation one block solve may
        take and a correction keep, or None where they are solved one by one
        (here; a MUMPS system gives :meth:`~contactcore.linear_solver.Tangent.column_budget`)."""
        return None

    def correction_columns(self, slot: int) -> tuple[int, int]:
        """``(new, kept)``: how many columns a low-rank correction of
        ``slot``'s factorisation may solve for at once (:meth:`solve_columns`)
        and how many it may keep and read in all: the :meth:`column_budget`
        for both, or solved one by one LOW_RANK_NEW and LOW_RANK_COLUMNS
        (:mod:`contactcore.tolerances`)."""
        budget = self.column_budget(slot)
        return (tol.LOW_RANK_NEW, tol.LOW_RANK_COLUMNS) if budget is None else (budget, budget)

    def solve_columns(self, rhs: sp.spmatrix, slot: int) -> np.ndarray:
        """``δU`` (n, q) for the q sparse columns of ``rhs`` with the slot's
        last factorisation (one process), as :meth:`solve` does them one by one."""
        out = np.zeros(rhs.shape)
        for j, column in enumerate(rhs.T.toarray()):
            out[:, j] = self.solve(None, column, slot=slot)[0]
        return out

    def close(self) -> None:
        """Release the matrices and factorisations the solves kept (none here)."""


ContactSystem.constraint_rows.flags.writeable = False  # one shared empty default: read, never written
