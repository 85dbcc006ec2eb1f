"""The UFL of linear elasticity shared by fe and xfem: the stress, each
load's integrand, and whether a load's form vanishes (no gmsh: an xfem run
on structured cells never imports it).

A load's form is its core formula (``load.field``,
:mod:`contactcore.scene.loads`) written with UFL's coordinates and
normal: no copy of a formula here.  Every number of a scene (E, ν through
λ and μ, a load's coefficients: a traction, a pressure, a body force, a
torque's rate and centre) enters a form as a ``dolfinx.fem.Constant``, never as a Python float: UFL writes a float into
the form's signature and ffcx into the C code, so each new material or load
value compiled new forms (0.3–0.8 s each).  With Constants a form's
compiled code depends on its structure only (elements, integrals, tags,
which kinds of load), and two scenes that differ in values share it.
"""
from __future__ import annotations


import numpy as np
import ufl
from dolfinx import fem

from contactcore.elasticity import lame
from contactcore.scene import BODY, EDGE, place_of
from contactcore.scene.loads import vanishes as _vanishes


def constant(domain, value) -> fem.Constant:
    """``value`` (a number or a tuple of numbers) as a float64 Constant on
    ``domain`` (a dolfinx or UFL mesh)."""
    return fem.Constant(domain, np.asarray(value, dtype=np.float64))


def sigma(w, E: float, nu: float, plane: str):
    """``σ(w) = 2μ ε(w) + λ tr ε(w) I`` with the Lamé constants of ``plane``
    stress or strain, λ and μ as Constants on ``w``'s mesh."""
    domain = ufl.domain.extract_unique_domain(w)
    lam, mu = (constant(domain, c) for c in lame(E, nu, plane))
    eps = ufl.sym(ufl.grad(w))
    return 2.0 * mu * eps + lam * ufl.tr(eps) * ufl.Identity(2)


def _coefficients(scene, load, msh) -> tuple:
    """The numbers ``load``'s formula is made of
    (:meth:`contactcore.scene.loads._Load.coefficients`: a traction or
    body force vector, a pressure, a torque's ``k = T/J`` and Γ's centre),
    each as a Constant on ``msh``."""
    return tuple(constant(msh, c) for c in load.coefficients(scene))


def _vector(field):
    """A formula's vector as UFL: a pair of components as a vector."""
    return ufl.as_vector(field) if isinstance(field, tuple) else field


def vanishes(scene, load) -> bool:
    """Whether ``load`` is of value zero, so that it has no form (dolfinx's
    assembler finds no kernel to call in a form whose integrand is zero).
    Decided from the load's numbers (its parameters of a magnitude,
    :func:`contactcore.scene.loads.vanishes`), not from the form: a
    Constant is never UFL's zero."""
    return _vanishes(load)


def body_force(scene, load, msh):
    """The body force ``b`` of a body load as a UFL vector on ``msh``: the
    core's formula (``load.field``; a torque's
    :func:`contactcore.scene.loads.torque_field`, ``b = k(−(y−y_c),
    x−x_c)``) with its numbers as Constants, so that a new load value needs
    no new kernel."""
    x = ufl.SpatialCoordinate(msh)
    return _vector(load.field(_coefficients(scene, load, msh), x[0], x[1]))


def edge_traction(scene, load, msh):
    """The traction of an edge load as a UFL vector on ``msh``: the core's
    formula (``load.field``: a traction's value, a pressure's ``−p n``, n
    the outward FacetNormal) with its numbers as Constants."""
    x = ufl.SpatialCoordinate(msh)
    return _vector(load.field(_coefficients(scene, load, msh), x[0], x[1], ufl.FacetNormal(msh)))


def load_integrand(scene, load, msh, v):
    """The integrand of ``load``'s linear form against the test function
    ``v`` (a vector on ``msh``): ``t · v`` for an edge load (to be
    integrated over its boundary), ``b · v`` for a body load (over its
    body), by where the load acts (:func:`contactcore.scene.place_of`, which
    refuses an unknown load by name)."""
    kind = place_of(load)
    if kind == EDGE:
        return ufl.dot(edge_traction(scene, load, msh), v)
    if kind == BODY:
        return ufl.dot(body_force(scene, load, msh), v)
