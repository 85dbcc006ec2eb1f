"""Result files, written atomically, with the provenance of every run.

Every file is written to a temporary name in its final folder and renamed
when complete, so an interrupted run never leaves a half-written file under
a good name.
"""
from __future__ import annotations

import csv
import io
import json
import os
import platform
import re
import signal
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path

from contactcore import CircleInterface, ContactError, ProfileData, SceneError, load_scene
from contactcore.collective import launched_size
from contactcore.profiles import sample_points
from contactcore.scene import Units
from contactcore.errors import check_writable, os_problem
from contactcore.estimate.runs import ERROR_SUFFIX

from . import janitor, pool

#: The file that marks a folder as a result folder of this tool (every
#: command writes it last): only such a folder is replaced by a new run.
MANIFEST = "run.json"


class OutFolderError(ContactError):
    """``--out`` names something that cannot hold this run's results."""


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _follow_umask(path: str, mode: int) -> None:
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
        _follow_umask(tmp, 0o666)
        yield Path(tmp)
        os.replace(tmp, path)
    finally:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)


#: The signals that end a command (``verification.cli.signals.ENDING``), held
#: while a result folder is swapped in and the one it replaces removed.
HELD_SIGNALS = (signal.SIGINT, signal.SIGTERM)


@contextmanager
def signals_held():
    """Hold Ctrl-C and SIGTERM until the block ends, then let the first
    that came act as it would have: a swap of result folders and the
    removal of the one replaced are not cut in half (a SIGTERM in
    ``shutil.rmtree`` left half of an earlier run in
    ``.NAME.earlier.RANDOM``, grader4, 2026-11-27).  The handlers are
    swapped, not the signal mask: a process-directed signal goes to any
    thread that does not block it (OpenBLAS's, MPI's).  Off the main
    thread, where Python sets no handler, or where a handler was set
    outside Python, the block runs as is."""
    came: list = []
    try:
        before = {sig: signal.getsignal(sig) for sig in HELD_SIGNALS}
        if None in before.values():  # a handler set outside Python, which could not be put back
            before = None
        for sig in before or ():
            signal.signal(sig, lambda *arrived: came.append(arrived))
    except ValueError:  # not the main thread
        before = None
    try:
        yield
    finally:
        if before is not None:
            for sig, handler in before.items():
                signal.signal(sig, handler)
            if came:
                _act(before[came[0][0]], *came[0])


def _act(handler, sig: int, frame) -> None:
    """Do what ``handler`` (a Python handler, SIG_DFL or SIG_IGN) does with ``sig``."""
    if callable(handler):
        handler(sig, frame)
    elif handler == signal.SIG_DFL:
        os.kill(os.getpid(), sig)


#: The exceptions of the ending signals that arrived while a command ran
#: (:func:`note_signal`), first first.  Python discards an exception raised
#: in a finalizer or a weakref callback ("Exception ignored in …"): a
#: SIGTERM whose handler ran there was lost, and the run went on to write
#: its results and exit 0 (mainsplit, 2026-11-28).
_ARRIVED: list[type[BaseException]] = []


def note_signal(ending: type[BaseException]) -> None:
    """Record that a signal ending the command arrived, as ``ending`` (the
    exception its handler raises): a block of :func:`atomic_folder` that
    ends anyway, its exception swallowed on the way, raises it then."""
    _ARRIVED.append(ending)


def forget_signals() -> None:
    """Clear :func:`note_signal`'s record: a command starts with none (one
    process may run several commands: ``main`` called in turn)."""
    _ARRIVED.clear()


def _end_if_signalled() -> None:
    """Raise the first recorded ending signal's exception
    (:func:`note_signal`): a result folder is not put in place after the
    command was asked to end."""
    if _ARRIVED:
        raise _ARRIVED[0]


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
        _follow_umask(str(tmp), 0o777)
        if watched:
            janitor.watch(build)
        yield tmp
        _end_if_signalled()
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


def writes_here() -> bool:
    """Whether this process writes result files: every process but
    mpirun's ranks after the first when they run one command together
    (:func:`verification.pool.distributed`): they compute alongside rank 0,
    which alone writes."""
    from .pool import distributed, launched_rank
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


def write_profile_csv(path: Path, profile: ProfileData, errors: dict | None = None) -> Path:
    """Columns ``s, x, y`` then the quantities (docs/scenes.md), full precision;
    ``errors`` (``{q + "_err": per-sample error}``) each beside its quantity."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    names = [c for n in profile.names for c in (n, f"{n}{ERROR_SUFFIX}") if c == n or c in (errors or {})]
    writer.writerow(names)
    cols = [profile.columns[n] if n in profile.columns else errors[n] for n in names]
    for row in zip(*cols):
        writer.writerow([repr(float(v)) for v in row])
    return write_text(path, buf.getvalue())


def read_profile_csv(path: Path) -> dict:
    """The columns of a profile CSV as lists of floats."""
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    return {name: [float(r[i]) for r in rows[1:]] for i, name in enumerate(rows[0])}


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
    top = Path(__file__).resolve().parent.parent
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


def cell(value) -> str:
    """A table cell: floats to 3 significant digits (small or large ones in
    exponent form), anything else as text."""
    if isinstance(value, float):
        if value != value:
            return "nan"
        return f"{value:.2e}" if value != 0 and not 1e-2 <= abs(value) < 1e4 else f"{value:.3g}"
    return str(value)


def md_escape(text) -> str:
    """``text`` safe inside a Markdown table cell: its pipes escaped, its
    lines joined (a line break would end the row)."""
    return " ".join(str(text).replace("|", "\\|").split())


def markdown_table(rows: list[dict], columns: list[str], headers: list[str] | None = None) -> str:
    """A Markdown table of ``rows`` (dicts) with ``columns`` in order."""
    head = headers or columns
    lines = ["| " + " | ".join(md_escape(h) for h in head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(md_escape(cell(r.get(c, ""))) for c in columns) + " |" for r in rows]
    return "\n".join(lines) + "\n"


def write_csv(path: Path, rows: list[dict], columns: list[str]) -> Path:
    """``rows`` (dicts) as CSV with ``columns`` in order, full precision."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(columns)
    writer.writerows([[repr(r.get(c, "")) if isinstance(r.get(c), float) else r.get(c, "") for c in columns]
                      for r in rows])
    return write_text(path, buf.getvalue())


def relink(markdown: str, folder: str) -> str:
    """``markdown`` written in ``folder``, with its relative image and file
    links made relative to the folder above (for a report that gathers it)."""
    return re.sub(r"\]\((?!https?:|/)([^)]+)\)", lambda m: f"]({folder}/{m.group(1)})", markdown)


#: The sidecar of every result folder that names each CSV column's unit.
UNITS_FILE = "units.json"
#: The columns in the scene's stress unit, in its length unit and in
#: stress per length (a spring's stiffness); docs/scenes.md, "Units".
STRESS_COLUMNS = ("sxx", "syy", "sxy", "tN", "tT", "mean_tN", "mean_tT", "rms_tN", "rms_tT", "max_tN", "max_tT",
                  "E_minus", "E_plus", "max_tN_away", "max_tT_away", "est_tN", "est_tT")
LENGTH_COLUMNS = ("x", "y", "ux", "uy", "gN", "gT", "mean_gN", "mean_gT", "max_gN", "max_gT", "h", "exclude",
                  "radius", "offset", "stick_length")
SPRING_COLUMNS = ("kN", "kT")
#: The columns whose unit is the same in every scene's.
FIXED_UNITS = {**dict.fromkeys(("total", "mesh", "assembly", "solve", "median_s"), "s"), "angle": "degree",
               "points_per_s": "1/s"}


def column_units(units: Units = Units()) -> dict[str, str]:
    """The unit of each CSV column that has one, in the scene's ``units``
    (:class:`contactcore.scene.Units`: the names of its length unit ℓ and
    stress unit F/ℓ², labels only).  ``s`` is not here: its unit is its
    CSV's (:func:`scene_units`).  Columns not named (counts, statuses, names,
    ratios) have no unit."""
    return {**dict.fromkeys(STRESS_COLUMNS, units.stress), **dict.fromkeys(LENGTH_COLUMNS, units.length),
            **dict.fromkeys(SPRING_COLUMNS, f"{units.stress}/{units.length}"), **FIXED_UNITS}


def column_unit(column: str, units: Units = Units()) -> str | None:
    """A CSV column's unit in the scene's ``units`` (:func:`column_units`),
    an estimated error's its quantity's; None for a column without one
    (and for ``s``, whose unit is its CSV's: :func:`scene_units`)."""
    return column_units(units).get(column.removesuffix(ERROR_SUFFIX))


def labelled(text: str, column: str, units: Units = Units()) -> str:
    """``text`` followed by the unit of ``column`` in the scene's ``units``
    (:func:`column_unit`) if it has one: an axis's or a table's label."""
    unit = column_unit(column, units)
    return f"{text} ({unit})" if unit else text


#: The result folder's copy of the scene it solved (``run``, ``paper``, ``study``).
SCENE_FILE = "scene.toml"


def parameter_unit(parameter: str, units: Units = Units()) -> str:
    """The unit of an ``s`` column by what it measures along its line: an
    arc length (in the scene's length unit) or a polar angle about Γ's
    centre (rad)."""
    return units.length if parameter == "arclength" else "rad"


def scene_units(folder: Path) -> dict[str, tuple[Units, str | None]]:
    """The scene's :class:`~contactcore.scene.Units` of each CSV in a
    scene's result folder under ``folder`` (one holding :data:`SCENE_FILE`;
    the nearest above the CSV) and the unit of its ``s`` column if it has
    one, by the CSV's path relative to ``folder``: a profile's
    (``profiles/<ID>.csv``) by its parameter, resolved as its samples were
    (:func:`contactcore.profiles.sample_points`: a line profile's is an arc
    length, an interface profile's a polar angle only on a circle and if it
    asks for one); Γ's own (``interface.csv``,
    :func:`contactcore.interface_path.along`) a polar angle on a circle,
    else an arc length."""
    found = {}
    for toml in sorted(Path(folder).rglob(SCENE_FILE), key=lambda p: len(p.parts)):  # the nearest last
        scene = load_scene(toml)
        along = parameter_unit("angle" if isinstance(scene.interface, CircleInterface) else "arclength",
                               scene.units)
        by_id = {p.id: parameter_unit(sample_points(scene, p, 2)[2], scene.units) for p in scene.profiles}
        for path in toml.parent.rglob("*.csv"):
            s = by_id.get(path.stem) if path.parent.name == "profiles" else (
                along if path.name == "interface.csv" else None)
            found[path.relative_to(folder).as_posix()] = (scene.units, s)
    return found


#: The key of ``run.json`` under which a table over several scenes
#: (``timing``, ``effectivity``, ``scaling``) records the units its rows
#: share (:func:`shared_units`), for :func:`write_units`.
RUN_UNITS = "units"


def shared_units(scenes, field: str) -> Units:
    """The :class:`~contactcore.scene.Units` every one of ``scenes`` is in
    (SI for none).  A table over several scenes (timing.csv,
    effectivity.csv) has one unit per column (``units.json``), so scenes in
    different units are refused before any solve, naming each scene's, as
    an error of the option ``field`` that named them."""
    found = {scene.units for scene in scenes}
    if len(found) > 1:
        said = ", ".join(f"{scene.name} in {scene.units.length} and {scene.units.stress}" for scene in scenes)
        raise SceneError(field, f"the scenes are in different units ({said}): one table gives each column one "
                         "unit (units.json), so run the scenes of each set of units separately")
    return found.pop() if found else Units()


def run_units(units: Units) -> dict:
    """``run.json``'s entry for the units a table's rows share (:data:`RUN_UNITS`)."""
    return {RUN_UNITS: {"length": units.length, "stress": units.stress}}


def _recorded_units(folder: Path) -> dict[Path, Units]:
    """The units each ``run.json`` under ``folder`` records for its folder's
    tables (:func:`run_units`), by that folder."""
    found = {}
    for manifest in Path(folder).rglob(MANIFEST):
        try:
            given = json.loads(manifest.read_text()).get(RUN_UNITS)
        except (OSError, ValueError, AttributeError):
            continue
        if isinstance(given, dict):
            found[manifest.parent] = Units(**given)
    return found


def write_units(folder: Path) -> Path:
    """``folder/units.json``: for every CSV under ``folder`` (by its path
    relative to it), the unit of each of its columns that has one
    (:func:`column_unit` in the units of its scene; outside a scene's
    folder, those the nearest ``run.json`` above it records for a table
    over several scenes, :func:`run_units`, else SI's; ``s``'s from
    :func:`scene_units`); a ``units.json`` the command wrote names columns
    these rules cannot (``against``'s outside.csv), and its entries win."""
    units, scenes, recorded = {}, scene_units(folder), _recorded_units(folder)
    given = json.loads((Path(folder) / UNITS_FILE).read_text()) if (Path(folder) / UNITS_FILE).exists() else {}
    for path in sorted(Path(folder).rglob("*.csv")):
        with open(path, newline="") as fh:
            header = next(csv.reader(fh), [])
        name = path.relative_to(folder).as_posix()
        table = next((recorded[d] for d in path.parents if d in recorded), Units())
        own, s = scenes.get(name, (table, None))
        found = {c: s if c == "s" else column_unit(c, own) for c in header}
        units[name] = {**{c: unit for c, unit in found.items() if unit}, **given.get(name, {})}  # the command's own
    return write_json(Path(folder) / UNITS_FILE, units)
