"""The involute of a gear drawn by unwinding a thread off its base circle, and the terms of a spur gear on
two of its teeth: the involute detail of the mesh sheet.
"""

from __future__ import annotations

import math

from ..geometry import Vec
from ..entities import Arc, Curve, Diagram, Dimension, Note, Point, Role, Segment
from ..record import Construction, Value
from .flank import FLANK_POINTS
from .generation import drawn_flank, undercut_flank
from .tooth import Gear, involute_point, inv, roll_angle, unwinding_points

THREAD = Diagram("involute", "by unwinding a thread")


def thread_construction(g: Gear, phi: float) -> Construction:
    """The involute of gear 1 drawn by unwinding a thread off its base circle (a separate detail)."""
    rb, ra = g.base_radius, g.addendum_radius
    O = Vec(0.0, 0.0)
    u_tip = roll_angle(rb, ra)
    count = 6
    step = u_tip / count
    theta0 = math.pi / 2 - u_tip / 2         # the flank stands upright on the detail
    marks = unwinding_points(rb, theta0, step, count, O, +1)
    pitch_angle = 2 * math.pi / g.teeth
    centre = theta0 + g.half_tooth_angle + inv(g.system.pressure_angle)   # the tooth whose flank this is
    a0, a1 = theta0 - 0.1, max(theta0 + u_tip + 0.15, centre + 1.5 * pitch_angle)
    rp, rd = g.pitch_radius, g.dedendum_radius
    ents = [Arc("thread base arc", Role.CENTRE_LINE, THREAD, O, rb, a0, a1),
            Arc("thread pitch arc", Role.CENTRE_LINE, THREAD, O, rp, a0, a1),
            Arc("thread addendum arc", Role.AUXILIARY, THREAD, O, ra, a0, a1),
            Arc("thread dedendum arc", Role.AUXILIARY, THREAD, O, rd, a0, a1)]
    rec = Construction("involute").then(
        "Involute by unwinding a thread: divide the base circle of gear 1 from the flank's root into equal arcs of "
        "roll angle $du.", *ents, *[Point(f"thread k{k}", Role.LABEL, THREAD, t, str(k)) for k, (t, _, _) in enumerate(marks)],
        values={"du": Value("angle", step)})
    tans = [Segment(f"thread tangent {k}", Role.AUXILIARY, THREAD, t, e) for k, (t, e, _) in enumerate(marks) if k]
    rec = rec.then("At each division draw the tangent and lay off along it the unwound arc r_b u (the thread held "
                   "tight): its ends are points of the involute.", *tans)
    fine = [involute_point(rb, theta0, u_tip * i / (FLANK_POINTS * 2 - 1), O, +1) for i in range(FLANK_POINTS * 2)]
    rec = rec.then("Join them: the involute flank from the base circle to the addendum circle (drawn computed exactly).",
                   Curve("involute", Role.RESULT, THREAD, tuple(fine)))
    # the terms of a spur gear on two of its teeth
    psi = g.half_tooth_angle
    space = centre + pitch_angle / 2
    u = Vec.polar(1.0, space)
    lab = lambda r, a: O + Vec.polar(r, a)  # noqa: E731
    ends = a1 + 0.02
    teeth = g.teeth_outline(O, centre, 2, FLANK_POINTS, drawn_flank(undercut_flank(g)))
    terms = [Curve("terms teeth", Role.GIVEN, THREAD, tuple(teeth)),
             Dimension("terms t", Role.DIMENSION, THREAD, lab(rp, centre - psi), lab(rp, centre + psi), -0.45 * g.system.module,
                       "t"),
             Dimension("terms p", Role.DIMENSION, THREAD, lab(rp, centre - psi), lab(rp, centre - psi + pitch_angle),
                       -(g.system.a + 1.3 * g.system.module), "p"),
             Dimension("terms a", Role.DIMENSION, THREAD, u * rp, u * ra, 0.0, "a"),
             Dimension("terms d", Role.DIMENSION, THREAD, u * rd, u * rp, 0.0, "d"),
             Note("terms pitch", Role.NOTE, THREAD, lab(rp, ends), "pitch circle"),
             Note("terms base", Role.NOTE, THREAD, lab(rb, ends), "base circle"),
             Note("terms addendum", Role.NOTE, THREAD, lab(ra, ends), "addendum circle"),
             Note("terms dedendum", Role.NOTE, THREAD, lab(rd, ends), "dedendum circle")]
    m = g.system.module
    rec = rec.then("The terms on two teeth of gear 1: tooth thickness t = \u03c0m/2 = $t and circular pitch p = \u03c0m = $p "
                   "(arcs of the pitch circle), addendum a = $a, dedendum d = $d, base pitch p_b = p cos \u03c6 = $pb.",
                   *terms, values={"t": Value("length", math.pi * m / 2), "p": Value("length", math.pi * m),
                                   "a": Value("length", g.system.a), "d": Value("length", g.system.d),
                                   "pb": Value("length", g.base_pitch)})
    return rec
