"""A command's result folder under one process or mpirun's ranks.

Contract: :func:`result_folder` yields the folder the command writes into:
on rank 0, which alone writes, ``out`` built aside and put in place whole
only if the block ends without an exception (:func:`verification.files.result_folder`,
which refuses a bad ``out`` with :class:`~verification.files.OutFolderError`);
on mpirun's other ranks ``out`` itself, in which they write nothing.  Every
rank raises the same refusal.  :func:`sign` writes what every finished
result folder holds besides the command's own files.
"""
from __future__ import annotations

from contextlib import ExitStack, contextmanager
from pathlib import Path

from .. import files


@contextmanager
def result_folder(out: Path, rank: int, distributed: bool):
    """The folder the command writes into: on rank 0, which alone writes,
    ``out`` built aside and put in place whole (:func:`files.result_folder`,
    which refuses a bad ``out``); on mpirun's other ranks ``out`` itself, in
    which they write nothing (:func:`files.writes_here`).  They learn rank
    0's verdict on ``out`` first, so that none goes on into a solve whose
    collectives would wait for ever on the rank that stopped."""
    with ExitStack() as stack:
        refusal = None
        if rank == 0:
            try:
                out = stack.enter_context(files.result_folder(out, watched=distributed))
            except files.OutFolderError as exc:
                refusal = str(exc)
        if distributed:
            from mpi4py import MPI
            refusal = MPI.COMM_WORLD.bcast(refusal, root=0)
        if refusal is not None:
            raise files.OutFolderError(refusal)
        yield out


def sign(folder: Path, argv: list) -> None:
    """What made the folder (its manifest, unless the command wrote one)
    and every CSV column's unit, beside the CSVs (their headers stay as read)."""
    if not (folder / files.MANIFEST).exists():  # every result folder says what made it
        files.write_json(folder / files.MANIFEST, files.provenance(list(argv)))
    files.write_units(folder)
