"""The per-station table of a cam: at each drawn station (cam angle), the follower's displacement s and its
velocity v, acceleration a and jerk j, the pressure angle, the radii of curvature of the pitch curve and of
the profile, and the point of contact -- what a student tabulates beside the construction.

Every value is the exact one at the station's cam angle (the law's closed form, :mod:`.laws`; the envelope's
analytic terms, :mod:`.envelope`).  With the cam's steady speed ``omega`` (rad/s), ``v = omega s'``, ``a =
omega^2 s''``, ``j = omega^3 s'''``; without it the columns are the derivatives per radian of cam angle (s',
s'', s'''), which are v, a and j at 1 rad/s.  A station on a join takes the later segment's values (the
program's convention), so a derivative that jumps there is read as it leaves the join.  An oscillating
follower's s is its swing (rad) and v, a, j are the arm's angular rates.

Radii of curvature are positive where the curve is convex; the pitch curve's is None for a flat face (it
has none: the face's foot is no pitch point), and a knife edge's pitch curve is its profile.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .envelope import evaluate
from .follower import Follower
from .laws import Program


@dataclass(frozen=True)
class StationTable:
    """The table's columns, each an array over the stations (SI: m or rad, per s^k or per rad^k)."""

    theta: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray
    pressure_angle: np.ndarray
    rho_pitch: np.ndarray | None
    rho_profile: np.ndarray
    contact: np.ndarray              # 2 x N, the cam frame at cam angle 0
    per_radian: bool                 # True: v, a, j are s', s'', s''' (no cam speed given)

    def __len__(self) -> int:
        return len(self.theta)


def station_table(program: Program, f: Follower, theta, omega: float | None = None) -> StationTable:
    """The table at the cam angles ``theta`` (rad) with the cam turning at ``omega`` (rad/s; None: per
    radian)."""
    ev = evaluate(program, f, np.asarray(theta, dtype=float))
    w = abs(omega) if omega else 1.0
    return StationTable(ev.theta, ev.s, ev.ds * w, ev.d2s * w ** 2, ev.d3s * w ** 3, ev.pressure_angle,
                        ev.rho_pitch, ev.rho_profile, ev.profile, not omega)


__all__ = ["StationTable", "station_table"]
