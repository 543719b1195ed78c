"""A progress bar on a terminal, for the long jobs (a sweep of many angles, its CSV, a batch of scenes).

Drawn on stderr only when stderr is a terminal, so a pipe, a file or a test's captured output never sees
it: from the start for a long job, else once the job has run a second; redrawn in place with a carriage
return at most every ``MIN_STEP`` of the way, and finished with a newline.  Nothing here knows what it
measures: the job calls ``update(done)``.
"""

from __future__ import annotations

import sys
import time
from typing import TextIO

WIDTH = 30
MIN_STEP = 0.01
LONG = 100_000
"""Jobs of at least this many items (angles, rows) show a bar from the start."""
AFTER = 1.0
"""s: a shorter job shows its bar once it has run this long (a slow sweep of a few thousand poses)."""


class Progress:
    def __init__(self, total: int, label: str, stream: TextIO | None = None, *, force: bool = False) -> None:
        self.total, self.label = max(int(total), 1), label
        stream = stream if stream is not None else sys.stderr
        self.stream = getattr(stream, "unescaped", stream)    # the CLI escapes control characters; not ours
        self.terminal = _is_terminal(self.stream)
        self.shown = force or (total >= LONG and self.terminal)
        self.last = -1.0
        self.start = time.perf_counter()

    def update(self, done: int) -> None:
        if not self.shown:
            if not self.terminal or done >= self.total or time.perf_counter() - self.start < AFTER:
                return
            self.shown = True
        f = min(max(done / self.total, 0.0), 1.0)
        if f < 1.0 and f - self.last < MIN_STEP:
            return
        self.last = f
        bar = "#" * round(f * WIDTH)
        self.stream.write(f"\r{self.label} [{bar:<{WIDTH}}] {f * 100:5.1f} % "
                          f"({time.perf_counter() - self.start:.1f} s)")
        self.stream.flush()

    def finish(self) -> None:
        if self.shown:
            self.update(self.total)
            self.stream.write("\n")
            self.stream.flush()


def _is_terminal(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


def is_tty(stream) -> bool:
    """Whether ``stream`` (or the terminal behind the CLI's escaping wrapper) is a terminal."""
    return _is_terminal(getattr(stream, "unescaped", stream))
