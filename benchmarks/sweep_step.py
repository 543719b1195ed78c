"""Accuracy against time for a sweep's step: what a sweep finds by sampling -- the transmission angle's
extremes, the limit positions (the rocker's swing, a slider's dead centres), the largest velocity and
acceleration of the output -- against the exact values, for a crank-rocker and an offset slider-crank.

The sweep is :func:`constructions.sweep.sweep` (the closed forms over arrays) at one turn of crank angles
in steps of 10, 5 (``drafting sweep``'s default), 1 (a sheet's sweep), 0.5, 0.1 and 0.01 deg; a value found
by sampling is the largest (or smallest) sample.  The exact values: the transmission angle's extremes and
the limit positions in closed form (:func:`constructions.mechanisms.classify.classify_four_bar`; for the
slider, x = sqrt((l +- r)^2 - e^2)), the largest velocity and acceleration by zooming in on the largest
sample until the bracket is below 1e-12 rad (:func:`accuracy_common.refine_max`).  Each error is the worst
over eight starting angles an eighth of a step apart (a sweep starts at the scene's angle, which may or may
not land on an extreme); the time is the median of 5 sweeps with the sampling of their extremes, one core.

Usage: ``python benchmarks/sweep_step.py``.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

from accuracy_common import (OFFSET, TURN, crank_rocker, e, exact_max, machine, markdown, ms,  # noqa: E402
                             slider_crank, timed)
from constructions.mechanisms.classify import classify_four_bar  # noqa: E402
from constructions.mechanisms.cycle import transmission_angles  # noqa: E402
from constructions.sweep import sweep  # noqa: E402

STEPS_DEG = (10.0, 5.0, 1.0, 0.5, 0.1, 0.01)
STARTS = 8
DEG = math.degrees


def _angles(start: float, step: float) -> np.ndarray:
    return start + np.radians(step) * np.arange(round(360.0 / step))


def _rocker(s, k) -> np.ndarray:
    _, _, c, o2 = k.joints
    (cx, cy), (ox, oy) = s.positions[c], s.positions[o2]
    return np.unwrap(np.arctan2(np.asarray(cy) - oy, np.asarray(cx) - ox))


def _wrap(a):
    return (a + math.pi) % TURN - math.pi


# -- the crank-rocker -------------------------------------------------------------------------------------

def _four_bar_found(scene, k, th):
    """The sweep at ``th`` and what it finds by sampling."""
    s = sweep(scene.mechanism, th, scene.omega, 0.0)
    mu = transmission_angles(k, s)
    rk = _rocker(s, k)
    w, a = np.abs(s.angular[4]), np.abs(s.angular_acceleration[4])
    return s, {"mu": (float(mu.min()), float(mu.max())),
               "rocker": (float(rk.max()), float(rk.min())),
               "crank": (float(th[np.argmax(rk)]), float(th[np.argmin(rk)])),
               "w": float(w.max()), "a": float(a.max())}


def four_bar_exact(scene, k):
    """The exact values: closed forms, and the largest |omega_4|, |alpha_4| refined."""
    m, om = scene.mechanism, scene.omega
    th = _angles(scene.angle, 1.0)

    def f(kind):
        return lambda t: np.abs(getattr(sweep(m, t, om, 0.0), kind)[4])
    s = sweep(m, th, om, 0.0)
    lp = sorted(k.limit_positions, key=lambda p: -p.rocker_angle)
    return {"mu": (k.transmission_min, k.transmission_max),
            "rocker": tuple(p.rocker_angle for p in lp), "crank": tuple(p.crank_angle for p in lp),
            "w": exact_max(f("angular"), th, np.abs(s.angular[4]))[1],
            "a": exact_max(f("angular_acceleration"), th, np.abs(s.angular_acceleration[4]))[1]}


def four_bar_rows(steps=STEPS_DEG, repeat: int = 5):
    """(step deg, angles, seconds, errors): errors in deg (transmission angle, rocker angle at the limit
    positions, crank angle there) and relative (largest omega_4, alpha_4), worst over the starts."""
    scene = crank_rocker()
    k = classify_four_bar(scene.mechanism)
    ex = four_bar_exact(scene, k)
    out = []
    for step in steps:
        th0 = _angles(scene.angle, step)
        _, t = timed(_four_bar_found, scene, k, th0, repeat=repeat)
        worst = np.zeros(5)
        for j in range(STARTS):
            _, got = _four_bar_found(scene, k, th0 + math.radians(step) * j / STARTS)
            rk = [got["rocker"][i] - ex["rocker"][i] for i in (0, 1)]
            err = (max(abs(got["mu"][i] - ex["mu"][i]) for i in (0, 1)) * 180 / math.pi,
                   max(abs(_wrap(x)) for x in rk) * 180 / math.pi,
                   max(abs(_wrap(got["crank"][i] - ex["crank"][i])) for i in (0, 1)) * 180 / math.pi,
                   abs(got["w"] - ex["w"]) / ex["w"], abs(got["a"] - ex["a"]) / ex["a"])
            worst = np.maximum(worst, err)
        out.append((step, th0.size, t, tuple(float(x) for x in worst)))
    return out, ex


# -- the offset slider-crank ------------------------------------------------------------------------------

def _slider_found(scene, th):
    s = sweep(scene.mechanism, th, scene.omega, 0.0)
    x = np.asarray(s.positions["C"][0])
    v, a = np.abs(np.asarray(s.velocities["C"][0])), np.abs(np.asarray(s.accelerations["C"][0]))
    return s, {"x": (float(x.max()), float(x.min())), "crank": (float(th[np.argmax(x)]), float(th[np.argmin(x)])),
               "v": float(v.max()), "a": float(a.max())}


def slider_exact(scene):
    m, om = scene.mechanism, scene.omega
    r, l = m.link(1).length, m.link(2).length
    outer, inner = math.sqrt((l + r) ** 2 - OFFSET ** 2), math.sqrt((l - r) ** 2 - OFFSET ** 2)
    th = _angles(scene.angle, 1.0)
    s = sweep(m, th, om, 0.0)

    def f(kind):
        return lambda t: np.abs(np.asarray(getattr(sweep(m, t, om, 0.0), kind)["C"][0]))
    return {"x": (outer, inner), "crank": (math.atan2(-OFFSET, outer), math.atan2(-OFFSET, inner) + math.pi),
            "v": exact_max(f("velocities"), th, np.abs(np.asarray(s.velocities["C"][0])))[1],
            "a": exact_max(f("accelerations"), th, np.abs(np.asarray(s.accelerations["C"][0])))[1]}


def slider_rows(steps=STEPS_DEG, repeat: int = 5):
    """(step deg, angles, seconds, errors): the dead centres' slider position (m) and crank angle (deg),
    the largest |V_C| and |A_C| (relative), worst over the starts."""
    scene = slider_crank()
    ex = slider_exact(scene)
    out = []
    for step in steps:
        th0 = _angles(scene.angle, step)
        _, t = timed(_slider_found, scene, th0, repeat=repeat)
        worst = np.zeros(4)
        for j in range(STARTS):
            _, got = _slider_found(scene, th0 + math.radians(step) * j / STARTS)
            err = (max(abs(got["x"][i] - ex["x"][i]) for i in (0, 1)),
                   max(abs(_wrap(got["crank"][i] - ex["crank"][i])) for i in (0, 1)) * 180 / math.pi,
                   abs(got["v"] - ex["v"]) / ex["v"], abs(got["a"] - ex["a"]) / ex["a"])
            worst = np.maximum(worst, err)
        out.append((step, th0.size, t, tuple(float(x) for x in worst)))
    return out, ex


def measure(steps=STEPS_DEG, repeat: int = 5):
    """Both mechanisms' rows and exact values: (four-bar rows, exact, slider rows, exact)."""
    return four_bar_rows(steps, repeat) + slider_rows(steps, repeat)


def tables(measured) -> str:
    fb, fx, sc, sx = measured
    a = markdown(["step (deg)", "angles", "sweep + extremes (ms)", "transmission angle extremes (deg)",
                  "limit positions: rocker angle (deg)", "limit positions: crank angle (deg)",
                  "largest omega_4 (relative)", "largest alpha_4 (relative)"],
                 [[f"{s:g}", str(n), ms(t)] + [e(x) for x in err] for s, n, t, err in fb])
    b = markdown(["step (deg)", "angles", "sweep + extremes (ms)", "dead centres: slider position (mm)",
                  "dead centres: crank angle (deg)", "largest V_C (relative)", "largest A_C (relative)"],
                 [[f"{s:g}", str(n), ms(t), e(err[0] * 1e3)] + [e(x) for x in err[1:]] for s, n, t, err in sc])
    return (f"Crank-rocker (gallery/cycle-four-bar.toml), exact: transmission angle {DEG(fx['mu'][0]):.6f}.."
            f"{DEG(fx['mu'][1]):.6f} deg, rocker limit angles {DEG(fx['rocker'][0]):.6f} / {DEG(fx['rocker'][1]):.6f}"
            f" deg, largest |omega_4| {fx['w']:.9g} rad/s, |alpha_4| {fx['a']:.9g} rad/s^2\n\n{a}\n\n"
            f"Offset slider-crank (r 50, l 140, e 20 mm), exact: dead centres x = {sx['x'][0] * 1e3:.6f} / "
            f"{sx['x'][1] * 1e3:.6f} mm, largest |V_C| {sx['v']:.9g} m/s, |A_C| {sx['a']:.9g} m/s^2\n\n{b}")


def chart_series(measured):
    """(name, [(ms, relative error), ...]) for the chart: angles as a fraction of their range."""
    fb, fx, sc, sx = measured
    mu, swing = DEG(fx["mu"][1] - fx["mu"][0]), DEG(fx["rocker"][0] - fx["rocker"][1])
    stroke = sx["x"][0] - sx["x"][1]

    def of(rows, i, scale):
        return [(t * 1e3, err[i] / scale) for _, _, t, err in rows]
    return [("transmission angle extremes / range", of(fb, 0, mu)),
            ("rocker's limit positions / swing", of(fb, 1, swing)),
            ("largest omega_4", of(fb, 3, 1.0)), ("largest alpha_4", of(fb, 4, 1.0)),
            ("slider's dead centres / stroke", of(sc, 0, stroke)), ("largest V_C", of(sc, 2, 1.0))]


if __name__ == "__main__":
    print(machine())
    print(tables(measure()))
