"""One result file written atomically: to a temporary name in its final
folder, renamed onto its name when complete.

Contract: :func:`atomic_path`, and :func:`write_text` and :func:`write_json`
built on it, never leave a half-written file under the final name: an
interrupted write leaves the earlier file (or none) and no temporary one.
The file gets the mode an ordinary ``open`` would give it (the umask).
Under mpirun only the process that writes (:func:`writes_here`, rank 0)
writes anything.
"""
from __future__ import annotations

import json
import os
import tempfile
from contextlib import contextmanager
from pathlib import Path

from .. import janitor
from .held_signals import signals_held


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def follow_umask(path: str, mode: int) -> None:
    """``mkstemp``/``mkdtemp`` create 0600/0700: give the file or folder the
    mode an ordinary ``open``/``mkdir`` would (``mode & ~umask``)."""
    os.chmod(path, mode & ~_umask())


@contextmanager
def atomic_path(path: Path, suffix: str = ""):
    """A temporary path beside ``path``, renamed onto it if the block
    succeeds: ``.NAME.RANDOM.SUFFIX``, or ``.tmp.RANDOM.SUFFIX`` where that
    would be too long a name (a legal ``NAME`` of 246 bytes or more)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    suffix = suffix or path.suffix
    fits = len(os.fsencode(f".{path.name}.{suffix}")) + janitor.RANDOM_PART <= janitor.name_max(path.parent)
    tmp = None
    try:
        with signals_held():  # a signal as the file is made acts once its name is known, and removes it
            fd, tmp = tempfile.mkstemp(prefix=f".{path.name}." if fits else ".tmp.", suffix=suffix, dir=path.parent)
            os.close(fd)
        follow_umask(tmp, 0o666)
        yield Path(tmp)
        os.replace(tmp, path)
    finally:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)


def writes_here() -> bool:
    """Whether this process writes result files: every process but
    mpirun's ranks after the first when they run one command together
    (:func:`verification.pool.distributed`): they compute alongside rank 0,
    which alone writes."""
    from ..pool import distributed, launched_rank
    return launched_rank() == 0 or not distributed()


def write_text(path: Path, text: str) -> Path:
    """``text`` into ``path``, atomically; nothing where this process does
    not write (:func:`writes_here`)."""
    if writes_here():
        with atomic_path(path) as tmp:
            tmp.write_text(text)
    return Path(path)


def write_json(path: Path, data) -> Path:
    """``data`` as indented JSON into ``path``, atomically (:func:`write_text`);
    numpy numbers and arrays as lists or numbers, anything else JSON cannot
    hold (a path) as its text."""
    return write_text(path, json.dumps(data, indent=2, default=_jsonable) + "\n")


def _jsonable(value):
    if hasattr(value, "tolist"):
        return value.tolist()
    return str(value)
