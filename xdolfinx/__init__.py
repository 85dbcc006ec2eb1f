"""dolfinx-based methods: the conforming reference (``fe``,
:mod:`xdolfinx.conforming`) and ``xfem`` (the package :mod:`xdolfinx.xfem`).

Each method module exposes ``METHOD``, ``build`` and ``solve(scene, h=None,
*, degree=1, paper=False, ...) -> contactcore.Result``; their typed options
are :mod:`xdolfinx.options`.  Importing the package loads nothing: the
method modules need dolfinx, the options do not.
"""
