"""Reductions over the ranks a system is distributed on.

Under ``mpirun`` a dolfinx method's system is split between ranks: each
owns a part of the unknowns and of Γ's quadrature points.  Newton's
decisions (converged, settled, which factorisation to reuse, cut back)
must be the same on every rank, or one rank waits for ever in a
collective that another skipped.  They are taken on values reduced here.
The communicator is any object with ``size`` and ``allgather`` (mpi4py's):
this module imports no MPI, and with no communicator (serial) every
reduction is the value itself.
"""
from __future__ import annotations

import os

import numpy as np

from .errors import ContactError


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

    def share(self, count: int) -> slice:
        """This rank's contiguous part of ``count`` items (all of them in
        serial): ranks take consecutive ranges in rank order, sizes differing
        by at most one."""
        if self.comm is None:
            return slice(0, count)
        r, n = self.comm.rank, self.comm.size
        return slice(count * r // n, count * (r + 1) // n)

    def raise_any(self, error: Exception | None) -> None:
        """Raise on every rank alike the error the first rank that met one
        met (``error``: this rank's, or None), so that no rank goes on into
        a collective that the others left.  Its type is kept where it can be
        made from its message alone, else it becomes a ContactError."""
        if self.comm is None:
            if error is not None:
                raise error
            return
        met = [e for e in self.comm.allgather(None if error is None else (type(error), str(error)))
               if e is not None]
        if not met:
            return
        kind, message = met[0]
        try:
            first = kind(message)
        except TypeError:
            first = ContactError(message)
        raise first from error

    def alike(self, make, *args):
        """``make(*args)``, a :class:`ContactError` it raises on any rank
        raised on every rank alike (:meth:`raise_any`): for work that one
        rank alone may refuse (the one holding Γ) before a collective."""
        try:
            made, error = make(*args), None
        except ContactError as exc:
            made, error = None, exc
        self.raise_any(error)
        return made


def launched_size() -> int:
    """How many ranks mpirun (or mpiexec) started, 1 without it, read from
    the launcher's environment: no MPI is imported to ask."""
    return next((int(os.environ[n]) for n in ("OMPI_COMM_WORLD_SIZE", "PMI_SIZE") if n in os.environ), 1)


#: The reductions of a system on one process.
SERIAL = Collective()
