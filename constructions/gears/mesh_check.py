"""The independent check of a pair in mesh: the closed forms of the contact geometry, from the gears'
numbers only (never the construction's points).

With r_a, r_b the addendum and base radii, C the centre distance and phi' the working pressure angle
(cos phi' = (r_b1 + r_b2)/C; phi at the standard distance, where it is the notes' formula):

    PT1 = r1' sin phi'      PT2 = r2' sin phi'      (r' = working pitch radii; PT1 + PT2 = C sin phi')
    approach AP = sqrt(r_a2^2 - r_b2^2) - PT2        recess PB = sqrt(r_a1^2 - r_b1^2) - PT1
    contact ratio = (AP + PB) / p_b,  p_b = 2 pi r_b / N = pi m cos phi

(each sqrt is the tangent length from the addendum circle's crossing to the base circle's touching
point: Pythagoras in the right triangle O-T-A).  For a rack at distance C from O1 (its addendum a_r):
AP = (a_r - (C - r1)) / sin phi, PT1 = r1 sin phi.  Interference when AP > PT1 or PB > PT2, equivalently
(the notes' form) r_a2 > sqrt(r_b2^2 + (C sin phi')^2) = O2T1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..geometry import acos_clamped, sqrt_nonneg
from .contact import Pair


@dataclass(frozen=True)
class ClosedForm:
    working_pressure_angle: float
    approach: float
    recess: float
    path: float
    base_pitch: float
    pt1: float
    pt2: float

    @property
    def contact_ratio(self) -> float:
        return self.path / self.base_pitch

    def values(self) -> dict[str, float]:
        out = {"AP": self.approach, "PB": self.recess, "AB": self.path, "p_b": self.base_pitch, "PT_1": self.pt1,
               "phi'": self.working_pressure_angle}
        if math.isfinite(self.pt2):
            out["PT_2"] = self.pt2
        out["C.R."] = self.contact_ratio
        return out


def closed_form(pair: Pair) -> ClosedForm:
    g1 = pair.pinion
    m = g1.system.module
    phi = g1.system.pressure_angle
    pb = math.pi * m * math.cos(phi)
    rb1, ra1 = g1.base_radius, g1.addendum_radius
    tip1 = sqrt_nonneg((ra1 - rb1) * (ra1 + rb1))
    if pair.rack:
        C = pair.distance
        r1 = g1.pitch_radius
        pt1 = r1 * math.sin(phi)
        ap = (pair.rack_teeth.a - (C - r1)) / math.sin(phi)
        pbr = tip1 - pt1
        return ClosedForm(phi, ap, pbr, ap + pbr, pb, pt1, math.inf)
    g2 = pair.gear
    C = pair.distance
    if pair.internal:
        # the ring's addendum circle r2 - a is cut between T2 and P: AP = PT2 - sqrt(r_a2^2 - r_b2^2), and
        # T1 lies between T2 and P (PT1 = r1' sin phi' < PT2 = r2' sin phi'); no interference point past P
        rb2, ra2 = g2.base_radius, g2.pitch_radius - g2.system.a
        phiw = phi if pair.centre_distance is None else acos_clamped((rb2 - rb1) / C)
        r1w = C * g1.teeth / (g2.teeth - g1.teeth)
        r2w = C + r1w
        pt1, pt2 = r1w * math.sin(phiw), r2w * math.sin(phiw)
        ap = pt2 - sqrt_nonneg((ra2 - rb2) * (ra2 + rb2))
        pbr = tip1 - pt1
        return ClosedForm(phiw, ap, pbr, ap + pbr, pb, pt1, math.inf)
    rb2, ra2 = g2.base_radius, g2.addendum_radius
    if pair.centre_distance is None:
        phiw = phi
        r1w, r2w = g1.pitch_radius, g2.pitch_radius
    else:
        phiw = acos_clamped((rb1 + rb2) / C)
        r1w = C * g1.teeth / (g1.teeth + g2.teeth)
        r2w = C - r1w
    pt1, pt2 = r1w * math.sin(phiw), r2w * math.sin(phiw)
    tip2 = sqrt_nonneg((ra2 - rb2) * (ra2 + rb2))
    ap, pbr = tip2 - pt2, tip1 - pt1
    return ClosedForm(phiw, ap, pbr, ap + pbr, pb, pt1, pt2)


def notes_contact_ratio(r1: float, r2: float, a1: float, a2: float, phi: float, pb: float) -> float:
    """The notes' contact-ratio formula as printed (standard centre distance)."""
    c = math.cos(phi) ** 2
    return ((sqrt_nonneg((r2 + a2) ** 2 - r2 ** 2 * c) - r2 * math.sin(phi)) / pb
            + (sqrt_nonneg((r1 + a1) ** 2 - r1 ** 2 * c) - r1 * math.sin(phi)) / pb)
