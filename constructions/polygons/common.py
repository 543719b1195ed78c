"""What every vector polygon shares: the pole and image labels, the names of acceleration components, the
words for a sense of rotation, the naming of singular positions (toggle, change point, limit position,
dead centre) from the mechanism and its pose, and the drawing of trial lines and their crossing.  The
thresholds that name a singular position are in :mod:`constructions.tolerance`.
"""

from __future__ import annotations

import math

from ..errors import IndeterminatePosition
from ..geometry import ORIGIN, Contact, Line, Vec, intersect_lines
from ..mechanisms.assembly import (CircleAndGuide, CrankTip, FixedToLink, SlotAlongGuide, SlotThrough, TwoCircles,
                                   TwoLines)
from ..mechanisms.model import Mechanism, describe_angle
from ..mechanisms.pose import Pose
from ..entities import Arrow, Point, Polygon, Role, ScaleBar, TrialLine
from ..record import Construction, StepKind, Value
from ..tolerance import CHANGE_POINT_REL, CONDITION_FLOOR, DEAD_CENTRE_SINE, ROUNDING, WARN_SINE


def rounding_estimate(condition: float) -> float:
    """Rough relative error of values read off a crossing at sine ``condition``."""
    return ROUNDING / max(condition, CONDITION_FLOOR) ** 2


def image_name(joint: str, prime: str = "") -> str:
    """The notes' lower-case label of a joint's image point: B -> b (velocity), b' (acceleration with
    ``prime="'"``); O2 -> o2."""
    return joint[0].lower() + joint[1:] + prime


def component_name(j: str, p: str, sup: str, m: Mechanism) -> str:
    """A_CB^t; about a fixed pivot the notes drop the pivot: A_C^t."""
    return f"A_{j}^{sup}" if p in m.ground else f"A_{j}{p}^{sup}"


def joined(*names: str) -> str:
    """Image points written together as the notes do (bcd, b'c'd'); with the pole among them (O_v), spaced
    so the subscript stays the pole's: "O_v c f"."""
    return (" " if any("_" in n for n in names) else "").join(names)


def sense(rate: float) -> str:
    """Words for the sense of an angular velocity or acceleration (CCW positive)."""
    return "counter-clockwise" if rate > 0 else "clockwise" if rate < 0 else "zero"


def sense_short(rate: float) -> str:
    return "CCW" if rate > 0 else "CW" if rate < 0 else ""


def singular_kind(m: Mechanism, step, pose: Pose) -> tuple[str, str]:
    """The kind of singular position a dyad's trial lines announce when they (nearly) fail to cross, and
    the angle that shows it: ("toggle" | "change point", transmission angle) for two links meeting at the
    joint, ("limit position", angle between the link and its guide or slot) otherwise."""
    j = step.joint
    p = pose.positions
    if isinstance(step, TwoCircles):
        kind = "change point" if change_point(m, pose) else "toggle"
        return kind, f"transmission angle {transmission_angle(pose, step):.3g} deg"
    if isinstance(step, TwoLines):                  # PRP: the two lines the joint slides on
        return "limit position", f"the two lines {j} slides on are parallel"
    line = pose.lines.get(j)
    centre = step.centre
    r = p[j] - p[centre]
    if line is not None and r.norm() > 0:
        a = math.degrees(math.acos(min(1.0, abs(line.direction.dot(r.unit())))))
        return "limit position", f"link {step.link.number} at {a:.3g}\u00b0 to the {'slot' if step.slide.on else 'guide'}"
    return "limit position", "link square to its guide"


def singular_position(m: Mechanism, step, pose: Pose, condition: float, polygon: str) -> IndeterminatePosition:
    """The error for trial lines that do not cross: the position named (toggle, change point, limit
    position) with the crank angle, the links in line and the transmission angle."""
    j = step.joint
    where = describe_angle(pose.angle)
    kind, angle = singular_kind(m, step, pose)
    if isinstance(step, TwoCircles):
        a, b = step.link_a, step.link_b
        reason = (f"{kind}: links {a.number} and {b.number} are in line at {j} ({angle}), so the trial lines "
                  f"for {j} are parallel (sine {condition:.1e}) and the {polygon} cannot close")
    elif isinstance(step, TwoLines):
        reason = (f"limit position (lock): {angle}, so the trial lines for {j} are parallel (sine "
                  f"{condition:.1e}) and the {polygon} cannot close")
    else:
        reason = (f"limit position (lock): link {step.link.number} stands square to the "
                  f"{'slot' if step.slide.on else 'guide'} of {j} ({angle}), so the trial lines for {j} are "
                  f"parallel (sine {condition:.1e}) and the {polygon} cannot close")
    return IndeterminatePosition(reason, position=where, kind=kind, condition=condition)


def transmission_angle(pose: Pose, step: TwoCircles) -> float:
    """The angle between the two links meeting at the joint a dyad finds, in degrees (0..180)."""
    p = pose.positions
    u = p[step.first] - p[step.joint]
    v = p[step.second] - p[step.joint]
    return math.degrees(abs(math.atan2(u.cross(v), u.dot(v))))


def near_singular_warning(m: Mechanism, step, pose: Pose, condition: float, what: str) -> str:
    kind, angle = singular_kind(m, step, pose)
    return (f"Near a {kind} at {step.joint} ({angle}; {describe_angle(pose.angle)}): the trial lines of the "
            f"{what} cross at {math.degrees(math.asin(min(condition, 1.0))):.3g} deg; values are sensitive "
            f"to the drawing (rounding error about {rounding_estimate(condition):.1e} relative).")


def dead_centre(pos, crank: CrankTip, arms, j: str) -> str | None:
    """At a dead centre the crank and the link it drives are in line: for a driving crank the polygon
    still closes (the driven joint is momentarily at rest along that link), but the position is
    singular for motion driven from the output, so the reader is told."""
    for link, centre in arms:
        if centre == crank.tip:
            a = pos[crank.tip] - pos[crank.pivot]
            b = pos[j] - pos[centre]
            if abs(a.unit().cross(b.unit())) < DEAD_CENTRE_SINE:
                return (f"Dead centre: crank {crank.pivot}{crank.tip} and link {link.number} "
                        f"({link.label}) are in line; driven by the crank the polygon closes, but the "
                        f"output could not drive the crank from here.")
    return None


def change_point(m: Mechanism, pose: Pose) -> bool:
    """All joints of the loop in one line (the branches of a four-bar meet); points merely fixed to a
    link do not count."""
    joints = set(m.ground) | {j for k in m.links for j in k.joints}
    pts = [p for n, p in pose.positions.items() if n in joints]
    far = max(pts, key=lambda p: p.distance_to(pts[0]))
    if far == pts[0]:
        return True
    axis = Line.through(pts[0], far)
    return all(abs(axis.signed_distance(p)) <= CHANGE_POINT_REL * m.size for p in pts)


def dyad_arms(step) -> tuple[bool, int | None, list]:
    """A dyad as (on a guide or slot, the slotted link or None, its arms (link, centre)): the link and its
    centre on a guide or slot, else both links with their outer joints."""
    guided = isinstance(step, CircleAndGuide)
    on = step.slide.on if guided else None
    arms = [(step.link, step.centre)] if guided else [(step.link_a, step.first), (step.link_b, step.second)]
    return guided, on, arms


def image_point(P: Vec, Q: Vec, D: Vec, ip: Vec, iq: Vec) -> tuple[Vec, float, float]:
    """The image d of a point D of a rigid link PQ, given the images p and q: the triangle pqd is similar
    to PQD (same complex ratio (D - P)/(Q - P)), exact for velocity and acceleration images alike.
    Returns d and (t, u), D's coordinates along PQ and square to it in units of |PQ|."""
    pq, pd = Q - P, D - P
    t = pd.dot(pq) / pq.dot(pq)
    u = pq.cross(pd) / pq.dot(pq)
    side = iq - ip
    return ip + side * t + side.perp() * u, t, u


class PolygonDrawing:
    """What the velocity and acceleration polygons share while they are drawn: the walk over the
    assembly plan (each dyad gives one vector equation, each point placed by its link an image) and the
    crossing of two trial lines, named as a singular position when they do not cross and warned about
    near one.  A subclass sets ``what`` ("velocity polygon"), the ``symbol`` of its vectors ("V"), its
    ``pole`` ("O_v") and ``diagram``, has ``m``, ``pose``, ``tol``, ``cond``, ``warnings`` and ``steps``, and
    draws ``dyad(step)`` and ``image(step)``."""

    what = "polygon"
    symbol = ""
    pole = ""
    diagram = None

    def draw_plan(self, plan) -> None:
        """Each step after the crank: an image, a slotted link through a joint, a joint on two lines, a
        yoke slid along its guide, or a dyad of two links (or a link and a guide or slot)."""
        for step in plan[1:]:
            if isinstance(step, FixedToLink):
                self.image(step)
            elif isinstance(step, SlotThrough):
                self.slot_through(step)
            elif isinstance(step, TwoLines):
                self.two_lines(step)
            elif isinstance(step, SlotAlongGuide):
                self.slot_along_guide(step)
            elif not isinstance(step, CrankTip):
                self.dyad(step)

    def _close(self, step, trials) -> Vec:
        """The crossing of two trial lines for ``step.joint``, recorded with its condition."""
        hit = intersect_lines(trials[0], trials[1], self.tol)
        if hit.contact is not Contact.CROSSING:
            raise singular_position(self.m, step, self.pose, hit.condition, self.what)
        self.cond[step.joint] = hit.condition
        if hit.condition < WARN_SINE:
            self.warnings.append(near_singular_warning(self.m, step, self.pose, hit.condition, self.what))
        return hit.points[0]

    def image_answer(self, words: str, prefix: str, p: str, q: str, d: str, corners: tuple[Vec, Vec, Vec],
                     label: str, values) -> None:
        """The step ``words`` that places the image of D, a point of link PQ: the image triangle ``corners``
        (p, q, d), d's ``label``, and D's absolute vector from the pole."""
        sym, tip = self.symbol, corners[2]
        self.steps.append((words, (Polygon(f"{prefix} {p}{q}{d}", Role.IMAGE, self.diagram, corners),
                                   Point(f"{prefix} {d}", Role.LABEL, self.diagram, tip, label),
                                   Arrow(f"result {sym}_{d}", Role.RESULT, self.diagram, ORIGIN, tip, f"{sym}_{d}")),
                           None, values, StepKind.ANSWER))

    def record(self, kind: str, scale: float | None, known: float) -> Construction:
        """The record in the notes' order: the equations, the pole, the ``kind`` scale (``known`` the length
        of the crank tip's vector), then the drawing steps."""
        rec = Construction(f"{kind.capitalize()} polygon")
        for words, eq in self.equations:
            rec = rec.then(words, equation=eq, kind=StepKind.GIVEN)
        rec = rec.then(f"Choose the pole {self.pole}.",
                       Point(f"pole {self.pole}", Role.LABEL, self.diagram, ORIGIN, self.pole))
        rec = rec.then(f"Choose the {kind} scale: 1 mm = $s; {self.symbol}_{self.crank.tip} is $len.",
                       ScaleBar(f"{kind} scale", Role.SCALE_BAR, self.diagram, kind, scale),
                       values={"s": Value("scale", scale, kind), "len": Value("paper length", known, kind)})
        for words, entities, eq, values, kind_ in self.steps:
            rec = rec.then(words, *entities, equation=eq, values=values, kind=kind_)
        return rec

    def parallel_trial(self, words: str, name: str, through: Vec, g: Vec, eq, slot: bool, *marks,
                       values=None) -> Line:
        """The step ``words``: the points ``marks``, then the trial line ``name`` through ``through``, parallel
        to a slot (``slot``) or a fixed guide of direction ``g``.  Returns that line."""
        label = "\u2225 slot" if slot else "\u2225 guide"
        self.steps.append((words, (*marks, TrialLine(name, Role.TRIAL, self.diagram, through, g, label)), eq,
                           values or {}, StepKind.CONSTRUCTION))
        return Line(through, g)

    def close_dyad(self, step, trials: list[Line], eq) -> tuple[Vec, Vec | None]:
        """The crossing of a dyad's trial lines: its arms' ``trials`` and, for a joint on a fixed guide, the
        line through the pole along it, or in the slot of a moving link the line ``slot_trial`` draws.
        Returns the crossing and where the sliding vector along the slot starts (None without a slot)."""
        start = None
        if isinstance(step, CircleAndGuide):
            j = step.joint
            g = self.pose.lines[j].direction
            if step.slide.on is None:
                trials = trials + [self.guide_trial(j, g, eq)]
            else:
                line, start = self.slot_trial(j, step.coincident, step.slide.on, g, eq)
                trials = trials + [line]
        return self._close(step, trials), start

    def yoke_crossing(self, step, eq, sliding: str, mark: str, images: dict[str, Vec]) -> Vec:
        """A yoke slid along its guide (:class:`SlotAlongGuide`): through the pole the direction of its motion,
        parallel to the guide, and through ``mark`` (the image of the joint J, known in ``images``) the
        direction of the ``sliding`` vector, parallel to the slot.  Their crossing is the image of every
        point of the yoke and of the point under J, written into ``images`` and returned."""
        j, jg = step.joint, step.coincident
        guide = self.guide_trial(jg, step.guides[0].line.direction, eq)
        slot = self.parallel_trial(f"Draw the direction of {sliding} through {mark}, parallel to the slot.",
                                   f"trial {sliding}", images[j], self.pose.lines[j].direction, eq, True)
        x = self._close(step, [guide, slot])
        for p in (*self.m.points_of(step.link.number), jg):
            images[p] = x
        return x

    def guide_trial(self, j: str, g: Vec, eq, name: str = "") -> Line:
        """The direction of the absolute velocity (acceleration) of a joint on a fixed guide: through the
        pole, parallel to the guide."""
        q = self.symbol
        return self.parallel_trial(f"Draw the direction of {q}_{j} through {self.pole}, parallel to the guide.",
                                   name or f"trial {q}_{j}", ORIGIN, g, eq, False)
