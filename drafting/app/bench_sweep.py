"""Throughput of the analytic full-cycle sweep (full states: positions, velocities and accelerations),
as a plain text table.

Used by ``benchmarks/analytic_sweep.py`` and ``drafting bench``.  Timings are reported, never asserted.

Three mechanisms side by side: the four-bar and slider-crank closed forms of
:mod:`constructions.analytic` (as the sweep runs them: the default call, on the default threads of
:mod:`constructions.sweep_threads`; the four-bar also on one thread and into the caller's buffers) and the
general dyad-chain solver of :mod:`constructions.vector_loops` on a six-bar (the notes' toggle linkage of ``gallery/notes-velocity-example-3.toml``: a four-bar
driving a slider through a second coupler).  A full state is everything the solver returns at one crank
angle: for the four-bar the positions, velocities and accelerations of B and C, the link angles,
omega2, omega3, alpha2, alpha3 and the condition (19 float64 arrays + 1 bool, ~153 bytes per angle);
for the six-bar the same for every joint and link.  The crank turns with omega = 10 rad/s and
alpha = 20 rad/s^2 (a nonzero alpha exercises every term).

Each row is one mechanism at one sweep size ``n``: the median wall time of ``repeats`` calls (after one
untimed warm-up call), the resulting full states per second, the best call, and the median process CPU
time of a call (every thread's) split into user and system time.  The split matters for large sweeps: a 1e7-angle
four-bar sweep writes ~1.5 GB of freshly allocated memory and the kernel's first-touch page faults
(system time) can rival the arithmetic (user time).  ``os.times`` ticks at 10 ms, so the CPU columns
mean little for small n.  On a shared machine the best call is the better estimate of what the cores
can do; the median shows what busy ones did.
"""

from __future__ import annotations

import math
import os
import time

import numpy as np

from constructions.geometry import Vec
from constructions.mechanisms.model import Branch, Link, Mechanism, Slide
from constructions.sweep_kernels import chain_sweep, four_bar, four_bar_buffers, slider_crank

__all__ = ["ALPHA", "CHAIN_MAX", "MECHANISMS", "OMEGA", "format_detail", "format_table", "sweep_rows",
           "toggle_linkage"]

#: Crank speed and angular acceleration of every benchmarked sweep (rad/s, rad/s^2).
OMEGA = 10.0
ALPHA = 20.0

#: Largest sweep given to the dyad-chain solver (its temporaries make 1e7 angles several GB).
CHAIN_MAX = 10**6


def toggle_linkage() -> Mechanism:
    """The notes' velocity Example 3 toggle linkage, as in ``gallery/notes-velocity-example-3.toml``
    (O1B = 40, BC = 100, O2C = 60, CD = 80 mm, O2 at (60, 80) mm, slider D on the x axis): built here
    rather than read from the scene file, so the benchmark does not depend on the scene reader."""
    mm = 1e-3
    return Mechanism(
        ground={"O1": Vec(0.0, 0.0), "O2": Vec(60 * mm, 80 * mm)},
        links=(Link(1, ("O1", "B"), 40 * mm), Link(2, ("B", "C"), 100 * mm), Link(3, ("O2", "C"), 60 * mm),
               Link(4, ("C", "D"), 80 * mm)),
        slides=(Slide(5, "D", Vec(0.0, 0.0), 0.0),), attached=(), crank=1,
        branches={"C": Branch(-1, ("B", "O2")), "D": Branch(1, ("C",))})


def _closed_form(fn, **mech):
    return lambda theta: fn(theta, OMEGA, ALPHA, **mech)


_FOUR_BAR = dict(crank_pivot=(0.0, 0.0), rocker_pivot=(0.1, 0.02), crank=0.03, coupler=0.09, rocker=0.07, branch=1)


def _into_buffers(fn, make, **mech):
    """The closed form writing into the caller's buffers, made once per sweep size and reused."""
    kept: dict = {}

    def solve(theta):
        n = theta.size
        if n not in kept:
            kept.clear()
            kept[n] = make(n)
        return fn(theta, OMEGA, ALPHA, out=kept[n], **mech)
    return solve


def _chain(m):
    return lambda theta: chain_sweep(m, theta, OMEGA, ALPHA)


#: The benchmarked mechanisms (SI units): name -> (solver of theta, largest n it is given).  A Grashof
#: crank-rocker (the default call; on the calling thread only; writing into buffers the caller keeps, which
#: spares a long sweep its page faults), the notes' 50 mm / 94 mm slider-crank with a 10 mm offset, the
#: toggle six-bar.
MECHANISMS = {
    "four-bar": (_closed_form(four_bar, **_FOUR_BAR), math.inf),
    "four-bar, one thread": (_closed_form(four_bar, threads=1, **_FOUR_BAR), math.inf),
    "four-bar, caller's buffers": (_into_buffers(four_bar, four_bar_buffers, **_FOUR_BAR), math.inf),
    "slider-crank": (_closed_form(slider_crank, crank_pivot=(0.0, 0.0), crank=0.05, coupler=0.094,
                                  guide_point=(0.0, 0.01), guide_angle=0.0, branch=1), math.inf),
    "six-bar (dyad chain)": (_chain(toggle_linkage()), CHAIN_MAX),
}


def _time_call(solve, theta):
    t0 = os.times()
    c0 = time.process_time()
    w0 = time.perf_counter()
    state = solve(theta)
    wall = time.perf_counter() - w0
    cpu = time.process_time() - c0
    t1 = os.times()
    del state  # free the output before the next call
    return wall, cpu, t1.user - t0.user, t1.system - t0.system


def sweep_rows(sizes=(10**3, 10**4, 10**5, 10**6, 10**7), repeats=5, mechanisms=None):
    """Time full-cycle sweeps (full states) of the benchmark mechanisms.

    Parameters
    ----------
    sizes : iterable of int
        Numbers of crank angles per sweep (``np.linspace(0, 2 pi, n)``).  The dyad chain is given the
        sizes up to :data:`CHAIN_MAX` only.
    repeats : int
        Timed calls per (mechanism, size), after one untimed warm-up call.
    mechanisms : iterable of str, optional
        Names from :data:`MECHANISMS` (default: all).

    Returns
    -------
    list of dict
        One dict per (mechanism, n) with keys ``mechanism``, ``n``, ``median_seconds``,
        ``angles_per_second`` (full states per second, n / median), ``best_angles_per_second``,
        ``cpu_angles_per_second`` (n / the median CPU time of the process, every thread's, which a busy
        machine's other processes do not inflate), ``cpu_user_seconds`` and ``cpu_system_seconds``
        (process CPU time, medians per call).
    """
    if repeats < 1:
        raise ValueError("repeats must be at least 1")
    names = list(MECHANISMS) if mechanisms is None else list(mechanisms)
    unknown = [n for n in names if n not in MECHANISMS]
    if unknown:
        raise ValueError(f"unknown mechanism(s) {unknown}; known: {list(MECHANISMS)}")
    rows = []
    for n in sizes:
        n = int(n)
        theta = np.linspace(0.0, 2.0 * np.pi, n)
        for name in names:
            solve, largest = MECHANISMS[name]
            if n > largest:
                continue
            _time_call(solve, theta)  # warm-up
            walls, cpus, users, systems = [], [], [], []
            for _ in range(repeats):
                wall, cpu, user, system = _time_call(solve, theta)
                walls.append(wall)
                cpus.append(cpu)
                users.append(user)
                systems.append(system)
            median = float(np.median(walls))
            cpu = float(np.median(cpus))
            rows.append(dict(
                mechanism=name,
                n=n,
                median_seconds=median,
                angles_per_second=n / median if median > 0 else float("inf"),
                best_angles_per_second=n / min(walls) if min(walls) > 0 else float("inf"),
                cpu_angles_per_second=n / cpu if cpu > 0 else float("inf"),
                cpu_user_seconds=float(np.median(users)),
                cpu_system_seconds=float(np.median(systems)),
            ))
        del theta
    return rows


def _align(header, lines, first_left=False):
    widths = [max(len(h), *(len(line[i]) for line in lines)) if lines else len(h)
              for i, h in enumerate(header)]

    def fmt(cells):
        first = cells[0].ljust(widths[0]) if first_left else cells[0].rjust(widths[0])
        rest = (c.rjust(w) for c, w in zip(cells[1:], widths[1:]))
        return "  ".join((first, *rest)).rstrip()

    return [fmt(header), "  ".join("-" * w for w in widths)] + [fmt(line) for line in lines]


def _n(n: int) -> str:
    return f"{n:.0e}" if n >= 10**3 else str(n)


def format_table(rows):
    """Format :func:`sweep_rows` output as one plain, aligned text table, the mechanisms side by side.

    One line per sweep size; for each mechanism the median full states per second and, in brackets,
    the best call's (``best_angles_per_second`` is optional); ``--`` where a mechanism was not run at
    that size.

    Parameters
    ----------
    rows : list of dict
        As returned by :func:`sweep_rows`.

    Returns
    -------
    str
        A title line, a header line, a rule, and one line per sweep size.
    """
    names: list[str] = []
    for r in rows:
        if r.get("mechanism", "") not in names:
            names.append(r.get("mechanism", ""))
    cell = {(r.get("mechanism", ""), r["n"]): r for r in rows}
    lines = []
    for n in sorted({r["n"] for r in rows}):
        line = [_n(n)]
        for m in names:
            r = cell.get((m, n))
            if r is None:
                line.append("--")
                continue
            text = f"{r['angles_per_second']:.2e}"
            if "best_angles_per_second" in r:
                text += f" [{r['best_angles_per_second']:.2e}]"
            line.append(text)
        lines.append(line)
    title = "full states per second (positions, velocities, accelerations), median of the calls [best call]"
    return "\n".join([title] + _align(["n", *names], lines))


def format_detail(rows):
    """One line per (mechanism, n): median wall time, full states/s, best call, full states per second
    of the process's CPU time (every thread's), and the median process CPU time of a call split into user and
    system (page faults of the fresh output) time."""
    header = ("mechanism", "n", "median s", "states/s", "best states/s", "cpu states/s", "cpu user s",
              "cpu sys s")
    lines = [(str(r.get("mechanism", "")), _n(r["n"]), f"{r['median_seconds']:.4g}",
              f"{r['angles_per_second']:.3g}",
              f"{r['best_angles_per_second']:.3g}" if "best_angles_per_second" in r else "",
              f"{r['cpu_angles_per_second']:.3g}" if "cpu_angles_per_second" in r else "",
              f"{r['cpu_user_seconds']:.2f}" if "cpu_user_seconds" in r else "",
              f"{r['cpu_system_seconds']:.2f}" if "cpu_system_seconds" in r else "") for r in rows]
    return "\n".join(_align(header, lines, first_left=True))
