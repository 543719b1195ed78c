"""What the accuracy-against-time benchmarks share: the mechanisms they measure (two gallery scenes and an
offset slider-crank of our own), a median timer, the refinement of a sampled extreme to the exact one,
and a markdown table.

The exact extreme of a smooth quantity f(theta) is found by zooming: f on a grid of :data:`ZOOM_POINTS`
angles across the bracket, the bracket narrowed to the best point's two neighbours, until it is narrower
than :data:`ZOOM_WIDTH` (1e-12 rad).  The value found is then exact to rounding (its angle to about 1e-8
rad, where the curvature of f drowns in rounding).
"""

from __future__ import annotations

import math
import os
import statistics
import sys
import time
from datetime import datetime, timezone
from pathlib import Path

CHECKOUT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(CHECKOUT))             # run from a checkout, uninstalled

import numpy as np  # noqa: E402

from drafting.app.bench import machine_speed  # noqa: E402
from drafting.scene.reader import load_scene, parse_scene  # noqa: E402

GALLERY = CHECKOUT / "gallery"
TURN = 2 * math.pi

OFFSET_SLIDER_CRANK = """
[drawing]
title = "Offset slider-crank (accuracy benchmark)"
[units]
length = "mm"
angle = "deg"
[frame]
O1 = [0, 0]
[[link]]
number = 1
joints = ["O1", "B"]
length = 50
[[link]]
number = 2
joints = ["B", "C"]
length = 140
[[slider]]
number = 3
joint = "C"
through = [0, -20]
angle = "0 deg"
[input]
link = 1
angle = "70 deg"
omega = "10 rad/s"
sense = "ccw"
[assembly]
C = "ahead of B"
"""
"""Crank 50 mm, coupler 140 mm, the guide 20 mm below the crank's pivot: the dead centres are not at crank
angles 0 and 180 deg, so no step lands on them by chance."""

OFFSET = 0.020
"""The offset slider-crank's guide offset (m, below O1), for its closed forms."""


def crank_rocker():
    """The gallery's crank-rocker (``cycle-four-bar.toml``: frame 60, crank 20, coupler 55, rocker 45 mm)."""
    return load_scene(GALLERY / "cycle-four-bar.toml")


def slider_crank():
    return parse_scene(OFFSET_SLIDER_CRANK, "offset-slider-crank.toml")


def quick_return():
    """The gallery's slotted-lever quick-return (``quick-return-slotted-lever.toml``): swept by the
    constraint equations."""
    return load_scene(GALLERY / "quick-return-slotted-lever.toml")


def timed(fn, *a, repeat: int = 5):
    """(result, median seconds of ``repeat`` runs)."""
    out, ts = None, []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn(*a)
        ts.append(time.perf_counter() - t0)
    return out, statistics.median(ts)


ZOOM_POINTS = 65
ZOOM_WIDTH = 1e-12


def refine_max(f, lo: float, hi: float) -> tuple[float, float]:
    """(angle, value) of the largest f (a function of an angle array) in [lo, hi], by zooming."""
    while True:
        t = np.linspace(lo, hi, ZOOM_POINTS)
        y = f(t)
        k = int(np.nanargmax(y))
        if hi - lo < ZOOM_WIDTH:
            return float(t[k]), float(y[k])
        lo, hi = t[max(k - 1, 0)], t[min(k + 1, ZOOM_POINTS - 1)]


def exact_max(f, thetas: np.ndarray, values: np.ndarray) -> tuple[float, float]:
    """The exact largest f near the largest of its samples ``values`` at ``thetas``."""
    k = int(np.nanargmax(values))
    h = float(thetas[1] - thetas[0])
    return refine_max(f, float(thetas[k]) - h, float(thetas[k]) + h)


def markdown(header: list[str], rows: list[list[str]]) -> str:
    """A markdown table."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def e(x: float) -> str:
    """An error, two figures (0 printed as 0)."""
    return "0" if x == 0 else f"{x:.1e}"


def ms(seconds: float) -> str:
    v = seconds * 1e3
    return f"{v:.3g}"


def machine() -> str:
    """The date, the machine's load and the speed of a fixed loop of plain Python in this run (the
    yardstick of ``drafting bench``: 7.5-8.1 ms on the project's machine when quiet)."""
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    return (f"{datetime.now(timezone.utc):%Y-%m-%d %H:%M} UTC, load average {load} on {os.cpu_count()} cores, "
            f"yardstick loop {machine_speed() * 1e3:.1f} ms")
