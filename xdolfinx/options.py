"""The dolfinx methods' typed options (:mod:`contactcore.discretisation`).

Plain dataclasses: importing this module imports no dolfinx, so a driver
checks a method's options before paying for its libraries; ``build``
imports the method.
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
    Γ (:class:`meshes.Grading`); ``petsc_options`` override the MUMPS LU
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
    paper_grid: ClassVar[str] = "xfem_cells"

    def __post_init__(self):
        check_degree(self.name, self.degree)

    def build(self, scene, resolution, timings):
        from . import conforming
        return conforming.build(scene, self, resolution, timings)


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
    paper_grid: ClassVar[str] = "xfem_cells"
    level_set: ClassVar[bool] = True

    def __post_init__(self):
        check_degree(self.name, self.degree)
        check_choice(self.name, "cell", self.cell, XFEM_CELLS)

    def build(self, scene, resolution, timings):
        from . import xfem
        return xfem.build(scene, self, resolution, timings)

    @classmethod
    def label(cls, result) -> str:
        return f"xfem P{result.degree} ({result.discretisation['cells']} cells)"
