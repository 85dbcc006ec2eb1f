"""The unit of every CSV column of a result folder (``units.json``).

Contract: a column's unit follows from its name and the units of the
scene it belongs to (:func:`column_unit`; an ``s`` column's from what it
measures along its line, :func:`scene_units`); a table over several scenes
shares one set of units, refused otherwise (:func:`shared_units`) and
recorded in ``run.json`` (:func:`run_units`).  :func:`write_units` writes
``units.json`` for every CSV of a folder.
"""
from __future__ import annotations

import csv
import json
from pathlib import Path

from contactcore import CircleInterface, SceneError, load_scene
from contactcore.estimate.runs import ERROR_SUFFIX
from contactcore.profiles import sample_points
from contactcore.scene import Units

from .atomic_files import write_json
from .result_folders import MANIFEST


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
