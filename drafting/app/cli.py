"""The ``drafting`` command.

    drafting                      render the built-in example (notes, velocity Example 1)
    drafting render SCENE...      sheets as SVG, PDF and PNG
    drafting solve SCENE --json   results in the scene's units and the analyses that ran
    drafting check SCENE...       graphical against analytic; exit 1 on disagreement
    drafting check SCENE --answers FILE   a student's values marked at drawing accuracy
    drafting render SCENE --lab   problem sheet, worked solution and answer key
    drafting batch SCENE --variants N --seed S -o DIR   N lab-sheet variants from the scene's [vary]
    drafting bench [--peers]      timings of rendering and of the analytic sweep (and its peers)
    drafting lint SCENE... [--json]   the sheet critic's findings; exit 1 when there are any
    drafting bench --gallery      every gallery sheet's solve, layout and SVG times (--json)
    drafting keys KIND            a scene kind's keys: unit, default, meaning (--markdown: every kind)
    drafting new KIND [--example NAME] [-o FILE]   an annotated starter scene that renders

Exit codes: 0 fine, 1 graphical and analytic disagree, 2 bad input (one sentence on stderr).
"""

from __future__ import annotations

import argparse
import importlib
import os
import signal
import sys
from collections.abc import Sequence
from types import ModuleType

from ..backends.faults import Interrupted, remove_temporaries, signals_handled
from .arguments import parser
from ..scene.textsafe import safe_streams

COMMANDS = {
    None: ".render_cmd", "render": ".render_cmd", "solve": ".solve_cmd", "check": ".check_cmd",
    "batch": ".batch_cmd", "bench": ".bench", "lint": ".lint_cmd", "export": ".cam_export",
    "sweep": ".sweep_cmd", "serve": "..serve.command", "keys": ".keys_cmd", "new": ".new_cmd",
}
"""Each command's module (relative to this package), imported only when that command runs: its
``run_command(args)`` runs it.  ``drafting --help`` and a command's start load nothing they do not use
(numpy, the engine, svgwrite, cairo are each loaded by the modules that draw or solve)."""


def main(argv: Sequence[str] | None = None, *, exiting: bool = False) -> int:
    """The command.  SIGINT and SIGTERM end it cleanly, temporary files removed, with exit code 130 or
    143; whatever reaches the terminal has its control characters escaped (a title cannot move the
    cursor).  The arguments are read and the command's module loaded first, under the caller's SIGINT
    handler (:mod:`drafting.entry`'s while the ``drafting`` command loads), then its own handlers run it."""
    with safe_streams():
        try:
            args, command = _load(argv, exiting)
            # the signal may come while the handlers are being put in place: the try holds that too
            # a process about to exit (``exiting``) ignores a late signal: its status is the work's
            with signals_handled(after=signal.SIG_IGN if exiting else None):
                return _main(args, command, exiting)
        except Interrupted as e:
            return _interrupted(e.name, e.exit_code)
        except KeyboardInterrupt:             # before the handlers were in place
            return _interrupted("SIGINT", 130)
        except BrokenPipeError:               # the reader went away (drafting ... | head): stop quietly
            remove_temporaries()
            _silence_stdout()
            return 141


def _interrupted(name: str, code: int) -> int:
    remove_temporaries()
    print(f"drafting: interrupted by {name}; no file was left half-written", file=sys.stderr)
    return code


def _silence_stdout() -> None:
    """After a broken pipe, point stdout at /dev/null so the interpreter's final flush cannot fail."""
    try:
        fd = os.open(os.devnull, os.O_WRONLY)
        os.dup2(fd, sys.__stdout__.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def _load(argv: Sequence[str] | None, exiting: bool = False) -> tuple[argparse.Namespace, ModuleType]:
    """The parsed arguments and the module of their command (:data:`COMMANDS`), imported now -- in the
    command's own process (``exiting``) with the collector tuned for loading first
    (:func:`drafting.app.parallel.collect_less`)."""
    args = parser().parse_args(argv)
    if exiting:
        from .parallel import collect_less
        collect_less()
    return args, importlib.import_module(COMMANDS[args.command], __package__)


def _main(args: argparse.Namespace, command: ModuleType, exiting: bool = False) -> int:
    from .solving import UserError                  # loaded by the command's module already
    if exiting:                                     # the process is the command's own: what the command
        from .parallel import tune_gc               # loaded is frozen out of the collector's way
        tune_gc()
    try:
        return command.run_command(args)
    except UserError as e:
        print(f"drafting: error: {e}", file=sys.stderr)
        return e.code
    finally:
        if exiting:
            from .parallel import leave_to_exit
            leave_to_exit()


if __name__ == "__main__":
    sys.exit(main(exiting=True))
