"""The turns between the cam's two frames, on points and vectors held as 2 x N arrays.

The cam turns about the origin O of the *fixed frame* (the follower's); the profile lives in the *cam
frame*, where the follower is laid out opposite to the cam's rotation (:mod:`.envelope`).  A point of the
fixed frame is carried into the cam frame by :func:`rotate` through ``-sigma theta``; :func:`quarter_turn`
is the quarter turn J counter-clockwise that makes a tangent a normal.
"""

from __future__ import annotations

import numpy as np


def rotate(a: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The points (x, y) turned counter-clockwise through the angles ``a`` (2 x N)."""
    c, s = np.cos(a), np.sin(a)
    return np.stack([c * x - s * y, s * x + c * y])


def quarter_turn(v: np.ndarray) -> np.ndarray:
    """J v: the vectors ``v`` (2 x N) turned a quarter turn counter-clockwise."""
    return np.stack([-v[1], v[0]])
