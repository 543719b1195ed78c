"""Planar linkages and their position by construction.

A :class:`Mechanism` is a frame with fixed pivots and rigid links.  A link has two base joints a
``length`` apart and any number of further points fixed to it (:class:`Attached`), so a coupler
triangle or a ternary rocker is one link; any of its points may be a joint of other links.  A joint
may also slide along a straight line (:class:`Slide`): a slider block on a fixed guide, a block on a
slot of a moving link (inverted slider-crank, slotted-lever quick-return, Whitworth), or a pin in a
slot.  One link, the crank, is driven from a fixed pivot.

:func:`assembly_plan` orders the construction as the notes do by hand: the crank tip from the input
angle, then, dyad by dyad, every joint found from two loci -- two circles (RRR), a circle and a guide
or slot (RRP), or the line of a slot through a known joint (RPR: the slotted link's direction) -- with
the assembly branch the scene chose, and the points of every link whose position is then fixed.
:func:`locate` carries the plan out at one crank angle and records it as a construction of the space
diagram.  :func:`mobility` counts the degrees of freedom as the notes do (Gruebler/Kutzbach, multiple
joints included).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Mapping

from .errors import CannotAssemble, DegenerateInput
from .formatting import Formatter, si_format
from .tolerance import scene_size
from .geometry import (Circle, Contact, Intersection, Line, Tolerance, Vec, intersect_circles,
                       intersect_line_circle, intersect_lines)
from .entities import AngleMark, Arc, Bar, Block, Diagram, Guide, Pivot, Plate, Point, Role, Segment
from .record import Construction, StepKind, Value


@dataclass(frozen=True, slots=True)
class Link:
    """A rigid link ``number`` with base joints ``joints[0]`` and ``joints[1]`` a ``length`` apart; further
    points of the same body are :class:`Attached` to it."""

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
    """Joint ``joint`` sliding along a straight line: in a slider block (link ``number``) pinned at the
    joint, or -- with ``number`` None -- as a pin in a slot.

    The line is a fixed guide when ``on`` is None (through ``through`` at ``angle`` CCW from +x), else a
    slot in link ``on``: the direction of the link's base line (first joint to second) turned by
    ``angle``, passing ``offset`` to the left of the link's first joint (measured square to the slot).
    A block on a slot turns with the slotted link.
    """

    number: int | None
    joint: str
    through: Vec
    angle: float
    on: int | None = None
    offset: float = 0.0

    @property
    def line(self) -> Line:
        """The fixed guide (for a slot use :meth:`slot_line`)."""
        if self.on is not None:
            raise DegenerateInput(f"the slot of {self.joint} moves with link {self.on}; it has no fixed line")
        return Line.at_angle(self.through, self.angle)

    def slot_line(self, first: Vec, second: Vec) -> Line:
        """The slot's line when the slotted link's base joints stand at ``first`` and ``second``."""
        d = (second - first).unit().rotated(self.angle)
        return Line(first - d.perp() * self.offset, d)

    @property
    def label(self) -> str:
        return f"block {self.number}" if self.number is not None else f"pin {self.joint}"


@dataclass(frozen=True, slots=True)
class Attached:
    """A point fixed to link ``link``: ``distance`` from the link's joint ``base``, at ``angle``
    measured counter-clockwise from the direction of the link (from ``base`` to its other joint).
    It may be a joint of other links (a ternary link's third joint)."""

    name: str
    link: int
    base: str
    distance: float
    angle: float


@dataclass(frozen=True, slots=True)
class Branch:
    """Which of two assemblies: ``sign`` +1 is LEFT of the directed line ``reference[0] -> [1]``
    (two circles), or AHEAD of the foot of ``reference[0]`` along the guide or slot (a circle and a
    line; for a slot through a known joint, the joint lies ahead of the slotted link's known point)."""

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

    def local(self, number: int) -> dict[str, Vec]:
        """The points of link ``number`` in its own frame: first base joint at the origin, second on +x."""
        k = self.link(number)
        p, q = k.joints
        out = {p: Vec(0.0, 0.0), q: Vec(k.length, 0.0)}
        for a in self.attached:
            if a.link == number:
                if a.base == p:
                    out[a.name] = Vec.polar(a.distance, a.angle)
                elif a.base == q:
                    out[a.name] = out[q] + Vec.polar(a.distance, math.pi + a.angle)
                else:
                    raise DegenerateInput(f"point {a.name} is measured from {a.base}, which is not a joint "
                                          f"of link {number} ({k.label})")
        return out

    def points_of(self, number: int) -> tuple[str, ...]:
        return tuple(self.local(number))

    def blocks(self) -> dict[int, Slide]:
        """Slider blocks by link number."""
        return {s.number: s for s in self.slides if s.number is not None}

    @property
    def size(self) -> float:
        """The scene size L (:func:`constructions.tolerance.scene_size`): link lengths, point distances on
        links, slot offsets, distances between fixed pivots and of fixed pivots from fixed guides --
        tolerances are relative to it, and it does not move with the origin."""
        lengths = [k.length for k in self.links] + [a.distance for a in self.attached]
        lengths += [abs(s.offset) for s in self.slides]
        lines = [(s.through.as_tuple(), s.angle) for s in self.slides if s.on is None]
        return scene_size(lengths, [p.as_tuple() for p in self.ground.values()], lines)

    def tolerance(self) -> Tolerance:
        return Tolerance(self.size)

    @functools.cached_property
    def plan(self) -> tuple[PlanStep, ...]:
        """The assembly plan (:func:`assembly_plan`), found once: the mechanism is immutable and a study
        asks for its plan several times."""
        return _assembly_plan(self)


def mobility(m: Mechanism) -> tuple[int, str]:
    """Degrees of freedom by the Gruebler/Kutzbach count, F = 3 (n - 1) - 2 j1 - j2, and its working.

    n counts the frame, the links and the slider blocks; a revolute joint shared by k bodies counts as
    k - 1 joints (a multiple joint); every block adds its sliding pair; a pin in a slot is a higher pair
    (j2: it slides and turns)."""
    bodies = 1 + len(m.links) + len(m.blocks())
    at: dict[str, int] = {g: 1 for g in m.ground}              # the frame carries its pivots
    for k in m.links:
        for j in m.points_of(k.number):
            at[j] = at.get(j, 0) + 1
    for s in m.slides:
        if s.number is not None:
            at[s.joint] = at.get(s.joint, 0) + 1                  # the block is pinned at the joint
    j1 = sum(c - 1 for c in at.values() if c > 1)
    j1 += len(m.blocks())                                         # each block's sliding pair
    j2 = sum(1 for s in m.slides if s.number is None)
    f = 3 * (bodies - 1) - 2 * j1 - j2
    return f, f"n = {bodies}, j1 = {j1}, j2 = {j2}: F = 3({bodies} - 1) - 2·{j1} - {j2} = {f}"


# -- the plan: which joint is found from which loci ---------------------------------------------------

@dataclass(frozen=True, slots=True)
class CrankTip:
    link: Link
    pivot: str
    tip: str


@dataclass(frozen=True, slots=True)
class TwoCircles:
    """Joint found where the circle about ``first`` (radius ``radius_a``, on link_a) meets the circle
    about ``second`` (radius ``radius_b``, on link_b)."""

    joint: str
    link_a: Link
    first: str
    link_b: Link
    second: str
    branch: Branch
    radius_a: float = 0.0
    radius_b: float = 0.0


@dataclass(frozen=True, slots=True)
class CircleAndGuide:
    """Joint found where the circle about ``centre`` (radius ``radius``, on ``link``) meets the guide of
    ``slide``, or its slot when the slotted link is already placed."""

    joint: str
    link: Link
    centre: str
    slide: Slide
    branch: Branch
    radius: float = 0.0
    coincident: str = ""          # on a slot: the point of the slotted link under the joint


@dataclass(frozen=True, slots=True)
class SlotThrough:
    """The slotted link ``link`` turns about its known point ``centre`` until its slot passes through the
    known joint ``joint`` (an RPR dyad: inverted slider-crank, slotted lever); ``coincident`` names the
    point of the slotted link under the joint (the notes' A_3 beside A_2)."""

    joint: str
    link: Link
    centre: str
    slide: Slide
    branch: Branch
    coincident: str


@dataclass(frozen=True, slots=True)
class TwoLines:
    """Joint found where the lines of two slides cross (a PRP dyad): the joint carries two blocks (or
    pins), each sliding on a fixed guide or on the slot of a placed link; ``coincident_a``/``_b`` name the
    point of each slotted link under the joint ("" for a fixed guide)."""

    joint: str
    slide_a: Slide
    slide_b: Slide
    coincident_a: str = ""
    coincident_b: str = ""


@dataclass(frozen=True, slots=True)
class FixedToLink:
    """A point of ``link`` placed once two of its points, ``via``, are known (rigid body)."""

    point: Attached | str
    link: Link
    via: tuple[str, str] = ("", "")

    @property
    def name(self) -> str:
        return self.point if isinstance(self.point, str) else self.point.name


PlanStep = CrankTip | TwoCircles | CircleAndGuide | SlotThrough | TwoLines | FixedToLink
Dyad = TwoCircles | CircleAndGuide | SlotThrough | TwoLines


def coincident_name(joint: str, link: int) -> str:
    """The point of link ``link`` under a sliding joint, as the notes write it: A on link 3 is A3."""
    return f"{joint}{link}"


def assembly_plan(m: Mechanism) -> tuple[PlanStep, ...]:
    """Order in which the joints are constructed; raises DegenerateInput when the linkage is not 1-DoF or
    is not a crank followed by dyads (it says which joint cannot be reached and why).  Found once per
    mechanism (:attr:`Mechanism.plan`)."""
    return m.plan


def _assembly_plan(m: Mechanism) -> tuple[PlanStep, ...]:
    crank = m.link(m.crank)
    pivots = [j for j in crank.joints if j in m.ground]
    if len(pivots) != 1:
        raise DegenerateInput(f"the crank, link {crank.number} ({crank.label}), must join one fixed pivot "
                              f"to one moving joint; fixed pivots are {', '.join(m.ground) or 'none'}")
    seen: set[str] = set()
    twice: set[str] = set()
    for s in m.slides:
        if s.joint in m.ground:
            raise DegenerateInput(f"slider joint {s.joint} is also a fixed pivot")
        if s.joint in seen and s.joint in twice:
            raise DegenerateInput(f"joint {s.joint} is carried by three sliders; a joint takes at most two")
        if s.joint in seen:
            twice.add(s.joint)
        seen.add(s.joint)
        if s.on is not None:
            m.link(s.on)
            if s.joint in m.points_of(s.on):
                raise DegenerateInput(f"joint {s.joint} cannot slide on link {s.on}, which it belongs to")
    local = {k.number: m.local(k.number) for k in m.links}
    tip = crank.other(pivots[0])
    plan: list[PlanStep] = [CrankTip(crank, pivots[0], tip)]
    known = set(m.ground) | {tip}
    posed: set[int] = set()                      # links whose every point is fixed
    slides: dict[str, list[Slide]] = {}
    for sl in m.slides:
        slides.setdefault(sl.joint, []).append(sl)
    everything = set(m.ground) | {j for pts in local.values() for j in pts} | set(slides)

    def pose_points(number: int) -> bool:
        """Once two points of a link are known, place the rest (FixedToLink)."""
        pts = local[number]
        have = [x for x in pts if x in known]
        if len(have) < 2:
            return False
        link = m.link(number)
        via = (link.joints[0], link.joints[1]) if all(j in known for j in link.joints) else (have[0], have[1])
        for x in pts:
            if x not in known:
                att = next((a for a in m.attached if a.name == x and a.link == number), None)
                plan.append(FixedToLink(att if att is not None and set(via) == set(link.joints) else x, link, via))
                known.add(x)
        posed.add(number)
        return True

    def circles(j: str) -> list[tuple[Link, str, float]]:
        """(link, known centre, radius) for every unposed link through j with exactly one known point."""
        out = []
        for k in m.links:
            pts = local[k.number]
            if k.number in posed or j not in pts:
                continue
            have = [x for x in pts if x in known]
            if len(have) == 1:
                out.append((k, have[0], pts[j].distance_to(pts[have[0]])))
        return out

    while True:
        progress = False
        for n in sorted(local):
            if n not in posed and pose_points(n):
                progress = True
        for j in sorted(everything - known):
            cs = circles(j)
            on_lines = slides.get(j, [])
            placed = [sl for sl in on_lines if sl.on is None or sl.on in posed]
            s = placed[0] if placed else (on_lines[0] if on_lines else None)
            if len(on_lines) == 2 and len(placed) == 2:
                a, b = placed
                plan.append(TwoLines(j, a, b,
                                     _coincident(m, j, a.on, everything) if a.on is not None else "",
                                     _coincident(m, j, b.on, everything) if b.on is not None else ""))
            elif s is None and len(cs) >= 2:
                (ka, a, ra), (kb, b, rb) = cs[:2]
                branch = _branch_for(m, j, (a, b))
                if branch.reference == (b, a):
                    (ka, a, ra), (kb, b, rb) = (kb, b, rb), (ka, a, ra)
                plan.append(TwoCircles(j, ka, a, kb, b, branch, ra, rb))
            elif s is not None and len(on_lines) == 1 and cs and (s.on is None or s.on in posed):
                k, c, r = cs[0]
                plan.append(CircleAndGuide(j, k, c, s, _branch_for(m, j, (c,)), r,
                                           _coincident(m, j, s.on, everything) if s.on is not None else ""))
            else:
                continue
            known.add(j)
            progress = True
        for j, s in [(sl.joint, sl) for key in sorted(slides) for sl in slides[key]]:
            if j in known and s.on is not None and s.on not in posed:
                pts = local[s.on]
                have = [x for x in pts if x in known]
                if len(have) == 1:
                    link = m.link(s.on)
                    plan.append(SlotThrough(j, link, have[0], s, _branch_for(m, j, (have[0],)),
                                            _coincident(m, j, s.on, everything)))
                    for x in pts:
                        known.add(x)
                    posed.add(s.on)
                    progress = True
        if not progress:
            break
    missing = sorted(everything - known)
    f, working = mobility(m)
    if f != 1:
        loose = (f"; joint {missing[0]} cannot be constructed: it needs two links to known joints, or one "
                 f"link and a guide or placed slot") if missing and f > 1 else ""
        # a joint named on one link only, that nothing else holds, is usually a fixed pivot left undeclared
        held = set(m.ground) | set(slides) | {a.name for a in m.attached}
        on_links: dict[str, list[int]] = {}
        for k in m.links:
            for j in k.joints:
                on_links.setdefault(j, []).append(k.number)
        loose_ends = [j for j in sorted(on_links) if len(on_links[j]) == 1 and j not in held
                      and j != tip and j in missing]
        if f > 1 and loose_ends:
            j = loose_ends[0]
            loose = (f"; {j} is held by link {on_links[j][0]} only: join it to another link, put it on a "
                     f"slider, or declare it a fixed pivot")
        raise DegenerateInput(f"the mechanism has {f} degrees of freedom ({working}); a crank drives only a "
                              f"mechanism with one{loose}")
    if missing:
        raise DegenerateInput(f"joint {missing[0]} cannot be constructed dyad by dyad: it needs two links to "
                              f"known joints, or one link and a guide or placed slot (a loop that must be "
                              f"solved as a whole is not drawn by this method)")
    return tuple(plan)


def _coincident(m: Mechanism, joint: str, link: int, names: set[str]) -> str:
    name = coincident_name(joint, link)
    while name in names:
        name += "'"
    return name


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
    (0 when they touched); ``lines`` maps every sliding joint to the line it slides on at this pose.
    """

    angle: float
    positions: Mapping[str, Vec]
    construction: Construction
    conditions: Mapping[str, float]
    lines: Mapping[str, Line] = field(default_factory=dict)

    def __getitem__(self, name: str) -> Vec:
        return self.positions[name]


def describe_angle(angle: float) -> str:
    return f"crank angle {math.degrees(angle):.6g} deg"


def place_rigid(local: Mapping[str, Vec], a: str, b: str, pa: Vec, pb: Vec, x: str) -> Vec:
    """Where point ``x`` of a rigid body stands when its points ``a`` and ``b`` stand at pa and pb."""
    turn = (pb - pa).angle() - (local[b] - local[a]).angle()
    return pa + (local[x] - local[a]).rotated(turn)


def slide_line(m: Mechanism, s: Slide, pos: Mapping[str, Vec]) -> Line:
    """The line ``s`` slides on at the positions ``pos`` (the guide, or the slot of a placed link)."""
    if s.on is None:
        return s.line
    k = m.link(s.on)
    return s.slot_line(pos[k.joints[0]], pos[k.joints[1]])


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
    return Segment(f"slot {s.joint} in link {s.on}", Role.PATH, Diagram.SPACE, line.at(lo - pad), line.at(hi + pad))


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
