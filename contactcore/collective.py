"""Reductions over the ranks a system is distributed on.

Under ``mpirun`` a dolfinx method's system is split between ranks: each
owns a part of the unknowns and of Γ's quadrature points.  Newton's
decisions (converged, settled, which factorisation to reuse, cut back)
must be the same on every rank, or one rank waits for ever in a
collective that another skipped.  They are taken on values reduced here.
The communicator is any object with ``size`` and ``allgather`` (mpi4py's):
this module imports no MPI, and with no communicator (serial, EFGM) every
reduction is the value itself.
"""
from __future__ import annotations

import numpy as np


class Collective:
    """Reductions over ``comm`` (None or one rank: serial)."""

    def __init__(self, comm=None):
        self.comm = comm if comm is not None and comm.size > 1 else None

    @property
    def parallel(self) -> bool:
        return self.comm is not None

    @property
    def rank(self) -> int:
        return 0 if self.comm is None else self.comm.rank

    def max(self, value: float) -> float:
        """The largest ``value`` of any rank."""
        return value if self.comm is None else max(self.comm.allgather(value))

    def sum(self, value):
        """The sum of ``value`` over the ranks."""
        return value if self.comm is None else sum(self.comm.allgather(value))

    def all(self, flag: bool) -> bool:
        """Whether ``flag`` holds on every rank."""
        return bool(flag) if self.comm is None else all(self.comm.allgather(bool(flag)))

    def gather(self, array: np.ndarray) -> np.ndarray:
        """Every rank's ``array`` concatenated along the first axis, in rank
        order, on every rank."""
        array = np.asarray(array)
        if self.comm is None:
            return array
        return np.concatenate(self.comm.allgather(array))


#: The reductions of a system on one process.
SERIAL = Collective()
