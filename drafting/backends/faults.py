"""Faults: interrupts (SIGINT, SIGTERM) and the temporary files that must not outlive them.

- Every temporary file the program creates is registered here *before* it is created
  (:func:`track`), so :func:`remove_temporaries` can remove whatever exists at any moment.
- :func:`signals_handled` (used by the CLI's ``main``) turns SIGINT and SIGTERM into
  :class:`Interrupted`, a BaseException (so no ``except Exception`` swallows it), after removing the
  temporary files.  The CLI ends with exit code 128 + signal: 130 for SIGINT, 143 for SIGTERM.
- Inside :func:`deferred` a signal is only recorded and acted upon when the block ends: used around
  cairo's conversions (a Python exception raised inside a C callback would be printed, not raised) and
  around the renames that put one scene's files in place together.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from collections.abc import Iterator

HANDLED = {signal.SIGINT: "SIGINT", signal.SIGTERM: "SIGTERM"}

_temps: set[str] = set()
_defer_depth = 0
_pending: int | None = None


class Interrupted(BaseException):
    """The run was interrupted by a signal; ``exit_code`` is 128 + the signal number."""

    def __init__(self, signum: int) -> None:
        self.signum = signum
        self.name = HANDLED.get(signum, f"signal {signum}")
        self.exit_code = 128 + int(signum)
        super().__init__(f"interrupted by {self.name}")


def track(path: os.PathLike | str) -> None:
    """Register a temporary file (before creating it)."""
    _temps.add(os.fspath(path))


def untrack(path: os.PathLike | str) -> None:
    """Forget a temporary file (after renaming it into place or removing it)."""
    _temps.discard(os.fspath(path))


def tracked() -> frozenset[str]:
    return frozenset(_temps)


def remove_temporaries() -> None:
    """Remove every registered temporary file that exists (safe to call at any moment, repeatedly)."""
    for p in list(_temps):
        try:
            os.unlink(p)
        except FileNotFoundError:
            pass
        except OSError:
            continue
        _temps.discard(p)


def _handler(signum, frame) -> None:
    global _pending
    if _defer_depth:
        if _pending is None:
            _pending = signum
        return
    remove_temporaries()
    raise Interrupted(signum)


def end_worker(signum, frame) -> None:
    """SIGTERM in a pool worker: its temporary files removed and the process gone at once -- or, inside
    a :func:`deferred` block (a cairo conversion, the renames that put a job's files in place), at the
    end of that block."""
    if _defer_depth:
        _handler(signum, frame)
        return
    remove_temporaries()
    os._exit(128 + signum)


@contextlib.contextmanager
def deferred() -> Iterator[None]:
    """Hold a signal that arrives inside the block until the block ends (then raise Interrupted).

    Only the main thread's blocks count: Python runs signal handlers in the main thread alone, so a
    block in another thread (sheets written by a thread pool in a notebook) neither holds the main
    thread's signal nor has it raised at its own end."""
    global _defer_depth, _pending
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    _defer_depth += 1
    try:
        yield
    finally:
        _defer_depth -= 1
        if _defer_depth == 0 and _pending is not None:
            signum, _pending = _pending, None
            remove_temporaries()
            raise Interrupted(signum)


@contextlib.contextmanager
def signals_handled(after=None) -> Iterator[None]:
    """SIGINT and SIGTERM raise :class:`Interrupted` inside the block (main thread only); afterwards the
    previous handlers are restored, or ``after`` is put in their place (the command line passes
    ``signal.SIG_IGN``: its work is done, so a signal in the moment before the process exits changes
    nothing, rather than killing it with a misleading status)."""
    global _pending
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {}
    try:
        for s in HANDLED:
            previous[s] = signal.signal(s, _handler)
        yield
    finally:
        for s, h in previous.items():
            signal.signal(s, h if after is None else after)
        _pending = None
