"""A pair of spur gears in mesh and its contact geometry, constructed as a drafter constructs it.

Gear 1 (the pinion) drives, turning clockwise; its centre O1 is at the origin, gear 2's centre O2 on +x
at the centre distance C (a rack: its pitch line square to O1P at C from O1).  The construction is
Cartesian, as a drafter works: the pitch point P divides O1O2 in the ratio of the teeth; the line of
action is drawn through P at the working pressure angle phi' (cos phi' = (r_b1 + r_b2)/C; phi itself at
the standard distance) to the common tangent of the pitch circles; the base circles touch it at the
interference points T1 and T2; the addendum circle of the driven gear cuts it where contact starts (A),
the driver's where it ends (B).  AP is the approach, PB the recess, AB the path of contact; contact
ratio AB / p_b.  Contact starting or ending outside T1T2 is interference, decided three ways (clear, at
the limit, interference) within 1e-9 of the scene size.  The closed forms that check these readings
are :mod:`constructions.gears.mesh_check`; the drawing of the pair is :mod:`constructions.gears.mesh`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import ConstructionError, DegenerateInput
from ..geometry import Circle as GCircle, Contact, Line, Tolerance, Vec, intersect_line_circle
from .tooth import Gear, ToothSystem

CLEAR, AT_LIMIT, INTERFERENCE = "clear", "at the limit", "interference"


@dataclass(frozen=True)
class Pair:
    """Gear 1 (the pinion, driver) with gear 2 -- or a rack when ``gear`` is None -- at ``centre_distance``
    (None: the standard distance (r1 + r2), or r1 from the rack's pitch line)."""

    pinion: Gear
    gear: Gear | None = None
    centre_distance: float | None = None
    rack_system: ToothSystem | None = None
    internal: bool = False                    # gear 2 is an internal gear (a ring) about the pinion

    def __post_init__(self) -> None:
        if self.gear is not None and self.gear.system.module != self.pinion.system.module:
            raise DegenerateInput("gears in mesh need the same module")
        if self.gear is not None and self.gear.system.pressure_angle != self.pinion.system.pressure_angle:
            raise DegenerateInput("gears in mesh need the same pressure angle")
        if self.internal and (self.gear is None or self.gear.teeth <= self.pinion.teeth):
            raise DegenerateInput("an internal gear needs more teeth than its pinion")

    @property
    def rack(self) -> bool:
        return self.gear is None

    @property
    def rack_teeth(self) -> ToothSystem:
        return self.rack_system or self.pinion.system

    @property
    def standard_distance(self) -> float:
        r1 = self.pinion.pitch_radius
        if self.internal:
            return self.gear.pitch_radius - r1
        return r1 if self.rack else r1 + self.gear.pitch_radius

    @property
    def distance(self) -> float:
        return self.standard_distance if self.centre_distance is None else self.centre_distance

    @property
    def size(self) -> float:
        """The scene size L the decisions are taken against: the centre distance plus the larger tip."""
        if self.internal:
            return self.gear.pitch_radius + self.gear.system.d
        ra2 = self.rack_teeth.a if self.rack else self.gear.addendum_radius
        return self.distance + max(self.pinion.addendum_radius, ra2)


@dataclass(frozen=True)
class ContactGeometry:
    """The contact geometry read off the construction (SI; points in the drawing's frame)."""

    points: dict[str, Vec]
    working_pressure_angle: float
    working_radii: tuple[float, float]          # r1', r2' (rack: r1', inf)
    approach: float                             # AP
    recess: float                               # PB
    path: float                                 # AB
    base_pitch: float
    limits: tuple[float, float]                 # PT1, PT2 (rack: PT1, inf)
    start: str                                  # CLEAR / AT_LIMIT / INTERFERENCE at A (against T1)
    end: str                                    # ... at B (against T2)
    tolerance: float

    @property
    def contact_ratio(self) -> float:
        return self.path / self.base_pitch

    @property
    def verdict(self) -> str:
        if INTERFERENCE in (self.start, self.end):
            return INTERFERENCE
        return AT_LIMIT if AT_LIMIT in (self.start, self.end) else CLEAR


def _three_way(reach: float, limit: float, tol: float) -> str:
    gap = limit - reach
    return CLEAR if gap > tol else AT_LIMIT if gap >= -tol else INTERFERENCE


def contact_geometry(pair: Pair) -> tuple[ContactGeometry, dict]:
    """The Cartesian construction of the contact geometry; also returns the lines and circles drawn."""
    p1 = pair.pinion
    phi = p1.system.pressure_angle
    C = pair.distance
    L = pair.size
    tol = Tolerance(L)
    if C < pair.standard_distance - tol.length:
        what = "rack's pitch line" if pair.rack else "centre distance"
        raise ConstructionError(f"the {what} {C:.6g} m is less than the standard {pair.standard_distance:.6g} m: "
                                f"the teeth would jam (an involute pair may be pulled apart, never pushed closer)")
    O1 = Vec(0.0, 0.0)
    rb1 = p1.base_radius
    if pair.rack:
        phi_w = phi
        r1w = p1.pitch_radius
        O2 = None
    elif pair.internal:
        g2 = pair.gear
        rb2 = g2.base_radius
        phi_w = phi if pair.centre_distance is None else math.acos(min(1.0, (rb2 - rb1) / C))
        r1w = C * p1.teeth / (g2.teeth - p1.teeth)
        O2 = Vec(-C, 0.0)                    # the ring's centre: P lies beyond O1, on the ring's pitch circle
        if g2.pitch_radius - g2.system.a <= rb2 + tol.length:
            raise ConstructionError(f"the internal gear's addendum circle (r - a) lies inside its base circle: a ring "
                                    f"of {g2.teeth} teeth has no involute at its tips (it needs more teeth)")
    else:
        g2 = pair.gear
        rb2 = g2.base_radius
        c = (rb1 + rb2) / C
        phi_w = phi if pair.centre_distance is None else math.acos(min(1.0, c))
        r1w = C * p1.teeth / (p1.teeth + g2.teeth)
        O2 = Vec(C, 0.0)
    P = Vec(r1w, 0.0)
    # the line of action through P at phi' to the common tangent (the y axis), leaning so the driver turning
    # clockwise pushes the contact from T1 towards T2
    d = Vec(math.sin(phi_w), -math.cos(phi_w))
    loa = Line(P, d)
    T1 = loa.foot(O1)
    pts = {"O1": O1, "P": P, "T1": T1}
    # where contact ends: the driver's addendum circle on the far side of P from T1
    cut1 = intersect_line_circle(loa, GCircle(O1, p1.addendum_radius), tol)
    B = cut1.points[0]                       # ahead along d (towards T2)
    if pair.rack:
        rs = pair.rack_teeth
        tip_x = C - rs.a                     # the rack's addendum line, square to O1P
        if tip_x >= r1w:
            raise ConstructionError("the rack's addendum line does not reach the pitch point: its teeth miss the pinion")
        # the line of action meets the addendum line x = tip_x behind P (towards T1)
        A = P + d * ((tip_x - P.x) / d.x)
        T2 = None
        limit2 = math.inf
        r2w = math.inf
    elif pair.internal:
        T2 = loa.foot(O2)                    # behind T1: both base circles touch the line on one side of P
        ra2 = pair.gear.pitch_radius - pair.gear.system.a
        cut2 = intersect_line_circle(loa, GCircle(O2, ra2), tol)
        A = cut2.points[0]                   # ahead of T2, between it and P
        pts |= {"O2": O2, "T2": T2}
        limit2 = math.inf                    # the recess side has no interference point
        r2w = C + r1w
    else:
        O2v = O2
        T2 = loa.foot(O2v)
        cut2 = intersect_line_circle(loa, GCircle(O2v, pair.gear.addendum_radius), tol)
        if cut2.contact is not Contact.CROSSING:
            raise ConstructionError("the addendum circle of gear 2 does not cut the line of action")
        A = cut2.points[1]                   # behind the foot T2, towards T1
        pts |= {"O2": O2v, "T2": T2}
        limit2 = P.distance_to(T2)
        r2w = C - r1w
    along = lambda q: d.dot(q - P)          # noqa: E731 -- signed distance along the line of action from P
    approach, recess = -along(A), along(B)
    if approach <= tol.length or recess <= tol.length:
        who = "gear 2 (or the rack)" if approach <= tol.length else "gear 1"
        raise ConstructionError(f"the addendum circle of {who} does not reach past the pitch point on the line of "
                                f"action: the teeth never come into contact there (centre distance too large)")
    pts |= {"A": A, "B": B}
    limit1 = P.distance_to(T1)
    start = _three_way(approach, limit1, tol.length)
    end = _three_way(recess, limit2, tol.length) if math.isfinite(limit2) else CLEAR
    geo = ContactGeometry(pts, phi_w, (r1w, r2w), approach, recess, A.distance_to(B), p1.base_pitch,
                          (limit1, limit2), start, end, tol.length)
    return geo, {"line": loa}
