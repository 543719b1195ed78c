"""The angle of action, the sliding at the tips and the pitch-line speed of a pair in mesh, from its path of
contact (read off the construction, or from the closed forms).

The arc of action, the arc a pitch circle turns through while a pair of teeth is in contact, is the path
of contact over the cosine of the (working) pressure angle, AB / cos phi'; over the pitch radius
r' = r_b / cos phi' it is the angle of action of each gear, AB / r_b (approach AP / r_b, recess PB / r_b):
as a check, contact ratio x 360 deg / N.  A point of contact at distance s from the pitch point P along the
line of action slides at (omega_1 + omega_2) s (the gears' relative angular velocity times the distance
from their instantaneous centre P; omega_1 - omega_2 for an internal gear, which turns the same way, and
omega_1 for a rack): the most at the start A and the end B of contact, where the tips meet the other
flank.  The pitch-line speed V = omega_1 r_1' is the same on both pitch circles (they roll).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .contact import Pair


@dataclass(frozen=True)
class Action:
    angle_of_action: tuple[float, float | None]     # per gear (rad): AB / r_b (None for a rack)
    approach_angle: tuple[float, float | None]      # AP / r_b
    recess_angle: tuple[float, float | None]        # PB / r_b
    omega: tuple[float, float] | None               # |omega_1|, |omega_2| (rad/s; the rack 0)
    pitch_line_speed: float | None                  # omega_1 r_1'
    sliding_start: float | None                     # at A: omega_rel AP
    sliding_end: float | None                       # at B: omega_rel PB

    def values(self) -> dict[str, float]:
        """The quantities by name, as the results table and the check name them."""
        out = {"delta_1": self.angle_of_action[0]}
        if self.angle_of_action[1] is not None:
            out["delta_2"] = self.angle_of_action[1]
        if self.omega is not None:
            out |= {"V_p": self.pitch_line_speed, "v_s A": self.sliding_start, "v_s B": self.sliding_end}
        return out


def relative_speed(pair: Pair, omega1: float) -> tuple[float, float]:
    """|omega_2| and the gears' relative angular velocity |omega_1 -/+ omega_2| for a pinion at |omega_1|."""
    if pair.rack:
        return 0.0, omega1
    w2 = omega1 * pair.pinion.teeth / pair.gear.teeth
    return w2, omega1 - w2 if pair.internal else omega1 + w2


def action(pair: Pair, approach: float, recess: float, working_pressure_angle: float,
           omega1: float | None = None) -> Action:
    """The angles of action from the approach AP and recess PB; the speeds when the pinion turns at ``omega1``."""
    rb = (pair.pinion.base_radius, None if pair.rack else pair.gear.base_radius)

    def per_gear(length: float) -> tuple[float, float | None]:
        return length / rb[0], None if rb[1] is None else length / rb[1]

    path = approach + recess
    if omega1 is None:
        return Action(per_gear(path), per_gear(approach), per_gear(recess), None, None, None, None)
    w1 = abs(omega1)
    w2, rel = relative_speed(pair, w1)
    v = w1 * rb[0] / math.cos(working_pressure_angle)
    return Action(per_gear(path), per_gear(approach), per_gear(recess), (w1, w2), v, rel * approach, rel * recess)
