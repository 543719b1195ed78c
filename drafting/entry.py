"""The ``drafting`` command's entry point: it imports the application only once it can answer an
interrupt, so a Ctrl-C while numpy and the engine are still loading ends the run with one line and exit
130 (no traceback, and no file exists yet).  Everything else is :func:`drafting.cli.main`."""

from __future__ import annotations

import sys


def main(argv=None) -> int:
    try:
        from .cli import main as run
    except KeyboardInterrupt:
        print("drafting: interrupted", file=sys.stderr)
        return 130
    return run(argv)
