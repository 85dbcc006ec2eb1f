"""The ghost exchange of a distributed system's unknowns: the one interface
through which the shared core (:class:`~contactcore.system.InterfaceOperator`)
moves values between a rank's owned unknowns and the local ones it reads.

Under mpirun each rank owns a contiguous block of the unknowns and also
reads some that other ranks own (ghosts).  Its *local* numbering is its
owned unknowns first, then those ghosts.  dolfinx's methods exchange
through its index maps (:class:`xdolfinx.contact_system.GhostExchange`),
EFGM through a PETSc scatter (:class:`efgm.petsc_matrices.ScatterExchange`).
"""
from __future__ import annotations

from abc import ABC, abstractmethod

import numpy as np


class Exchange(ABC):
    """Owned values to local ones and back, on one rank of many; each
    exchange of the project subclasses it."""

    #: this rank's owned unknowns
    owned_size: int
    #: its local unknowns: the owned ones, then the ghosts it reads
    local_size: int

    @abstractmethod
    def forward(self, owned: np.ndarray) -> np.ndarray:
        """Owned values (``owned_size``) -> local values (``local_size``):
        each ghost takes its owner's value."""

    @abstractmethod
    def reverse(self, local: np.ndarray) -> np.ndarray:
        """Local contributions (``local_size``) -> their sums over every
        rank that holds them, on the owners (``owned_size``)."""
