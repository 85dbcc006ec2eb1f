"""The parts of the command line ``python -m verification``, one idea per
module; :mod:`verification.__main__` (``main``) joins them.

- :mod:`.arguments`: one argument's text to its value (argparse's ``type=``);
- :mod:`.runners`: each command's runner, from the parsed arguments to its driver;
- :mod:`.commands`: the command table (``Command``, :func:`~.commands.commands`);
- :mod:`.parser`: the argparse parser of that table, refusing in one line;
- :mod:`.checks`: the checks every command makes before it runs;
- :mod:`.folders`: the result folder, rank 0's alone under mpirun;
- :mod:`.logs`: the command's log on stderr, repeats counted;
- :mod:`.signals`: how Ctrl-C and SIGTERM end a command, the exit statuses;
- :mod:`.held_imports`: the slow C imports run with both signals held.

Contract: only :mod:`verification.__main__` and these modules import this
package (argparse and the logging configuration stay with the command line:
tests/test_cli_layout.py), and importing any of them loads no numerics
(dolfinx, gmsh, matplotlib, efgm: tests/test_imports.py); a driver's module
is imported when its command runs.
"""
