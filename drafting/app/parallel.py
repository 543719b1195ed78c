"""Running independent jobs (scenes to render, variants of a batch) over an executor, with the fault
guarantees of a single process.

Any object with the :class:`concurrent.futures.Executor` interface will do (``submit`` returning
futures): a thread pool, a process pool, or a cluster's executor such as Dask's
``distributed.Client().get_executor()``.  Without one, :func:`run` makes a process pool over the cores
the process may use -- forked, so each worker starts with the engine already imported (from a process
running threads, such as a notebook's kernel, through the fork server instead) -- or, for fewer
than :data:`SERIAL_BELOW` jobs or one core, runs them one after the other in this process (a pool's
start-up and the pickling of results cost more than they save on a few jobs).  ``concurrent.futures``
and ``multiprocessing`` are loaded only when jobs run over an executor: one scene does without them.

Faults, with the default process pool:

- Each job writes its own files atomically (:mod:`drafting.backends.files`: temporary files named with the
  worker's pid, renamed into place together), so a job is on disk whole or not at all.
- The workers ignore SIGINT (a Ctrl-C reaches the whole process group; the parent decides) and turn
  SIGTERM into the same clean end as the command's (temporary files removed first); on Linux each
  worker is sent SIGTERM when the parent dies, even by ``kill -9``.
- When the parent is interrupted (SIGINT, SIGTERM, a broken pipe, any exception) it cancels the jobs
  not started, sends SIGTERM to the workers, waits for them (SIGKILL after :data:`GRACE_SECONDS`) and
  removes any temporary file a worker left in the output folders -- so an interrupted run leaves no
  half-written file, only the jobs that finished.
"""

from __future__ import annotations

import contextlib
import gc
import os
import signal
import sys
import threading
from typing import TYPE_CHECKING, Any, Callable, Iterable, Iterator, Sequence

from constructions import sweep_threads

from ..backends import faults

if TYPE_CHECKING:
    import concurrent.futures as cf

SERIAL_BELOW = 3
"""Fewer jobs than this run serially when no executor is given (see the module docstring)."""
GRACE_SECONDS = 20.0
"""How long an interrupted worker may take to remove its temporary files before it is killed."""
HELD = frozenset({signal.SIGINT, signal.SIGTERM})
"""The signals held back (blocked) while this process starts its pool: see :func:`_held`."""


class WorkerLost(Exception):
    """A worker process of the pool died (killed from outside): one sentence."""


def cores() -> int:
    """The cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


#: The young-generation threshold of a process the command owns (the default is 700).
GC_YOUNG = 20_000


def collect_less() -> None:
    """Young collections less often (a sheet allocates many small short-lived objects and few cycles).
    The command's own process sets it before its modules load, so the engine's thousands of functions,
    classes and dataclasses are not interrupted by some fifty collections on the way."""
    gc.set_threshold(GC_YOUNG, 20, 20)


def tune_gc() -> None:
    """For a process the command owns (never a caller's, such as a notebook's): what is loaded so far --
    modules, unit tables, fonts -- is moved out of the garbage collector's way (``gc.freeze``), and young
    collections run less often (:func:`collect_less`).
    Measured on the default sheet: ~10 % off solve + layout + SVG (median 25.2 -> 22.2 ms)."""
    gc.freeze()
    collect_less()


def leave_to_exit() -> None:
    """For a process the command owns, its work done: everything it made is frozen too, so the
    interpreter's last full collection at exit has nothing to traverse (some 10 ms of a render; the
    objects end with the process, which flushes its streams and runs its exit handlers as always)."""
    gc.freeze()


def _worker_init() -> None:
    """In each pool worker: SIGINT ignored (the parent coordinates), SIGTERM a clean end, and SIGTERM
    when the parent dies (Linux); the collector tuned as in the command's own process; each sweep on the
    worker's own thread (the pool already uses every core)."""
    tune_gc()
    sweep_threads.one_thread()
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, faults.end_worker)
    if hasattr(signal, "pthread_sigmask"):      # started with them blocked (_held): its own handlers now run
        signal.pthread_sigmask(signal.SIG_UNBLOCK, HELD)
    try:
        import ctypes
        libc = ctypes.CDLL(None, use_errno=True)
        PR_SET_PDEATHSIG = 1
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGTERM, 0, 0, 0)
        if os.getppid() == 1:                   # the parent died before prctl
            os._exit(128 + signal.SIGTERM)
    except (OSError, AttributeError):
        pass


@contextlib.contextmanager
def _held() -> Iterator[None]:
    """SIGINT and SIGTERM blocked while this process starts its pool.  A forked worker inherits the
    block, so a signal sent to it before :func:`_worker_init` has put its own handlers in place waits
    for them (else it ran this process's handler mid-fork: "Exception ignored ... _releaseLock" and a
    worker that lived on); and this process takes its own signal only once every worker is recorded in
    the pool, so that :func:`_stop_pool` ends them all (else a worker forked but not yet recorded was
    never told, and the exit waited for it for ever).  Found by the fault tests sending the signal while
    the pool starts."""
    if not hasattr(signal, "pthread_sigmask") or threading.current_thread() is not threading.main_thread():
        yield
        return
    before = signal.pthread_sigmask(signal.SIG_BLOCK, HELD)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, before)


def _call(fn: Callable[[Any], Any], job: Any) -> Any:
    """One job in a worker: an interrupt ends the worker at once, its temporary files removed."""
    try:
        return fn(job)
    except faults.Interrupted as e:
        import multiprocessing
        faults.remove_temporaries()
        if multiprocessing.parent_process() is not None:       # a pool worker: end the process
            os._exit(e.exit_code)
        raise


def default_executor(n_jobs: int, workers: int | None = None) -> cf.Executor | None:
    """A process pool over the cores for ``n_jobs`` jobs, or None (run serially) for a few jobs or one
    core."""
    n = workers or cores()
    if n_jobs < SERIAL_BELOW or n < 2:
        return None
    import concurrent.futures as cf            # loaded for a pool only: a serial run does without
    import multiprocessing
    methods = multiprocessing.get_all_start_methods()
    # fork: each worker starts with the engine imported -- unless this process runs threads (a notebook's),
    # which a fork would copy mid-step; then the fork server.  The sweep's idle pool threads do not count:
    # they work only while a sweep call waits for them, and a forked child makes its own
    if "fork" in methods and threading.active_count() - sweep_threads.pool_threads() == 1:
        ctx = multiprocessing.get_context("fork")
    else:
        ctx = multiprocessing.get_context("forkserver" if "forkserver" in methods else "spawn")
    return cf.ProcessPoolExecutor(max_workers=min(n, n_jobs), mp_context=ctx, initializer=_worker_init)


def run(fn: Callable[[Any], Any], jobs: Sequence[Any], *, executor: cf.Executor | None = None,
        on_done: Callable[[int, Any], None] | None = None, folders: Iterable[os.PathLike | str] = (),
        workers: int | None = None) -> list[Any]:
    """``[fn(job) for job in jobs]``, the jobs run over ``executor`` (default: :func:`default_executor`).

    ``on_done(i, result)`` is called in this process, in the order the jobs finish.  ``fn`` must be a
    module-level function and the jobs and results picklable (for a process pool or a cluster).
    ``folders`` are where the jobs write: after an interrupt, temporary files the workers left there
    are removed.  An exception of a job is raised here (the others are cancelled first)."""
    jobs = list(jobs)
    own = executor is None
    if own:
        executor = default_executor(len(jobs), workers)
    if executor is None:                                  # serial, in this process
        out = []
        for i, job in enumerate(jobs):
            r = fn(job)
            out.append(r)
            if on_done is not None:
                on_done(i, r)
        return out
    import concurrent.futures as cf
    results: list[Any] = [None] * len(jobs)
    futures: dict[cf.Future, int] = {}
    clean = False
    try:
        with _held() if own else contextlib.nullcontext():      # the pool forks its workers on the first submit
            for i, job in enumerate(jobs):
                futures[executor.submit(_call, fn, job)] = i
        for fut in cf.as_completed(futures):
            i = futures[fut]
            try:
                results[i] = fut.result()
            except cf.process.BrokenProcessPool:
                raise WorkerLost("a worker process ended before its job was done (killed from outside?); "
                                 "the jobs that finished are written whole, the others not at all") from None
            if on_done is not None:
                on_done(i, results[i])
        clean = True
        return results
    finally:
        if not clean:
            if own:
                _stop_pool(executor, folders)
            else:
                for f in futures:
                    f.cancel()
        elif own:
            executor.shutdown(wait=True)


def _stop_pool(executor: cf.Executor, folders: Iterable[os.PathLike | str]) -> None:
    """End a process pool now: SIGTERM to every worker (each removes its temporary files), wait, SIGKILL
    what is left, then remove the temporary files of the workers that are gone."""
    import concurrent.futures as cf
    with faults.deferred():
        procs = list((getattr(executor, "_processes", None) or {}).values()) \
            if isinstance(executor, cf.ProcessPoolExecutor) else []
        manager = getattr(executor, "_executor_manager_thread", None)       # (shutdown forgets it)
        try:          # the pool's own thread cancels what has not started (cancelling it here races it)
            executor.shutdown(wait=False, cancel_futures=True)
        except Exception:
            pass
        for p in procs:
            try:
                if p.is_alive():
                    os.kill(p.pid, signal.SIGTERM)
            except (OSError, ValueError):
                pass
        for p in procs:
            p.join(GRACE_SECONDS)
            if p.is_alive():
                try:
                    p.kill()
                except (OSError, ValueError):
                    pass
                p.join(5.0)
        # the pool's own thread, which notices its workers gone and closes its wake-up pipe, ends before
        # this returns: at exit Python 3.11 wakes that thread through the pipe, and if the two cross the
        # write hits the closed pipe ("Exception ignored ... Bad file descriptor" after the interrupt line)
        if manager is not None:
            manager.join(GRACE_SECONDS + 5.0)
        from ..backends.files import remove_stale_temporaries
        for folder in folders:
            remove_stale_temporaries(folder)
    sys.stderr.flush()
