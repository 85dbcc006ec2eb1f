"""Registries of declared classes (laws, loads): each class held to its
contract at import, so a class that declares too little is refused, by
name, before any scene uses it, and no name is registered twice."""
from __future__ import annotations

from typing import Callable

from .errors import ContactError


def add(kind: str, contract: Callable, registry: dict, cls) -> None:
    """Put ``cls`` into ``registry`` under its ``name``, held to
    ``contract`` (which raises a ContactError naming what it lacks); a
    name already there is a ContactError naming both classes (``kind``,
    "law" or "load", names them)."""
    contract(cls)
    if cls.name in registry:
        raise ContactError(f"the {kind} name '{cls.name}' is registered twice ({registry[cls.name].__qualname__}, "
                           f"{cls.__qualname__})")
    registry[cls.name] = cls


def registered(kind: str, contract: Callable, classes) -> dict:
    """``{name: class}`` of ``classes``, each added by :func:`add`."""
    out = {}
    for cls in classes:
        add(kind, contract, out, cls)
    return out


def declared_dimensions(cls, where: str, allowed) -> dict[str, str]:
    """The ``{parameter: dimension}`` a law or load class ``cls`` declares
    (its tuple ``parameters``, its dict ``dimensions``), each dimension
    one of ``allowed``, or a ContactError naming ``where`` and what is
    missing: no tuple of names, no dict, a parameter without an allowed
    dimension (unscaled, it would reach every method in the user's units
    against a dimensionless scene), a dimension for no parameter."""
    parameters = getattr(cls, "parameters", None)
    if not isinstance(parameters, tuple) or not all(isinstance(p, str) for p in parameters):
        raise ContactError(f"{where}: declares no tuple 'parameters' of its parameters' names")
    dims = getattr(cls, "dimensions", None)
    if not isinstance(dims, dict):
        raise ContactError(f"{where}: declares no 'dimensions' (parameter -> one of {', '.join(allowed)}): "
                           "the scaling could not make its parameters dimensionless")
    for p in parameters:
        if dims.get(p) not in allowed:
            raise ContactError(f"{where}: declares no dimension for its parameter '{p}' (got {dims.get(p)!r}; one "
                               f"of {', '.join(allowed)}): unscaled, it would reach every method in the "
                               "user's units against a dimensionless scene, a silently wrong answer")
    extra = sorted(set(dims) - set(parameters))
    if extra:
        raise ContactError(f"{where}: declares a dimension for '{extra[0]}', which is not among its parameters "
                           f"({', '.join(parameters)})")
    return dict(dims)
