"""The four-bar sweep's default call against one thread, side by side in one process: for each size the
calls alternate, fresh output each time, and the median [best] full states per second of each is printed,
with the machine's load and speed (the yardstick of ``drafting bench``: a plain-Python sum of 200,000
squares) before and after.  A second pass sets one thread against the default thread count with
:data:`constructions.sweep_threads.THREADED_FROM` lifted (threads at every size): where the threads beat one
thread is where the threshold belongs.  (Two passes, not three columns: a call on pieces of another length
makes the next call on the thread remake its scratch arrays.)

Usage: ``python benchmarks/sweep_threads.py [calls [n ...]]`` (default 15 calls each at 1e3 .. 1e6).
"""

import os
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled

import numpy as np  # noqa: E402

from constructions import sweep_threads  # noqa: E402
from constructions.sweep_kernels import four_bar  # noqa: E402

MECHANISM = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.1, 0.02), crank=0.03, coupler=0.09, rocker=0.07, branch=1)


def yardstick() -> str:
    """The least of three timings of the plain-Python loop, and the load average."""
    best = min(_loop() for _ in range(3))
    return f"yardstick {best * 1e3:.1f} ms, load {' '.join(f'{x:.2f}' for x in os.getloadavg())}"


def _loop() -> float:
    t = time.perf_counter()
    sum(i * i for i in range(200_000))
    return time.perf_counter() - t


def side_by_side(sizes, calls, columns):
    """Rows of (n, {column: wall times}): ``columns`` maps a name to the keywords of its call, or to None for
    the default thread count with the threshold lifted."""
    rows = []
    for n in sizes:
        theta = np.linspace(0.0, 2.0 * np.pi, n)
        times = {c: [] for c in columns}
        for k in range(calls + 1):                       # the first round warms up, untimed
            for c, kw in columns.items():
                saved = sweep_threads.THREADED_FROM
                sweep_threads.THREADED_FROM = 2 if kw is None else saved
                try:
                    t = time.perf_counter()
                    state = four_bar(theta, 10.0, 20.0, **(kw or {}), **MECHANISM)
                    wall = time.perf_counter() - t
                finally:
                    sweep_threads.THREADED_FROM = saved
                del state
                if k:
                    times[c].append(wall)
        rows.append((n, times))
    return rows


def main(argv) -> None:
    calls = int(argv[0]) if argv else 15
    sizes = tuple(int(float(a)) for a in argv[1:]) or (10**3, 10**4, 10**5, 10**6)
    threads = sweep_threads.default_threads()
    print(f"before: {yardstick()}; default threads {threads}, threaded from {sweep_threads.THREADED_FROM} "
          f"angles; {calls} calls each, alternating; median [best] full states/s")
    for columns in ({"one thread": dict(threads=1), "default": {}},
                    {"one thread": dict(threads=1), f"{threads} threads at any size": None}):
        for n, times in side_by_side(sizes, calls, columns):
            cells = [f"{c} {n / statistics.median(v):.2e} [{n / min(v):.2e}]" for c, v in times.items()]
            ratio = statistics.median(times["one thread"]) / statistics.median(list(times.values())[1])
            print(f"{n:>9.0e}  " + "  ".join(cells) + f"  second/one {ratio:.2f}")
    print(f"after: {yardstick()}")


if __name__ == "__main__":
    main(sys.argv[1:])
