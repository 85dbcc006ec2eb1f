"""What a law class declares, checked when it is registered.

Contract (:mod:`contactcore.laws`' module doc): a law class declares the
dimension of each of its ``parameters`` (one of :data:`DIMENSIONS`, which
:mod:`contactcore.scaling` makes dimensionless by the scene's units) and
the capabilities :data:`CAPABILITIES` as bools, and a frictional one a
``slip_bound(t_N)`` method.  :func:`law_contract` returns the declared
dimensions or raises a ContactError naming what is missing;
:func:`registry` builds ``{name: class}`` of classes that all pass it, no
name twice.  :func:`frictionless` asks a law's slip bound, never a
parameter by name.  Nothing here knows a particular law.
"""
from __future__ import annotations

import numpy as np

from ..errors import ContactError
from ..registry import declared_dimensions, registered


#: The dimensions a law's parameter may declare (:attr:`_Law.dimensions`),
#: each made dimensionless by :mod:`contactcore.scaling` with the scene's
#: units (``L`` length, ``S`` modulus, ``U`` displacement, ``Σ = S U/L``):
STIFFNESS = "stress per length"  #: a spring, Pa/m in SI: × L/S
STRESS = "stress"  #: a traction or strength, Pa: / Σ
DISPLACEMENT = "displacement"  #: compared with a jump (a gap, a slip), m: / U
LENGTH = "length"  #: a distance in the geometry, m: / L
DIMENSIONLESS = "dimensionless"  #: μ, β: unchanged
DIMENSIONS = (STIFFNESS, STRESS, DISPLACEMENT, LENGTH, DIMENSIONLESS)

#: The capabilities every law class declares (contactcore.laws' module doc), each a bool.
CAPABILITIES = ("homogeneous", "unilateral", "frictional")


def frictionless(law) -> bool:
    """Whether ``law`` is frictional with a slip bound of zero (Coulomb's
    μ = 0): its closed points carry no shear, so a sticking one is
    reported as slipping (:attr:`contactcore.interface_path.Increment.frictionless`).
    Asked of the bound at a unit pressure, not of a parameter's name."""
    return bool(law.frictional) and not np.any(law.slip_bound(np.array([-1.0])))


def law_contract(cls) -> dict[str, str]:
    """The declared dimension of each parameter of the law class ``cls``
    (contactcore.laws' module doc), or a ContactError naming what ``cls`` fails to declare: a
    parameter without a dimension in :data:`DIMENSIONS`, a dimension for
    no parameter, a capability of :data:`CAPABILITIES` that is not a bool,
    ``frictional`` without a ``slip_bound`` method."""
    name = getattr(cls, "name", cls.__name__)
    where = f"the '{name}' law ({cls.__module__}.{cls.__qualname__})"
    dims = declared_dimensions(cls, where, DIMENSIONS)
    for cap in CAPABILITIES:
        if not isinstance(getattr(cls, cap, None), bool):
            raise ContactError(f"{where}: declares no '{cap}' (True or False; contactcore.laws' module doc): the "
                               "health checks and Newton's cut-backs read it")
    if cls.frictional and not callable(getattr(cls, "slip_bound", None)):
        raise ContactError(f"{where}: is frictional but has no method 'slip_bound(t_N)', the largest |t_T| of a "
                           "closed point, which the health checks, Newton's decisions and the profiles read")
    return dims


def registry(*classes) -> dict:
    """``{name: class}`` of law classes, each held to :func:`law_contract`
    (at import: a law that declares too little is refused before any scene
    uses it), no name twice (:func:`contactcore.registry.registered`)."""
    return registered("law", law_contract, classes)
