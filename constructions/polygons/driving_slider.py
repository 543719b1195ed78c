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
from ..record import Construction, Step, StepKind, Value
from .velocity import velocity_polygon

__all__ = ["DrivenCrank", "along_line", "driven_crank", "driving_steps", "with_first"]


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
    from .acceleration import acceleration_polygon
    va = velocity_polygon(m, pose, omega)
    aa = acceleration_polygon(m, va, 0.0)
    _, a0 = along_line(m, s, pose.positions, va.velocities, va.angular, aa.accelerations, aa.angular)
    return DrivenCrank(block, speed, acceleration, k, a0, omega, (acceleration - a0) / k)


def driving_steps(dc: DrivenCrank, crank: int, along: str) -> tuple[Step, Step]:
    """The steps that open the velocity and the acceleration polygon of a slider-driven mechanism: the
    crank's omega and alpha from the block's speed and acceleration (module docstring)."""
    w = "\u03c9"
    sense = ("counter-clockwise" if dc.omega >= 0 else "clockwise", "counter-clockwise" if dc.alpha >= 0 else "clockwise")
    v = Step(f"Block {dc.block} drives at $v along {along}. Drawn at {w}_{crank} = 1 rad/s the polygon gives it $k; "
             f"velocities grow with {w}_{crank}, so {w}_{crank} = $v \u00f7 $k \u00d7 1 rad/s = $w {sense[0]}. "
             f"The polygon is drawn at it.",
             values=(("v", Value("velocity", dc.speed)), ("k", Value("velocity", dc.rate)),
                     ("w", Value("angular velocity", abs(dc.omega)))), kind=StepKind.GIVEN)
    minus_free = "+" if dc.free < 0 else "\u2212"          # a - a0 with a0 < 0 written as a + |a0|
    a = Step(f"Block {dc.block} accelerates at $a along {along}. Drawn with \u03b1_{crank} = 0 the polygon gives it "
             f"$a0; each 1 rad/s\u00b2 of \u03b1_{crank} adds $ka, so \u03b1_{crank} = ($a "
             f"{minus_free} $f) \u00f7 $ka \u00d7 1 rad/s\u00b2 = $al {sense[1]}. The polygon "
             f"is drawn at it.",
             values=(("a", Value("acceleration", dc.acceleration)), ("a0", Value("acceleration", dc.free)),
                     ("f", Value("acceleration", abs(dc.free))),
                     ("ka", Value("acceleration", dc.rate)), ("al", Value("angular acceleration", abs(dc.alpha)))),
             kind=StepKind.GIVEN)
    return v, a


def with_first(c: Construction, step: Step) -> Construction:
    """The record ``c`` with ``step`` before its first."""
    return Construction(c.title, (step,) + c.steps)
