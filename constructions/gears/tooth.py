"""Spur-gear geometry: the tooth system, one gear's circles and pitches, and the involute flank.

A :class:`ToothSystem` is the module (SI metres; a diametral pitch P in 1/inch gives m = 25.4 mm / P),
the pressure angle and the addendum and dedendum constants (full depth 1 and 1.25, stub 0.8 and 1.0,
in modules).  A :class:`Gear` adds its number of teeth: pitch radius r = mN/2, base radius r_b = r cos(phi),
addendum radius r + k_a m, dedendum radius r - k_d m, circular pitch p = pi m, base pitch
p_b = p cos(phi) = 2 pi r_b / N, tooth thickness at the pitch circle t = p/2.

The involute of a circle of radius r_b unwound through the roll angle u from the polar angle theta_0 is
``r_b (cos(theta_0 + u) + u sin(theta_0 + u), sin(theta_0 + u) - u cos(theta_0 + u))``: the end of a
thread of length r_b u held tight off the circle.  Its radius is r_b sqrt(1 + u^2) and its polar angle
theta_0 + inv(alpha) with tan(alpha) = u and inv(alpha) = tan(alpha) - alpha.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import DegenerateInput
from ..geometry import Vec
from .flank import CutFlank

INCH = 0.0254

FULL_DEPTH = (1.0, 1.25)
STUB = (0.8, 1.0)
SYSTEMS = {"full depth": FULL_DEPTH, "stub": STUB}


def inv(alpha: float) -> float:
    """The involute function inv(alpha) = tan(alpha) - alpha."""
    return math.tan(alpha) - alpha


def involute_point(rb: float, theta0: float, u: float, centre: Vec = Vec(0.0, 0.0), sense: int = 1) -> Vec:
    """The involute point of roll angle ``u`` (>= 0) off the base circle (centre, rb), its thread
    leaving the circle at polar angle ``theta0``; ``sense`` +1 unwinds counter-clockwise, -1 clockwise."""
    a = theta0 + sense * u
    c, s = math.cos(a), math.sin(a)
    return Vec(centre.x + rb * (c + sense * u * s), centre.y + rb * (s - sense * u * c))


def roll_angle(rb: float, radius: float) -> float:
    """The roll angle at which the involute of base radius ``rb`` reaches ``radius`` (>= rb)."""
    return math.sqrt(max(radius * radius - rb * rb, 0.0)) / rb


@dataclass(frozen=True)
class ToothSystem:
    """Module (m, SI), pressure angle (rad) and addendum and dedendum constants (in modules), and the tip
    radius of the rack cutter that generates the teeth, in modules (None: the basic rack's,
    :func:`constructions.gears.generation.tip_round`)."""

    module: float
    pressure_angle: float
    addendum: float = 1.0
    dedendum: float = 1.25
    cutter_tip: float | None = None

    def __post_init__(self) -> None:
        if not (self.module > 0 and math.isfinite(self.module)):
            raise DegenerateInput(f"the module must be a positive length, not {self.module!r}")
        if not (0.0 < self.pressure_angle < math.radians(45.0)):
            raise DegenerateInput("the pressure angle must lie between 0 and 45 deg")
        if not (self.addendum > 0.0 and self.dedendum > 0.0):
            raise DegenerateInput("the addendum and dedendum constants must be positive")
        if self.cutter_tip is not None and not (0.0 <= self.cutter_tip < math.inf):
            raise DegenerateInput("the cutter's tip radius must be a length of 0 or more")

    @classmethod
    def from_diametral_pitch(cls, pitch_per_inch: float, pressure_angle: float, addendum: float = 1.0,
                             dedendum: float = 1.25) -> "ToothSystem":
        """A system given by its diametral pitch P (teeth per inch of pitch diameter): m = 25.4 mm / P."""
        return cls(INCH / pitch_per_inch, pressure_angle, addendum, dedendum)

    @property
    def circular_pitch(self) -> float:
        return math.pi * self.module

    @property
    def base_pitch(self) -> float:
        return math.pi * self.module * math.cos(self.pressure_angle)

    @property
    def tooth_thickness(self) -> float:
        return math.pi * self.module / 2.0

    @property
    def a(self) -> float:
        """The addendum as a length."""
        return self.addendum * self.module

    @property
    def d(self) -> float:
        """The dedendum as a length."""
        return self.dedendum * self.module


@dataclass(frozen=True)
class Gear:
    """An external spur gear of ``teeth`` teeth cut in ``system``."""

    teeth: int
    system: ToothSystem

    def __post_init__(self) -> None:
        if not isinstance(self.teeth, int) or self.teeth < 3:
            raise DegenerateInput(f"a gear needs at least 3 teeth, not {self.teeth!r}")

    @property
    def pitch_radius(self) -> float:
        return self.system.module * self.teeth / 2.0

    @property
    def base_radius(self) -> float:
        return self.pitch_radius * math.cos(self.system.pressure_angle)

    @property
    def addendum_radius(self) -> float:
        return self.pitch_radius + self.system.a

    @property
    def dedendum_radius(self) -> float:
        return self.pitch_radius - self.system.d

    @property
    def base_pitch(self) -> float:
        """2 pi r_b / N (equal to pi m cos(phi))."""
        return 2.0 * math.pi * self.base_radius / self.teeth

    @property
    def half_tooth_angle(self) -> float:
        """Half the tooth's angular thickness at the pitch circle: (t/2)/r = pi/(2N)."""
        return math.pi / (2.0 * self.teeth)

    def flank_start(self, centre_angle: float, side: int) -> float:
        """The polar angle where the flank of the tooth centred at ``centre_angle`` leaves the base circle:
        ``side`` -1 is the flank clockwise of the centre line (it unwinds counter-clockwise), +1 the other."""
        return centre_angle + side * (self.half_tooth_angle + inv(self.system.pressure_angle))

    def thickness_at(self, radius: float) -> float:
        """The tooth's arc thickness at ``radius`` (between base and addendum circles):
        2 radius (pi/(2N) + inv(phi) - inv(alpha)), cos(alpha) = r_b / radius."""
        alpha = math.acos(min(1.0, self.base_radius / radius))
        return 2.0 * radius * (self.half_tooth_angle + inv(self.system.pressure_angle) - inv(alpha))

    def tooth_outline(self, centre: Vec, centre_angle: float, flank_points: int,
                      cut: CutFlank | None = None) -> list[Vec]:
        """One tooth's outline from its root on one side (dedendum circle) over the tip to the other root,
        counter-clockwise about the gear: the radial root line where the dedendum circle lies inside the
        base circle, the involute flanks computed exactly at ``flank_points`` roll angles, the tip arc.
        With ``cut`` (:class:`constructions.gears.flank.CutFlank`) the flanks are as a rack cutter
        leaves them: the involute down to ``cut.involute_from``, then the fillet to the root circle."""
        rb, ra, rd = self.base_radius, self.addendum_radius, self.dedendum_radius
        u_tip = roll_angle(rb, ra)
        # where the tip would be pointed the flanks meet before the addendum circle: stop them there
        if self.thickness_at(ra) < 0:
            lo, hi = 0.0, u_tip
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                if self.thickness_at(rb * math.sqrt(1 + mid * mid)) > 0:
                    lo = mid
                else:
                    hi = mid
            u_tip = lo
        t0 = self.flank_start(centre_angle, -1)
        r_start = max(rb, rd) if cut is None else cut.involute_from
        u_start = roll_angle(rb, r_start)
        us = [u_start + (u_tip - u_start) * i / (flank_points - 1) for i in range(flank_points)]
        t1 = self.flank_start(centre_angle, +1)
        right = [involute_point(rb, t0, u, centre, +1) for u in us]
        left = [involute_point(rb, t1, u, centre, -1) for u in us]
        out: list[Vec] = []
        if cut is not None:          # the fillet from the root up to the involute (its last point is on it)
            out += [centre + Vec.polar(r, centre_angle - a) for r, a in reversed(cut.fillet[1:])]
        elif rd < rb:
            out.append(centre + Vec.polar(rd, t0))
        out += right
        a0, a1 = (right[-1] - centre).angle(), (left[-1] - centre).angle()
        span = (a1 - a0) % (2 * math.pi)
        if span < math.pi:
            for i in range(1, 6):
                out.append(centre + Vec.polar(right[-1].distance_to(centre), a0 + span * i / 6))
        out += reversed(left)
        if cut is not None:
            out += [centre + Vec.polar(r, centre_angle + a) for r, a in cut.fillet[1:]]
        elif rd < rb:
            out.append(centre + Vec.polar(rd, t1))
        return out

    def teeth_outline(self, centre: Vec, first_centre_angle: float, count: int, flank_points: int,
                      cut: CutFlank | None = None) -> list[Vec]:
        """``count`` consecutive teeth, counter-clockwise from the one centred at ``first_centre_angle``,
        joined by arcs of the dedendum circle (``cut`` as for :meth:`tooth_outline`)."""
        pts: list[Vec] = []
        step = 2 * math.pi / self.teeth
        for k in range(count):
            tooth = self.tooth_outline(centre, first_centre_angle + k * step, flank_points, cut)
            if pts:
                a0, a1 = (pts[-1] - centre).angle(), (tooth[0] - centre).angle()
                span = (a1 - a0) % (2 * math.pi)
                rr = pts[-1].distance_to(centre)
                pts += [centre + Vec.polar(rr, a0 + span * i / 6) for i in range(1, 6)]
            pts += tooth
        return pts


def unwinding_points(rb: float, theta0: float, roll_step: float, count: int, centre: Vec = Vec(0.0, 0.0),
                     sense: int = 1) -> list[tuple[Vec, Vec, float]]:
    """The thread construction of the involute: at each of ``count`` equal divisions of the base circle
    (roll angles k * roll_step from ``theta0``) the tangent point, the thread's end laid off along the
    tangent by the unwound arc r_b u, and u -- a drafter's points of the curve."""
    out = []
    for k in range(count + 1):
        u = k * roll_step
        a = theta0 + sense * u
        touch = centre + Vec.polar(rb, a)
        tangent = Vec(math.sin(a), -math.cos(a)) * sense        # the thread's direction off the circle
        out.append((touch, touch + tangent * (rb * u), u))
    return out


def ring_outline(teeth: int, system: ToothSystem, centre: Vec, first_centre_angle: float, count: int,
                 flank_points: int) -> list[Vec]:
    """``count`` teeth of an internal gear (a ring): its tooth is the space of an external gear of as many
    teeth with addendum and dedendum exchanged (the ring's tips point inwards, at r - a); the ring tooth
    centred at ``first_centre_angle`` is that gear's space there."""
    ghost = Gear(teeth, ToothSystem(system.module, system.pressure_angle, system.dedendum, system.addendum))
    half = math.pi / teeth
    return ghost.teeth_outline(centre, first_centre_angle - half, count + 1, flank_points)
