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

import math
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


STATION_ROWS = 9
"""The most rows of a table of stations up to 36 stations: the stations are set in two to four column groups
side by side (12 stations in two groups of six, 24 in three of eight, 36 in four of nine), read down each
group, as a student lays the table out on the sheet; six stations or fewer in one."""


def station_rows(th, s_head: str) -> tuple[tuple[str, ...], ...]:
    """The table of the stations' lift: station number, cam angle (degrees) and ``$s<i>``, in column
    groups of :data:`STATION_ROWS` rows (at most four groups: more rows when there are more stations)."""
    n = len(th)
    groups = 1 if n <= 6 else min(4, max(2, math.ceil(n / STATION_ROWS)))
    rows = math.ceil(n / groups)
    head = ("Station", "\u03b8 (\u00b0)", s_head) * groups
    body = []
    for r in range(rows):
        cells: list[str] = []
        for g in range(groups):
            i = g * rows + r
            cells += [str(i), degree_text(th[i]), f"$s{i}"] if i < n else ["", "", ""]
        body.append(tuple(cells))
    return (head, *body)


def degree_text(theta: float) -> str:
    """A station's cam angle (rad) in degrees as the construction writes it: 10, 22.5, 337.5."""
    return f"{math.degrees(theta):.6g}"


__all__ = ["StationTable", "station_table", "station_rows", "degree_text", "STATION_ROWS"]
