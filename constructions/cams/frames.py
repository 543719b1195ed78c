"""The turns between the cam's two frames, on points and vectors held as 2 x N arrays.

The cam turns about the origin O of the *fixed frame* (the follower's); the profile lives in the *cam
frame*, where the follower is laid out opposite to the cam's rotation (:mod:`.envelope`).  A point of the
fixed frame is carried into the cam frame by :func:`rotate` through ``-sigma theta`` (by :func:`rotated`
when the turn's cosines and sines serve several points); :func:`quarter_turn` is the quarter turn J
counter-clockwise that makes a tangent a normal.
"""

from __future__ import annotations

import numpy as np


def pair(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The rows x and y (arrays of one shape) as one 2 x N array: what ``np.stack([x, y])`` makes, without
    its checks (these run thousands of times in a cam's searches)."""
    out = np.empty((2,) + np.shape(x))
    out[0] = x
    out[1] = y
    return out


def rotate(a: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The points (x, y) turned counter-clockwise through the angles ``a`` (2 x N)."""
    return rotated(np.cos(a), np.sin(a), x, y)


def rotated(c: np.ndarray, s: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """:func:`rotate` with the angles' cosines ``c`` and sines ``s`` given."""
    return pair(c * x - s * y, s * x + c * y)


def quarter_turn(v: np.ndarray) -> np.ndarray:
    """J v: the vectors ``v`` (2 x N) turned a quarter turn counter-clockwise."""
    return pair(-v[1], v[0])
