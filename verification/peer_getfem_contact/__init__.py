"""GetFEM's own contact bricks: an independent peer of our exact contact.

Our exact laws (``enforcement = "exact"``) are enforced by Nitsche's method
(docs/contact-enforcement.md).  This module solves the same scene with a
different formulation in a different code, GetFEM 5.4 (Debian's
``python3-getfem``): Lagrange multipliers on Γ with Alart and Curnier's
augmented Lagrangian (Alart & Curnier, CMAME 92, 1991; Renard, CMAME 256,
2013, for the integral form GetFEM implements).  Only the studies import it;
a missing GetFEM is a clear error.

The model, in GetFEM's own terms:

* the − and the + body are two GetFEM meshes, from the same gmsh model as
  our fe method (:func:`meshes.build.build_model`): triangles of size h,
  geometry of the elements' degree (curved on a circle at degree 2), the
  two meshes conforming along Γ but separate objects, so each body has its
  own displacement ``u1`` (−) and ``u2`` (+), ``FEM_PK(2, k)``;
* ``add_integral_contact_between_nonmatching_meshes_brick``, option 1 (the
  non-symmetric Alart–Curnier method): the multiplier λ, the traction on
  the − body, is a ``FEM_PK(2, 1)`` field on the − body's side of Γ; the
  + body's trace is projected onto it.  GetFEM's normal is the − body's
  outward normal, our n; its contact holds where ``λ_N − r (u1 − u2)·n < 0``;
* friction (``coulomb``): GetFEM's quasi-static law acts on the slip
  increment ``(u1 − w1) − (u2 − w2)`` with ``w`` the previous increment's
  displacements (``alpha`` = 1): a point sticks when its jump does not
  move, ``|λ_T| ≤ μ|λ_N|``, and slips against its increment otherwise.
  With multipliers a stick is exact, so the slip accumulated so far is the
  jump itself; this is the slip state our Nitsche law converges to
  (docs/contact-enforcement.md, "The slip state");
* ``unilateral`` (closed points tied, open points free): the same brick
  without a previous displacement and with μ = :data:`TIE_FRICTION`: a
  closed point's total tangential jump is held at zero.  A point that
  slips all the same is refused by name (the tie did not hold);
* edges held by multipliers of degree k (both components, or one at a
  prescribed displacement, as the layered-slip closed form's top), edge
  tractions and pressures as source terms, each increment's factors of
  the loads and supports (:meth:`Scene.factors`), GetFEM's Newton with
  MUMPS.

Sign conventions (docs/scenes.md): λ is the traction on the − body, so
``t_N = λ·n`` (< 0 in compression) and ``t_T = λ·t``, ``t = (n_y, −n_x)``;
``g = (u2 − u1)·(n, t)``.  The interface record (:class:`InterfacePath`)
holds Gauss points of each Γ facet, so profiles report λ's mean over each
facet, as for our exact laws.  Each point's status at an increment is
GetFEM's own test: open where ``λ_N + r g_N ≥ 0``, else stick where
``|λ_T + r Δg_T| ≤ μ (−λ_N − r g_N)``, else slip.

One idea a module, each with its maths and contract:

- :mod:`~verification.peer_getfem_contact.solver`: :func:`solve`, the
  entry point, the increments;
- :mod:`~verification.peer_getfem_contact.reach`: what the peer covers
  (:data:`METHOD`, ``_check``);
- :mod:`~verification.peer_getfem_contact.bodies`: the two bodies' meshes
  from gmsh, their spaces, Γ's multiplier space (:data:`MULTIPLIER_DEGREE`,
  :data:`FACE_MATCH`);
- :mod:`~verification.peer_getfem_contact.bricks`: the model's bricks,
  the Alart–Curnier contact, supports and loads per increment
  (:data:`AUGMENTATION`, :data:`TIE_FRICTION`);
- :mod:`~verification.peer_getfem_contact.newton`: GetFEM's Newton judged
  by the residual in force units (:data:`NEWTON_RESIDUAL`,
  :data:`NEWTON_ITERATIONS`, :data:`LINEAR_SOLVER`);
- :mod:`~verification.peer_getfem_contact.gamma`: Γ's Gauss points, the
  jump, traction and status there (:data:`FACET_POINTS`);
- :mod:`~verification.peer_getfem_contact.fields`:
  :class:`GetFEMContactFields`, the answer at points;
- :mod:`~verification.peer_getfem_contact.scenes`: the study's scenes
  (:data:`STUDIES`, :func:`exact_scene`, :data:`WEDGE`,
  :data:`INCLINED_A`, :data:`WEDGE_SLIP`);
- :mod:`~verification.peer_getfem_contact.comparison`: GetFEM's answer
  against ours (:class:`Difference`, :func:`differences`,
  :func:`status_split`, :func:`path_means`);
- :mod:`~verification.peer_getfem_contact.runs`: the study over h
  (:func:`study`, :func:`check_sizes`);
- :mod:`~verification.peer_getfem_contact.tables`: its tables
  (:func:`markdown`);
- ``__main__``: the command line (:func:`main`).

The arrows: ``__main__`` → ``runs``, ``scenes``, ``tables``; ``runs`` →
``solver``, ``comparison``, ``scenes``; ``solver`` → ``reach``,
``bodies``, ``bricks``, ``newton``, ``gamma``, ``fields``; ``bricks``,
``gamma``, ``fields`` → ``bodies``; ``gamma`` → ``fields``; ``newton``,
``scenes``, ``runs`` → ``reach``.

The package's public names, imported here as
``verification.peer_getfem_contact.NAME`` as they were when it was one
module, are those listed above.  Private names imported here too,
because the tests and docs/peer-contact.md reach them as
``peer_getfem_contact.NAME``: ``_check``, ``_edge_traction``,
``_facet_points``, ``_Gamma`` and ``_table``.  A setting is read where it
lives: to vary one (``AUGMENTATION``, say), set it in its module
(``peer_getfem_contact.bricks.AUGMENTATION = 10.0``); setting the name
imported here changes nothing.  :func:`main` is imported from
``__main__`` on first use (``peer_getfem_contact.main``, or ``from
verification.peer_getfem_contact import main``): imported here at once,
``python -m verification.peer_getfem_contact`` would find its own
``__main__`` imported before running it, and runpy warns.
"""
from .bodies import FACE_MATCH, MULTIPLIER_DEGREE
from .bricks import AUGMENTATION, TIE_FRICTION, _edge_traction  # noqa: F401  (the tests' check)
from .comparison import Difference, differences, path_means, status_split
from .fields import GetFEMContactFields
from .gamma import FACET_POINTS, _facet_points, _Gamma  # noqa: F401  (the tests' checks)
from .newton import LINEAR_SOLVER, NEWTON_ITERATIONS, NEWTON_RESIDUAL
from .reach import METHOD, _check  # noqa: F401  (the tests' check)
from .runs import check_sizes, study
from .scenes import INCLINED_A, STUDIES, WEDGE, WEDGE_SLIP, exact_scene
from .solver import solve
from .tables import _table, markdown  # noqa: F401  (docs/peer-contact.md's script)


def __getattr__(name: str):
    """``main``, the command line, imported from ``__main__`` on first use."""
    if name == "main":
        from .__main__ import main
        return main
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = [
    # solver
    "solve",
    # reach
    "METHOD",
    # bodies
    "MULTIPLIER_DEGREE", "FACE_MATCH",
    # bricks
    "AUGMENTATION", "TIE_FRICTION",
    # newton
    "NEWTON_RESIDUAL", "NEWTON_ITERATIONS", "LINEAR_SOLVER",
    # gamma
    "FACET_POINTS",
    # fields
    "GetFEMContactFields",
    # scenes
    "STUDIES", "exact_scene", "WEDGE", "INCLINED_A", "WEDGE_SLIP",
    # comparison
    "Difference", "differences", "status_split", "path_means",
    # runs
    "study", "check_sizes",
    # tables
    "markdown",
    # __main__
    "main",
]
