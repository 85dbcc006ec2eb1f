"""Registries of declared classes (laws, loads): each class held to its
contract at import, so a class that declares too little is refused, by
name, before any scene uses it, and no name is registered twice."""
from __future__ import annotations

from typing import Callable

from .errors import ContactError


def registered(kind: str, contract: Callable, classes) -> dict:
    """``{name: class}`` of ``classes``, each held to ``contract`` (which
    raises a ContactError naming what it lacks); ``kind`` ("law", "load")
    names them in the error of a name given twice."""
    out = {}
    for cls in classes:
        contract(cls)
        if cls.name in out:
            raise ContactError(f"the {kind} name '{cls.name}' is registered twice ({out[cls.name].__qualname__}, "
                               f"{cls.__qualname__})")
        out[cls.name] = cls
    return out
