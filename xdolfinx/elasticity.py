"""The UFL of linear elasticity shared by fe and xfem: the stress, each
load's integrand, and whether a load's form vanishes (no gmsh: an xfem run
on structured cells never imports it).

Every number of a scene (E, ν through λ and μ, a traction, a pressure, a
body force, a torque's coefficient and centre) enters a form as a
``dolfinx.fem.Constant``, never as a Python float: UFL writes a float into
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
from contactcore.scene import BodyForce, Pressure, Torque, Traction
from contactcore.scene.loads import torque_field, torque_rate


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


def _coefficients(scene, load) -> tuple[float, ...]:
    """The numbers a load's form is made of: the traction or body force
    vector, the pressure, or a torque's ``k = T/J`` (``J = πR⁴/2``, as
    :func:`contactcore.scene.body_force`)."""
    if isinstance(load, (Traction, BodyForce)):
        return tuple(float(c) for c in load.value)
    if isinstance(load, Pressure):
        return (float(load.value),)
    if isinstance(load, Torque):
        return (torque_rate(scene, load),)
    raise TypeError(f"not a load: {load!r}")


def vanishes(scene, load) -> bool:
    """Whether ``load`` is of value zero, so that it has no form (dolfinx's
    assembler finds no kernel to call in a form whose integrand is zero).
    Decided from the load's numbers, not from the form: a Constant is never
    UFL's zero."""
    return all(c == 0.0 for c in _coefficients(scene, load))


def body_force(scene, load, msh):
    """The body force ``b`` of a :class:`~contactcore.scene.BodyForce` or
    :class:`~contactcore.scene.Torque` as a UFL vector on ``msh``: the
    core's formula (a torque: :func:`contactcore.scene.loads.torque_field`,
    ``b = k(−(y−y_c), x−x_c)``, and its rate ``torque_rate``) with its
    numbers as Constants, so that a new load value needs no new kernel."""
    if isinstance(load, BodyForce):
        return constant(msh, _coefficients(scene, load))
    (k,) = _coefficients(scene, load)
    k, centre = constant(msh, k), constant(msh, scene.interface.centre)
    x = ufl.SpatialCoordinate(msh)
    return ufl.as_vector(torque_field(k, centre, x[0], x[1]))


def load_integrand(scene, load, msh, v):
    """The integrand of ``load``'s linear form against the test function
    ``v`` (a vector on ``msh``): ``t̄ · v`` for a traction, ``−p n · v`` for a
    pressure (n the outward normal), ``b · v`` for a body force or torque."""
    if isinstance(load, Traction):
        return ufl.dot(constant(msh, _coefficients(scene, load)), v)
    if isinstance(load, Pressure):
        (p,) = _coefficients(scene, load)
        return -constant(msh, p) * ufl.dot(ufl.FacetNormal(msh), v)
    return ufl.dot(body_force(scene, load, msh), v)
