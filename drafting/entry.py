"""The ``drafting`` command's entry point: it imports the application (and the command, which
:func:`drafting.app.cli.main` loads before putting its own handlers in place) only once it can answer an
interrupt, so a Ctrl-C while numpy and the engine are still loading ends the run with one line and exit
130 (no traceback, and no file exists yet).  Everything else is :func:`drafting.app.cli.main`.

While loading, SIGINT ends the process at once (``os._exit``) rather than raising KeyboardInterrupt: an
exception raised inside the import machinery can land in one of its callbacks, where Python can only
print it ("Exception ignored in ...") and go on."""

from __future__ import annotations

import os
import signal
import threading


def _end_while_loading(signum, frame) -> None:
    os.write(2, b"drafting: interrupted\n")
    os._exit(130)


def main(argv=None) -> int:
    main_thread = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGINT, _end_while_loading) if main_thread else None
    try:
        from .app.cli import main as run
    except BaseException:
        if main_thread:
            signal.signal(signal.SIGINT, previous)
        raise
    return run(argv, exiting=True)          # loads the command's own modules under our handler, then its own
