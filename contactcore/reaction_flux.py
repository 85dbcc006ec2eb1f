"""A β-free exact enforcement for methods with no nodes on Γ (xfem, efgm):
a multiplier mesh on Γ and the least-squares reaction as Nitsche's flux
(``XFEM(flux="reaction")``, ``EFGM(flux="reaction")``;
docs/contact-enforcement.md, "A β-free exact enforcement for xfem and efgm").

fe's nodal reaction (:mod:`xdolfinx.nodal`) puts Nitsche's points at Γ's
nodes.  xfem and efgm have none, so Γ gets its own mesh of multiplier
nodes, mortar-style (Wohlmuth, SINUM 2000, Acta Numerica 2011): P1 hats
``ψ_k`` in arclength along Γ at spacing ``H = c h`` (``c`` =
:data:`~contactcore.tolerances.MULTIPLIER_SPACING`, Γ's ends nodes; a
closed Γ periodic).  From the method's own Gauss-point operator (``m``
points ``x_p``, weights ``w_p``, rows ``G_p`` giving ``g_N, g_T`` of point
``p`` in its frame; :class:`~contactcore.system.InterfaceOperator`):

    Ψ_pk = ψ_k(x_p),   B = (Ψᵀ W ⊗ I₂) G   (2M × n),   D_k = Σ_p ψ_k(x_p) w_p,

and the operator Newton reads has the ``M`` multiplier nodes as points,
weights ``D``, jump rows ``Ĝ = D⁻¹ B`` (a weighted gap) and the law
evaluated node-wise, as :mod:`contactcore.exact` does at fe's nodes; its
forces ``Ĝᵀ D t = Bᵀ t`` are those of the traction ``Σ_k ψ_k t_k``.

The flux is the least-squares reaction.  With ``R = A u − b`` the bulk's
residual (no interface) and ``f`` the free (not prescribed) unknowns,

    L = −(B_f B_fᵀ)⁻¹ B_f P_f,   τ = L R = S u − L b,   S = L A,

``P_f`` restricting to ``f``.  The multipliers' answer ``u*`` solves
``R_f(u*) + B_fᵀ λ* = 0`` with the law at every node, so ``L R(u*) = λ*``
and ``τ(u*) = λ*``: the law at ``y = ĝ + τ/γ`` returns ``λ*`` for every
γ, and ``u*`` solves Nitsche's residual (Chouly, Hild & Renard, Math.
Comp. 2015, with ``τ`` in place of ``σ(u)n``) at every β: the answer does
not move with β.  Where the unknowns include multipliers of the supports
(efgm's saddle point, :mod:`efgm.method`), ``A`` is the augmented matrix
and ``B`` is zero on their rows: ``R``'s displacement rows then hold the
supports' reactions, as a prescribed unknown's row does for fe and xfem.

A row of ``B_f`` of (near) zero norm (a component held on both sides,
:data:`~contactcore.tolerances.REACTION_ROW_ZERO`) is dropped from the law
with its ``Ĝ`` and ``L`` rows; where the rows kept leave ``B_f B_fᵀ``
rank-deficient (its Jacobi-scaled smallest eigenvalue below
:data:`~contactcore.tolerances.REACTION_RANK`) it is refused with a
:class:`~contactcore.errors.DiscretisationError` naming the node.  γ₀ per
node is the points' γ₀ averaged with weights ``ψ_k w_p``.

``(B_f B_fᵀ)⁻¹`` couples every node, so ``L`` and ``S`` are dense over the
unknowns near Γ (their tangent ``SᵀWΓ⁻¹S`` too), at a cost that grows
with Γ's unknowns squared.  Under mpirun xfem keeps every cell near Γ on
one rank, which computes them alone (:mod:`xdolfinx.reaction`); efgm's
runs on one process only (:func:`check_serial`).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from . import tolerances as tol
from .errors import DiscretisationError
from .exact import is_exact
from .geometry import CircleInterface, LineInterface, tangent_of
from .interface_path import piece_centres
from .system import InterfaceOperator

#: The option value that asks for this flux, and the default's (Γ's Gauss
#: points with the cells' stress): every method's ``flux`` is one of these.
FLUXES = ("stress", "reaction")


@dataclass(frozen=True)
class MultiplierChain:
    """Γ's multiplier nodes: at arclength ``start + k·step`` (``count``
    nodes; ``period`` Γ's length where it is closed, else None); ``origin``
    a straight Γ's point (a circle's centre), ``direction`` its tangent
    (unread on a circle), ``radius`` a circle's (None on a line)."""

    start: float
    step: float
    count: int
    period: float | None
    origin: np.ndarray
    direction: np.ndarray
    radius: float | None = None

    def arclength(self, points: np.ndarray) -> np.ndarray:
        """The arclength of points on Γ (m,): along a line from its
        ``origin``, clipped to Γ's ends; around a circle from +x, in [0, 2πR)."""
        d = np.asarray(points, float).reshape(-1, 2) - self.origin
        if self.radius is None:
            return np.clip(d @ self.direction, self.start, self.start + self.step * (self.count - 1))
        return (np.arctan2(d[:, 1], d[:, 0]) % (2 * np.pi)) * self.radius

    def nodes(self) -> np.ndarray:
        """The nodes' positions (M, 2)."""
        s = self.start + self.step * np.arange(self.count)
        if self.radius is None:
            return self.origin + s[:, None] * self.direction
        angle = s / self.radius
        return self.origin + self.radius * np.column_stack([np.cos(angle), np.sin(angle)])

    def hats(self, points: np.ndarray) -> sp.csr_matrix:
        """``Ψ`` (m × M): each P1 hat of the chain at the points."""
        s = (self.arclength(points) - self.start) / self.step
        last = self.count - 1 if self.period is None else self.count
        k = np.clip(np.floor(s).astype(np.int64), 0, last - 1)
        a = s - k
        m = len(s)
        cols = np.concatenate([k, (k + 1) % self.count if self.period is not None else k + 1])
        return sp.csr_matrix((np.concatenate([1.0 - a, a]), (np.tile(np.arange(m), 2), cols)),
                             shape=(m, self.count))


def multiplier_chain(interface, domain, spacing: float, method: str) -> MultiplierChain:
    """The multiplier nodes of Γ at about ``spacing`` (module doc): a
    straight Γ's chord split into ``max(1, round(length/spacing))`` equal
    intervals, its ends nodes; a circle wholly inside the domain into
    ``max(3, round(2πR/spacing))``, periodic.  Any other Γ (a circle that
    leaves the domain, a general level set) is refused, naming ``method``."""
    if isinstance(interface, LineInterface):
        direction = tangent_of(np.asarray([interface.normal], float))[0]
        origin = np.asarray(interface.point, float)
        s0, s1 = sorted((interface.chord(domain) - origin) @ direction)
        count = max(1, int(round((s1 - s0) / spacing)))
        return MultiplierChain(float(s0), float(s1 - s0) / count, count + 1, None, origin, direction)
    if isinstance(interface, CircleInterface) and \
            float(domain.distance_to_boundary(np.asarray([interface.centre], float))[0]) > interface.radius:
        period = 2 * np.pi * interface.radius
        count = max(3, int(round(period / spacing)))
        return MultiplierChain(0.0, period / count, count, period, np.asarray(interface.centre, float),
                               np.zeros(2), float(interface.radius))
    raise DiscretisationError(f'{method}: flux = "reaction" takes a straight Γ or a circle inside the domain '
                              '(its multiplier nodes are placed by arclength); use flux = "stress"')


def multiplier_operator(operator: InterfaceOperator, A: sp.csr_matrix, fixed: np.ndarray, chain: MultiplierChain,
                        method: str) -> InterfaceOperator:
    """The interface at ``chain``'s nodes with the least-squares reaction as
    flux (module doc), from the method's Gauss-point ``operator`` (with its
    ``stabilisation``), the bulk's assembled ``A`` (scipy, n × n: for efgm
    the augmented matrix) and its prescribed unknowns ``fixed``."""
    psi = chain.hats(operator.points)
    D = psi.T @ operator.weights
    B = (sp.kron(psi, sp.identity(2), format="csr").T @ sp.diags(np.repeat(operator.weights, 2)) @ operator.G).tocsr()
    free = np.setdiff1d(np.arange(A.shape[0]), np.asarray(fixed, np.int64))
    nodes = chain.nodes()
    kept = _kept_rows(B[:, free])
    L = _least_squares(B[:, free], kept, free, A.shape[0], nodes, method)
    G = (sp.diags(kept / np.repeat(D, 2)) @ B).tocsr()
    gamma0 = (psi.T @ (operator.weights * operator.stabilisation)) / D
    return InterfaceOperator(G, D, nodes, None, S=(L @ A).tocsr(), stabilisation=gamma0,
                             pieces=piece_centres(nodes, D, [1] * len(D)), load_flux=L)


def _kept_rows(Bf: sp.csr_matrix) -> np.ndarray:
    """(2M,) 1.0 for a row of ``B_f`` that takes part in the law, 0.0 for
    one whose norm is within :data:`~contactcore.tolerances.REACTION_ROW_ZERO`
    of the largest (its component held on both sides)."""
    norms = np.sqrt(np.asarray(Bf.multiply(Bf).sum(axis=1)).ravel())
    return (norms > tol.REACTION_ROW_ZERO * np.max(norms, initial=0.0)).astype(float)


def _least_squares(Bf: sp.csr_matrix, kept: np.ndarray, free: np.ndarray, n: int, nodes: np.ndarray,
                   method: str) -> sp.csr_matrix:
    """``L = −(B_f B_fᵀ)⁻¹ B_f P_f`` (2M × n) on the ``kept`` rows, zero on
    the others; refused where ``B_f B_fᵀ`` is rank-deficient: its smallest
    eigenvalue, scaled by its diagonal (Jacobi), below
    :data:`~contactcore.tolerances.REACTION_RANK` of its largest, naming
    a node of the undetermined multipliers (:func:`_first_undetermined`)."""
    rows = np.flatnonzero(kept)
    Bs = Bf[rows]
    used = np.unique(Bs.indices)  # the free unknowns Γ's jumps read
    Bk = Bs[:, used].toarray()
    BB = Bk @ Bk.T
    scale = 1.0 / np.sqrt(np.diag(BB))
    values, vectors = np.linalg.eigh(scale[:, None] * BB * scale[None, :])
    null = vectors[:, values < tol.REACTION_RANK * np.max(values, initial=0.0)]
    if null.shape[1]:
        x, y = nodes[rows[_first_undetermined(null)] // 2]
        raise DiscretisationError(
            f'{method}: flux = "reaction": the multipliers on Γ are not determined near ({x:.6g}, {y:.6g}): the '
            f'jumps there cannot tell them apart (B_f B_fᵀ, scaled by its diagonal, has eigenvalues below '
            f'{tol.REACTION_RANK:g} of its largest); use flux = "stress"')
    inverse = -np.linalg.solve(BB, Bk)
    return sp.csr_matrix((inverse.ravel(), (np.repeat(rows, len(used)), np.tile(free[used], len(rows)))),
                         shape=(len(kept), n))


def _first_undetermined(null: np.ndarray) -> int:
    """The first row (along Γ) that the near-null space ``null`` (columns
    orthonormal) weighs at least half as much as its heaviest: the
    projector's diagonal ``diag(V Vᵀ)``, the same for any basis of that
    space, so round-off's choice of eigenvectors does not choose the node."""
    weight = np.sum(null * null, axis=1)
    return int(np.flatnonzero(weight >= 0.5 * np.max(weight))[0])


def serial_refusal(method: str) -> str:
    """Why ``method``'s reaction flux is refused under mpirun (one line)."""
    return (f'{method}: flux = "reaction" runs on one process only (Γ\'s multipliers read the assembled rows of '
            'every unknown near Γ, which one rank need not hold): run it without mpirun, or use flux = "stress"')


def check_serial(method: str, flux: str, law, ranks: int) -> None:
    """Refuse ``flux="reaction"`` for an exactly enforced ``law`` on more
    than one rank (:func:`serial_refusal`), before any mesh is built."""
    if flux == "reaction" and is_exact(law) and ranks > 1:
        raise DiscretisationError(serial_refusal(method))
