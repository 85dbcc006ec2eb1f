"""EFGM's typed options (:mod:`contactcore.discretisation`).

A plain dataclass: importing it imports no numerics; ``build`` imports
:mod:`efgm.method` (:attr:`~contactcore.discretisation.Discretisation.module`).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

from contactcore import health
from contactcore import tolerances as tol
from contactcore.discretisation import Discretisation, Resolution, check_choice, check_degree

#: The MLS bases by name (``--basis``) and their degree.
BASES = {"linear": 1, "quadratic": 2}

#: The weight functions and support shapes EFGM offers.
WEIGHT_NAMES = ("cubic", "quartic")
SUPPORTS = ("circular", "rectangular")


@dataclass(frozen=True)
class EFGM(Discretisation):
    """EFGM (:mod:`efgm.method`): an MLS basis of ``degree`` 1 or 2, or
    ``basis`` "linear" or "quadratic" (the same choice by name; it sets
    ``degree``); ``dmax`` the support dilation (default by degree,
    :data:`efgm.method.DMAX`); ``weight`` and ``support`` the weight
    function and support shape; ``nodes`` any (N, 2) point set instead of
    a grid (it must include nodes on the supported boundaries); ``gauss``
    points per direction of each background cell (default by degree); the
    condition estimate only with ``estimate_condition``; ``comm`` the
    mpi4py communicator to spread the work over (default: ``COMM_WORLD``
    when mpirun started several ranks, else one process without MPI;
    :mod:`efgm.distributed`)."""

    degree: int = 1
    basis: str | None = None
    dmax: float | None = None
    weight: str = "cubic"
    support: str = "circular"
    nodes: object = field(default=None, compare=False)
    gauss: int | None = None
    estimate_condition: bool = False
    comm: object = None

    name: ClassVar[str] = "efgm"
    module: ClassVar[str] = "efgm.method"
    paper_grid: ClassVar[str] = "efgm_nodes"
    # its cells, Γ's points and rows split in fixed contiguous ranges
    # (:mod:`efgm.distributed`); one process without MPI outside mpirun
    distributed: ClassVar[bool] = True
    needs_mpi: ClassVar[bool] = False

    def __post_init__(self):
        if self.basis is not None:
            check_choice(self.name, "basis", self.basis, tuple(BASES))
            object.__setattr__(self, "degree", BASES[self.basis])
        check_degree(self.name, self.degree)
        check_choice(self.name, "weight", self.weight, WEIGHT_NAMES)
        check_choice(self.name, "support", self.support, SUPPORTS)

    def resolution(self, scene, h, paper):
        """Given ``nodes`` fix the spacing themselves; otherwise the one rule."""
        if self.nodes is not None:
            return Resolution(None)
        return super().resolution(scene, h, paper)

    def check_spacing(self, scene, resolution) -> None:
        """Penalty Coulomb springs that dwarf the softer body at the node
        spacing of ``resolution`` (:func:`contactcore.health.check_friction_springs`)."""
        from efgm.nodes import node_set

        health.check_friction_springs(scene, node_set(scene, resolution, self.nodes).h,
                                      tol.EFGM_FRICTION_SPRINGS, self.name)

    def spacing_warnings(self, scene, h: float) -> list[str]:
        """Penalty springs of any law above ``EFGM_SPRING_WARN`` at the node
        spacing ``h`` (:func:`contactcore.health.stiff_spring_warnings`):
        per solve, since a study's reused system carries no law."""
        return health.stiff_spring_warnings(scene, h, tol.EFGM_SPRING_WARN[self.degree], self.name, self.degree)

    @classmethod
    def label(cls, result) -> str:
        return f"efgm ({result.discretisation['nodes']} nodes)"
