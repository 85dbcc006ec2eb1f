"""How a command ended by a signal reports it, shared by every command
line (``python -m verification``, ``python -m meshes``): the exit statuses
a shell expects and the exception SIGTERM raises where the command is."""

#: The exit status of a command ended by Ctrl-C: 128 + SIGINT, as a shell reports it.
INTERRUPTED = 130
#: ... and by SIGTERM (``kill``, ``timeout``, a batch scheduler): 128 + SIGTERM.
TERMINATED = 143


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised where the process is, so that it ends as Ctrl-C does:
    what is under way discarded, one line."""
