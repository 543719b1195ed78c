"""Throughput of the analytic full-cycle sweep (positions + velocities), as a plain text table.

Used by ``benchmarks/analytic_sweep.py``.  Timings are reported, never asserted.

Each row is one mechanism at one sweep size ``n``: the median wall time of ``repeats`` calls (after
one untimed warm-up call), the resulting crank angles per second, the best call, and the median
process CPU time of a call split into user and system time.  The split matters for large sweeps: the
outputs are ~105 bytes per angle (13 float64 arrays + 1 bool), so a 1e7-angle sweep writes ~1 GB of
freshly allocated memory and the kernel's first-touch page faults (system time) can rival the
arithmetic (user time).  ``os.times`` ticks at 10 ms, so the CPU columns mean little for small n.
"""

from __future__ import annotations

import os
import time

import numpy as np

from constructions.analytic import four_bar, slider_crank

__all__ = ["MECHANISMS", "format_table", "sweep_rows"]

#: The benchmarked mechanisms (SI units): a Grashof crank-rocker and an offset slider-crank
#: (the notes' 50 mm / 94 mm slider-crank with a 10 mm offset).
MECHANISMS = {
    "four-bar": (four_bar, dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.1, 0.02), crank=0.03,
                                coupler=0.09, rocker=0.07, branch=1)),
    "slider-crank": (slider_crank, dict(crank_pivot=(0.0, 0.0), crank=0.05, coupler=0.094,
                                        guide_point=(0.0, 0.01), guide_angle=0.0, branch=1)),
}


def _time_call(fn, theta, omega1, mech):
    t0 = os.times()
    w0 = time.perf_counter()
    state = fn(theta, omega1, **mech)
    wall = time.perf_counter() - w0
    t1 = os.times()
    del state  # free the ~105 bytes/angle of output before the next call
    return wall, t1.user - t0.user, t1.system - t0.system


def sweep_rows(sizes=(10**3, 10**4, 10**5, 10**6, 10**7), repeats=5):
    """Time full-cycle sweeps of the benchmark mechanisms.

    Parameters
    ----------
    sizes : iterable of int
        Numbers of crank angles per sweep (``np.linspace(0, 2 pi, n)``).
    repeats : int
        Timed calls per (mechanism, size), after one untimed warm-up call.

    Returns
    -------
    list of dict
        One dict per (mechanism, n) with keys ``mechanism``, ``n``, ``median_seconds``,
        ``angles_per_second`` (n / median), ``best_angles_per_second``, ``cpu_user_seconds`` and
        ``cpu_system_seconds`` (medians per call).
    """
    if repeats < 1:
        raise ValueError("repeats must be at least 1")
    rows = []
    omega1 = 10.0
    for n in sizes:
        n = int(n)
        theta = np.linspace(0.0, 2.0 * np.pi, n)
        for name, (fn, mech) in MECHANISMS.items():
            _time_call(fn, theta, omega1, mech)  # warm-up
            walls, users, systems = [], [], []
            for _ in range(repeats):
                wall, user, system = _time_call(fn, theta, omega1, mech)
                walls.append(wall)
                users.append(user)
                systems.append(system)
            median = float(np.median(walls))
            rows.append(dict(
                mechanism=name,
                n=n,
                median_seconds=median,
                angles_per_second=n / median if median > 0 else float("inf"),
                best_angles_per_second=n / min(walls) if min(walls) > 0 else float("inf"),
                cpu_user_seconds=float(np.median(users)),
                cpu_system_seconds=float(np.median(systems)),
            ))
        del theta
    return rows


def format_table(rows):
    """Format :func:`sweep_rows` output as a plain, aligned text table.

    Parameters
    ----------
    rows : list of dict
        As returned by :func:`sweep_rows` (the CPU and best-call keys are optional).

    Returns
    -------
    str
        One header line, a rule, and one line per row.
    """
    header = ("mechanism", "n", "median s", "angles/s", "best angles/s", "cpu user s", "cpu sys s")
    lines = []
    for r in rows:
        lines.append((
            str(r["mechanism"]) if "mechanism" in r else "",
            f"{r['n']:.0e}" if r["n"] >= 10**3 else str(r["n"]),
            f"{r['median_seconds']:.4g}",
            f"{r['angles_per_second']:.3g}",
            f"{r['best_angles_per_second']:.3g}" if "best_angles_per_second" in r else "",
            f"{r['cpu_user_seconds']:.2f}" if "cpu_user_seconds" in r else "",
            f"{r['cpu_system_seconds']:.2f}" if "cpu_system_seconds" in r else "",
        ))
    widths = [max(len(h), *(len(line[i]) for line in lines)) if lines else len(h)
              for i, h in enumerate(header)]

    def fmt(cells):
        first = cells[0].ljust(widths[0])
        rest = (c.rjust(w) for c, w in zip(cells[1:], widths[1:]))
        return "  ".join((first, *rest)).rstrip()

    out = [fmt(header), "  ".join("-" * w for w in widths)]
    out.extend(fmt(line) for line in lines)
    return "\n".join(out)
