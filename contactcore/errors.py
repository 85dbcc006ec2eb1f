"""Errors shared by every method: each names the problem in its message.

The drivers in :mod:`verification` turn them into a one-line message and a
non-zero exit status; nothing else should be needed to explain the failure.
"""
import numpy as np


class ContactError(Exception):
    """Base class of every error this project raises on purpose."""


class SceneError(ContactError, ValueError):
    """A scene description that is malformed or physically invalid.

    The message starts with the dotted path of the offending field
    (e.g. ``materials.minus.E``) so the user can find it in the TOML file.
    """

    def __init__(self, field: str, problem: str):
        self.field = field
        self.problem = problem
        super().__init__(f"{field}: {problem}")

    def __reduce__(self):
        """Rebuilt from its two parts: a study's worker process hands it back
        pickled (from its message alone it could not be made, and the pool
        broke)."""
        return type(self), (self.field, self.problem)


class SolverError(ContactError, RuntimeError):
    """A linear or nonlinear solve that failed (singular matrix, divergence)."""


class SolverOptionError(SolverError):
    """A solver option that cannot be used: the input's fault, not the
    system's (no hint about springs or rigid modes belongs to it)."""


class DiscretisationError(ContactError, ValueError):
    """Discretisation parameters that cannot work (e.g. h <= 0, bad degree)."""


class FieldsError(ContactError, ValueError):
    """Arguments of ``fields.displacement``/``stress`` that have no answer: a
    malformed array, a body that does not exist, a point outside the domain
    or outside the body named for it (:func:`contactcore.result.check_points`)."""


def os_problem(path, exc: OSError) -> str:
    """What an OSError on ``path`` means, in a phrase for a one-line error:
    its ``strerror``, and for a name the file system cannot hold (ENAMETOOLONG)
    the longest component's size in bytes."""
    import errno
    import os
    text = exc.strerror or str(exc)
    if exc.errno == errno.ENAMETOOLONG:
        longest = max((len(os.fsencode(part)) for part in os.fspath(path).split(os.sep)), default=0)
        text += f" (a component of {longest} bytes; a file system holds names up to 255)"
    return text


def check_writable(path, *, kind: str = "folder", option: str = "--out", error: type = ContactError):
    """``path`` as where a command writes, checked before any work and
    touching nothing: refuse a path below a file, one whose nearest existing
    folder is not writable (missing parents are created later), a name the
    file system cannot hold, and, for ``kind`` "folder", an existing file,
    for ``kind`` "file" (written beside itself and renamed over any earlier
    one), an existing folder.  The ``error`` raised names ``option`` first
    (``--out: PATH is a file``): the one check of every command's output
    path (``python -m verification``'s result folders, ``python -m
    meshes``'s mesh file)."""
    import os
    from pathlib import Path
    if kind not in ("folder", "file"):
        raise ValueError(f"kind: 'folder' or 'file' (got {kind!r})")
    path = Path(path)
    try:
        if kind == "file" and path.is_dir():
            raise error(f"{option}: {path} is a folder; give the name of the file to write")
        start = path if kind == "folder" else path.parent
        for parent in [start, *start.parents]:
            if parent.exists() and not parent.is_dir():
                where = "is a file" if parent == path else f"lies below the file {parent}"
                raise error(f"{option}: {path} {where}")
            if parent.exists():
                if not os.access(parent, os.W_OK | os.X_OK):
                    raise error(f"{option}: {path} cannot be created or written ({parent} is not writable)")
                break
    except OSError as exc:  # a name too long for the file system (ENAMETOOLONG), ...
        raise error(f"{option}: {path} cannot be created: {os_problem(path, exc)}") from None
    return path


def require_finite(what: str, values) -> None:
    """SolverError naming ``what`` unless every value is finite: a run
    never reports NaN or ∞ as an answer."""
    bad = ~np.isfinite(np.asarray(values, float))
    if bad.any():
        raise SolverError(f"{what}: {int(bad.sum())} of {bad.size} values are not finite (NaN or ∞), "
                          "so the answer is refused; the scene's magnitudes may exceed the floating-point range")


def quoted(value: float, *bounds: float, least: int = 6) -> str:
    """``value`` in the fewest significant digits (``least`` at least; 6 like ``:g``)
    that keep it on its own side of each of ``bounds``: a value refused
    for lying just outside a range is never quoted rounded onto or into it
    (30.000001 against 30 reads "30.000001", not "30"); at 17 digits it is
    the value itself."""
    value = float(value)
    for digits in range(least, 18):
        text = f"{value:.{digits}g}"
        shown = float(text)
        if all((shown > b) == (value > b) and (shown < b) == (value < b) for b in map(float, bounds)):
            return text
    return repr(value)
