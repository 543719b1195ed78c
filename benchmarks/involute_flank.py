"""Accuracy against time for a drawn involute flank: points per flank (equal steps of roll angle from the
base or dedendum circle to the addendum circle) against the chord error of the polyline -- the largest
distance between the exact involute and the straight chords that draw it -- and the time to compute one
tooth outline (best of 7).  Gears: 20 and 40 teeth, module 5 mm, 20 deg full depth (the gallery pair), and
a 12-tooth pinion (a long flank for its size).  The chord error of each chord is found by sampling the
exact involute at 64 points between its ends.  Measured (this machine): 16 points 6.3 um, 24 points
2.7 um, 32 points 1.5 um in the model for module 5; the default (constructions.gears.flank.FLANK_POINTS =
24) keeps it near 5 um on paper at 2:1, about 1/50 of a thin line (0.25 mm), at ~0.1 ms a tooth; the
error scales with the module.

Usage: ``python benchmarks/involute_flank.py``
"""

import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled

from constructions.gears.flank import FLANK_POINTS  # noqa: E402
from constructions.gears.tooth import Gear, ToothSystem, involute_point, roll_angle  # noqa: E402
from constructions.geometry import Vec  # noqa: E402


def chord_error(g: Gear, n: int) -> float:
    rb = g.base_radius
    u0 = roll_angle(rb, max(rb, g.dedendum_radius))
    u1 = roll_angle(rb, g.addendum_radius)
    us = [u0 + (u1 - u0) * i / (n - 1) for i in range(n)]
    worst = 0.0
    for a, b in zip(us, us[1:]):
        p, q = involute_point(rb, 0.0, a), involute_point(rb, 0.0, b)
        d = q - p
        L = d.norm()
        for k in range(1, 64):
            x = involute_point(rb, 0.0, a + (b - a) * k / 64)
            worst = max(worst, abs(d.cross(x - p)) / L)
    return worst


def timing(g: Gear, n: int) -> float:
    best = math.inf
    for _ in range(7):
        t = time.perf_counter()
        g.tooth_outline(Vec(0.0, 0.0), 0.0, n)
        best = min(best, time.perf_counter() - t)
    return best


def main() -> None:
    s = ToothSystem(0.005, math.radians(20))
    gears = [Gear(12, s), Gear(20, s), Gear(40, s)]
    print("points/flank | chord error (um): 12 T   20 T   40 T | tooth outline time (us), 20 T")
    for n in (4, 6, 8, 12, 16, 24, 32, 48, 64):
        errs = [chord_error(g, n) * 1e6 for g in gears]
        mark = "  <- default" if n == FLANK_POINTS else ""
        print(f"{n:12d} | {errs[0]:10.4f} {errs[1]:8.4f} {errs[2]:8.4f} | {timing(gears[1], n) * 1e6:8.1f}{mark}")


if __name__ == "__main__":
    main()
