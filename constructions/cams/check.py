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
- the smallest base radius of a flat-faced follower: ``max(-(s + s''))`` over a dense grid of the turn.
"""

from __future__ import annotations

import math

import numpy as np

from .laws import TAU, Program
from .profile import FLAT, Follower


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
    e = f.offset
    d0 = math.sqrt(f.prime_radius ** 2 - e * e)
    phi = math.atan((ds - sg * e) / (d0 + s))
    P = _turn_back(theta, sg, e, d0 + s)
    rr = f.roller_radius
    C = _turn_back(theta, sg, e + sg * rr * math.sin(phi), d0 + s - rr * math.cos(phi))
    return {"P": P, "C": C, "phi": phi, "s": s}


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
