"""XFEM's global matrix and load vectors: away from the band dolfinx
assembles the standard elasticity from UFL on V; the band cells are added
by the kernels of :mod:`xdolfinx.xfem.kernels` into the same PETSc matrix
(``setValuesBlockedLocal``), after dolfinx_mpc's habit of extending dolfinx
rather than replacing it."""
from __future__ import annotations

import numpy as np
import ufl
from dolfinx import fem, mesh
from dolfinx.fem import petsc as fem_petsc
from petsc4py import PETSc

from contactcore import BODIES
from contactcore import tolerances as tol
from contactcore.scene import EDGE, place_of

from ..elasticity import load_integrand, sigma, vanishes
from .kernels import band_kernels, band_loads
from .space import EnrichedFunctionSpace

_TAG_UNCUT = {"minus": 1, "plus": 2}
_TAG_BAND = 3


def stiffness_matrix(space: EnrichedFunctionSpace, bulk) -> PETSc.Mat:
    """The bulk stiffness: dolfinx's assembly of ``bulk`` (the UFL form of
    the cells outside the band) plus the band kernels, in one matrix."""
    A = space.create_matrix()
    fem_petsc.assemble_matrix(A, bulk)
    for blocks, K in band_kernels(space, space.scene.voigt_matrices()):
        A.setValuesBlockedLocal(blocks.astype(PETSc.IntType), blocks.astype(PETSc.IntType), np.ascontiguousarray(K),
                                addv=PETSc.InsertMode.ADD_VALUES)
    A.assemble()
    return A


def tags(space: EnrichedFunctionSpace):
    """Cell tags (uncut −, uncut +, band) and boundary-facet tags by name for
    facets whose cell is outside the band (the band's are the kernels')."""
    import meshes

    msh, scene, num_cells = space.msh, space.scene, space.cells.num_cells
    values = np.where(space.cut.cell_side > 0, _TAG_UNCUT["plus"], _TAG_UNCUT["minus"]).astype(np.int32)
    values[space.band] = _TAG_BAND
    cell_tags = mesh.meshtags(msh, 2, np.arange(num_cells, dtype=np.int32), values)
    msh.topology.create_connectivity(1, 2)
    f2c = msh.topology.connectivity(1, 2)
    in_band = np.zeros(num_cells, bool)
    in_band[space.band] = True
    facets, names = [], []
    tol_L = tol.NODE_MATCH * scene.length_scale
    for name in scene.domain.boundary_names:
        found = mesh.locate_entities_boundary(msh, 1, lambda x, name=name: scene.domain.on_boundary(name, x[:2].T, tol_L))
        keep = [f for f in found if not in_band[f2c.links(f)[0]]]
        facets += keep
        names += [meshes.BOUNDARY[name]] * len(keep)
    order = np.argsort(facets)
    facet_tags = mesh.meshtags(msh, 1, np.asarray(facets, np.int32)[order], np.asarray(names, np.int32)[order])
    return cell_tags, facet_tags


def _equispaced_geometry(msh) -> None:
    """Give ``msh``'s UFL domain the coordinate element ffcx 0.5 gives it
    when it first compiles a form on it (the equispaced variant of the same
    Lagrange element; ffcx.analysis replaces it in place).  The replacement
    changes the domain's hash, so a form whose domains UFL had numbered
    before it got a signature of its own: the xfem load form of the second
    scene of a study compiled anew though only values differed.  A mesh
    from gmsh (fe's) has that element from the start."""
    domain = msh.ufl_domain()
    element = domain.ufl_coordinate_element()
    if element.sub_elements()[0].variant() is None:
        sub = ufl.FiniteElement(element.family(), element.cell(), element.degree(), element.quadrature_scheme(),
                                variant="equispaced")
        domain._ufl_coordinate_element = ufl.VectorElement(sub)


def ufl_forms(space: EnrichedFunctionSpace, cell_tags, facet_tags):
    """Bulk stiffness and one linear form per load for the cells outside the
    band, in UFL, on the standard part V; None for a load of value zero
    (:func:`~xdolfinx.elasticity.vanishes`).  Material and load values
    enter as Constants, so their compiled code depends on the structure
    only (:mod:`xdolfinx.elasticity`)."""
    import meshes

    scene, msh, V = space.scene, space.msh, space.V
    _equispaced_geometry(msh)
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    dx = ufl.Measure("dx", domain=msh, subdomain_data=cell_tags)
    ds = ufl.Measure("ds", domain=msh, subdomain_data=facet_tags)
    a = sum(ufl.inner(sigma(u, scene.materials[b].E, scene.materials[b].nu, scene.plane),
                      ufl.sym(ufl.grad(v))) * dx(_TAG_UNCUT[b]) for b in BODIES)
    linear = []
    for load in scene.loads:
        if vanishes(scene, load):
            linear.append(None)
            continue
        where = ds(meshes.BOUNDARY[load.boundary]) if place_of(load) == EDGE \
            else dx(_TAG_UNCUT[load.body])
        linear.append(load_integrand(scene, load, msh, v) * where)
    return a, linear


def forms(space: EnrichedFunctionSpace, cell_tags, facet_tags):
    """:func:`ufl_forms` compiled (dolfinx forms; None for a load of value zero)."""
    a, linear = ufl_forms(space, cell_tags, facet_tags)
    return fem.form(a), [None if L is None else fem.form(L) for L in linear]


def load_vector(space: EnrichedFunctionSpace, L, load) -> np.ndarray:
    """One load's vector on the owned unknowns: UFL outside the band (V's
    part), the kernels on the band cells this rank owns, each summed onto
    the owners of its rows."""
    local = np.zeros(2 * space.num_blocks)
    for blocks, f in band_loads(space, load):
        index = (2 * blocks[:, None] + np.arange(2)).ravel()
        keep = np.repeat(blocks >= 0, 2)
        np.add.at(local, index[keep], f[keep])
    out = space.exchange.reverse(local)
    if L is None:  # a load of value zero
        return out
    b = fem_petsc.assemble_vector(L)
    b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    out[:b.getLocalSize()] += b.getArray()
    b.destroy()
    return out
