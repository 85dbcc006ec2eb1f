"""Moving-least-squares shape functions (the paper's §VII, Eqs. 19–23; EFG:
Belytschko, Lu & Gu, "Element-free Galerkin methods", IJNME 37, 1994).

For a point ``x`` with neighbours ``I`` (nodes whose support holds ``x``),

    Φ_I(x) = p̃(x)ᵀ A(x)⁻¹ p̃(x_I) w_I(x),   A(x) = Σ_I w_I(x) p̃(x_I) p̃(x_I)ᵀ,

with the monomial basis of degree 1 (``1, ξ, η``) or 2 (``… ξ², ξη, η²``)
*shifted and scaled* at the evaluation point, ``p̃(y) = p((y − x̄)/s)``,
``x̄ = x`` and ``s`` the largest support radius among the neighbours, so that
the moment matrix stays well conditioned whatever the node spacing.  The
shape functions do not depend on ``x̄``; derivatives are taken with ``x̄``
held fixed: with ``γ = A⁻¹ p̃(x)``,

    ∂Φ_I = (∂γ)ᵀ p̃_I w_I + γᵀ p̃_I ∂w_I,   ∂γ = A⁻¹ (∂p̃(x) − ∂A γ),
    ∂A = Σ_I ∂w_I p̃_I p̃_Iᵀ.

*Visibility* (Belytschko et al. 1996, the criterion cut at Γ): with
``seen_from`` (N, 2), node I takes part in the MLS fit of body b only where
``seen_from[I, b]``; a point of body b then has the shape functions of the
nodes body b sees, which reproduce the basis in b on their own and are
smooth up to Γ from b's side.  Without it (or without bodies) every node is
seen everywhere.

Weights ``w(r)``: the cubic spline and the quartic spline of Belytschko et
al. (1994), on circular supports (``r = |x − x_I| / r_I``) or rectangular ones
(``w(r_x) w(r_y)``).  Everything is vectorised over points; neighbours come
from buckets of candidates found with ``scipy.spatial.cKDTree``.

One idea a module, each with its maths and contract:

- :mod:`~efgm.shape.mls`: :class:`MLS`, the one class a node set's shape
  functions are, made of the mixins below;
- :mod:`~efgm.shape.weights`: the cubic and quartic splines
  (:data:`WEIGHTS`) and each neighbour's ``w``, ``∇w``;
- :mod:`~efgm.shape.basis`: the monomials, shifted and scaled, and the
  change of basis between two centres (:func:`basis_size`);
- :mod:`~efgm.shape.neighbours`: the nodes whose support holds a point,
  by buckets of candidates (:data:`BUCKET`, :data:`BUCKETS_PER_NODE`,
  :data:`RADIUS_CLASS_RATIO`);
- :mod:`~efgm.shape.evaluation`: Φ and ∇Φ at points (:class:`ShapeValues`),
  the linear basis in closed form;
- :mod:`~efgm.shape.cells`: Φ and ∇Φ at groups of points, the moments
  summed once per group;
- :mod:`~efgm.shape.moments`: the moment matrix, its inverse (no LAPACK)
  and its regularity;
- :mod:`~efgm.shape.refusal`: a singular moment matrix refused by name
  (too few nodes, on one line, a body thinner than the spacing);
- :mod:`~efgm.shape.parallel`: points in chunks over threads
  (:data:`CHUNK`, :data:`POINT_CHUNK`, :func:`threads`,
  :func:`parallel_map`) and one BLAS call at a time (:func:`matmul`).

The arrows: ``mls`` → ``neighbours``, ``weights``, ``evaluation``,
``cells``, ``moments``, ``refusal``, ``basis``; ``evaluation`` →
``moments``, ``parallel``; ``cells`` → ``basis``, ``moments``,
``parallel``.  ``MLS`` is one class made of the mixins (each module's
``_Name``), which share its attributes as each module's contract lists
them.

The package's public names, imported here as ``efgm.shape.NAME`` as they
were when it was one module, are those listed above; the private helpers
stay in their homes.
"""
from .basis import basis_size
from .evaluation import ShapeValues
from .mls import MLS
from .neighbours import BUCKET, BUCKETS_PER_NODE, RADIUS_CLASS_RATIO
from .parallel import CHUNK, POINT_CHUNK, matmul, parallel_map, threads
from .weights import WEIGHTS, cubic_spline, quartic_spline

__all__ = [
    # mls
    "MLS",
    # weights
    "WEIGHTS", "cubic_spline", "quartic_spline",
    # basis
    "basis_size",
    # neighbours
    "BUCKET", "BUCKETS_PER_NODE", "RADIUS_CLASS_RATIO",
    # evaluation
    "ShapeValues",
    # parallel
    "CHUNK", "POINT_CHUNK", "matmul", "parallel_map", "threads",
]
