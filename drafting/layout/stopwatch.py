"""Where a sheet's layout time goes: the page planner's and the label placer's time, summed while a
benchmark asks for it (``drafting bench --gallery``); otherwise nothing is timed."""

from __future__ import annotations

import functools
import time
from typing import Callable, TypeVar

F = TypeVar("F", bound=Callable)

STAGES = ("plan", "labels")
"""The timed parts of the layout: the page planner (every plan tried, the text flowed into it) and the
label placer (every drawing's labels and leaders)."""

_totals: dict[str, float] | None = None


def timed(stage: str) -> Callable[[F], F]:
    """``fn`` with its time added to ``stage``'s total while :func:`start` has been called (the stages'
    functions do not call each other)."""
    def wrap(fn: F) -> F:
        @functools.wraps(fn)
        def run(*args, **kwargs):
            if _totals is None:
                return fn(*args, **kwargs)
            t0 = time.perf_counter()
            try:
                return fn(*args, **kwargs)
            finally:
                if _totals is not None:
                    _totals[stage] += time.perf_counter() - t0
        return run  # type: ignore[return-value]
    return wrap


def start() -> None:
    """Time the stages from now on, from zero."""
    global _totals
    _totals = dict.fromkeys(STAGES, 0.0)


def stop() -> dict[str, float]:
    """The stages' totals since :func:`start` (seconds); timing off again."""
    global _totals
    got, _totals = _totals or dict.fromkeys(STAGES, 0.0), None
    return got
