"""The dolfinx methods' typed options (:mod:`contactcore.discretisation`).

Plain dataclasses: importing this module imports no dolfinx, so a driver
checks a method's options before paying for its libraries; ``build``
imports the method's module (:attr:`~contactcore.discretisation.Discretisation.module`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from contactcore import tolerances as _tol
from contactcore.bodies import symbol_of
from contactcore.discretisation import Discretisation, check_choice, check_degree
from contactcore.reaction_flux import FLUXES

#: The background cells of XFEM: structured quadrilaterals (the paper's),
#: structured triangles, or gmsh triangles (used for a disc).
XFEM_CELLS = ("quad", "triangle", "gmsh")

#: fe's flux of an exactly enforced law (Nitsche's consistent traction τ):
#: ``"stress"`` the cells' weighted-average stress at Γ's Gauss points,
#: ``"reaction"`` the nodal reaction at Γ's nodes (xdolfinx.nodal), whose
#: answer is the node-to-node multipliers' at every β (under mpirun the
#: cells within two layers of Γ on one rank, xdolfinx.gamma_partition).
FE_FLUXES = ("stress", "reaction")


def refinement(reach: float) -> str:
    """What to do where a body reaches at most ``reach`` of a cell's
    diameter from Γ, less than ``SLIVER_EVAL_DEPTH`` needs: the factor to
    divide h by, or, where it does not reach into any cell, that Γ only
    grazes it (xfem's two refusals of an unresolved body)."""
    return (f"divide h by about {_tol.SLIVER_EVAL_DEPTH / reach:.3g} or more" if reach > 0
            else "Γ only grazes it")


@dataclass(frozen=True)
class FE(Discretisation):
    """The conforming reference (:mod:`xdolfinx.conforming`): P``degree``
    triangles on a mesh that follows Γ; ``geometry_order`` defaults to the
    degree (second-order cells on a curved Γ); ``grading`` refines toward
    Γ (:class:`meshes.Grading`); ``petsc_options`` override the MUMPS
    defaults; the condition estimate runs only with ``estimate_condition``;
    ``comm`` defaults to ``MPI.COMM_WORLD``.

    ``mesh``: a gmsh file of the scene's mesh in the scene's units (a path)
    with the physical groups of :mod:`meshes.tags` by name, instead of
    fe's own mesh: it fixes the cells, their geometry order and the
    run's h (its largest cell diameter, :mod:`meshes.read`), so it takes
    no ``grading``, ``geometry_order`` or ``h``; it is checked against
    the scene before anything is built (:func:`meshes.read.check_mesh`).

    ``flux`` (:data:`FE_FLUXES`): an exactly enforced law's Nitsche flux,
    ``"stress"`` (default: the cells' stress at Γ's Gauss points) or
    ``"reaction"`` (Nitsche's points at Γ's nodes and each node's reaction
    as flux, :mod:`xdolfinx.nodal`: the answer does not move with β; under
    mpirun the cells within two layers of Γ are kept on one rank,
    :mod:`xdolfinx.gamma_partition`; no part in a penalty law's answer)."""

    degree: int = 1
    geometry_order: int | None = None
    grading: object = None
    mesh: object = None
    flux: str = "stress"
    petsc_options: dict | None = None
    estimate_condition: bool = False
    jit_params: dict | None = None
    comm: object = None

    name: ClassVar[str] = "fe"
    module: ClassVar[str] = "xdolfinx.conforming"
    paper_grid: ClassVar[str] = "xfem_cells"
    field_output: ClassVar[str] = "mesh"
    distributed: ClassVar[bool] = True
    # one field per body, each over the whole fitted mesh (contactcore.budget)
    field_copies: ClassVar[int] = 2
    about: ClassVar[str] = ("conforming P1/P2 triangles on a gmsh mesh that follows Γ, one field per body; at P1 "
                            "its stress is each cell's own constant (the reference is fe P2)")
    # where a coarser map pays (Discretisation.coarse_map_min_unknowns):
    # exact C-coulomb's solve in one warm process, the map's CPU over the
    # search's from every point sticking (medians of 7 pairs, P2 5;
    # OMP_NUM_THREADS=1, 2026-11-29): P1 1.11, 1.02, 1.13, 1.01, 0.95 at
    # 6 018, 9 256, 11 460, 16 290, 23 178 unknowns; P2 1.08, 0.83, 0.93
    # at 6 294, 12 454, 23 438 (its gmsh build is a P1 run's larger share)
    coarse_map_from: ClassVar[dict[int, int]] = {1: 18_000, 2: 9_000}

    def __post_init__(self):
        check_degree(self.name, self.degree)
        check_choice(self.name, "flux", self.flux, FE_FLUXES)
        if self.mesh is not None:
            import os

            from contactcore import DiscretisationError
            if not isinstance(self.mesh, (str, os.PathLike)) or not str(self.mesh).strip():
                raise DiscretisationError(f"fe: mesh must name a mesh file (got {self.mesh!r})")
            for option in ("grading", "geometry_order"):
                if getattr(self, option) is not None:
                    raise DiscretisationError(f"fe: {option} means nothing with mesh= (the file {self.mesh} fixes "
                                              "the cells and their geometry order): give one of the two")

    def mesh_file(self):
        """The file of ``mesh`` read (:func:`meshes.read.read_mesh_file`), or None."""
        if self.mesh is None:
            return None
        from meshes.read import read_mesh_file
        return read_mesh_file(self.mesh)

    def resolution(self, scene, h, paper):
        """The one rule's (:func:`contactcore.discretisation.resolution`),
        or with ``mesh`` the file's own h (its largest cell diameter) in
        the dimensionless ``scene``'s unit: an ``h`` or the paper's grid
        beside it is refused by name."""
        if self.mesh is None:
            return super().resolution(scene, h, paper)
        from contactcore import DiscretisationError
        from contactcore.discretisation import Resolution
        from contactcore.scaling import Scales, decimal_quotient
        if paper or h is not None:
            raise DiscretisationError(f"fe: the mesh {self.mesh} fixes the resolution (h is its largest cell "
                                      f"diameter): give no {'paper grid' if paper else 'h'} with it")
        return Resolution(decimal_quotient(self.mesh_file().h, Scales.of(scene.user).length))

    def mesh_warnings(self, scene) -> list[str]:
        """The checks of ``mesh`` against the dimensionless ``scene``'s
        user scene (:func:`meshes.read.check_mesh`): a refusal naming the
        problem, or the warnings of a mesh that solves."""
        from meshes.read import check_mesh
        return check_mesh(scene.user, self.mesh_file(), self.degree)

    def check_spacing(self, scene, resolution) -> None:
        """With ``mesh``: a resolution other than the file's refused (a
        coarser solve's first map, :mod:`contactcore.newton.guess`, has
        no coarser mesh of the file: it is not taken), then the file held
        to the scene before anything is built (:meth:`mesh_warnings`)."""
        if self.mesh is None:
            return
        from contactcore import DiscretisationError
        own = self.resolution(scene, None, False)
        if resolution != own:
            raise DiscretisationError(f"fe: the mesh {self.mesh} has one resolution, h = {own.h:g} (dimensionless)")
        self.mesh_warnings(scene)

    def spacing_warnings(self, scene, h: float) -> list[str]:
        """P1's exactly enforced Γ traction near incompressibility
        (:func:`contactcore.health.traction_locking_warnings`: fe's, whose
        Γ traction is σ(u)·n of its own P1 field)."""
        from contactcore import health
        return health.traction_locking_warnings(scene, self.degree)

    def check(self, scene) -> None:
        """Refuse, before anything is built, a body thinner than a fitted
        mesh can hold (:func:`contactcore.scene.check_fitted_thickness`):
        gmsh failed on it with a message about a curve, or lost Γ."""
        from contactcore.scene import check_fitted_thickness
        super().check(scene)
        if self.mesh is None:  # a given mesh is held to the scene by check_spacing instead
            check_fitted_thickness(scene)


@dataclass(frozen=True)
class XFEM(Discretisation):
    """Heaviside-enriched P``degree`` (:mod:`xdolfinx.xfem`) on a mesh that
    ignores Γ, of ``cell`` (:data:`XFEM_CELLS`); ``gauss`` points per
    direction of a cut cell's sub-cells (default by degree); ``flux``
    (:data:`~contactcore.reaction_flux.FLUXES`) an exactly enforced law's
    Nitsche flux, ``"stress"`` (default: the cut cells' stress at Γ's
    Gauss points) or ``"reaction"`` (a multiplier mesh on Γ and the
    least-squares reaction, :mod:`contactcore.reaction_flux`: the answer
    does not move with β; under mpirun the cells near Γ on one rank,
    :mod:`xdolfinx.reaction`); the rest as :class:`FE`."""

    degree: int = 1
    cell: str = "quad"
    gauss: int | None = None
    flux: str = "stress"
    petsc_options: dict | None = None
    estimate_condition: bool = False
    comm: object = None

    name: ClassVar[str] = "xfem"
    module: ClassVar[str] = "xdolfinx.xfem"
    paper_grid: ClassVar[str] = "xfem_cells"
    level_set: ClassVar[bool] = True
    field_output: ClassVar[str] = "mesh"
    distributed: ClassVar[bool] = True
    about: ClassVar[str] = ("P1/P2 on a grid that ignores Γ, Heaviside-enriched where Γ cuts a cell; at P1 its stress "
                            "is recovered by patches (a degree higher than the cells' own)")
    # where a coarser map pays (as FE's): P1 1.14, 1.06, 1.04, 0.88, 0.89
    # at 5 274, 6 432, 8 112, 9 968, 14 208 unknowns; P2 1.22, 0.93, 0.94
    # at 5 434, 10 890, 20 418
    coarse_map_from: ClassVar[dict[int, int]] = {1: 9_000, 2: 9_000}

    def __post_init__(self):
        check_degree(self.name, self.degree)
        check_choice(self.name, "cell", self.cell, XFEM_CELLS)
        check_choice(self.name, "flux", self.flux, FLUXES)

    @property
    def recovered_stress(self) -> bool:
        """P1's reported stress is recovered (:mod:`contactcore.recovery`,
        :class:`xdolfinx.xfem.fields.XFEMFields`), not read from the cell:
        it converges one order faster, as the displacement (measured with
        the orders of the other methods, the Richardson effectivity of xfem
        P1's stresses was 3.0-6.2 on the pressurised and twisted rods: a
        rate 2 read as 1).  P2's is its displacement's own."""
        return self.degree == 1

    def _check_snapped_away(self, scene, grid) -> None:
        """Refuse a body across a straight Γ no thicker than XFEM's snap
        distance (:data:`~contactcore.tolerances.XFEM_SNAP` of a cell's
        diameter) on the structured grid ``grid``: the node row beside Γ is
        snapped onto it and the body vanishes, which was refused later as
        "Γ crosses no cell of the mesh" (grader9 #5).  In the words of the
        cut's own refusal of a body thinner than SLIVER_EVAL_DEPTH of a cell."""
        thickness = scene.body_thickness()
        if grid is None or thickness is None:
            return
        import math

        from contactcore import DiscretisationError
        from contactcore import tolerances as tol

        _, steps, _ = grid
        diameter = self.degree * math.hypot(*steps)  # a cell's: degree nodes along each side
        for body, t in thickness.items():
            if t <= tol.XFEM_SNAP * diameter:
                reach = t / diameter
                raise DiscretisationError(
                    f"xfem: no cell resolves body {symbol_of(body)}: it reaches at most {reach:.3g} of a cell's diameter "
                    f"from Γ, within xfem's snap distance ({tol.XFEM_SNAP:g} of it: the nodes beside Γ are moved "
                    f"onto it and the body vanishes; at least {tol.SLIVER_EVAL_DEPTH:g} is needed to evaluate its "
                    f"fields); {refinement(reach)}")

    def check_spacing(self, scene, resolution) -> None:
        """Refuse a pin that is not a node of the structured grid at
        ``resolution`` (:func:`structured_grid`): xfem holds a pin at a node
        only, and its mesh ignores the scene (gmsh's, on a disc or with
        ``cell="gmsh"``, makes every pin a node), so a pin between nodes
        was refused after the mesh was built, after any other method of the
        run had solved (grader6 #5).  Named in the user's units: the pin,
        the h, the grid and the nearest node."""
        grid = structured_grid(scene, self.cell, self.degree, resolution)
        self._check_snapped_away(scene, grid)
        if grid is None or not scene.pins:
            return
        import math

        from contactcore import DiscretisationError
        from contactcore import tolerances as tol
        from contactcore.scaling import Scales

        corner, steps, nodes = grid
        user, L = scene.user, Scales.of(scene.user).length
        for i, pin in enumerate(scene.pins):
            nearest = [c + min(max(round((x - c) / d), 0), n) * d for x, c, d, n in zip(pin.point, corner, steps, nodes)]
            gap = math.hypot(pin.point[0] - nearest[0], pin.point[1] - nearest[1])
            if gap > tol.NODE_MATCH * scene.length_scale:
                unit = user.units.length
                x, y = user.pins[i].point
                h = "the paper's grid" if resolution.counts is not None else f"h = {resolution.h * L:g} {unit}"
                raise DiscretisationError(
                    f"pins[{i}]: ({x:g}, {y:g}) {unit} is not a node of xfem's grid at {h} ({self.cell} cells, "
                    f"degree {self.degree}: nodes every {steps[0] * L:g} × {steps[1] * L:g} {unit} from the "
                    f"domain's corner); the nearest is {gap * L:.3g} {unit} away, and xfem holds a pin at a node "
                    "only: put the pin on a node at every h the run solves, or use gmsh's cells (--cell gmsh), "
                    "whose mesh makes the pin a node, or fe or efgm")


def cell_counts(scene, h: float) -> list[int]:
    """Cells per side of xfem's structured mesh of the rectangle with
    cells of size ≈ h (:func:`xdolfinx.xfem.cells.background_mesh` builds
    it; :meth:`XFEM.check_spacing` predicts its nodes before any mesh)."""
    return [max(1, round(s / h)) for s in scene.domain.size]


def structured_grid(scene, cell: str, degree: int, resolution):
    """XFEM's nodes on a rectangle of structured ``cell`` cells at
    ``resolution``, as ``(corner, steps, counts)``: the nodes are
    ``corner + j·steps`` for ``j = 0 … counts`` per direction (the cells'
    vertices at degree 1; at degree 2 also the mid-sides and, of a quad,
    its centre: half the cell); None on gmsh's mesh (a disc, or
    ``cell="gmsh"``), which does not follow this rule.  Cells per side by
    :func:`cell_counts`."""
    from contactcore.geometry import Rectangle

    if cell == "gmsh" or not isinstance(scene.domain, Rectangle):
        return None
    cells = resolution.counts or cell_counts(scene, resolution.h)
    nodes = [degree * n for n in cells]
    return tuple(scene.domain.corner), [s / n for s, n in zip(scene.domain.size, nodes)], nodes
