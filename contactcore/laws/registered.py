"""The penalty laws a scene may name: :data:`LAWS`, and a plugin's :func:`register`.

Contract: :data:`LAWS` is ``{name: class}`` of the shipped penalty laws,
each held to :func:`~contactcore.laws.contract.law_contract` at import;
:func:`register` adds a law class from outside the package under the same
checks (no name twice), :func:`unregister` removes it.
:data:`InterfaceLaw` is the type of a scene's penalty law: any law class.
"""
from __future__ import annotations

from ..registry import add
from .contract import law_contract, registry
from .coulomb import CoulombLaw
from .linear import LinearLaw
from .springs import _Law
from .unilateral import UnilateralLaw


def register(cls, laws: dict | None = None):
    """Register the law class ``cls`` (held to :func:`law_contract`) in
    ``laws`` (default :data:`LAWS`, the penalty laws; an exact form goes
    into :data:`contactcore.exact.EXACT_LAWS`) under its ``name``, so that
    a scene file's ``type = "<name>"`` builds it
    (:func:`contactcore.enforcement.make_law`): a law from outside the
    package, as a plugin (or a test) adds it.  Refused like the built-in
    ones: a class that declares too little, a name already registered.
    Returns ``cls`` (usable as a decorator); :func:`unregister` undoes it."""
    add("law", law_contract, LAWS if laws is None else laws, cls)
    return cls


def unregister(name: str, laws: dict | None = None) -> None:
    """Remove the law ``name`` that :func:`register` added (nothing if absent)."""
    (LAWS if laws is None else laws).pop(name, None)


#: Every penalty law by the name a scene file gives it.
LAWS = registry(LinearLaw, UnilateralLaw, CoulombLaw)

#: The type of a scene's penalty law: any law class (a union of the shipped
#: ones would leave out a law :func:`register` adds; takeover31 #5).  An
#: exactly enforced law is a :class:`contactcore.exact._ExactLaw`.
InterfaceLaw = _Law
