"""A mechanism's motion over an array of crank angles, as the closed forms and the sweep both hold it."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import numpy as np

__all__ = ["XY", "MotionArrays"]

XY = tuple[np.ndarray, np.ndarray]


@dataclass(frozen=True, eq=False)
class MotionArrays:
    """A mechanism over crank angles ``thetas`` (rad).

    positions, velocities, accelerations : name -> (x array, y array), m, m/s, m/s^2
    angular, angular_acceleration : link number -> array, rad/s, rad/s^2
    assembles : bool array (False at a gap)
    model : which solver gave the numbers ("four-bar", "slider-crank", "dyad chain", ...)
    """

    thetas: np.ndarray
    positions: Mapping[str, XY]
    velocities: Mapping[str, XY]
    accelerations: Mapping[str, XY]
    angular: Mapping[int, np.ndarray]
    angular_acceleration: Mapping[int, np.ndarray]
    assembles: np.ndarray
    model: str
