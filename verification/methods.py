"""The methods a driver can run, by name, imported only when used.

Every entry names a module with ``METHOD`` and ``solve(scene, h=None, *,
degree=1, paper=False, ...) -> contactcore.Result``.  Lazy import keeps an
``efgm`` run free of dolfinx and gmsh.
"""
from __future__ import annotations

import importlib

#: Method name -> module implementing it, in the order plots list them.
METHODS = {
    "fe": "xdolfinx.conforming",
}


def solver(name: str):
    """The ``solve`` function of method ``name``."""
    return importlib.import_module(METHODS[name]).solve


def expand(names: list[str]) -> list[str]:
    """``all`` means every method built so far."""
    return list(METHODS) if "all" in names else names
