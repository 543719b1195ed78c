"""Planar linkages and their position by construction.

A :class:`Mechanism` is a frame with fixed pivots, binary links between named joints, straight guides
on which a joint's slider block runs, and extra points fixed to a link.  One link, the crank, is driven
from a fixed pivot.  :func:`assembly_plan` orders the joints as the notes do by hand: the crank tip from
the input angle, then every joint found from two loci -- two circles (an RRR dyad) or a circle and a
guide (an RRP dyad) -- with the assembly branch the scene chose, then the points fixed to links.
:func:`locate` carries out the plan at one crank angle and records it as a construction of the space
diagram.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

from .errors import CannotAssemble, DegenerateInput
from .formatting import Formatter, si_format
from .geometry import (Circle, Contact, Intersection, Line, Tolerance, Vec, intersect_circles,
                       intersect_line_circle)
from .record import Arc, Bar, Block, Construction, Diagram, Guide, Pivot, Plate, Point, Role, StepKind, Value


@dataclass(frozen=True, slots=True)
class Link:
    """A rigid binary link ``number`` between joints ``joints[0]`` and ``joints[1]``."""

    number: int
    joints: tuple[str, str]
    length: float

    def other(self, joint: str) -> str:
        return self.joints[1] if joint == self.joints[0] else self.joints[0]

    @property
    def label(self) -> str:
        return "".join(self.joints)


@dataclass(frozen=True, slots=True)
class Slide:
    """A slider block (link ``number``) carrying joint ``joint`` along a fixed straight guide."""

    number: int
    joint: str
    through: Vec
    angle: float

    @property
    def line(self) -> Line:
        return Line.at_angle(self.through, self.angle)


@dataclass(frozen=True, slots=True)
class Attached:
    """A point fixed to link ``link``: ``distance`` from the link's joint ``base``, at ``angle``
    measured counter-clockwise from the direction of the link (from ``base`` to its other joint)."""

    name: str
    link: int
    base: str
    distance: float
    angle: float


@dataclass(frozen=True, slots=True)
class Branch:
    """Which of two assemblies: ``sign`` +1 is LEFT of the directed line ``reference[0] -> [1]``
    (two circles), or AHEAD of the foot of ``reference[0]`` along the guide (circle and guide)."""

    sign: int
    reference: tuple[str, ...]

    def describe(self) -> str:
        if len(self.reference) == 2:
            return f"{'left' if self.sign > 0 else 'right'} of {self.reference[0]}->{self.reference[1]}"
        return f"{'ahead of' if self.sign > 0 else 'behind'} {self.reference[0]}"


@dataclass(frozen=True)
class Mechanism:
    ground: Mapping[str, Vec]
    links: tuple[Link, ...]
    slides: tuple[Slide, ...]
    attached: tuple[Attached, ...]
    crank: int
    branches: Mapping[str, Branch]

    def link(self, number: int) -> Link:
        for k in self.links:
            if k.number == number:
                return k
        raise DegenerateInput(f"there is no link {number}")

    @property
    def size(self) -> float:
        """The scene scale L: the longest link or frame distance; tolerances are relative to it."""
        pts = list(self.ground.values()) + [s.through for s in self.slides]
        spans = [k.length for k in self.links]
        spans += [p.distance_to(q) for p in pts for q in pts]
        spans += [a.distance for a in self.attached]
        return max(spans)

    def tolerance(self) -> Tolerance:
        return Tolerance(self.size)


# -- the plan: which joint is found from which loci ---------------------------------------------------

@dataclass(frozen=True, slots=True)
class CrankTip:
    link: Link
    pivot: str
    tip: str


@dataclass(frozen=True, slots=True)
class TwoCircles:
    """Joint found where the circle about ``first`` (radius link_a) meets the circle about ``second``."""

    joint: str
    link_a: Link
    first: str
    link_b: Link
    second: str
    branch: Branch


@dataclass(frozen=True, slots=True)
class CircleAndGuide:
    """Joint found where the circle about ``centre`` (radius ``link``) meets the guide of ``slide``."""

    joint: str
    link: Link
    centre: str
    slide: Slide
    branch: Branch


@dataclass(frozen=True, slots=True)
class FixedToLink:
    point: Attached
    link: Link


PlanStep = CrankTip | TwoCircles | CircleAndGuide | FixedToLink


def assembly_plan(m: Mechanism) -> tuple[PlanStep, ...]:
    """Order in which the joints are constructed; raises DegenerateInput when the linkage is not a
    crank followed by dyads (it says which joint cannot be reached)."""
    crank = m.link(m.crank)
    pivots = [j for j in crank.joints if j in m.ground]
    if len(pivots) != 1:
        raise DegenerateInput(f"the crank, link {crank.number} ({crank.label}), must join one fixed pivot "
                              f"to one moving joint; fixed pivots are {', '.join(m.ground) or 'none'}")
    plan: list[PlanStep] = [CrankTip(crank, pivots[0], crank.other(pivots[0]))]
    known = set(m.ground) | {crank.other(pivots[0])}
    joints = {j for k in m.links for j in k.joints} | {s.joint for s in m.slides}
    slides = {s.joint: s for s in m.slides}
    for s in m.slides:
        if s.joint in m.ground:
            raise DegenerateInput(f"slider joint {s.joint} is also a fixed pivot")
    while True:
        progress = False
        for j in sorted(joints - known):
            circles = [(k, k.other(j)) for k in m.links if j in k.joints and k.other(j) in known]
            if len(circles) >= 2 and j not in slides:
                (ka, a), (kb, b) = circles[:2]
                branch = _branch_for(m, j, (a, b))
                if branch.reference == (b, a):
                    (ka, a), (kb, b) = (kb, b), (ka, a)
                plan.append(TwoCircles(j, ka, a, kb, b, branch))
            elif circles and j in slides:
                k, c = circles[0]
                plan.append(CircleAndGuide(j, k, c, slides[j], _branch_for(m, j, (c,))))
            else:
                continue
            known.add(j)
            progress = True
        if not progress:
            break
    missing = sorted(joints - known)
    if missing:
        raise DegenerateInput(f"joint {missing[0]} cannot be constructed: it needs two links to known "
                              f"joints, or one link and a slider guide")
    for a in m.attached:
        link = m.link(a.link)
        if a.base not in link.joints:
            raise DegenerateInput(f"point {a.name} is measured from {a.base}, which is not a joint of "
                                  f"link {link.number} ({link.label})")
        plan.append(FixedToLink(a, link))
    return tuple(plan)


def _branch_for(m: Mechanism, joint: str, centres: tuple[str, ...]) -> Branch:
    b = m.branches.get(joint)
    expect = (f'"left of {centres[0]}->{centres[1]}" or "right of {centres[0]}->{centres[1]}"'
              if len(centres) == 2 else f'"ahead of {centres[0]}" or "behind {centres[0]}"')
    if b is None:
        raise DegenerateInput(f"joint {joint} has two assemblies; choose one with {expect}")
    if sorted(b.reference) != sorted(centres):
        raise DegenerateInput(f"the branch of {joint} must be given relative to the joints it is found "
                              f"from: {expect}")
    return b


# -- the pose at one crank angle ----------------------------------------------------------------------

@dataclass(frozen=True)
class Pose:
    """Positions of every joint and point at one crank angle, with the construction that found them.

    ``conditions`` maps each constructed joint to the sine of the angle at which its two loci crossed
    (0 when they touched).
    """

    angle: float
    positions: Mapping[str, Vec]
    construction: Construction
    conditions: Mapping[str, float]

    def __getitem__(self, name: str) -> Vec:
        return self.positions[name]


def describe_angle(angle: float) -> str:
    return f"crank angle {math.degrees(angle):.6g} deg"


def locate(m: Mechanism, angle: float, plan: tuple[PlanStep, ...] | None = None, *,
           fmt: Formatter = si_format) -> Pose:
    """Construct the mechanism at crank ``angle`` (radians, CCW from +x)."""
    plan = assembly_plan(m) if plan is None else plan
    tol = m.tolerance()
    where = describe_angle(angle)
    pos: dict[str, Vec] = dict(m.ground)
    cond: dict[str, float] = {}
    rec = Construction("Space diagram")
    frame = [Pivot(f"pivot {n}", Role.GIVEN, Diagram.SPACE, p, n) for n, p in m.ground.items()]
    frame += [Guide(f"guide {s.joint}", Role.GIVEN, Diagram.SPACE, s.through, s.line.direction)
              for s in m.slides]
    rec = rec.then("Draw the frame: the fixed pivots" + (" and the slider guide" if m.slides else "")
                   + " at the space scale.", *frame, kind=StepKind.GIVEN)
    for step in plan:
        if isinstance(step, CrankTip):
            tip = pos[step.pivot] + Vec.polar(step.link.length, angle)
            pos[step.tip] = tip
            rec = rec.then(
                f"Draw the crank {step.link.label} (link {step.link.number}) at $angle.",
                Bar(f"link {step.link.number}", Role.GIVEN, Diagram.SPACE, pos[step.pivot], tip,
                    step.link.number),
                Point(f"joint {step.tip}", Role.LABEL, Diagram.SPACE, tip, step.tip),
                values={"angle": Value("angle", angle)}, kind=StepKind.GIVEN)
        elif isinstance(step, TwoCircles):
            ca = Circle(pos[step.first], step.link_a.length)
            cb = Circle(pos[step.second], step.link_b.length)
            hit = intersect_circles(ca, cb, tol)
            p = _pick(hit, step.branch, step.joint, where, fmt,
                      f"the circle of link {step.link_a.number} ({step.link_a.label} = "
                      f"{fmt('length', step.link_a.length)}) about {step.first} and the circle of link "
                      f"{step.link_b.number} ({step.link_b.label} = {fmt('length', step.link_b.length)}) "
                      f"about {step.second}")
            pos[step.joint] = p
            cond[step.joint] = hit.condition
            rec = rec.then(
                f"Find {step.joint}: swing {step.link_a.label} about {step.first} and "
                f"{step.link_b.label} about {step.second}; take the crossing "
                f"{step.branch.describe()}.",
                _arc_through(f"path {step.joint} about {step.first}", ca, p),
                _arc_through(f"path {step.joint} about {step.second}", cb, p),
                Bar(f"link {step.link_a.number}", Role.GIVEN, Diagram.SPACE, pos[step.first], p,
                    step.link_a.number),
                Bar(f"link {step.link_b.number}", Role.GIVEN, Diagram.SPACE, pos[step.second], p,
                    step.link_b.number),
                Point(f"joint {step.joint}", Role.LABEL, Diagram.SPACE, p, step.joint))
        elif isinstance(step, CircleAndGuide):
            c = Circle(pos[step.centre], step.link.length)
            line = step.slide.line
            hit = intersect_line_circle(line, c, tol)
            p = _pick(hit, step.branch, step.joint, where, fmt,
                      f"the circle of link {step.link.number} ({step.link.label} = "
                      f"{fmt('length', step.link.length)}) about {step.centre} and the guide of "
                      f"{step.joint}")
            pos[step.joint] = p
            cond[step.joint] = hit.condition
            rec = rec.then(
                f"Find {step.joint}: swing {step.link.label} about {step.centre} to meet the guide; "
                f"take the crossing {step.branch.describe()}.",
                _arc_through(f"path {step.joint} about {step.centre}", c, p),
                Bar(f"link {step.link.number}", Role.GIVEN, Diagram.SPACE, pos[step.centre], p,
                    step.link.number),
                Block(f"block {step.slide.number}", Role.GIVEN, Diagram.SPACE, p, line.direction,
                      step.slide.number),
                Point(f"joint {step.joint}", Role.LABEL, Diagram.SPACE, p, step.joint))
        else:
            a, link = step.point, step.link
            base, other = pos[a.base], pos[link.other(a.base)]
            p = base + Vec.polar(a.distance, (other - base).angle() + a.angle)
            pos[a.name] = p
            rec = rec.then(
                f"Mark {a.name} on link {link.number}: {a.base}{a.name} = $d at $angle from {link.label}.",
                Plate(f"plate {a.name}", Role.GIVEN, Diagram.SPACE, (base, other, p), link.number),
                Point(f"point {a.name}", Role.LABEL, Diagram.SPACE, p, a.name),
                values={"d": Value("length", a.distance), "angle": Value("angle", a.angle)})
    return Pose(angle, pos, rec, cond)


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
