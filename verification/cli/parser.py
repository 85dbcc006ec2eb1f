"""The argparse parser of the command table, whose refusals are one line.

Contract: :func:`build_parser` turns :func:`verification.cli.commands.commands`
into one parser (``prog`` ``python -m verification``, a subcommand a
command, ``-q``/``-v`` on each); its ``parse_args`` returns the Namespace
with ``command`` and ``verbosity`` set, prints ``--help`` and exits 0, or
refuses a command line with one line ``error: COMMAND: problem`` and exit
status 2 (:class:`OneLineParser`).
"""
from __future__ import annotations

import argparse

from .commands import Command, commands as command_table


class OneLineParser(argparse.ArgumentParser):
    """argparse, whose refusal of a command line ends as every other bad
    input does: one line ``error: COMMAND: problem``, exit status 2 (not
    the usage block; ``--help`` shows it)."""

    def error(self, message: str):
        """Exit 2 after the one line (argparse's ``error``, without the usage block)."""
        command = self.prog.removeprefix("python -m verification").strip()
        self.exit(2, f"error: {command + ': ' if command else ''}{message}\n")


def build_parser(commands: dict[str, Command] | None = None) -> argparse.ArgumentParser:
    """The argparse parser of the command table (:func:`~verification.cli.commands.commands` by default)."""
    commands = command_table() if commands is None else commands
    parser = OneLineParser(prog="python -m verification")
    common = OneLineParser(add_help=False)
    talk = common.add_mutually_exclusive_group()
    talk.add_argument("-q", "--quiet", action="store_const", dest="verbosity", const=-1, default=0,
                      help="errors and warnings only")
    talk.add_argument("-v", "--verbose", action="store_const", dest="verbosity", const=1,
                      help="also the debug messages of this tool")
    sub = parser.add_subparsers(dest="command", required=True)
    for name, command in commands.items():
        p = sub.add_parser(name, parents=[common], help=command.help, epilog=command.epilog or None,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        for a in command.args:
            p.add_argument(*a.flags, **a.options)
    return parser
