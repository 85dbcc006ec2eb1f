"""A run's result folder, built beside its final name and put in place whole.

Contract: :func:`result_folder` (and :func:`atomic_folder` under it)
builds the results in a temporary folder beside ``path`` and renames it
onto ``path`` only if the block succeeds: at every moment ``path`` holds
one whole run, an earlier one or the new one, never a mix or a half.  An
``--out`` that cannot hold a run (a file, a folder this tool did not
write: no :data:`MANIFEST`) is refused with an :class:`OutFolderError`
before anything is touched.
"""
from __future__ import annotations

import os
import tempfile
from contextlib import contextmanager
from pathlib import Path

from contactcore import ContactError
from contactcore.errors import check_writable, os_problem

from .. import janitor
from .atomic_files import follow_umask
from .held_signals import end_if_signalled, signals_held


#: The file that marks a folder as a result folder of this tool (every
#: command writes it last): only such a folder is replaced by a new run.
MANIFEST = "run.json"


class OutFolderError(ContactError):
    """``--out`` names something that cannot hold this run's results."""


#: The atomic folders being built in this process, innermost last.
_BUILDING: list[janitor.Build] = []


@contextmanager
def atomic_folder(path: Path, watched: bool = False):
    """A temporary folder beside ``path`` that replaces it if the block
    succeeds (named ``.NAME.RANDOM``, or ``.build.RANDOM`` where ``NAME``
    is too long to carry: :func:`verification.janitor.build_prefix`).  An earlier folder at ``path`` is moved aside (renamed, not
    deleted) until the new one is in place, and put back if the block is
    interrupted in between: at every moment ``path`` holds one whole run.
    Ctrl-C and SIGTERM wait while the folders are swapped and the earlier
    one removed (:func:`signals_held`); one that arrives then ends the
    command with the new run in place.  They wait too while the temporary
    folder is made, until it is known to be removed if the block ends: one
    that came just as ``mkdtemp`` returned left an empty ``.NAME.RANDOM``.
    ``watched``: a janitor puts it right if this process is killed before
    it can (:func:`verification.janitor.watch`)."""
    path = Path(path)
    build, built = None, False
    try:
        with signals_held():  # one that comes as the folder is made acts once it is known to be settled
            try:
                path.parent.mkdir(parents=True, exist_ok=True)
                tmp = Path(tempfile.mkdtemp(prefix=janitor.build_prefix(path), dir=path.parent))
            except OSError as exc:  # a place the system will not let us write (/proc, /sys, a read-only mount)
                raise OutFolderError(f"{path} cannot be created ({exc.strerror or exc})") from None
            build = janitor.Build(path, tmp)
            _BUILDING.append(build)
        follow_umask(str(tmp), 0o777)
        if watched:
            janitor.watch(build)
        yield tmp
        end_if_signalled()
        built = True
    finally:
        if build is not None:
            _put_in_place(build, built, watched)


def _put_in_place(build: janitor.Build, built: bool, watched: bool) -> None:
    """The end of :func:`atomic_folder`'s ``build``: the new folder in
    place of the earlier one if it was ``built``, then every other folder
    of it removed (:meth:`~verification.janitor.Build.settle`), Ctrl-C and
    SIGTERM held meanwhile; the janitor of a ``watched`` build stopped."""
    path, tmp = build.path, build.tmp
    with signals_held():  # one that comes now acts once every step below is done
        try:
            if built:
                if path.exists():
                    os.replace(path, build.earlier)
                os.replace(tmp, path)
        finally:
            build.settle()
            _BUILDING.remove(build)
            if watched and janitor.watching():
                janitor.unwatch()


def discard_unfinished() -> None:
    """Settle every atomic folder under way (:meth:`verification.janitor.Build.settle`),
    innermost first, as if its block had been interrupted: for a process
    that ends at once, without unwinding (rank 0 under mpirun, whose ranks
    mpirun kills a second after it asks them to end)."""
    for build in reversed(_BUILDING):
        build.settle()


def check_out(path: Path) -> Path:
    """``path`` as a result folder: refuse an existing file, a path below a
    file, a folder that cannot be created, and a non-empty folder that this
    tool did not write (no :data:`MANIFEST`), all with an
    :class:`OutFolderError` that names it; nothing is touched."""
    path = check_writable(path, kind="folder", error=OutFolderError)
    try:
        unwritten = path.is_dir() and any(path.iterdir()) and not (path / MANIFEST).is_file()
    except OSError as exc:  # a name too long for the file system (ENAMETOOLONG), ...
        raise OutFolderError(f"--out: {path} cannot be created: {os_problem(path, exc)}") from None
    if unwritten:
        raise OutFolderError(f"--out: {path} is a non-empty folder that this tool did not write (no {MANIFEST}); "
                             "give a new or empty folder")
    return path


@contextmanager
def result_folder(path: Path, watched: bool = False):
    """Build a run's results in a temporary folder beside ``path`` and put it
    in place of ``path`` (an earlier run's folder is replaced whole) only if
    the block succeeds: a failed or interrupted run leaves nothing under the
    final name (``watched``: :func:`atomic_folder`'s)."""
    try:
        with atomic_folder(check_out(path), watched) as tmp:
            yield tmp
    except OutFolderError as exc:
        message = str(exc)
        raise OutFolderError(message if message.startswith("--out: ") else f"--out: {message}") from None
