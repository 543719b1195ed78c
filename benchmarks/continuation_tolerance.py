"""Accuracy against time for the constraint continuation (the sweep of a linkage no closed form covers: a
slot in a moving link, a ternary link joined at its third point): its residual tolerance against its
time and its error.

:func:`constructions.mechanisms.constraint_continuation.continue_constraints` is run over one turn in 1 deg
steps (360 angles) at residual tolerances 1e-4 .. 1e-14 (the default, ``constraint_kinematics.TOLERANCE``;
the benchmark sets the module constant for the block solver and the one-pose solver alike, and puts it
back).  Its error is the largest over the turn, as a fraction of the largest value of its kind: positions
(of the mechanism's size), velocities and accelerations of every point.  The references:

* the crank-rocker and the offset slider-crank of :mod:`accuracy_common`, continued by the constraint
  equations though a closed form covers them, against the closed form (:func:`constructions.sweep.sweep`);
* the gallery's slotted-lever quick-return (the sheet's own route), against its closed form written out
  here: the lever's angle phi = atan2(A - O2), its rates phi' = (u x u') / |u|^2 and
  phi'' = (u x u'') / |u|^2 - 2 (u . u')(u x u') / |u|^4 (u = O2A), the ram from the rod's length.

The time is the median of 3 runs (one core); the closed form's time over the same angles is printed beside.

Usage: ``python benchmarks/continuation_tolerance.py``.
"""

from __future__ import annotations

import math
import sys
from contextlib import contextmanager
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

from accuracy_common import crank_rocker, e, machine, markdown, ms, quick_return, slider_crank, timed  # noqa: E402
from constructions.mechanisms import constraint_continuation, constraint_kinematics  # noqa: E402
from constructions.mechanisms.constraint_continuation import continue_constraints  # noqa: E402
from constructions.sweep import sweep  # noqa: E402

TOLERANCES = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14)
ANGLES = 360


@contextmanager
def tolerance(tol: float):
    """The continuation's residual tolerance set to ``tol`` for the block and the one-pose solver."""
    old = constraint_kinematics.TOLERANCE, constraint_continuation.TOLERANCE
    constraint_kinematics.TOLERANCE = constraint_continuation.TOLERANCE = tol
    try:
        yield
    finally:
        constraint_kinematics.TOLERANCE, constraint_continuation.TOLERANCE = old


def _largest(ref: dict, names) -> float:
    return max(float(np.nanmax(np.hypot(*ref[n]))) for n in names)


def _error(got: dict, ref: dict, names, size: float) -> float:
    return max(float(np.nanmax(np.hypot(got[n][0] - ref[n][0], got[n][1] - ref[n][1]))) for n in names) / size


def closed_form_reference(scene, th):
    """positions, velocities, accelerations: name -> (x, y) of the moving points, by the closed form."""
    s = sweep(scene.mechanism, th, scene.omega, 0.0)
    moving = [n for n in s.positions if n not in scene.mechanism.ground]
    return {k: {n: tuple(np.asarray(a) for a in getattr(s, k)[n]) for n in moving}
            for k in ("positions", "velocities", "accelerations")}


def ram_guide(scene, th) -> tuple[float, float]:
    """The quick-return's ram guide (its y, m) and the side of P the ram stands (+1 ahead, -1 behind), read
    off the first pose the scene solves: the branch the closed form follows."""
    first = sweep(scene.mechanism, th[:1], scene.omega, 0.0).positions
    q, p = (float(np.asarray(first[n][0])[0]) for n in ("Q", "P"))
    return float(np.asarray(first["Q"][1])[0]), 1.0 if q >= p else -1.0


def quick_return_reference(scene, th, guide_y: float, sign: float):
    """The slotted lever's P and the ram Q of the quick-return in closed form (module docstring)."""
    m, w = scene.mechanism, scene.omega
    o1, o2 = m.ground["O1"], m.ground["O2"]
    r, lever, rod = m.link(1).length, m.link(3).length, m.link(4).length
    c, s = np.cos(th), np.sin(th)
    ux, uy = o1.x - o2.x + r * c, o1.y - o2.y + r * s            # u = O2A and its theta-derivatives
    u1x, u1y, u2x, u2y = -r * s, r * c, -r * c, -r * s
    n2 = ux * ux + uy * uy
    cr1, cr2, dot1 = ux * u1y - uy * u1x, ux * u2y - uy * u2x, ux * u1x + uy * u1y
    phi = np.arctan2(uy, ux)
    p1 = cr1 / n2
    p2 = cr2 / n2 - 2 * dot1 * cr1 / n2 ** 2
    ep, en = (np.cos(phi), np.sin(phi)), (-np.sin(phi), np.cos(phi))
    P = (o2.x + lever * ep[0], o2.y + lever * ep[1])
    P1 = (lever * p1 * en[0], lever * p1 * en[1])
    P2 = (lever * (p2 * en[0] - p1 * p1 * ep[0]), lever * (p2 * en[1] - p1 * p1 * ep[1]))
    dy = guide_y - P[1]
    dx = sign * np.sqrt(rod * rod - dy * dy)
    dy1, dy2 = -P1[1], -P2[1]
    dx1 = -dy * dy1 / dx
    dx2 = -(dy1 * dy1 + dy * dy2 + dx1 * dx1) / dx
    z = np.zeros_like(th)
    return {"positions": {"P": P, "Q": (P[0] + dx, z + guide_y)},
            "velocities": {"P": (w * P1[0], w * P1[1]), "Q": (w * (P1[0] + dx1), z)},
            "accelerations": {"P": (w * w * P2[0], w * w * P2[1]), "Q": (w * w * (P2[0] + dx2), z)}}


def _run(scene, th):
    return continue_constraints(scene.mechanism, th, scene.omega, 0.0)


def rows(mechanism: str, tolerances=TOLERANCES, angles: int = ANGLES, repeat: int = 3):
    """(tolerance, seconds, position, velocity, acceleration error) of the continuation of ``mechanism``
    ("crank-rocker", "slider-crank" or "quick-return"), and the closed form's seconds."""
    scene = {"crank-rocker": crank_rocker, "slider-crank": slider_crank, "quick-return": quick_return}[mechanism]()
    th = scene.angle + 2 * math.pi * np.arange(angles) / angles
    if mechanism == "quick-return":
        ref, t_ref = timed(quick_return_reference, scene, th, *ram_guide(scene, th), repeat=repeat)
    else:
        ref, t_ref = timed(closed_form_reference, scene, th, repeat=repeat)
    names = list(ref["positions"])
    size = _largest(ref["positions"], names) if mechanism != "quick-return" else scene.mechanism.link(3).length
    out = []
    for tol in tolerances:
        with tolerance(tol):
            got, t = timed(_run, scene, th, repeat=repeat)
        kinds = [{n: getattr(got, k)[n] for n in names} for k in ("positions", "velocities", "accelerations")]
        errs = [_error(kinds[0], ref["positions"], names, size)]
        errs += [_error(kinds[i], ref[k], names, _largest(ref[k], names))
                 for i, k in ((1, "velocities"), (2, "accelerations"))]
        out.append((tol, t) + tuple(errs))
    return out, t_ref


MECHANISMS = (("crank-rocker", "the crank-rocker (gallery/cycle-four-bar.toml), closed form"),
              ("slider-crank", "the offset slider-crank, closed form"),
              ("quick-return", "the slotted-lever quick-return (gallery), closed form of P and Q"))


def measure(tolerances=TOLERANCES, angles: int = ANGLES, repeat: int = 3):
    """name -> (rows, closed form's seconds) for every mechanism."""
    return {name: rows(name, tolerances, angles, repeat) for name, _ in MECHANISMS}


def tables(measured, angles: int = ANGLES) -> str:
    parts = []
    for name, what in MECHANISMS:
        data, t_ref = measured[name]
        parts.append(f"{angles} angles, {what}: {ms(t_ref)} ms\n\n" + markdown(
            ["tolerance (residual)", "continuation (ms)", "positions (/ size)", "velocities (/ largest)",
             "accelerations (/ largest)"],
            [[f"{tol:.0e}", ms(t)] + [e(x) for x in errs] for tol, t, *errs in data]))
    return "\n\n".join(parts)


def chart_series(measured):
    """(name, [(ms, the larger of the velocity and acceleration errors), ...]) a mechanism each."""
    return [(name, [(t * 1e3, max(v, a)) for _, t, _, v, a in measured[name][0]]) for name, _ in MECHANISMS]


if __name__ == "__main__":
    print(machine())
    print(tables(measure()))
