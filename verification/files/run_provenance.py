"""What produced a result folder: the command, the code, the machine.

Contract: :func:`provenance` is ``run.json``'s record of a run: the
command as it could be typed again, the interpreter, the working folder,
the host, the MPI ranks each solve spread over, the project's version and
git commit (``+dirty`` with uncommitted changes), and the versions of the
numerical packages imported.  Nothing here is written or timed.
"""
from __future__ import annotations

import os
import platform
import sys
from pathlib import Path

from contactcore.collective import launched_size

from .. import pool


def versions() -> dict:
    """Versions of Python and of the numerical packages this run imported."""
    out = {"python": platform.python_version()}
    for name in ("numpy", "scipy", "dolfinx", "petsc4py", "gmsh", "ufl", "basix", "ffcx", "matplotlib"):
        mod = sys.modules.get(name)
        if mod is not None:
            out[name] = getattr(mod, "__version__", "unknown")
    return out


def package_version() -> str:
    """This project's installed version (pyproject.toml), or "unknown"."""
    from importlib import metadata
    try:
        return metadata.version("jameel-contact")
    except metadata.PackageNotFoundError:
        return "unknown"


def git_commit() -> str | None:
    """The commit of the source tree this code runs from (with ``+dirty`` if
    it has uncommitted changes), or None outside a git checkout."""
    import subprocess
    top = Path(__file__).resolve().parents[2]
    try:
        head = subprocess.run(["git", "-C", str(top), "rev-parse", "HEAD"], capture_output=True, text=True,
                              timeout=10)
        if head.returncode != 0:
            return None
        dirty = subprocess.run(["git", "-C", str(top), "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, timeout=10).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return None
    return head.stdout.strip() + ("+dirty" if dirty else "")


def provenance(argv: list[str]) -> dict:
    """What produced a result folder: the command (``python`` in it is the
    interpreter recorded under ``"python"``; under a launcher of K
    ranks, mpirun's or mpiexec's alike, written ``mpirun -n K``, and with
    ``-m mpi4py.futures`` under a pool of them), the code (version and git
    commit), the machine, the MPI ranks each solve spread over
    (:func:`ranks`) and the versions of the packages."""
    launched = launched_size()
    launcher = ([f"mpirun -n {launched}"] if launched > 1 else []) + ["python"]
    launcher += ["-m mpi4py.futures"] if pool.under_mpi_pool() else []
    return {"command": " ".join([*launcher, "-m verification", *argv]), "python": sys.executable, "cwd": os.getcwd(),
            "host": platform.node(), "ranks": ranks(), "version": package_version(), "commit": git_commit(),
            "versions": versions()}


def ranks() -> int:
    """How many MPI ranks each solve of this job spreads over: mpirun's
    count (read from the launcher, :func:`contactcore.collective.launched_size`),
    1 without mpirun or under an mpi4py.futures pool, whose workers each
    solve alone (:func:`verification.pool.distributed`)."""
    return launched_size() if pool.distributed() else 1
