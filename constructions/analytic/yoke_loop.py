"""The Scotch yoke in closed form: the displacement, velocity and acceleration of a yoke whose slot
stands square to its line of stroke, over crank angles."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["ScotchYokeState", "scotch_yoke"]


@dataclass(frozen=True)
class ScotchYokeState:
    """The yoke along its line of stroke (positive along the stroke direction): ``x`` the slot's distance
    ahead of the crank pivot's foot (m), ``v`` its velocity (m/s), ``a`` its acceleration (m/s^2)."""

    x: np.ndarray
    v: np.ndarray
    a: np.ndarray


def scotch_yoke(theta1, omega1, alpha1=0.0, *, crank: float, stroke_angle: float = 0.0) -> ScotchYokeState:
    """Closed-form motion of a Scotch yoke, vectorised over ``theta1``, ``omega1`` and ``alpha1`` (rad,
    rad/s, rad/s^2, CCW positive, broadcast against each other) for a crank of length ``crank`` (m) and a
    line of stroke at ``stroke_angle`` (rad) from +x.

    The slot is square to the stroke, so the yoke moves with the crank pin's component along the stroke:
    with phi = theta1 - stroke_angle, x = r cos(phi); differentiating, v = -r omega sin(phi) and
    a = -r omega^2 cos(phi) - r alpha sin(phi) (simple harmonic motion at constant omega).  The yoke does
    not turn, so no term of its motion comes from a rotation of the slot.
    """
    if not crank > 0.0:
        raise ValueError(f"the crank length must be positive, not {crank!r}")
    th, w, al = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (theta1, omega1, alpha1)))
    phi = th - stroke_angle
    c, s = np.cos(phi), np.sin(phi)
    out = (crank * c, -crank * w * s, -crank * w * w * c - crank * al * s)
    for arr in out:
        arr.setflags(write=False)
    return ScotchYokeState(*out)
