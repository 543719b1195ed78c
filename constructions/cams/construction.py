"""The graphical construction of a disk cam's profile, step by step as the notes draw it.

Notes, "Graphical construction of cam (roller follower)" and "Roller follower with offset":

1. divide the cam angle (360 deg) into N equal portions;
2. calculate and tabulate s at every interval;
3. draw the base circle (r_b);
4. draw the prime circle (r_b + r_0; a roller follower);
5. draw the offset circle (radius e; an offset follower);
6. draw the N follower lines -- radial lines, or lines tangent to the offset circle -- laid out opposite
   to the cam's rotation (the cam is held still and the follower walked round it);
7. on each line mark the roller centre s_i beyond the prime circle and draw the roller circle (a flat
   face: the face line square to the line at r_b + s_i; a knife edge: the edge itself);
8. draw the profile tangent to every roller circle (face line): their envelope.

The stations and roller centres are computed in the cam frame of :mod:`constructions.cams.envelope`; the
profile drawn is the exact envelope, its contact points on the roller circles marked.  Measured values
read off the construction: the roller centres and contact points at the
segment joins (their distance from O is the prime circle plus the lift tabulated there), and the pressure angle at the station where it is largest (the angle between the
follower's line and the roller's radius to its contact point; flat-faced: the face is square to its line).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..entities import Circle, Curve, Diagram, Note, Pivot, Point, Role, RotationArrow, Segment
from ..geometry import Vec
from ..quantities import Measured
from ..record import Construction, StepKind, Value
from ..tolerance import STATION_REL
from .charts import displacement_diagram, svaj_charts
from .laws import DWELL, TAU, Program
from .envelope import evaluate
from .follower import FLAT, KNIFE, OSC_FLAT, OSCILLATING, ROLLER, Follower, drawn_follower
from .profile import CamProfile, analyse
from .stations import degree_text, station_rows
from .details import details_words, profile_details

CAM = Diagram("cam", "profile")


@dataclass
class CamConstruction:
    construction: Construction
    stations: np.ndarray                  # the cam angles of the stations (rad)
    table: np.ndarray                     # s at each station (SI)
    centres: np.ndarray                   # roller centres (knife: edges; flat: the feet of the face lines) 2 x N
    contacts: np.ndarray                  # contact points on each roller circle / face line, 2 x N
    profile: CamProfile
    measured: list[Measured]
    station_names: dict[str, int]         # "P_120" -> station index


def _v(p) -> Vec:
    return Vec(float(p[0]), float(p[1]))


def construct(program: Program, f: Follower, divisions: int, *, omega: float | None = None,
              degrees=lambda a: f"{math.degrees(a):.4g} deg", samples: int = 2048) -> CamConstruction:
    """The construction with ``divisions`` equal portions of the turn."""
    if divisions < 4:
        raise ValueError("divide the cam angle into at least 4 portions")
    cp = analyse(program, f, samples)
    n = divisions
    step = TAU / n
    th = np.arange(n) * step
    ev = evaluate(program, f, th)
    sg = f.sense
    O = Vec(0.0, 0.0)
    turn = "counter-clockwise" if sg > 0 else "clockwise"
    opposite = "clockwise" if sg > 0 else "counter-clockwise"
    rb, rr, e = f.base_radius, f.roller_radius, f.offset
    osc = f.kind == OSCILLATING
    swing = f.kind in (OSCILLATING, OSC_FLAT)
    lk = "angle" if swing else "length"        # an oscillating follower's lift is its swing

    # the program in words (given)
    parts = []
    vals: dict[str, Value] = {}
    for i, seg in enumerate(program.segments):
        a, b = program.starts[i], program.starts[i] + seg.beta
        vals[f"a{i}"], vals[f"b{i}"] = Value("angle", a), Value("angle", b)
        if seg.kind == DWELL:
            vals[f"h{i}"] = Value(lk, program.levels[i])
            parts.append(f"dwell at $h{i} from $a{i} to $b{i}")
        else:
            vals[f"h{i}"] = Value(lk, seg.lift)
            parts.append(f"{seg.law} {seg.kind} of $h{i} from $a{i} to $b{i}")
    vals["rb"] = Value("length", rb)
    what = {KNIFE: "a knife-edge follower", ROLLER: "a roller follower of radius $rr",
            FLAT: "a flat-faced follower",
            OSCILLATING: "an oscillating roller follower of radius $rr on an arm $l pivoted $a from the cam centre "
                         "(the lift is the arm's swing)",
            OSC_FLAT: "an oscillating flat-faced follower pivoted $a from the cam centre, its face "
                      + ("$ef from the line through the pivot along the arm, towards the cam" if f.face_offset > 0 else
                         "$ef from the line through the pivot along the arm, away from the cam" if f.face_offset else
                         "along the line through the pivot") + " (the lift is the arm's swing)"}[f.kind]
    if f.kind in (ROLLER, OSCILLATING):
        vals["rr"] = Value("length", rr)
    if osc:
        vals["l"], vals["a"] = Value("length", f.arm_length), Value("length", f.pivot_distance)
    if f.kind == OSC_FLAT:
        vals["a"] = Value("length", f.pivot_distance)
        if f.face_offset:
            vals["ef"] = Value("length", abs(f.face_offset))
    off = ""
    if e and f.kind != FLAT:
        vals["e"] = Value("length", abs(e))
        off = f", its axis offset $e to the {'right' if e > 0 else 'left'} of the cam centre"
    rec = Construction("Cam profile").then(
        f"Given: the follower's motion program -- {'; '.join(parts)}; {what}{off}; base circle radius $rb; the "
        f"cam turns {turn}.", values=vals, kind=StepKind.GIVEN)
    rec = rec.then(f"Divide the cam angle (360\u00b0) into N = {n} equal portions of $d.",
                   values={"d": Value("angle", step)})

    # 2: the table of s
    tvals = {f"s{i}": Value(lk, float(ev.s[i])) for i in range(n)}
    rec = rec.then("Calculate s at every station and set it out in a table: the station, its cam angle and s.",
                   values=tvals, table=station_rows(th, "swing s" if f.kind in (OSCILLATING, OSC_FLAT) else "s"))

    # 3-5: circles
    rec = rec.then("Draw the base circle of radius $rb about the cam centre O.",
                   Pivot("O", Role.GIVEN, CAM, O, "O"),
                   Circle("base circle", Role.CENTRE_LINE, CAM, O, rb, "base circle"),
                   values={"rb": Value("length", rb)})
    if f.kind in (ROLLER, OSCILLATING):
        rec = rec.then("Draw the prime circle of radius r_b + r_0 = $rp.",
                       Circle("prime circle", Role.CENTRE_LINE, CAM, O, f.prime_radius, "prime circle"),
                       values={"rp": Value("length", f.prime_radius)})
    if e and f.kind != FLAT:
        rec = rec.then("Draw the offset circle of radius e = $e about O.",
                       Circle("offset circle", Role.CENTRE_LINE, CAM, O, abs(e), "offset circle"),
                       values={"e": Value("length", abs(e))})

    # 6: the follower's lines laid out opposite to the rotation (an oscillating follower: its pivots)
    if osc:
        rec, centres = _oscillating_steps(rec, f, th, ev, step, opposite)
    elif f.kind == OSC_FLAT:
        rec, centres = _oscillating_face_steps(rec, f, cp, th, ev, step, opposite)
    else:
        rec, centres = _translating_steps(rec, f, program, cp, th, ev, step, opposite)
    contacts = ev.profile

    # 8: the envelope
    prof = cp.trimmed
    curve = Curve("profile", Role.RESULT, CAM, tuple(Vec(float(x), float(y)) for x, y in zip(prof[0], prof[1])),
                  True, "cam profile")
    marks = [Point(f"C{i}", Role.RESULT, CAM, _v(contacts[:, i])) for i in range(n)] if f.kind != KNIFE else []
    tangent = {OSCILLATING: "tangent to every roller circle (their envelope; its contact points marked)",
               ROLLER: "tangent to every roller circle (their envelope; its contact points marked)",
               KNIFE: "through every knife-edge point (the pitch curve itself)",
               FLAT: "tangent to every face line (their envelope; its contact points marked)",
               OSC_FLAT: "tangent to every face line (their envelope; its contact points marked)"}[f.kind]
    details = profile_details(cp, CAM)
    rec = rec.then(f"Draw the cam profile {tangent}{details_words(details)}.", curve, *marks,
                   *(d for _, d in details))
    rec = _follower_step(rec, f, program, cp, centres, turn)
    label_every = max(1, n // 12)
    ell = f.arm_length if osc else f.pivot_distance if swing else 1.0
    rec = rec.then("Draw the displacement diagram: lay the cam angle off along a line, divide it into the same "
                   f"{n} portions numbered as the stations on the cam, and set up on each station's line the "
                   + ("swing drawn as the arc it sweeps at radius $l" if swing else "tabulated lift s_i")
                   + "; the curve through their tops is the follower's motion, and the lift at each numbered "
                   "station is the one marked on the cam's follower line of the same number.",
                   *_displacement(program, f, th, ev.s, ell, label_every * math.ceil(n / (7 * label_every))),
                   values={"l": Value("length", ell)} if swing else None)

    # answers read off the construction
    measured: list[Measured] = []
    names: dict[str, int] = {}
    k_max = int(np.argmax(ev.s))
    join_stations = sorted({int(round(t / step)) % n for t in program.starts
                            if abs(t / step - round(t / step)) < STATION_REL})
    for i in join_stations:
        tag = degree_text(th[i])
        measured.append(Measured(f"P_{tag}", "length", _v(centres[:, i])))
        names[f"P_{tag}"] = i
        measured.append(Measured(f"C_{tag}", "length", _v(contacts[:, i])))
        names[f"C_{tag}"] = i
    if osc or f.kind == ROLLER:
        # the angle between the direction the roller centre is driven (square to the arm, or along the
        # follower's line) and the roller's radius to its contact point
        if osc:
            A = np.stack([f.pivot_distance * np.cos(-sg * th), f.pivot_distance * np.sin(-sg * th)])
            arm = centres - A
            px, py = arm[1], -arm[0]                     # square to the arm, the way the swing lifts
            path = "the roller centre's path (square to the arm)"
        else:
            px, py = np.sin(sg * th), np.cos(sg * th)    # the follower's axis at each station (cam frame)
            path = "the follower's line"
        rx, ry = centres[0] - contacts[0], centres[1] - contacts[1]
        phis = np.arctan2(px * ry - py * rx, px * rx + py * ry) * sg
        k = int(np.argmax(np.abs(phis)))
        measured.append(Measured("phi_max", "angle", float(phis[k])))
        names["phi_max"] = k
        rec = rec.then(f"The pressure angle, read at each station between {path} and the roller's radius to its "
                       f"contact point, is largest at station $t: $phi.",
                       values={"t": Value("angle", float(th[k])), "phi": Value("angle", float(abs(phis[k])))},
                       kind=StepKind.ANSWER)
    elif f.kind == OSC_FLAT:
        # the angle between the face's normal and the way the arm drives its point at the contact (square to
        # the line from the pivot A_i to the contact point C_i), both read off the drawn lines
        A = np.stack([f.pivot_distance * np.cos(-sg * th), f.pivot_distance * np.sin(-sg * th)])
        r = contacts - A
        px, py = r[1], -r[0]
        nx, ny = ev.normal                                    # square to the drawn face line, away from O
        phis = np.arctan2(px * ny - py * nx, px * nx + py * ny) * sg
        k = int(np.argmax(np.abs(phis)))
        measured.append(Measured("phi_max", "angle", float(phis[k])))
        names["phi_max"] = k
        rec = rec.then("The pressure angle, read at each station between the face's normal and the contact point's "
                       "path (square to the line from the pivot to the contact), is largest at station $t: $phi.",
                       values={"t": Value("angle", float(th[k])), "phi": Value("angle", float(abs(phis[k])))},
                       kind=StepKind.ANSWER)
    elif f.kind == KNIFE:
        k = int(np.argmax(np.abs(ev.pressure_angle)))
        rec = rec.then("The pressure angle is largest at station $t: $phi.",
                       values={"t": Value("angle", float(th[k])),
                               "phi": Value("angle", float(abs(ev.pressure_angle[k])))}, kind=StepKind.ANSWER)
    rec = rec.then("The largest lift in the table: $s.", values={"s": Value(lk, float(ev.s[k_max]))},
                   kind=StepKind.ANSWER)
    charts = svaj_charts(program, omega, angular=swing)
    jn = [j for j in program.joins() if j.consequence]
    words = ("The s-v-a-j diagrams against the cam angle" + (" with the cam at its given speed" if omega else
                                                            ", per radian of cam angle (no cam speed given)"))
    if jn:
        words += "; at " + "; ".join(f"{degrees(j.theta)} ({j.before} to {j.after}) {j.consequence}" for j in jn)
    rec = rec.then(words + ".", *charts)
    return CamConstruction(rec, th, ev.s, centres, contacts, cp, measured, names)


def _displacement(program, f, th, s, ell, label_every):
    """The displacement diagram beside the cam, to the right of everything drawn round it: a translating
    follower's on the level of its end at zero lift (so a lift projects straight across to the follower's
    line at station 0), a swing's beyond the pivot circle."""
    if f.kind in (OSCILLATING, OSC_FLAT):          # beyond the pivot circle's numbers, a little above O
        a = f.pivot_distance
        return displacement_diagram(program, th, s, ell, label_every, 1.3 * a, Vec(1.15 * a, 0.1 * a), CAM)
    reach = (f.base_radius if f.kind == FLAT else f.prime_radius) + program.lift
    y0 = f.base_radius if f.kind == FLAT else f.d0
    return displacement_diagram(program, th, s, ell, label_every, 1.8 * reach, Vec(1.35 * reach, y0), CAM,
                                0.0 if f.kind == FLAT else f.offset)


def _follower_step(rec, f, program, cp, centres, turn):
    """The follower drawn in place at station 0 and the cam's sense of rotation about O."""
    rb, sg = f.base_radius, f.sense
    reach = (f.prime_radius if f.kind in (ROLLER, OSCILLATING, KNIFE) else rb) + program.lift
    face = None
    if f.kind == FLAT:
        face = 1.1 * max(abs(v) for v in cp.face_width)
    elif f.kind == OSC_FLAT:
        f0 = next(e for e in rec.entities() if e.name == "face 0")
        face = (f0.start, f0.end)
    parts = drawn_follower(f, CAM, centres[:, 0], reach, pivot=(f.pivot_distance, 0.0), face=face)
    start = math.radians(200.0 if sg > 0 else 290.0)
    arrow = RotationArrow("cam rotation", Role.GIVEN, CAM, Vec(0.0, 0.0), 0.5 * rb, start, sg * math.radians(90.0))
    what = "on its arm about the pivot A" if f.kind in (OSCILLATING, OSC_FLAT) else "on its stem in its guide"
    return rec.then(f"Draw the follower in place at station 0, {what}, in true size, and the cam's rotation "
                    f"\u03c9 ({turn}) about O.", *parts, arrow)


def _translating_steps(rec, f, program, cp, th, ev, step, opposite):
    n, sg = len(th), f.sense
    rb, rr, e = f.base_radius, f.roller_radius, f.offset
    reach = (f.prime_radius if f.kind != FLAT else rb) + program.lift
    a = -sg * th
    ux, uy = -np.sin(a), np.cos(a)              # the axis direction at each station (cam frame)
    wx, wy = np.cos(a), np.sin(a)               # +x of the fixed frame at each station
    foot = np.stack([e * wx, e * wy]) if f.kind != FLAT else np.zeros((2, n))
    lines = []
    label_every = max(1, n // 12)
    notes = []
    for i in range(n):
        p0 = _v(foot[:, i])
        p1 = Vec(float(foot[0, i] + ux[i] * reach * 1.12), float(foot[1, i] + uy[i] * reach * 1.12))
        lines.append(Segment(f"line {i}", Role.AUXILIARY, CAM, p0, p1))
        if i % label_every == 0:
            q = Vec(float(foot[0, i] + ux[i] * reach * 1.25), float(foot[1, i] + uy[i] * reach * 1.25))
            if i == 0:                             # beside the follower's stem drawn on line 0
                q = Vec(q.x - sg * (0.5 * (rr if f.kind == ROLLER else 0.12 * rb) + 0.15 * reach), q.y)
            notes.append(Note(f"station {i}", Role.LABEL, CAM, q, f"{i}"))
    kind_lines = "radial lines from O" if not e or f.kind == FLAT else "lines tangent to the offset circle"
    rec = rec.then(f"Draw the {n} follower lines ({kind_lines}) every $d, laid out {opposite} -- opposite to the "
                   f"cam's rotation, the cam held still and the follower walked round it; the stations are numbered "
                   f"0 to {n - 1} from the follower's line at 0\u00b0.", *lines, *notes, values={"d": Value("angle", step)})

    # 7: roller circles / face lines / edges
    centres = ev.pitch if f.kind != FLAT else np.stack([(rb + ev.s) * ux, (rb + ev.s) * uy])
    ents = []
    if f.kind == ROLLER:
        for i in range(n):
            ents.append(Point(f"P{i}", Role.PATH, CAM, _v(centres[:, i])))
            ents.append(Circle(f"roller {i}", Role.AUXILIARY, CAM, _v(centres[:, i]), rr))
        words = ("On each line mark the roller centre s_i beyond the prime circle (where the line meets it) and "
                 "draw a roller circle of radius $rr about it.")
        wv = {"rr": Value("length", rr)}
    elif f.kind == KNIFE:
        for i in range(n):
            ents.append(Point(f"P{i}", Role.PATH, CAM, _v(centres[:, i])))
        words = "On each line mark the knife edge s_i beyond the base circle (where the line meets it)."
        wv = {}
    else:
        lo, hi = cp.face_width
        half = max(abs(lo), abs(hi)) * 1.15 + 0.05 * rb
        for i in range(n):
            c = centres[:, i]
            ents.append(Segment(f"face {i}", Role.AUXILIARY, CAM,
                                Vec(float(c[0] - wx[i] * half), float(c[1] - wy[i] * half)),
                                Vec(float(c[0] + wx[i] * half), float(c[1] + wy[i] * half))))
        words = "On each line draw the face line square to it at r_b + s_i from O."
        wv = {}
    rec = rec.then(words, *ents, values=wv)

    return rec, centres


def _oscillating_steps(rec, f, th, ev, step, opposite):
    """The pivot circle, the pivots laid out opposite to the rotation, the arm swung through the table's
    angle from where its arc meets the prime circle, the roller circles."""
    n = len(th)
    rec, A = _pivots(rec, f, th, step, opposite)
    centres = ev.pitch
    ents = []
    for i in range(n):
        ents.append(Segment(f"arm {i}", Role.AUXILIARY, CAM, _v(A[:, i]), _v(centres[:, i])))
        ents.append(Point(f"P{i}", Role.PATH, CAM, _v(centres[:, i])))
        ents.append(Circle(f"roller {i}", Role.AUXILIARY, CAM, _v(centres[:, i]), f.roller_radius))
    rec = rec.then("From each pivot A_i strike an arc of the arm's length $l: where it meets the prime circle is the "
                   "roller centre at zero lift; swing the arm about A_i through the tabulated angle, away from O, to "
                   "the roller centre, and draw a roller circle of radius $rr about it.", *ents,
                   values={"l": Value("length", f.arm_length), "rr": Value("length", f.roller_radius)})
    return rec, centres


def _pivots(rec, f, th, step, opposite):
    """The pivot circle and the arm's pivots A_i laid out opposite to the cam's rotation."""
    n, sg = len(th), f.sense
    a = -sg * th
    A = np.stack([f.pivot_distance * np.cos(a), f.pivot_distance * np.sin(a)])
    pts, notes = [], []
    label_every = max(1, n // 12)
    for i in range(n):
        pts.append(Point(f"A{i}", Role.PATH, CAM, _v(A[:, i])))
        if i % label_every == 0:
            notes.append(Note(f"station {i}", Role.LABEL, CAM, _v(A[:, i] * 1.08), f"{i}"))
    rec = rec.then(f"Draw the pivot circle of radius $a about O and mark the arm's pivot A_i on it every $d, laid out "
                   f"{opposite} -- opposite to the cam's rotation; A_0 is the pivot at 0\u00b0.",
                   Circle("pivot circle", Role.CENTRE_LINE, CAM, Vec(0.0, 0.0), f.pivot_distance, "pivot circle"),
                   *pts, *notes, values={"a": Value("length", f.pivot_distance), "d": Value("angle", step)})
    return rec, A


def _oscillating_face_steps(rec, f, cp, th, ev, step, opposite):
    """The pivots laid out opposite to the rotation; from each, the face at the arm's angle beta0 + psi_i to
    the line A_i O (beta0: the face tangent to the base circle at zero lift), drawn over the reach the
    contact needs."""
    n = len(th)
    rec, A = _pivots(rec, f, th, step, opposite)
    N = ev.normal                                  # the face's normal in the cam frame, away from O
    T = np.stack([-N[1], N[0]])                   # along the face, from the pivot's foot towards the cam
    foot = A - f.face_offset * N                  # the foot of the perpendicular from A_i on the face
    lo, hi = cp.face_width
    pad = 0.08 * (hi - lo) + 0.02 * f.pivot_distance
    ents = []
    for i in range(n):
        p0, p1 = foot[:, i] + (lo - pad) * T[:, i], foot[:, i] + (hi + pad) * T[:, i]
        ents.append(Segment(f"arm {i}", Role.AUXILIARY, CAM, _v(A[:, i]), _v(p0)))     # the arm, to the face
        ents.append(Segment(f"face {i}", Role.AUXILIARY, CAM, _v(p0), _v(p1)))
    off = " and the face $ef from it" if f.face_offset else ""
    rec = rec.then(f"From each pivot A_i draw the arm at beta_0 + psi_i to the line A_i O{off}, where beta_0 = $b0 "
                   f"puts the face tangent to the base circle at zero lift (a sin beta_0 = r_b + e_f) and psi_i is "
                   f"the tabulated swing: the face line at station i.", *ents,
                   values={"b0": Value("angle", f.beta0), **({"ef": Value("length", abs(f.face_offset))}
                                                            if f.face_offset else {})})
    centres = np.stack([ev.support * N[0], ev.support * N[1]])   # the foot of the perpendicular from O
    return rec, centres


__all__ = ["construct", "CamConstruction", "CAM"]
