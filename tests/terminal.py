"""How a test starts a command as a user's terminal would."""
from __future__ import annotations

import signal


def with_ctrl_c() -> None:
    """``preexec_fn`` for a child that must take Ctrl-C as a terminal's
    command does: SIGINT back to its default. A shell starts a background
    job's processes with SIGINT ignored, pytest's workers and their children
    inherit that, and Python installs no KeyboardInterrupt handler over an
    ignored SIGINT: started so, the run went on to its end, exit 0."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
