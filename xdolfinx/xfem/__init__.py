"""The extended finite element method ("xfem"), the paper's §VI (Eqs. 8–18).

A mesh of the outer domain that ignores Γ (structured triangles or
quadrilaterals, or gmsh triangles of a disc); Γ is the scene's level set.
The displacement is

    u(x) = Σ_I N_I(x) u_I + Σ_J N_J(x) (H(x) − H(x_J)) a_J,

the shifted Heaviside enrichment of Eq. (8), ``H = +1`` on the + side
(φ ≥ 0), −1 on the − side, on the nodes of the cells Γ cuts.  The jump
across Γ is ``[[u]] = 2 Σ_J N_J a_J`` ("2N̄").

One idea per module, after GetFEM's split of an enriched space
(``MeshFem('levelset')``) from its cut integration (``MeshIm('levelset')``):

- :mod:`.cells`: the background mesh, each node's side of Γ, the Lagrange
  basis of each cell at physical points;
- :mod:`.cut`: the cut integration (regions, Γ's rules, depths, checks);
- :mod:`.space`: the enriched space (which nodes, their numbering, the
  matrix's sparsity);
- :mod:`.kernels`: the band cells' element matrices and loads, the
  interface operator, one Heaviside shift and one stress product;
- :mod:`.assembly`: dolfinx's UFL assembly outside the band, joined with
  the kernels; :mod:`.supports`: the prescribed unknowns;
- :mod:`.fields`: point evaluation and the recovered stress;
- this module: :func:`build`, the method's entry point.
"""
from __future__ import annotations

import numpy as np
from mpi4py import MPI

from contactcore import Result, Scene, Timings
from contactcore import discretisation
from contactcore.constraints import Constraints
from contactcore.discretisation import Built, Resolution, make
from contactcore.exact import is_exact

from ..contact_system import PETScSystem
from ..options import XFEM
from .assembly import forms, load_vector, stiffness_matrix, tags
from .cells import CellBasis, background_cell, background_mesh, cell_counts, node_sides
from .cut import GAUSS_POINTS, CutIntegration
from .fields import XFEMFields
from .kernels import band_kernels, interface_operator, side_strains
from .space import MIN_CUT_FRACTION, EnrichedFunctionSpace
from .supports import support_rows
from ..quiet import quiet_jit
from ..reaction import multiplier_spacing, reaction_interface
from .traction import contrast_warnings, curved_stabilisation_warnings, with_traction

METHOD = XFEM.name

__all__ = ["GAUSS_POINTS", "METHOD", "MIN_CUT_FRACTION", "CellBasis", "CutIntegration", "EnrichedFunctionSpace",
           "XFEMFields", "background_cell", "background_mesh", "band_kernels", "build", "cell_counts",
           "enriched_space", "interface_operator", "node_sides", "side_strains", "solve", "support_rows"]


def enriched_space(msh, degree: int, scene: Scene, gauss: int, **choices) -> EnrichedFunctionSpace:
    """The enriched space of ``scene`` on ``msh``: its cells, their cut
    integration with ``gauss`` points per direction, and the enrichment
    (``choices``: ``enriched``, ``band``, as :class:`EnrichedFunctionSpace`)."""
    cells = CellBasis(msh, degree, scene)
    return EnrichedFunctionSpace(cells, CutIntegration(cells, scene, gauss), **choices)


@quiet_jit
def build(scene: Scene, options: XFEM, resolution: Resolution, timings: Timings) -> Built:
    """The XFEM system of ``scene`` (:class:`~contactcore.discretisation.Discretisation`'s
    ``build``; :class:`xdolfinx.options.XFEM` for the options)."""
    h, degree = resolution.h, options.degree
    comm = MPI.COMM_WORLD if options.comm is None else options.comm
    with timings.measure("mesh"):
        reaction = options.flux == "reaction" and is_exact(scene.law)  # Γ's multipliers, the reaction as flux
        msh = background_mesh(scene, h, options.cell, resolution.counts, comm, order=degree, cut_on_one_rank=reaction)
        space = enriched_space(msh, degree, scene, GAUSS_POINTS[degree] if options.gauss is None else options.gauss)
    with timings.measure("assembly"):
        bulk, loads = forms(space, *tags(space))
        rows, values, owners = support_rows(space)
        K, constraints = stiffness_matrix(space, bulk), Constraints.on_dofs(rows, values, owners, space.cells.ranks)
        interface, work = with_traction(interface_operator(space), space), None
        if reaction:
            interface, work = reaction_interface(scene, K, constraints.dofs, interface,
                                                  multiplier_spacing(options.cell, options.degree, h), space, options.name)
        system = PETScSystem(K, [load_vector(space, L, load) for L, load in zip(loads, scene.loads)], constraints,
                             interface, comm=msh.comm, work=work, petsc_options=options.petsc_options,
                             estimate_condition=options.estimate_condition, what=f"scene {scene.name} (xfem)")
    return Built(system, lambda x: XFEMFields(space, x), 2 * space.numbering.index_map.size_global, h=h,
                 warnings=space.cut.thin_body_warnings() + space.cells.snap_warnings() + contrast_warnings(scene, degree)
                 + curved_stabilisation_warnings(scene, degree), record=_record(space, h, background_cell(scene, options.cell), options.flux))


def _record(space: EnrichedFunctionSpace, h: float, cell: str, flux: str) -> dict:
    """What ran, for the run's summary: the cells, the cut cells, the
    enriched nodes over every rank and the flux of an exact law."""
    ranks, owned = space.cells.ranks, space.cells.owned_cells
    return {"h": h, "cell": cell, "degree": space.degree,
            "cells": ranks.sum(owned), "cut_cells": ranks.sum(sum(c < owned for c in space.cut.regions)),
            "enriched_nodes": ranks.sum(int(np.count_nonzero(space.enriched[:space.cells.owned_nodes]))),
            "gauss": space.cut.gauss, "flux": flux}


def solve(scene: Scene, h: float | None = None, *, paper: bool = False, progress=None, reuse=None,
          **options) -> Result:
    """Solve ``scene`` with XFEM: the contract's
    :func:`contactcore.discretisation.solve` with :class:`xdolfinx.options.XFEM`
    ``(**options)``."""
    return discretisation.solve(scene, make(XFEM, **options), h, paper=paper, progress=progress, reuse=reuse)
