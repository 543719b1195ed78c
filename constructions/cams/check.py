"""The independent check of a cam: closed forms written the way a textbook writes them, from the program's
s, s' alone (never the construction's rotations or the envelope's derivative formulas).

- the roller centre: at polar radius ``sqrt(e^2 + (d0 + s)^2)`` from O, the axis laid out at ``-sigma
  theta``: in the fixed frame ``(e, d0 + s)``, turned back by the cam's angle;
- the pressure angle ``phi = atan((s' - sigma e) / (d0 + s))``; the contact point is the roller centre
  less ``rr`` along the common normal, which makes ``phi`` with the axis: ``(e + sigma rr sin phi,
  d0 + s - rr cos phi)`` in the fixed frame;
- a flat face touches at ``sigma s'`` from the axis: ``(sigma s', rb + s)`` in the fixed frame (the
  notes' ``x = -(rb + s) sin theta - s' cos theta``, ``y = (rb + s) cos theta - s' sin theta`` for a
  CW cam);
- the smallest base radius of a flat-faced follower: ``max(-(s + s''))`` over a dense grid of the turn;
- an oscillating flat face by Kennedy's theorem: the face at ``beta = asin((rb + e_f) / a) + psi`` from the
  line of centres, the common normal square to it through the instant centre of cam and arm on the line
  of centres (``x_I = s' a / (sigma + s')``), so the contact is the foot of the perpendicular from that
  centre to the face.
"""

from __future__ import annotations

import math

import numpy as np

from ..geometry import acos_clamped, asin_clamped, sqrt_nonneg
from .laws import TAU, Program
from .follower import FLAT, OSC_FLAT, OSCILLATING, Follower


def _turn_back(theta: float, sense: int, x: float, y: float) -> tuple[float, float]:
    a = -sense * theta
    return (math.cos(a) * x - math.sin(a) * y, math.sin(a) * x + math.cos(a) * y)


def closed_form_point(program: Program, f: Follower, theta: float) -> dict[str, tuple[float, float] | float]:
    """At cam angle ``theta``: the roller centre ``P`` (knife edge: the edge), the contact point ``C`` and the
    pressure angle ``phi`` in the cam frame, by the closed forms above."""
    s, ds, d2, _ = (float(v[0]) for v in program.derivatives(np.array([theta])))
    sg = f.sense
    if f.kind == FLAT:
        return {"P": _turn_back(theta, sg, 0.0, f.base_radius + s),        # the face line's foot on the axis
                "C": _turn_back(theta, sg, sg * ds, f.base_radius + s), "phi": 0.0, "s": s}
    if f.kind == OSCILLATING:
        return _oscillating(f, theta, s, ds)
    if f.kind == OSC_FLAT:
        return _oscillating_face(f, theta, s, ds)
    e = f.offset
    d0 = sqrt_nonneg(f.prime_radius ** 2 - e * e)
    phi = math.atan((ds - sg * e) / (d0 + s))
    P = _turn_back(theta, sg, e, d0 + s)
    rr = f.roller_radius
    C = _turn_back(theta, sg, e + sg * rr * math.sin(phi), d0 + s - rr * math.cos(phi))
    return {"P": P, "C": C, "phi": phi, "s": s}


def _oscillating(f: Follower, theta: float, s: float, ds: float) -> dict:
    """An oscillating roller by Kennedy's theorem: the roller centre B from the arm's angle (the law of
    cosines places the arm at zero lift), and the common normal through B and the instant centre I of
    cam and follower, on the line of centres OA where both move alike: sigma x_I = -s' (x_I - a), so
    x_I = s' a / (sigma + s')."""
    a, L, rp, sg = f.pivot_distance, f.arm_length, f.prime_radius, f.sense
    g0 = acos_clamped((rp * rp - a * a - L * L) / (2 * a * L))
    g = g0 - s
    B = (a + L * math.cos(g), L * math.sin(g))
    xi = ds * a / (sg + ds)
    nx, ny = B[0] - xi, B[1]
    k = math.hypot(nx, ny)
    nx, ny = nx / k, ny / k
    if nx * B[0] + ny * B[1] < 0:          # the normal's outward sense: away from the cam's centre
        nx, ny = -nx, -ny
    rr = f.roller_radius
    C = (B[0] - rr * nx, B[1] - rr * ny)
    dirn = (math.sin(g), -math.cos(g))     # the roller centre's path as the swing grows
    phi = sg * math.atan2(dirn[0] * ny - dirn[1] * nx, dirn[0] * nx + dirn[1] * ny)
    return {"P": _turn_back(theta, sg, *B), "C": _turn_back(theta, sg, *C), "phi": phi, "s": s}


def _oscillating_face(f: Follower, theta: float, s: float, ds: float) -> dict:
    """An oscillating flat face by Kennedy's theorem: the face line at the swung angle, the instant centre I
    of cam and arm where both move alike on the line of centres, and the contact where the normal to the
    face through I meets it.  ``P`` is the foot of the perpendicular from O to the face."""
    a, sg = f.pivot_distance, f.sense
    beta = asin_clamped((f.base_radius + f.face_offset) / a) + s
    nx, ny = math.sin(beta), math.cos(beta)            # the face's normal, away from the cam centre
    c = a * math.sin(beta) - f.face_offset             # the face's distance from O
    xi = ds * a / (sg + ds)
    C = (xi + (c - nx * xi) * nx, (c - nx * xi) * ny)
    # the pressure angle: between the normal and the way the arm drives its point at the contact
    vx, vy = C[1], -(C[0] - a)
    phi = sg * math.atan2(vx * ny - vy * nx, vx * nx + vy * ny)
    return {"P": _turn_back(theta, sg, c * nx, c * ny), "C": _turn_back(theta, sg, *C), "phi": phi, "s": s}


def min_base_radius_flat(program: Program, start: float = 0.0, end: float = TAU, n: int = 200001) -> float:
    """The smallest base radius that keeps a flat-faced follower's profile convex over [start, end]:
    ``max(-(s + s''))`` on a dense grid (0 if s + s'' never goes negative)."""
    th = np.linspace(start, end, n)
    s, _, d2, _ = program.derivatives(th)
    return max(float(np.max(-(s + d2))), 0.0)


def lift(program: Program) -> float:
    """The largest lift: the rises' lifts summed up to the highest level the program reaches."""
    level, top = 0.0, 0.0
    for seg in program.segments:
        level += seg.sign * seg.lift
        top = max(top, level)
    return top


__all__ = ["closed_form_point", "min_base_radius_flat", "lift"]
