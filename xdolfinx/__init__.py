"""dolfinx-based methods: the conforming reference (``fe``) and ``xfem``.

Each method module exposes ``METHOD`` and ``solve(scene, h=None, *,
degree=1, paper=False, ...) -> contactcore.Result``.  Importing the package
loads nothing: ``conforming`` and ``xfem`` need dolfinx, ``linear_solver``
(PETSc + MUMPS, shared with EFGM) needs petsc4py only.
"""
