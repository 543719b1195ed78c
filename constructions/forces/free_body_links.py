"""The free bodies of a mechanism's force analysis, drawn as textbooks draw them: every moving body pulled
free of the others and set side by side in one free-body diagram, so that all of them are drawn at one
scale.

Each body keeps its shape and its turn as it stands in the mechanism: a link as the line of its pins (a
ternary link as a plate), a block on its joint, every pin and point lettered, and its caption saying what
it is -- a *two-force member* (two forces, no couple: equal, opposite and along the line of its pins), a
*three-force member* (three forces, no couple: their lines meet in one point, I), *two forces and a
couple* (the crank with its driving torque).  Every force acts at its point of application: a force that
pushes into the body has its tip there, one that pulls has its tail there, so the arrows stand outside the
body; their lengths are not to scale (the magnitudes are on the force polygons), the largest on the sheet
``ARROW`` of the mechanism's size.  Couples and torques are arcs turning their way.

The lines the constructions drew on a body's free body (the three-force lines through I, the crank's
resultant and its arm h, a slot's force line) are moved with the body, each trial line cut to a segment
through the points of its body on it, so lines of different bodies never meet.
"""

from __future__ import annotations

import math
from dataclasses import fields, replace

from ..entities import (Arrow, BodyOutline, Diagram, Entity, MomentArc, Point, Role, Segment, TrialLine)
from ..geometry import Vec
from ..mechanisms.model import slide_line
from ..mechanisms.topology import Contact
from ..tolerance import NEGLIGIBLE
from .bodies import torque_name
from .board import Drawing, body_label

FREE_BODIES = Diagram("free-body")
"""The one diagram every free body of a sheet is drawn in (one panel, one scale)."""
ARROW = 0.35
"""The longest force arrow on the free bodies, as a fraction of the mechanism's size."""
ARROW_LEAST = 0.6
"""The shortest arrow, as a fraction of the longest (a small force still reads as an arrow)."""
GAP = 0.25
"""The room between two free bodies (and for their captions), as a fraction of the mechanism's size."""
LINE_PAD = 0.08
"""How far a trial line runs past the points it joins, as a fraction of the mechanism's size."""
MOMENT_R = 0.1
"""The radius of a couple's arc, as a fraction of the mechanism's size (at most 0.4 of its body)."""
ASPECT = 1.5
"""The free bodies are set in rows to fill a box this much wider than high."""
POSITIONS = ("at", "tail", "tip", "through", "start", "end", "vertex", "centre", "center", "caption_at")
"""The fields of an entity that are points (moved with its body); directions are not."""
POINT_LISTS = ("outline", "vertices", "pins", "points")


def moved(e: Entity, by: Vec) -> Entity:
    """``e`` moved by ``by`` into the free-body diagram."""
    new: dict = {"diagram": FREE_BODIES}
    for f in fields(e):
        v = getattr(e, f.name)
        if f.name in POSITIONS and isinstance(v, Vec):
            new[f.name] = v + by
        elif f.name in POINT_LISTS and isinstance(v, tuple):
            new[f.name] = tuple(x + by if isinstance(x, Vec) else (x[0], x[1] + by) for x in v)
    return replace(e, **new)


def _extent_points(e: Entity) -> list[Vec]:
    out = []
    for f in fields(e):
        v = getattr(e, f.name)
        if f.name in POSITIONS and isinstance(v, Vec):
            out.append(v)
        elif f.name in POINT_LISTS and isinstance(v, tuple):
            out += [x if isinstance(x, Vec) else x[1] for x in v]
    if isinstance(e, MomentArc):
        out += [e.centre + Vec(s * e.radius, t * e.radius) for s, t in ((1, 0), (-1, 0), (0, 1), (0, -1))]
    return out


def _cut(line: TrialLine, on: list[Vec], pad: float) -> Segment:
    """A trial line cut to a segment through the points of its body ``on`` it (and its own point)."""
    u = line.direction.unit()
    tol = 1e-9 * max((p.distance_to(line.through) for p in on), default=1.0) + 1e-12
    ts = [0.0] + [(p - line.through).dot(u) for p in on if abs(u.cross(p - line.through)) <= tol]
    lo, hi = min(ts) - pad, max(ts) + pad
    return Segment(line.name, line.role, line.diagram, line.through + u * lo, line.through + u * hi, line.label)


class _Body:
    """One body's free body in the mechanism's coordinates, before it is moved beside the others."""

    def __init__(self, d: Drawing, number: int, big: float) -> None:
        m, pos = d.m, d.pos
        self.number = number
        self.label = body_label(m, number)
        blocks = m.blocks()
        names = (blocks[number].joint,) if number in blocks else m.points_of(number)
        joints = _joints(d, number)
        pts = [pos[n] for n in names]
        mid = sum(pts, Vec(0.0, 0.0)) / len(pts)
        extent = max((p.distance_to(q) for p in pts for q in pts), default=0.0)
        self.ents: list[Entity] = []
        forces = [x for x in d.forces.get(number, []) if x.vector.norm() > 0.0]
        for i, x in enumerate(forces):
            u = x.vector.unit()
            length = ARROW * m.size * max(ARROW_LEAST, x.vector.norm() / big)
            into = u.dot(mid - x.at) > 0 or (mid - x.at).norm() <= NEGLIGIBLE * m.size
            tail, tip = (x.at - u * length, x.at) if into else (x.at, x.at + u * length)
            role = Role.LOAD if x.kind in ("load", "weight", "inertia", "spring") else Role.RESULT
            self.ents.append(Arrow(f"fbd {self.label}: {x.label} {i}", role, FREE_BODIES, tail, tip, x.label))
        couples = _couples(d, number)
        r = MOMENT_R * m.size if extent == 0.0 else min(MOMENT_R * m.size, 0.4 * extent)
        for i, (name, c, centre, start) in enumerate(couples):
            centre = mid if centre is None else centre
            self.ents.append(MomentArc(f"fbd {self.label}: {name}", Role.LOAD if name != torque_name(m) else Role.RESULT,
                                       FREE_BODIES, centre, r * (1 + 0.4 * i), start, c, name))
        shape = _shape(d, number, names)
        self.caption = _caption(self.label, len(forces), len(couples))
        self.outline = BodyOutline(f"fbd {self.label}: body", Role.GIVEN, FREE_BODIES, shape,
                                   tuple((n, pos[n]) for n in names if n in joints),
                                   tuple((n, pos[n]) for n in names if n not in joints), number,
                                   slide_line(m, blocks[number], pos).direction if number in blocks else None,
                                   self.caption)
        self.ents.insert(0, self.outline)
        self.forces = forces

    def points(self) -> list[Vec]:
        return [p for e in self.ents for p in _extent_points(e)]

    def box(self) -> tuple[float, float, float, float]:
        """The body's extent with its forces and lines; its caption is set under the middle of it."""
        pts = self.points()
        box = min(p.x for p in pts), min(p.y for p in pts), max(p.x for p in pts), max(p.y for p in pts)
        under = Vec((box[0] + box[2]) / 2, box[1])
        i = self.ents.index(self.outline)
        self.outline = self.ents[i] = replace(self.outline, caption_at=under)
        return box


def _joints(d: Drawing, number: int) -> set[str]:
    """The points of a body that are pins (joined to another body or the frame, or a block's joint)."""
    m = d.m
    blocks = m.blocks()
    if number in blocks:
        return {blocks[number].joint}
    own = set(m.points_of(number))
    others = set(m.ground) | {s.joint for s in m.slides}
    for k in m.links:
        if k.number != number:
            others |= set(m.points_of(k.number))
    return own & others


def _shape(d: Drawing, number: int, names) -> tuple[Vec, ...]:
    """A block's joint, a slender link's two extreme points, or a plate's convex hull."""
    pos = d.pos
    pts = [pos[n] for n in names]
    if len(pts) <= 2:
        return tuple(pts)
    a, b = max(((p, q) for p in pts for q in pts), key=lambda pq: pq[0].distance_to(pq[1]))
    u = (b - a).unit()
    if all(abs(u.cross(p - a)) <= 1e-9 * d.m.size for p in pts):
        return (a, b)
    return _hull(pts)


def _hull(pts: list[Vec]) -> tuple[Vec, ...]:
    """The convex hull, counter-clockwise (Andrew's monotone chain)."""
    s = sorted(set((p.x, p.y) for p in pts))
    if len(s) <= 2:
        return tuple(Vec(*p) for p in s)

    def half(seq):
        h: list = []
        for p in seq:
            while len(h) >= 2 and ((h[-1][0] - h[-2][0]) * (p[1] - h[-2][1])
                                   - (h[-1][1] - h[-2][1]) * (p[0] - h[-2][0])) <= 0:
                h.pop()
            h.append(p)
        return h
    lower, upper = half(s), half(reversed(s))
    return tuple(Vec(*p) for p in lower[:-1] + upper[:-1])


def _couples(d: Drawing, number: int) -> list[tuple[str, float, Vec | None, float]]:
    """The couples on a body as (label, moment CCW positive, centre or None for the body's middle, start
    angle of the arc): the scene's couples, a guide's couple on its block (and on the slotted link that
    guides it), the inertia couple where there is no inertia force, and the crank's driving torque."""
    m, pos = d.m, d.pos
    out = [(cp.name, cp.torque, None, math.pi / 4) for cp in d.effects.couples if cp.body == number and cp.torque]
    small = NEGLIGIBLE * d.scale * m.size
    on_guide = 0.0
    for k, (_, c) in d.contacts.items():
        if not isinstance(k, Contact) or abs(c) <= small:
            continue
        if k.block == number:
            out.append((f"M_{k.guide}{k.block}", c, None, math.pi / 4))
        elif k.guide == number:
            on_guide -= c
            out.append((f"M_{k.block}{k.guide}", -c, None, math.pi / 4))
    rest = d.couples.get(number, 0.0) - sum(cp.torque for cp in d.effects.couples if cp.body == number) - on_guide
    if abs(rest) > small:
        out.append((f"C_I{number}", rest, None, math.pi / 4))
    if number == m.crank and d.torque:
        crank = m.link(number)
        o = m.crank_pivot()
        arm = pos[crank.other(o)] - pos[o]
        start = arm.angle() + math.copysign(math.pi / 4, d.torque)
        out.append((torque_name(m), d.torque, pos[o], start))
    return out


def _caption(label: str, forces: int, couples: int) -> str:
    """What the body is: a two- or three-force member, two forces and a couple, or just its name."""
    if couples == 0 and forces in (2, 3):
        return f"{label}: {'two' if forces == 2 else 'three'}-force member"
    if couples == 1 and forces == 2:
        return f"{label}: two forces and a couple"
    return label


def _rows(sizes: list[tuple[float, float]], gap: float) -> list[list[int]]:
    """The bodies in order split into rows, the split whose bounding box best fills an ASPECT box."""
    n = len(sizes)
    best = None
    for cuts in range(1 << max(n - 1, 0)):
        rows, row = [], [0]
        for i in range(1, n):
            if cuts >> (i - 1) & 1:
                rows.append(row)
                row = []
            row.append(i)
        rows.append(row)
        w = max(sum(sizes[i][0] for i in r) + gap * (len(r) - 1) for r in rows)
        h = sum(max(sizes[i][1] for i in r) for r in rows) + gap * (len(rows) - 1)
        key = (max(w / ASPECT, h), len(rows))
        if best is None or key < best[0]:
            best = (key, rows)
    return best[1] if best else []


def free_bodies(d: Drawing) -> list[tuple[str, tuple]]:
    """The free body of every moving body (links, then blocks) set side by side in :data:`FREE_BODIES`,
    as (words, entities) steps; the free-body lines the constructions drew in ``d.steps`` are moved with
    their bodies (``d.steps`` is rewritten)."""
    m = d.m
    order = [k.number for k in m.links] + sorted(m.blocks())
    big = max((x.vector.norm() for b in order for x in d.forces.get(b, [])), default=0.0) or 1.0
    bodies = [_Body(d, b, big) for b in order]
    drawn = {b.label: b for b in bodies}
    pad = LINE_PAD * m.size
    cut: dict[str, Entity] = {}
    for words, ents, *_ in d.steps:
        for e in ents:
            if e.diagram.kind == "free-body" and e.diagram.name in drawn:
                body = drawn[e.diagram.name]
                on = [p for _, p in body.outline.pins + body.outline.points] + \
                     [x.at for x in body.forces] + [q.at for q in _points_of(d, e.diagram.name)]
                cut[e.name] = _cut(e, on, pad) if isinstance(e, TrialLine) else e
                body.ents.append(cut[e.name])
    boxes = [b.box() for b in bodies]
    gap = GAP * m.size
    rows = _rows([(x1 - x0, y1 - y0) for x0, y0, x1, y1 in boxes], gap)
    widths = [sum(boxes[i][2] - boxes[i][0] for i in r) + gap * (len(r) - 1) for r in rows]
    offsets: dict[str, Vec] = {}
    top = 0.0
    for r, w in zip(rows, widths):
        h = max(boxes[i][3] - boxes[i][1] for i in r)
        x = (max(widths) - w) / 2
        for i in r:
            x0, y0, x1, y1 = boxes[i]
            offsets[bodies[i].label] = Vec(x - x0, top - h / 2 - (y0 + y1) / 2)
            x += x1 - x0 + gap
        top -= h + gap
    d.steps[:] = [(words, tuple(moved(cut[e.name], offsets[e.diagram.name]) if e.name in cut else e for e in ents),
                   *rest) for words, ents, *rest in d.steps]
    out = []
    for b in bodies:
        own = [moved(e, offsets[b.label]) for e in b.ents if e.name not in cut]
        names = ", ".join(x.label for x in b.forces) or "no force"
        out.append((f"Free body of {b.caption}: {names} (each at its point of application; arrows not to scale).",
                    tuple(own)))
    return out


def _points_of(d: Drawing, name: str) -> list[Point]:
    return [e for _, ents, *_ in d.steps for e in ents
            if isinstance(e, Point) and e.diagram.kind == "free-body" and e.diagram.name == name]


__all__ = ["FREE_BODIES", "free_bodies", "moved"]
