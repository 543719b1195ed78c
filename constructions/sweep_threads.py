"""How many threads one sweep call runs on, and the pool they come from.

numpy releases the GIL inside its ufunc loops, so the sweep's closed-form kernels
(:mod:`constructions.sweep_kernels`) split a large call over threads: contiguous pieces of the angles,
each written by one thread into its own slice of the same output, so the numbers are the same bit for
bit on any number of threads.  The default is :func:`default_threads`: min(2, the cores this process may
run on), or the environment variable :data:`ENV` (an integer >= 1; any other value is ignored).  A
process that already uses every core -- a worker of a process pool -- sets one thread with
:func:`one_thread`.

The pool is made on first need and kept (no thread is started per call); its threads wait idle between
calls and end with the interpreter.  A forked child starts without it and makes its own.  This module
loads nothing but the standard library, so a pool worker may set its thread count before the engine is
imported.
"""

from __future__ import annotations

import itertools
import os
import threading

__all__ = ["ENV", "PREFIX", "THREADED_FROM", "default_threads", "in_pieces", "one_thread", "pool_threads", "threads_for"]

ENV = "DRAFTING_SWEEP_THREADS"
"""The environment variable that sets the default thread count of a sweep call (an integer >= 1)."""

THREADED_FROM = 30_000
"""Calls over fewer angles than this run on the calling thread.  Measured on the four-bar (2 cores of a
virtual machine, 2026-11-27, the other core free): two threads against one gave 0.5 of the speed at 1e3
angles, 0.64 at 1e4, 1.06 at 2e4, 1.1-1.15 at 3e4 and 5e4, 1.3-1.5 at 1e5 and 1e6.  Each thread takes the
GIL back after every numpy call (some 180 for a chunk), and when the other holds it the wait is the wake-up
of a sleeping thread, tens of microseconds here, against a few microseconds of arithmetic per call on a
few thousand angles."""

PREFIX = "sweep-thread"
"""The name prefix of the pool's threads (:mod:`drafting.app.parallel` tells them from a caller's own)."""

_lock = threading.Lock()
_pool = None
_process_threads: int | None = None


def _cores() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def default_threads() -> int:
    """The thread count of a sweep call that names none: 1 after :func:`one_thread`, else :data:`ENV` if it
    holds an integer >= 1, else min(2, the cores this process may run on)."""
    if _process_threads is not None:
        return _process_threads
    try:
        n = int(os.environ.get(ENV, ""))
    except ValueError:
        n = 0
    return n if n >= 1 else min(2, _cores())


def one_thread() -> None:
    """Every sweep call of this process on its calling thread (for a pool worker: the pool already uses
    every core)."""
    global _process_threads
    _process_threads = 1


def threads_for(n: int, threads: int | None = None) -> int:
    """The threads a call over ``n`` angles runs on: ``threads`` (None: :func:`default_threads`), but one
    below :data:`THREADED_FROM` angles and never more than there are angles."""
    if threads is None:
        threads = default_threads()
    elif isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
        raise ValueError(f"threads must be an integer >= 1 or None, not {threads!r}")
    return 1 if n < THREADED_FROM else min(threads, n)


def pool_threads() -> int:
    """How many of this process's threads are the pool's (idle between sweep calls)."""
    return sum(t.name.startswith(PREFIX) for t in threading.enumerate())


def _executor():
    global _pool
    with _lock:
        if _pool is None:
            import concurrent.futures
            _pool = concurrent.futures.ThreadPoolExecutor(thread_name_prefix=PREFIX)
        return _pool


def _forget_pool() -> None:
    global _pool, _lock
    _pool, _lock = None, threading.Lock()   # a forked child has none of the parent's threads


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_forget_pool)


def in_pieces(solve, n: int, threads: int | None, most: int) -> None:
    """``solve(i, j)`` for pieces [i, j) covering angles 0..n, on :func:`threads_for` ``(n, threads)``
    threads, the calling thread one of them.  The pieces depend on ``n`` and ``most`` alone, never on the
    thread count, so every angle goes through the same numpy calls with the same neighbours on any number
    of threads (numpy's vector loops and their scalar tails may give a NaN a different sign: the pieces,
    not the threads, decide which): one piece below :data:`THREADED_FROM` angles, else pieces of at most
    ``most`` angles and of at most half of them, so that two threads share even a few chunks' work.  The
    threads take the next piece as they come free; each piece is written by one thread.  Returns when
    every piece is done (an exception in any is raised here)."""
    size = max(1, n if n < THREADED_FROM else min(most, -(-n // 2)))
    count = -(-n // size)
    threads = threads_for(n, threads)
    if threads <= 1 or count <= 1:
        for k in range(count):
            solve(k * size, min(k * size + size, n))
        return
    taken = itertools.count()        # next() on it is atomic: no piece is taken twice

    def work():
        while (k := next(taken)) < count:
            solve(k * size, min(k * size + size, n))
    pool = _executor()
    helpers = [pool.submit(work) for _ in range(min(threads, count) - 1)]
    try:
        work()
    finally:
        for f in helpers:            # every helper done before the output is handed back
            f.exception()
    for f in helpers:
        f.result()
