"""A slider as the driving input: a piston driving a slider-crank, a hydraulic cylinder driving a boom.

The construction turns the crank (:mod:`constructions.mechanisms.pose`: the crank angle follows from the
block's stroke position by :func:`constructions.mechanisms.inverse_position.inverse_position`), and the
polygons start from the crank's rate; so the crank's omega and alpha follow from the block's given speed
and acceleration along its line by the polygons themselves, which are linear in the crank's rates:

* velocities are proportional to omega_1: the velocity polygon drawn at omega_1 = 1 rad/s gives the
  block's speed along its line per unit crank speed, k = ds/dtheta_1, and omega_1 = v / k;
* the acceleration along the line is alpha_1 k + (the part from the normal and Coriolis components, which
  the polygon at alpha_1 = 0 gives: a_0), so alpha_1 = (a - a_0) / k.

k = 0 is a dead centre: the slider cannot drive the crank through it.

The speed along the line is that of the block relative to what it slides on: on a fixed guide V_J . e; in
the slot of link g (the cylinder's barrel), V_J - V_Jg, with Jg the point of g under the joint, along
the slot.  Its acceleration likewise: (A_J - A_Jg) . d, where the Coriolis part 2 omega_g k x V_rel is
square to the slot and drops out.  :func:`along_line` reads both off any set of velocities and
accelerations -- the polygons' or the analytic check's.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

from ..errors import DegenerateInput
from ..geometry import Vec
from ..mechanisms.model import Mechanism, Slide, slide_line
from ..mechanisms.pose import Pose
from .acceleration import acceleration_polygon
from .velocity import velocity_polygon

__all__ = ["DrivenCrank", "along_line", "driven_crank"]


def along_line(m: Mechanism, s: Slide, pos: Mapping[str, Vec], vel: Mapping[str, Vec], ang: Mapping[int, float],
               acc: Mapping[str, Vec] | None = None, alp: Mapping[int, float] | None = None
               ) -> tuple[float, float | None]:
    """(speed, acceleration) of block ``s`` along its guide or slot, relative to it (SI; positive in the
    line's direction); the acceleration None without ``acc``."""
    d = slide_line(m, s, pos).direction.unit()
    j = s.joint
    if s.on is None:
        return vel[j].dot(d), (acc[j].dot(d) if acc is not None else None)
    o = m.link(s.on).joints[0]
    r = pos[j] - pos[o]
    w = ang[s.on]
    v_rel = vel[j] - (vel[o] + r.perp() * w)
    if acc is None:
        return v_rel.dot(d), None
    a_g = acc[o] + r.perp() * alp[s.on] - r * (w * w)
    return v_rel.dot(d), (acc[j] - a_g).dot(d)


@dataclass(frozen=True)
class DrivenCrank:
    """The crank's rates that give the block its ``speed`` and ``acceleration`` along its line: ``rate``
    (k = ds/dtheta_1, m/rad, read off the velocity polygon at 1 rad/s) and ``free`` (a_0, the block's
    acceleration along its line at omega_1 with alpha_1 = 0), whence ``omega`` = v / k and ``alpha`` =
    (a - a_0) / k."""

    block: int
    speed: float
    acceleration: float
    rate: float
    free: float
    omega: float
    alpha: float


def driven_crank(m: Mechanism, pose: Pose, block: int, speed: float, acceleration: float = 0.0) -> DrivenCrank:
    """The crank's omega and alpha at ``pose`` that drive block ``block`` at ``speed`` (m/s) and
    ``acceleration`` (m/s^2) along its line, read off the polygons (module docstring)."""
    s = m.blocks().get(block)
    if s is None:
        raise DegenerateInput(f"there is no slider block {block}")
    unit = velocity_polygon(m, pose, 1.0)
    k, _ = along_line(m, s, pose.positions, unit.velocities, unit.angular)
    if abs(k) <= 1e-9 * m.size:
        raise DegenerateInput(f"block {block} is at a dead centre here (it does not move as the crank turns), "
                              f"so it cannot drive the mechanism")
    omega = speed / k
    if omega == 0.0:
        return DrivenCrank(block, speed, acceleration, k, 0.0, 0.0, acceleration / k)
    va = velocity_polygon(m, pose, omega)
    aa = acceleration_polygon(m, va, 0.0)
    _, a0 = along_line(m, s, pose.positions, va.velocities, va.angular, aa.accelerations, aa.angular)
    return DrivenCrank(block, speed, acceleration, k, a0, omega, (acceleration - a0) / k)
