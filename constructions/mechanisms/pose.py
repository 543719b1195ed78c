"""The linkage at one crank angle, constructed and recorded as the space diagram.

:func:`locate` carries out the assembly plan (:mod:`.assembly`) at one crank angle: the frame, the crank,
then every joint where its two loci cross on the branch the scene chose, and the points fixed to each
placed link -- each step recorded with what it draws.  A :class:`Pose` holds the positions found, the
construction, and how well each crossing was conditioned.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Mapping

from ..entities import AngleMark, Arc, Bar, Block, Diagram, Guide, Pivot, Plate, Point, Role, Segment
from ..errors import CannotAssemble
from ..formatting import Formatter, si_format
from ..geometry import (Circle, Contact, Intersection, Line, Tolerance, Vec, intersect_circles,
                        intersect_line_circle, intersect_lines)
from ..record import Construction, StepKind, Value
from .assembly import (CircleAndGuide, CrankTip, PlanStep, SlotAlongGuide, SlotThrough, TwoCircles, TwoLines,
                       assembly_plan)
from .model import Attached, Branch, Link, Mechanism, Slide, describe_angle, place_rigid, slide_line


@dataclass(frozen=True)
class Pose:
    """Positions of every joint and point at one crank angle, with the construction that found them.

    ``conditions`` maps each constructed joint to the sine of the angle at which its two loci crossed
    (0 when they touched); ``lines`` maps every sliding joint to the line it slides on at this pose.
    """

    angle: float
    positions: Mapping[str, Vec]
    construction: Construction
    conditions: Mapping[str, float]
    lines: Mapping[str, Line] = field(default_factory=dict)

    def __getitem__(self, name: str) -> Vec:
        return self.positions[name]



def locate(m: Mechanism, angle: float, plan: tuple[PlanStep, ...] | None = None, *,
           fmt: Formatter = si_format) -> Pose:
    """Construct the mechanism at crank ``angle`` (radians, CCW from +x)."""
    plan = assembly_plan(m) if plan is None else plan
    tol = m.tolerance()
    where = describe_angle(angle)
    pos: dict[str, Vec] = dict(m.ground)
    cond: dict[str, float] = {}
    lines: dict[str, Line] = {}
    rec = Construction("Space diagram")
    fixed = [s for s in m.slides if s.on is None]
    frame = [Pivot(f"pivot {n}", Role.GIVEN, Diagram.SPACE, p, n) for n, p in m.ground.items()]
    frame += [Guide(f"guide {s.joint}", Role.GIVEN, Diagram.SPACE, s.through, s.line.direction) for s in fixed]
    rec = rec.then("Draw the frame: the fixed pivots" + (" and the slider guide" if fixed else "")
                   + " at the space scale.", *frame, kind=StepKind.GIVEN)
    drawn: set[int] = set()
    partial: set[str] = set()

    def bar(link: Link, a: str, b: str) -> list:
        """The link's outline once it is placed: a bar, or a plate through all its points."""
        if link.number in drawn:
            return []
        pts = m.local(link.number)
        if not all(x in pos for x in pts):
            name = f"link {link.number} {a}{b}"
            if name in partial:                     # already drawn while the link's other points were unknown
                return []
            partial.add(name)
            return [Bar(name, Role.GIVEN, Diagram.SPACE, pos[a], pos[b], link.number)]
        drawn.add(link.number)
        if len(pts) == 2:
            p, q = link.joints
            return [Bar(f"link {link.number}", Role.GIVEN, Diagram.SPACE, pos[p], pos[q], link.number)]
        return [Plate(f"link {link.number}", Role.GIVEN, Diagram.SPACE, tuple(pos[x] for x in pts), link.number)]

    for step in plan:
        if isinstance(step, CrankTip):
            tip = pos[step.pivot] + Vec.polar(step.link.length, angle)
            pos[step.tip] = tip
            # the crank angle dimensioned as a drafter would: from +x, counter-clockwise, to the crank
            turn = math.remainder(angle, 2 * math.pi)
            marks = []
            if abs(turn) > 1e-6:
                r_mark = 0.45 * step.link.length
                marks = [Segment("crank angle datum", Role.DIMENSION, Diagram.SPACE, pos[step.pivot],
                                 pos[step.pivot] + Vec(1.4 * r_mark, 0.0)),
                         AngleMark("crank angle", Role.DIMENSION, Diagram.SPACE, pos[step.pivot], r_mark, 0.0, turn,
                                   "$angle")]
            rec = rec.then(
                f"Draw the crank {step.link.label} (link {step.link.number}) at $angle.",
                *bar(step.link, step.pivot, step.tip),
                Point(f"joint {step.tip}", Role.LABEL, Diagram.SPACE, tip, step.tip), *marks,
                values={"angle": Value("angle", angle)}, kind=StepKind.GIVEN)
        elif isinstance(step, TwoCircles):
            ca = Circle(pos[step.first], step.radius_a or step.link_a.length)
            cb = Circle(pos[step.second], step.radius_b or step.link_b.length)
            hit = intersect_circles(ca, cb, tol)
            a_name, b_name = f"{step.first}{step.joint}", f"{step.second}{step.joint}"
            p = _pick(hit, step.branch, step.joint, where, fmt,
                      f"the circle of link {step.link_a.number} ({a_name} = {fmt('length', ca.radius)}) about "
                      f"{step.first} and the circle of link {step.link_b.number} ({b_name} = "
                      f"{fmt('length', cb.radius)}) about {step.second}")
            pos[step.joint] = p
            cond[step.joint] = hit.condition
            rec = rec.then(
                f"Find {step.joint}: swing {a_name} about {step.first} and {b_name} about {step.second}; "
                f"take the crossing {step.branch.describe()}.",
                _arc_through(f"path {step.joint} about {step.first}", ca, p),
                _arc_through(f"path {step.joint} about {step.second}", cb, p),
                *bar(step.link_a, step.first, step.joint), *bar(step.link_b, step.second, step.joint),
                Point(f"joint {step.joint}", Role.LABEL, Diagram.SPACE, p, step.joint))
        elif isinstance(step, CircleAndGuide):
            c = Circle(pos[step.centre], step.radius or step.link.length)
            line = slide_line(m, step.slide, pos)
            lines[step.joint] = line
            hit = intersect_line_circle(line, c, tol)
            where_line = "guide" if step.slide.on is None else f"slot in link {step.slide.on}"
            p = _pick(hit, step.branch, step.joint, where, fmt,
                      f"the circle of link {step.link.number} ({step.centre}{step.joint} = "
                      f"{fmt('length', c.radius)}) about {step.centre} and the {where_line} of {step.joint}")
            pos[step.joint] = p
            if step.coincident:
                pos[step.coincident] = p
            cond[step.joint] = hit.condition
            block = ([Block(f"block {step.slide.number}", Role.GIVEN, Diagram.SPACE, p, line.direction,
                            step.slide.number)] if step.slide.number is not None else [])
            if step.slide.on is not None:
                block.append(_slot_segment(m, step.slide, pos, p))
            rec = rec.then(
                f"Find {step.joint}: swing {step.centre}{step.joint} about {step.centre} to meet the "
                f"{where_line}; take the crossing {step.branch.describe()}.",
                _arc_through(f"path {step.joint} about {step.centre}", c, p),
                *bar(step.link, step.centre, step.joint), *block,
                Point(f"joint {step.joint}", Role.LABEL, Diagram.SPACE, p, step.joint))
        elif isinstance(step, TwoLines):
            la, lb = slide_line(m, step.slide_a, pos), slide_line(m, step.slide_b, pos)
            hit = intersect_lines(la, lb, tol)
            if hit.contact is not Contact.CROSSING:
                raise CannotAssemble(f"the lines {step.joint} slides on ({_line_name(step.slide_a)} and "
                                     f"{_line_name(step.slide_b)}) are parallel, so {step.joint} cannot be placed",
                                     position=where)
            p = hit.points[0]
            pos[step.joint] = p
            for c in (step.coincident_a, step.coincident_b):
                if c:
                    pos[c] = p
            cond[step.joint] = hit.condition
            blocks = [Block(f"block {sl.number}", Role.GIVEN, Diagram.SPACE, p, ln.direction, sl.number)
                      for sl, ln in ((step.slide_a, la), (step.slide_b, lb)) if sl.number is not None]
            blocks += [_slot_segment(m, sl, pos, p) for sl in (step.slide_a, step.slide_b) if sl.on is not None]
            rec = rec.then(
                f"Find {step.joint} where the {_line_name(step.slide_a)} and the {_line_name(step.slide_b)} cross.",
                *blocks, Point(f"joint {step.joint}", Role.LABEL, Diagram.SPACE, p, step.joint))
        elif isinstance(step, SlotThrough):
            p = _slot_through(m, step, pos, tol, where, fmt)
            pts = m.local(step.link.number)
            pos.update(p)
            line = slide_line(m, step.slide, pos)
            lines[step.joint] = line
            cond[step.joint] = 1.0
            ent = []
            if step.slide.number is not None:
                ent.append(Block(f"block {step.slide.number}", Role.GIVEN, Diagram.SPACE, pos[step.joint],
                                 line.direction, step.slide.number))
            far = max(pts, key=lambda x: pos[x].distance_to(pos[step.centre]))
            ends = [line.parameter(pos[x]) for x in (step.centre, far, step.joint)]
            if step.slide.offset == 0:                       # the slot along the link: centre to far end
                ends = ends[:2] + [min(max(ends[2], min(ends[:2])), max(ends[:2]))]
            ent.append(Segment(f"slot {step.joint}", Role.PATH, Diagram.SPACE, line.at(min(ends)),
                               line.at(max(ends))))       # on the slot's own line (offset from the link)
            rec = rec.then(
                f"Turn link {step.link.number} ({step.link.label}) about {step.centre} until its slot passes "
                f"through {step.joint}" + (f" ($e from {step.centre})" if step.slide.offset else "")
                + f"; {step.joint} lies {step.branch.describe()} along the slot.",
                *bar(step.link, *step.link.joints), *ent,
                *[Point(f"joint {x}", Role.LABEL, Diagram.SPACE, pos[x], x) for x in pts if x != step.centre
                  and x not in m.ground],
                values={"e": Value("length", abs(step.slide.offset))} if step.slide.offset else None)
        elif isinstance(step, SlotAlongGuide):
            pos.update(_slot_along_guide(m, step, pos, tol, where))
            line = slide_line(m, step.slide, pos)
            lines[step.joint] = line
            cond[step.joint] = 1.0
            ent = [Block(f"block {sl.number}", Role.GIVEN, Diagram.SPACE, pos[sl.joint], sl.line.direction,
                         sl.number) for sl in step.guides]
            if step.slide.number is not None:
                ent.append(Block(f"block {step.slide.number}", Role.GIVEN, Diagram.SPACE, pos[step.joint],
                                 line.direction, step.slide.number))
            ent.append(_slot_segment(m, step.slide, pos, pos[step.joint]))
            k = step.link
            rec = rec.then(
                f"Slide link {k.number} ({k.label}) along its guide, without turning, until its slot passes "
                f"through {step.joint}.",
                *bar(k, *k.joints), *ent,
                *[Point(f"joint {x}", Role.LABEL, Diagram.SPACE, pos[x], x) for x in m.points_of(k.number)])
        else:
            link, x = step.link, step.name
            a, b = step.via
            pts = m.local(link.number)
            p = place_rigid(pts, a, b, pos[a], pos[b], x)
            pos[x] = p
            att = step.point if isinstance(step.point, Attached) else None
            if att is not None:
                words = f"Mark {x} on link {link.number}: {att.base}{x} = $d at $angle from {link.label}."
                values = {"d": Value("length", att.distance), "angle": Value("angle", att.angle)}
            else:
                words = (f"Mark {x} on link {link.number} from its own shape: {a}{x} = $da from {a} and "
                         f"{b}{x} = $db from {b}, on the side the link's triangle {a}{b}{x} has.")
                values = {"da": Value("length", pts[x].distance_to(pts[a])),
                          "db": Value("length", pts[x].distance_to(pts[b]))}
            rec = rec.then(words, *bar(link, a, b), Point(f"point {x}", Role.LABEL, Diagram.SPACE, p, x),
                           values=values)
    return Pose(angle, pos, rec, cond, lines)


def _slot_segment(m: Mechanism, s: Slide, pos: Mapping[str, Vec], at: Vec) -> Segment:
    """The slot drawn along its link, from the link's first joint's foot to past the joint it carries."""
    line = slide_line(m, s, pos)
    first = pos[m.link(s.on).joints[0]]
    t0, t1 = line.parameter(first), line.parameter(at)
    lo, hi = min(t0, t1), max(t0, t1)
    pad = 0.1 * (hi - lo)
    return Segment(f"slot {s.joint} in link {s.on}", Role.GIVEN, Diagram.SPACE, line.at(lo - pad), line.at(hi + pad))


def _line_name(s: Slide) -> str:
    return "guide" if s.on is None else f"slot in link {s.on}"


def _slot_through(m: Mechanism, step: SlotThrough, pos: dict[str, Vec], tol: Tolerance, where: str,
                  fmt: Formatter) -> dict[str, Vec]:
    """Turn the slotted link about its known point until the slot passes through the joint.

    With r = J - P (P the link's known point) and the slot at signed offset e from P (the slot line passes
    e to the right of P, square to it: :meth:`Slide.slot_line`), the slot's direction d satisfies
    cross(d, r) = -e and J lies at
    s = d.r = +/- sqrt(|r|^2 - e^2) along it: s > 0 (J ahead of P's foot) for branch +1."""
    s = step.slide
    J, P = pos[step.joint], pos[step.centre]
    r = J - P
    rho = r.norm()
    e = s.offset
    gap = abs(e) - rho
    if gap > tol.length:
        raise CannotAssemble(f"the slot of link {step.link.number} passes {fmt('length', abs(e))} from "
                             f"{step.centre}, farther than {step.joint} ({fmt('length', rho)}), so it cannot "
                             f"reach {step.joint}", position=where)
    along = math.sqrt(max((rho - abs(e)) * (rho + abs(e)), 0.0)) * step.branch.sign
    # d such that d.r = along and cross(d, r) = e:  r = along d - e perp(d)... solve in r's frame
    u = r / rho
    d = (u * along + u.perp() * e) / rho
    pts = m.local(step.link.number)
    k = step.link
    # the slot direction in the link's frame is the base line turned by s.angle
    base_dir = d.rotated(-s.angle)
    turn = base_dir.angle()
    first_world = pos[step.centre] - (pts[step.centre] - pts[k.joints[0]]).rotated(turn)
    out = {x: first_world + (pts[x] - pts[k.joints[0]]).rotated(turn) for x in pts if x != step.centre}
    out[step.coincident] = J
    return out


def _slot_along_guide(m: Mechanism, step: SlotAlongGuide, pos: dict[str, Vec], tol: Tolerance,
                      where: str) -> dict[str, Vec]:
    """Slide the yoke along its guide until its slot passes through the joint.

    The yoke's first joint B = P0 + t g on the guide (P0 its point, g its direction, the yoke's base
    line); the slot, of direction d = g turned by the slot's angle, passes e to the right of B: through
    B - e perp(d).  The joint J lies on it when cross(d, J - B + e perp(d)) = 0, that is
    t = (cross(d, J - P0) + e) / cross(d, g)."""
    s, guide = step.slide, step.guides[0].line
    g = guide.direction
    d = g.rotated(s.angle)
    square = d.cross(g)
    if abs(square) < tol.sine:
        raise CannotAssemble(f"the slot of link {step.link.number} runs along its guide, so the yoke cannot be "
                             f"slid to meet {step.joint}", position=where)
    t = (d.cross(pos[step.joint] - guide.point) + s.offset) / square
    first = guide.point + g * t
    out = {x: first + p.rotated(g.angle()) for x, p in m.local(step.link.number).items()}
    out[step.coincident] = pos[step.joint]
    return out


def _pick(hit: Intersection, branch: Branch, joint: str, where: str, fmt: Formatter, loci: str) -> Vec:
    if hit.contact is Contact.APART:
        raise CannotAssemble(f"{loci} do not meet (they miss by {fmt('length', hit.gap)}), so {joint} "
                             f"cannot be placed", position=where)
    if hit.contact is Contact.TANGENT:
        return hit.points[0]
    # TwoCircles: points are (left, right) of first->second; CircleAndGuide: (ahead, behind).
    return hit.points[0] if branch.sign > 0 else hit.points[1]


def _arc_through(name: str, circle: Circle, p: Vec, span: float = math.radians(24)) -> Arc:
    a = (p - circle.center).angle()
    return Arc(name, Role.PATH, Diagram.SPACE, circle.center, circle.radius, a - span / 2, a + span / 2)
