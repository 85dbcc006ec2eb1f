"""GetFEM's model of the scene: elasticity, Alart–Curnier contact, supports, loads.

The bricks, in GetFEM's own terms (GetFEM 5.4's user documentation: the
model object and its bricks, contact with friction):

* isotropic linearised elasticity per body, the Lamé pair of the scene's
  plane stress or strain (:func:`contactcore.elasticity.lame`);
* ``add_integral_contact_between_nonmatching_meshes_brick``, option 1
  (the non-symmetric Alart–Curnier method; Alart & Curnier, CMAME 92,
  1991; Renard, CMAME 256, 2013, for the integral form): the multiplier
  λ, the traction on the − body; the + body's trace projected onto it.
  GetFEM's normal is the − body's outward normal, our n; contact holds
  where ``λ_N − r (u1 − u2)·n < 0``, ``r`` the augmentation
  (:data:`AUGMENTATION` × the larger Young's modulus);
* friction (``coulomb``): GetFEM's quasi-static law acts on the slip
  increment ``(u1 − w1) − (u2 − w2)``, ``w`` the previous increment's
  displacements (``alpha`` = 1): a point sticks when its jump does not
  move, ``|λ_T| ≤ μ|λ_N|``, and slips against its increment otherwise;
  with multipliers a stick is exact, so the slip so far is the jump
  itself, the slip state our Nitsche law converges to
  (docs/contact-enforcement.md, "The slip state");
* ``unilateral`` (closed points tied, open points free): the same brick
  without a previous displacement and with μ = :data:`TIE_FRICTION`;
* edges held by multipliers of degree k (both components, or one at a
  prescribed displacement, as the layered-slip closed form's top), edge
  tractions and pressures as source terms.

Contract: :func:`_bricks` adds every brick at load factor 0;
:func:`_set_loads` sets increment k's factors (:meth:`Scene.factors`) of
the edge tractions and the supports' displacements.  The data names are
``T{i}_{var}`` (load i) and ``D{i}_{var}`` (support i) for ``var`` in
:data:`_Bodies.VARS`, ``w_{var}`` the previous displacements, ``r`` and
``friction`` the augmentation and μ.
"""
from __future__ import annotations

import numpy as np

from contactcore import Scene
from contactcore.elasticity import lame
from contactcore.scene import Pressure
from verification.peer_getfem import EDGE_NORMALS

from .bodies import _GAMMA, _Bodies

#: Alart–Curnier's augmentation r, a multiple of the larger Young's modulus
#: (GetFEM's documentation: "close to the Young modulus").  It moves the
#: discrete answer little (10 E: C-coulomb's C4 t_T by 0.69 % RMS at
#: h = 0.05) and decides whether Newton finds the status map: at E/3 and
#: E/10 it did not on C-coulomb's first increment (docs/peer-contact.md).
AUGMENTATION = 1.0

#: μ standing for "no limit" in the tied law (``unilateral``): a closed
#: point would have to carry a shear 1e6 times its pressure to slip.
TIE_FRICTION = 1e6


def _bricks(gf, md, scene: Scene, bodies: _Bodies, degree: int) -> None:
    """Elasticity per body, the contact brick, clamped edges, tractions at
    factor 0 (set per increment by :func:`_set_loads`)."""
    for body, var in _Bodies.VARS.items():
        md.add_fem_variable(var, bodies.mfu[body])
        mat = scene.materials[body]
        lam, mu = lame(mat.E, mat.nu, scene.plane)
        md.add_initialized_data(f"lambda_{var}", [lam])
        md.add_initialized_data(f"mu_{var}", [mu])
        md.add_isotropic_linearized_elasticity_brick(bodies.mim[body], var, f"lambda_{var}", f"mu_{var}")
        for i, support in enumerate(scene.supports):
            if support.boundary in bodies.edges[body]:
                _support(gf, md, bodies, body, i, support, degree)
        for i, load in enumerate(scene.loads):
            if load.boundary in bodies.edges[body]:
                md.add_initialized_data(f"T{i}_{var}", [0.0, 0.0])
                md.add_source_term_brick(bodies.mim[body], var, f"T{i}_{var}", bodies.edges[body][load.boundary])
    md.add_fem_variable("lambda", bodies.mflambda)
    md.add_initialized_data("r", [AUGMENTATION * max(m.E for m in scene.materials.values())])
    if scene.law.name == "coulomb":
        md.add_initialized_data("friction", [scene.law.mu])
        md.add_initialized_data("alpha", [1.0])
        for var in _Bodies.VARS.values():
            md.add_initialized_fem_data(f"w_{var}", md.mesh_fem_of_variable(var), np.zeros(md.variable(var).size))
        md.add_integral_contact_between_nonmatching_meshes_brick(
            bodies.mim["minus"], "u1", "u2", "lambda", "r", "friction", _GAMMA, _GAMMA, 1, "alpha", "w_u1", "w_u2")
    else:
        md.add_initialized_data("friction", [TIE_FRICTION])
        md.add_integral_contact_between_nonmatching_meshes_brick(
            bodies.mim["minus"], "u1", "u2", "lambda", "r", "friction", _GAMMA, _GAMMA, 1)


def _support(gf, md, bodies: _Bodies, body: str, i: int, support, degree: int) -> None:
    """Support i on one body's part of its edge, by multipliers of degree k:
    both components held (GetFEM's Dirichlet brick), or one, ``u_c = d``
    weakly, ``∫ m v_c + ∫ q (u_c − d) = 0`` for every multiplier q of a
    scalar field on the edge; its value ``D{i}_{var}`` set per increment
    (:func:`_set_loads`)."""
    var, region, mim = _Bodies.VARS[body], bodies.edges[body][support.boundary], bodies.mim[body]
    data = f"D{i}_{var}"
    if support.fix == "xy":
        md.add_initialized_data(data, [0.0, 0.0])
        md.add_Dirichlet_condition_with_multipliers(mim, var, degree, region, data)
        return
    c, mult = "xy".index(support.fix) + 1, f"m{i}_{var}"
    mf = gf.MeshFem(bodies.mesh[body], 1)
    mf.set_fem(gf.Fem(f"FEM_PK(2,{degree})"))
    bodies.keep.append(mf)
    md.add_filtered_fem_variable(mult, mf, region)
    md.add_initialized_data(data, [0.0])
    md.add_linear_term(mim, f"{mult}*Test_{var}({c}) + Test_{mult}*{var}({c})", region)
    md.add_source_term(mim, f"{data}*Test_{mult}", region)


def _edge_traction(load) -> np.ndarray:
    """A load's traction on its edge: a pressure p is ``−p n_out``."""
    if isinstance(load, Pressure):
        return -load.value * np.asarray(EDGE_NORMALS[load.boundary], float)
    return np.asarray(load.value, float)


def _set_loads(md, scene: Scene, bodies: _Bodies, k: int) -> None:
    """Each edge traction and each support's displacement at increment k's
    factor."""
    factors, held = scene.factors(k)
    for body, var in _Bodies.VARS.items():
        for i, (load, f) in enumerate(zip(scene.loads, factors)):
            if load.boundary in bodies.edges[body]:
                md.set_variable(f"T{i}_{var}", f * _edge_traction(load))
        for i, (support, f) in enumerate(zip(scene.supports, held)):
            if support.boundary in bodies.edges[body]:
                md.set_variable(f"D{i}_{var}", [f * support.value["xy".index(c)] for c in support.fix])
