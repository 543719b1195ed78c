"""A pair of spur gears in mesh, drawn as the notes draw it, step by step: the data, the pitch circles and
the line of action, the base and addendum circles, the path of contact and the interference check, the
contact ratio, a few teeth of each (as a rack cutter leaves them where it undercuts them) and the involute
detail (:mod:`constructions.gears.thread`).  The contact geometry itself is constructed in
:mod:`constructions.gears.contact` and read off here; the closed forms that check the readings are
:mod:`constructions.gears.mesh_check`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..geometry import Vec
from ..quantities import Measured
from ..entities import AngleMark, Arc, Circle, Curve, Diagram, Dimension, Pivot, Point, Role, RotationArrow, Segment
from ..record import Construction, StepKind, Value
from .action import Action, action
from .action_step import action_step
from .contact import AT_LIMIT, CLEAR, INTERFERENCE, ContactGeometry, Pair, contact_geometry
from .flank import FLANK_POINTS
from .generation import drawn_flank, fewest_uncut, straight_depth, tip_round, undercut_flank
from .thread import THREAD, thread_construction
from .tooth import ring_outline

SPACE = Diagram("overall")
DETAIL = Diagram("space", "contact at the pitch point")


@dataclass
class MeshAnalysis:
    pair: Pair
    construction: Construction
    geometry: ContactGeometry
    warnings: tuple[str, ...] = field(default_factory=tuple)
    action: Action | None = None

    def measured(self) -> list[Measured]:
        g = self.geometry
        # the path of contact is read off the detail at the pitch point, the base pitch (p cos phi) off
        # the involute diagram's pitch -- not off the overall diagram, drawn smaller
        on, pitch = DETAIL.key, THREAD.key
        out = [Measured("AP", "length", g.approach, diagram=on), Measured("PB", "length", g.recess, diagram=on),
               Measured("AB", "length", g.path, diagram=on),
               Measured("p_b", "length", g.base_pitch, diagram=pitch),
               Measured("PT_1", "length", g.limits[0], diagram=on)]
        if math.isfinite(g.limits[1]):
            out.append(Measured("PT_2", "length", g.limits[1], diagram=on))
        out.append(Measured("phi'", "angle", g.working_pressure_angle))
        out.append(Measured("C.R.", "ratio", g.contact_ratio))      # AB / p_b, the notes' C.R.
        kinds = {"delta_1": "angle", "delta_2": "angle", "V_p": "velocity", "v_s A": "velocity", "v_s B": "velocity"}
        out += [Measured(k, kinds[k], v) for k, v in (self.action.values() if self.action else {}).items()]
        return out


def _v(kind: str, x: float) -> Value:
    return Value(kind, x)


def mesh_analysis(pair: Pair, fmt=None, teeth_drawn: int = 2, flank_points: int = FLANK_POINTS,
                  thread: bool = True, speed: float | None = None) -> MeshAnalysis:
    """The pair drawn as the notes' contact-geometry diagram, step by step, and its readings; with the
    pinion's ``speed`` (rad/s) the pitch-line speed and the sliding at the tips as well."""
    geo, _ = contact_geometry(pair)
    p1, g2 = pair.pinion, pair.gear
    sysm = p1.system
    pts = geo.points
    O1, P, T1, A, B = pts["O1"], pts["P"], pts["T1"], pts["A"], pts["B"]
    C = pair.distance
    phi_w = geo.working_pressure_angle
    rec = Construction("Gears in mesh: contact geometry")
    warnings: list[str] = []
    name2 = "the rack" if pair.rack else "internal gear 2" if pair.internal else "gear 2"
    if pair.internal:
        ra2_, rd2_ = g2.pitch_radius - sysm.a, g2.pitch_radius + sysm.d
    elif not pair.rack:
        ra2_, rd2_ = g2.addendum_radius, g2.dedendum_radius
    # 1 the data
    given = [Pivot("O1", Role.GIVEN, SPACE, O1, "O1")]
    vals = {"m": _v("length", sysm.module), "phi": _v("angle", sysm.pressure_angle), "C": _v("length", C)}
    if pair.rack:
        rack_x = C
        top, bottom = P.y + 0.75 * p1.addendum_radius, P.y - 0.75 * p1.addendum_radius
        given.append(Segment("rack pitch line", Role.CENTRE_LINE, SPACE, Vec(rack_x, bottom), Vec(rack_x, top), "pitch line"))
        words = (f"Given: pinion 1 ({p1.teeth} teeth, the driver, turning clockwise) and a rack, module $m, pressure angle "
                 f"$phi; the rack's pitch line $C from O1.")
    else:
        O2 = pts["O2"]
        given += [Pivot("O2", Role.GIVEN, SPACE, O2, "O2"),
                  Segment("line of centres", Role.CENTRE_LINE, SPACE, O1, O2)]
        words = (f"Given: gear 1 ({p1.teeth} teeth, the driver, turning clockwise) and {name2} ({g2.teeth} teeth), module "
                 f"$m, pressure angle $phi, centre distance O1O2 = $C"
                 + (" (the standard distance)." if pair.centre_distance is None else "."))
    given.append(RotationArrow("rotation 1", Role.GIVEN, SPACE, O1, 0.55 * p1.pitch_radius, math.radians(250.0),
                               -math.radians(80.0), "ω_1"))
    if not pair.rack:            # an external pair turns in opposite senses, an internal one in the same
        s2 = -1.0 if pair.internal else 1.0
        given.append(RotationArrow("rotation 2", Role.GIVEN, SPACE, pts["O2"], 0.55 * g2.pitch_radius,
                                   math.radians(250.0 if pair.internal else 290.0), s2 * math.radians(80.0),
                                   "ω_2"))
    rec = rec.then(words, *given, values=vals, kind=StepKind.GIVEN)
    # 2 pitch circles and the pitch point
    r1w, r2w = geo.working_radii
    T2p = pts.get("T2")
    h = 0.6 * (T1.distance_to(T2p) if T2p is not None else 2.2 * max(T1.distance_to(P), geo.recess, geo.approach))

    def arc(name, role, centre, r):
        half = 2 * math.asin(min(1.0, 1.3 * h / (2 * r)))
        a = (P - centre).angle()
        return Arc(name, role, DETAIL, centre, r, a - half, a + half)
    ents = [Circle("pitch circle 1", Role.CENTRE_LINE, SPACE, O1, r1w), Point("P", Role.LABEL, SPACE, P, "P"),
            arc("detail pitch 1", Role.CENTRE_LINE, O1, r1w), Point("detail P", Role.LABEL, DETAIL, P, "P")]
    vals = {"r1": _v("length", r1w)}
    if pair.rack:
        words = "Pitch circle of the pinion, r1 = mN1/2 = $r1, touching the rack's pitch line at the pitch point P."
    else:
        ents += [Circle("pitch circle 2", Role.CENTRE_LINE, SPACE, pts["O2"], r2w),
                 arc("detail pitch 2", Role.CENTRE_LINE, pts["O2"], r2w)]
        vals["r2"] = _v("length", r2w)
        if pair.centre_distance is None:
            words = ("Pitch circles r1 = mN1/2 = $r1 and r2 = mN2/2 = $r2; they touch at the pitch point P on the line "
                     "of centres.")
        else:
            words = ("At the stated centre distance the pitch point P divides O1O2 in the ratio of the teeth: working "
                     "pitch circles r1' = C N1/(N1+N2) = $r1 and r2' = $r2.")
    rec = rec.then(words, *ents, values=vals)
    # 3 the line of action
    d = Vec(math.sin(phi_w), -math.cos(phi_w))
    far = max(geo.path, p1.addendum_radius) * 0.35
    along = [d.dot(q - P) for q in (T1, A, B, pts.get("T2")) if q is not None]
    lo, hi = min(along) - far, max(along) + far
    near = [d.dot(q - P) for q in (T1, A, B, T2p) if q is not None]
    tangent_len = 0.8 * p1.addendum_radius if pair.rack else 0.5 * min(r1w, r2w)
    mark_r = 0.45 * h
    tangent_len = min(tangent_len, 0.9 * h)
    ents = [Segment("common tangent", Role.AUXILIARY, DETAIL, P + Vec(0, -tangent_len), P + Vec(0, tangent_len)),
            # labelled in the detail, where the line is long enough to carry its name (at 1:5 the label of a
            # line a few mm long lands by the line of centres)
            Segment("line of action", Role.PATH, SPACE, P + d * lo, P + d * hi),
            Segment("detail line of action", Role.PATH, DETAIL, P + d * (max(near) + 0.1 * h),
                    P + d * (min(near) - 0.1 * h), "line of action"),
            AngleMark("pressure angle", Role.DIMENSION, DETAIL, P, mark_r, -math.pi / 2, -math.pi / 2 + phi_w,
                      "\u03c6'" if pair.centre_distance is not None and not pair.rack else "\u03c6")]
    vals = {"phiw": _v("angle", phi_w)}
    if pair.centre_distance is not None and not pair.rack:
        words = ("Through P draw the line of action at the working pressure angle \u03c6' to the common tangent of the "
                 "pitch circles: cos \u03c6' = (r_b1 + r_b2)/C, \u03c6' = $phiw.")
    else:
        words = "Through P draw the line of action at the pressure angle $phiw to the common tangent of the pitch circles."
    rec = rec.then(words, *ents, values=vals)
    # 4 base circles and the interference points
    ents = [Circle("base circle 1", Role.CENTRE_LINE, SPACE, O1, p1.base_radius),
            Segment("O1T1", Role.AUXILIARY, SPACE, O1, T1), Point("T1", Role.LABEL, SPACE, T1, "T1"),
            Point("detail T1", Role.LABEL, DETAIL, T1, "T1"), arc("detail base 1", Role.CENTRE_LINE, O1, p1.base_radius)]
    vals = {"rb1": _v("length", p1.base_radius)}
    if pair.rack:
        words = ("The base circle r_b1 = r1 cos \u03c6 = $rb1 touches the line of action at the interference point T1 "
                 "(the foot of the perpendicular from O1).")
    else:
        T2 = pts["T2"]
        ents += [Circle("base circle 2", Role.CENTRE_LINE, SPACE, pts["O2"], g2.base_radius),
                 Segment("O2T2", Role.AUXILIARY, SPACE, pts["O2"], T2), Point("T2", Role.LABEL, SPACE, T2, "T2"),
                 Point("detail T2", Role.LABEL, DETAIL, T2, "T2"),
                 arc("detail base 2", Role.CENTRE_LINE, pts["O2"], g2.base_radius)]
        vals["rb2"] = _v("length", g2.base_radius)
        words = ("The base circles r_b1 = $rb1 and r_b2 = $rb2 (r cos \u03c6) touch the line of action at the "
                 "interference points T1 and T2, the feet of the perpendiculars from O1 and O2.")
    rec = rec.then(words, *ents, values=vals)
    # 5 addendum and dedendum circles
    ents = [Circle("addendum circle 1", Role.GIVEN, SPACE, O1, p1.addendum_radius),
            Circle("dedendum circle 1", Role.AUXILIARY, SPACE, O1, p1.dedendum_radius),
            arc("detail addendum 1", Role.PATH, O1, p1.addendum_radius)]
    vals = {"ra1": _v("length", p1.addendum_radius)}
    if pair.rack:
        tip_x = C - pair.rack_teeth.a
        top, bottom = P.y + 0.75 * p1.addendum_radius, P.y - 0.75 * p1.addendum_radius
        ents.append(Segment("rack addendum line", Role.GIVEN, SPACE, Vec(tip_x, bottom), Vec(tip_x, top)))
        ents.append(Segment("detail rack addendum line", Role.AUXILIARY, DETAIL, Vec(tip_x, P.y - h), Vec(tip_x, P.y + h)))
        vals["a2"] = _v("length", pair.rack_teeth.a)
        words = "Addendum circle of the pinion r_a1 = r1 + a = $ra1; the rack's addendum line $a2 inside its pitch line."
    else:
        ents += [Circle("addendum circle 2", Role.GIVEN, SPACE, pts["O2"], ra2_),
                 Circle("dedendum circle 2", Role.AUXILIARY, SPACE, pts["O2"], rd2_),
                 arc("detail addendum 2", Role.PATH, pts["O2"], ra2_)]
        vals["ra2"] = _v("length", ra2_)
        words = ("Addendum circles r_a1 = r1 + a = $ra1 and r_a2 = " + ("r2 - a (inside: an internal gear) = " if pair.internal
                 else "") + "$ra2 (dedendum circles thin).")
    rec = rec.then(words, *ents, values=vals)
    # 6 the path of contact
    off = -0.3 * h
    ents = [Point("A", Role.LABEL, DETAIL, A, "A"), Point("B", Role.LABEL, DETAIL, B, "B"),
            Segment("path of contact", Role.RESULT, DETAIL, A, B),
            Segment("overview path of contact", Role.RESULT, SPACE, A, B),
            Dimension("approach", Role.DIMENSION, DETAIL, A, P, off, "AP $ap"),
            Dimension("recess", Role.DIMENSION, DETAIL, P, B, off, "PB $pb")]
    vals = {"ap": _v("length", geo.approach), "pb": _v("length", geo.recess), "ab": _v("length", geo.path)}
    words = (f"Contact starts at A, where the addendum {'line' if pair.rack else 'circle'} of the driven {name2} cuts "
             f"the line of action, and ends at B on the driver's addendum circle: approach AP = $ap, recess PB = $pb, "
             f"path of contact AB = $ab.")
    rec = rec.then(words, *ents, values=vals, kind=StepKind.ANSWER)
    # 7 interference
    vals = {"pt1": _v("length", geo.limits[0]), "ap": _v("length", geo.approach)}
    verdict = {CLEAR: "inside", AT_LIMIT: "exactly at", INTERFERENCE: "outside"}
    words = f"Interference check: A lies {verdict[geo.start]} T1 (AP = $ap against PT1 = $pt1)"
    if not pair.rack and not pair.internal:
        vals |= {"pt2": _v("length", geo.limits[1]), "pb": _v("length", geo.recess)}
        words += f"; B lies {verdict[geo.end]} T2 (PB = $pb against PT2 = $pt2)"
    words += {CLEAR: ": no interference.", AT_LIMIT: ": at the limit of interference (contact starts or ends at an "
              "interference point), no interference.", INTERFERENCE: ": INTERFERENCE -- contact off the involutes, "
              "below a base circle."}[geo.verdict]
    # the stretch of the path of contact off the involutes, dimensioned on the far side from AP and PB
    marks, said = [], []
    if geo.start == INTERFERENCE:
        vals["i1"] = _v("length", geo.approach - geo.limits[0])
        marks.append(Dimension("interference at A", Role.DIMENSION, DETAIL, A, T1, -off, "interference $i1"))
        said.append("AT1 = $i1")
    if geo.end == INTERFERENCE:
        vals["i2"] = _v("length", geo.recess - geo.limits[1])
        marks.append(Dimension("interference at B", Role.DIMENSION, DETAIL, pts["T2"], B, -off,
                               "interference $i2"))
        said.append("T2B = $i2")
    if said:
        words += " The stretch off the involutes is dimensioned: " + " and ".join(said) + "."
    rec = rec.then(words, *marks, values=vals, kind=StepKind.ANSWER)
    if geo.verdict == INTERFERENCE:
        where = [w for w, v in (("starts before T1", geo.start), ("ends after T2", geo.end)) if v == INTERFERENCE]
        warnings.append("Interference: contact " + " and ".join(where)
                        + ", below a base circle where there is no involute (the teeth would be undercut when cut by "
                          "generation).")
    # 8 contact ratio
    cr = geo.contact_ratio
    vals = {"pbase": _v("length", geo.base_pitch), "ab": _v("length", geo.path), "cr": _v("number", cr)}
    rec = rec.then("Base pitch p_b = \u03c0 m cos \u03c6 = $pbase; contact ratio AB / p_b = $ab / $pbase = $cr.",
                   values=vals, kind=StepKind.ANSWER)
    act = action(pair, geo.approach, geo.recess, phi_w, speed)
    rec = action_step(rec, pair, act)
    if cr < 1.0:
        warnings.append(f"Contact ratio {cr:.3f} is below 1: a pair of teeth leaves contact before the next pair "
                        f"engages (the drive is not continuous).")
    # 9 teeth, as a rack cutter leaves them where it undercuts them
    cut1 = undercut_flank(p1)
    cut2 = undercut_flank(g2) if not pair.rack and not pair.internal else None
    for number, gear, cut in ((1, p1, cut1), (2, g2, cut2)):
        if cut is not None and cut.severed:
            warnings.append(f"Cut by generation, the {gear.teeth} teeth of gear {number} would be cut through at "
                            f"their root (the cutter's tip round crosses the tooth's centre line): no such gear can "
                            f"be generated with this cutter; its teeth are drawn as involutes only.")
    cut1, cut2 = drawn_flank(cut1), drawn_flank(cut2)
    ents = [Curve("teeth 1", Role.GIVEN, DETAIL, tuple(p1.teeth_outline(O1, p1.half_tooth_angle - teeth_drawn * 2 * math.pi
                                                                          / p1.teeth, 2 * teeth_drawn + 1, flank_points,
                                                                          cut1)))]
    if pair.rack:
        ents.append(Curve("rack teeth", Role.GIVEN, DETAIL, tuple(_rack_outline(pair, teeth_drawn + 1))))
    else:
        O2 = pts["O2"]
        if pair.internal:
            ents.append(Curve("teeth 2", Role.GIVEN, DETAIL, tuple(ring_outline(
                g2.teeth, sysm, O2, -g2.half_tooth_angle - teeth_drawn * 2 * math.pi / g2.teeth, 2 * teeth_drawn + 1,
                flank_points))))
        else:
            ents.append(Curve("teeth 2", Role.GIVEN, DETAIL, tuple(g2.teeth_outline(
                O2, math.pi + g2.half_tooth_angle - teeth_drawn * 2 * math.pi / g2.teeth, 2 * teeth_drawn + 1, flank_points,
                cut2))))
    rec = rec.then(f"A few teeth of each, their involute flanks computed exactly ({flank_points} points a flank): a "
                   f"pair in contact at P, the flanks square to the line of action there.", *ents)
    for number, gear, cut in ((1, p1, cut1), (2, g2, cut2)):
        if cut is None:
            continue
        vals = {"rx": _v("length", cut.involute_from), "rho": _v("length", tip_round(gear)),
                "hs": _v("length", straight_depth(gear)), "nmin": _v("number", fewest_uncut(gear))}
        rec = rec.then(f"Cut by generation, the {gear.teeth} teeth of gear {number} are undercut: the cutter (the system's "
                       f"basic rack, its tip rounded to $rho) runs its straight flank $hs deep, past the interference "
                       f"point, as it does for fewer than 2 depth / (m sin\u00b2 \u03c6) = $nmin teeth; its tip round "
                       f"cuts the involute away below R = $rx, as drawn.", values=vals)
    if thread:
        rec = rec + thread_construction(p1, phi_w)
    return MeshAnalysis(pair, rec, geo, tuple(warnings), act)


def _rack_outline(pair: Pair, count: int) -> list[Vec]:
    """The rack's teeth about the pitch point: straight flanks at the pressure angle, a tooth centred a
    quarter pitch below P so its flank passes through P."""
    s = pair.rack_teeth
    p = s.circular_pitch
    phi = s.pressure_angle
    x0 = pair.distance                       # pitch line
    xa, xd = x0 - s.a, x0 + s.d
    t = math.tan(phi)
    out: list[Vec] = []
    reach = 1.1 * pair.pinion.addendum_radius
    for k in range(-count - 1, count + 2):
        yc = -p / 4 + k * p                  # tooth centre on the pitch line
        if abs(yc) > reach:
            continue
        half = p / 4
        lower = [Vec(xd, yc - half - s.d * t), Vec(xa, yc - half + s.a * t)]
        upper = [Vec(xa, yc + half - s.a * t), Vec(xd, yc + half + s.d * t)]
        out += lower + upper
    back = xd + 1.5 * s.module                # the rack's body behind its roots
    return [Vec(back, out[0].y)] + out + [Vec(back, out[-1].y), Vec(back, out[0].y)]
