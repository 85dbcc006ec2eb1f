"""The PETSc solver options the environment sets where the toolkit's
solvers never read them.

Each solver reads its options under a prefix of its own
(contactcore.linear_solver), so a solver option (``ksp_``, ``pc_``,
``mat_mumps_``…) that PETSc reads at ``PetscInitialize`` never reaches it:
``-mat_mumps_icntl_7 5`` left the ordering at the toolkit's own without a
word (grader5, fault 6).  PETSc 3.18 reads, in this order
(src/sys/objects/options.c, ``PetscOptionsInsert``; measured with this
build, 3.18.5, through ``petsc4py.init()``, 2026-11-28):

* ``$HOME/.petscrc``, then ``.petscrc`` and ``petscrc`` in the working
  directory: one option a line (``-name [value]``), ``#`` starts a
  comment, an ``alias`` line names no option;
* the environment's ``PETSC_OPTIONS`` (a string of options), then
  ``PETSC_OPTIONS_YAML`` (a YAML mapping);
* in a string or a file, ``-options_file FILE`` reads FILE the same way,
  ``-options_file_yaml FILE`` a YAML file, ``-options_string_yaml TEXT`` a
  YAML string, and ``-prefix_push P`` / ``-prefix_pop`` put ``P`` before
  the names between them.

``-skip_petscrc`` skips the three files only on the command line given to
``PetscInitialize`` (or in its ``file`` argument): petsc4py passes no
options there, and in ``PETSC_OPTIONS`` or a file it skips nothing (the
files were read before ``PETSC_OPTIONS``; measured: ``-skip_petscrc`` in
``PETSC_OPTIONS``, or in ``$HOME/.petscrc``, left the working directory's
files read).  PETSc's names are case-insensitive, and so is every name
compared here.  Files that cannot be read are passed over: PETSc stops
at its own start on them, with its own message.
"""
from __future__ import annotations

import os
import re
from pathlib import Path

#: The prefixes of the PETSc options a solver reads (KSP, PC and the
#: factorisation's package): the toolkit's solvers read theirs under a
#: prefix of their own (contactcore.linear_solver), so such an option set
#: where PETSc reads it at its start never reaches them; global ones
#: (``-log_view``, ``-info``) and a matrix's own (``-mat_view``: the
#: assembled matrices carry no prefix) still apply.
SOLVER_OPTION_PREFIXES = ("ksp_", "pc_", "mat_mumps_", "mat_superlu", "mat_umfpack_", "mat_cholmod_")

#: How deep ``-options_file`` may nest before the reading stops (a file
#: that names itself).
_NESTING = 16


def _solver(name: str) -> bool:
    return name.lower().startswith(SOLVER_OPTION_PREFIXES)


class _Reader:
    """PETSc's reading of its start-up options, names only, each with where
    it was set (:func:`given`)."""

    def __init__(self):
        self.found: list[tuple[str, str]] = []  # (name, where)

    def string(self, text: str, where: str, depth: int = 0) -> None:
        """``PetscOptionsInsertString``: options, ``-options_file`` and its
        kin, ``-prefix_push`` and ``-prefix_pop``."""
        words, prefixes, i = text.split(), [], 0
        while i < len(words):
            word = words[i]
            if not re.match(r"-[A-Za-z]", word):
                i += 1
                continue
            key, value = word[1:].lower(), words[i + 1] if i + 1 < len(words) else None
            takes = value is not None and not re.match(r"-[A-Za-z]", value)
            if key == "options_file" and takes:
                self.file(value, f"{value} (-options_file in {where})", depth + 1)
            elif key == "options_file_yaml" and takes:
                self.yaml_file(value, f"{value} (-options_file_yaml in {where})")
            elif key == "options_string_yaml" and takes:
                self.yaml(value, f"-options_string_yaml in {where}")
            elif key == "prefix_push" and takes:
                prefixes.append(value)
            elif key == "prefix_pop":
                prefixes = prefixes[:-1]
            else:
                self.found.append(("".join(prefixes) + word[1:], where))
            i += 2 if takes and key in ("options_file", "options_file_yaml", "options_string_yaml",
                                        "prefix_push") else 1

    def file(self, path: str, where: str, depth: int = 0) -> None:
        """``PetscOptionsInsertFile``: one option a line, ``#`` a comment,
        ``alias`` lines skipped; the rest read as a string."""
        if depth > _NESTING:
            return
        try:
            text = Path(path).expanduser().read_text(errors="replace")
        except OSError:
            return
        lines = (line.split("#", 1)[0].strip() for line in text.splitlines())
        self.string("\n".join(line for line in lines if line and not line.lower().startswith("alias")), where,
                    depth)

    def yaml_file(self, path: str, where: str) -> None:
        try:
            text = Path(path).expanduser().read_text(errors="replace")
        except OSError:
            return
        self.yaml(text, where)

    def yaml(self, text: str, where: str) -> None:
        """A YAML mapping: its nested keys joined by ``_`` (``ksp: {type:
        cg}`` sets ``ksp_type``), a list's mappings under the same prefix."""
        try:
            import yaml
            data = yaml.safe_load(text)
        except Exception:  # noqa: BLE001 - PETSc refuses it at its start, with its own message
            return

        def walk(node, prefix):
            if isinstance(node, dict):
                for key, value in node.items():
                    name = f"{prefix}_{str(key).lstrip('-')}" if prefix else str(key).lstrip("-")
                    if isinstance(value, (dict, list)):
                        walk(value, name)
                    else:
                        self.found.append((name, where))
            elif isinstance(node, list):
                for item in node:
                    walk(item, prefix)
            elif prefix:
                self.found.append((prefix, where))
        walk(data, "")


def given(environ=None, cwd: str | Path | None = None) -> list[tuple[str, str]]:
    """Every option name PETSc reads at its start, in its order (module
    doc), with where it was set: ``$HOME/.petscrc``, ``.petscrc`` and
    ``petscrc`` in ``cwd`` (the working directory), ``PETSC_OPTIONS``,
    ``PETSC_OPTIONS_YAML``, and the files they name.  A file read twice
    (the working directory is $HOME) counts once."""
    environ = os.environ if environ is None else environ
    cwd = Path.cwd() if cwd is None else Path(cwd)
    reader, seen = _Reader(), set()
    home = environ.get("HOME", "")
    rc = ([(Path(home) / ".petscrc", "$HOME/.petscrc")] if home else []) + [
        (cwd / ".petscrc", ".petscrc in the working directory"), (cwd / "petscrc", "petscrc in the working directory")]
    for path, where in rc:
        try:
            real = path.resolve()
        except OSError:
            continue
        if real in seen:
            continue
        seen.add(real)
        reader.file(str(path), where)
    reader.string(environ.get("PETSC_OPTIONS", ""), "PETSC_OPTIONS")
    if environ.get("PETSC_OPTIONS_YAML"):
        reader.yaml(environ["PETSC_OPTIONS_YAML"], "PETSC_OPTIONS_YAML")
    return reader.found


def unread(environ=None, cwd: str | Path | None = None) -> str:
    """The solver options (:data:`SOLVER_OPTION_PREFIXES`, any case) that
    PETSc reads at its start (:func:`given`) and the toolkit's solvers
    never read, as ``"WHERE sets a, b; WHERE sets c"``; "" if none."""
    by_place: dict[str, list[str]] = {}
    for name, where in given(environ, cwd):
        if _solver(name) and name not in by_place.setdefault(where, []):
            by_place[where].append(name)
    return "; ".join(f"{where} sets {', '.join(names)}" for where, names in by_place.items() if names)
