"""dolfinx-based methods: the conforming reference (``fe``).

Each method module exposes ``METHOD`` and ``solve(scene, h=None, *,
degree=1, paper=False, ...) -> contactcore.Result``.
"""
from . import conforming

__all__ = ["conforming"]
