"""The dolfinx methods' typed options (:mod:`contactcore.discretisation`).

Plain dataclasses: importing this module imports no dolfinx, so a driver
checks a method's options before paying for its libraries; ``build``
imports the method's module (:attr:`~contactcore.discretisation.Discretisation.module`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from contactcore.discretisation import Discretisation, check_choice, check_degree

#: The background cells of XFEM: structured quadrilaterals (the paper's),
#: structured triangles, or gmsh triangles (used for a disc).
XFEM_CELLS = ("quad", "triangle", "gmsh")


@dataclass(frozen=True)
class FE(Discretisation):
    """The conforming reference (:mod:`xdolfinx.conforming`): P``degree``
    triangles on a mesh that follows Γ; ``geometry_order`` defaults to the
    degree (second-order cells on a curved Γ); ``grading`` refines toward
    Γ (:class:`meshes.Grading`); ``petsc_options`` override the MUMPS
    defaults; the condition estimate runs only with ``estimate_condition``;
    ``comm`` defaults to ``MPI.COMM_WORLD``."""

    degree: int = 1
    geometry_order: int | None = None
    grading: object = None
    petsc_options: dict | None = None
    estimate_condition: bool = False
    jit_params: dict | None = None
    comm: object = None

    name: ClassVar[str] = "fe"
    module: ClassVar[str] = "xdolfinx.conforming"
    paper_grid: ClassVar[str] = "xfem_cells"
    field_output: ClassVar[str] = "mesh"
    distributed: ClassVar[bool] = True

    def __post_init__(self):
        check_degree(self.name, self.degree)


@dataclass(frozen=True)
class XFEM(Discretisation):
    """Heaviside-enriched P``degree`` (:mod:`xdolfinx.xfem`) on a mesh that
    ignores Γ, of ``cell`` (:data:`XFEM_CELLS`); ``gauss`` points per
    direction of a cut cell's sub-cells (default by degree); the rest as
    :class:`FE`."""

    degree: int = 1
    cell: str = "quad"
    gauss: int | None = None
    petsc_options: dict | None = None
    estimate_condition: bool = False
    comm: object = None

    name: ClassVar[str] = "xfem"
    module: ClassVar[str] = "xdolfinx.xfem"
    paper_grid: ClassVar[str] = "xfem_cells"
    level_set: ClassVar[bool] = True
    field_output: ClassVar[str] = "mesh"
    distributed: ClassVar[bool] = True

    def __post_init__(self):
        check_degree(self.name, self.degree)
        check_choice(self.name, "cell", self.cell, XFEM_CELLS)

    @classmethod
    def label(cls, result) -> str:
        return f"xfem P{result.degree} ({result.discretisation['cells']} cells)"
