"""Result files, written atomically, with the provenance of every run.

Every file is written to a temporary name in its final folder and renamed
when complete, so an interrupted run never leaves a half-written file under
a good name (:mod:`~verification.files.atomic_files`); a run's folder is
built beside its final name and put in place whole
(:mod:`~verification.files.result_folders`).  The package's face: its
public names, from the modules below.

* ``held_signals``: Ctrl-C and SIGTERM held while folders are swapped;
* ``atomic_files``: one file written atomically (``write_text``, ``write_json``);
* ``result_folders``: a run's folder built aside and put in place whole;
* ``tables``: profile CSVs, CSVs of rows, Markdown tables;
* ``units``: every CSV column's unit (``units.json``);
* ``run_provenance``: what produced a result folder (``run.json``).

Arrows: ``units`` → ``result_folders`` → ``atomic_files`` → ``held_signals``;
``result_folders`` → ``held_signals``; ``units``, ``tables`` → ``atomic_files``.
"""
from .atomic_files import atomic_path, write_json, write_text, writes_here
from .held_signals import HELD_SIGNALS, forget_signals, note_signal, signals_held
from .result_folders import MANIFEST, OutFolderError, atomic_folder, check_out, discard_unfinished, result_folder
from .run_provenance import git_commit, package_version, provenance, ranks, versions
from .tables import cell, markdown_table, md_escape, read_profile_csv, relink, write_csv, write_profile_csv
from .units import (FIXED_UNITS, LENGTH_COLUMNS, RUN_UNITS, SCENE_FILE, SPRING_COLUMNS, STRESS_COLUMNS, UNITS_FILE,
                    column_unit, column_units, labelled, parameter_unit, run_units, scene_units, shared_units,
                    write_units)

__all__ = ["FIXED_UNITS", "HELD_SIGNALS", "LENGTH_COLUMNS", "MANIFEST", "OutFolderError", "RUN_UNITS", "SCENE_FILE",
           "SPRING_COLUMNS", "STRESS_COLUMNS", "UNITS_FILE", "atomic_folder", "atomic_path", "cell", "check_out",
           "column_unit", "column_units", "discard_unfinished", "forget_signals", "git_commit", "labelled",
           "markdown_table", "md_escape", "note_signal", "package_version", "parameter_unit", "provenance", "ranks",
           "read_profile_csv", "relink", "result_folder", "run_units", "scene_units", "shared_units", "signals_held",
           "versions", "write_csv", "write_json", "write_profile_csv", "write_text", "write_units", "writes_here"]
