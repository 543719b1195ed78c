"""Drawing the entities of one diagram as paper commands.

``draw_entities`` turns a diagram's entities (bars, pivots, blocks, guides, arcs, arrows, trial lines,
images, points) into layered drawing commands at a given scale, with the label requests, the symbols
labels must not cover and the line segments they should avoid, ready for :mod:`drafting.labels`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Sequence

from constructions.geometry import Vec
from constructions.record import (Arc, Arrow, Bar, Block, Entity, Guide, Pivot, Plate, Point,
                                  Polygon as PolygonEntity, Role, TrialLine)

from . import layout as L
from .paper import Circle, Command, Line, Polygon, Polyline, Rect, command_points, translated
from .style import area_style_for, line_style_for

ARROW_LEN = 3.5
ARROW_HALF = 0.9
TRIAL_EXT = 10.0        # trial lines run 10 mm past the furthest point of their diagram on them
TRIAL_LONE = 20.0
PIN_R = 1.2
DOT_R = 0.55
BLOCK_L = 10.0
BLOCK_H = 6.0
RAIL_EXT = 12.0
HATCH_STEP = 1.6
HATCH_LEN = 1.8
ON_LINE = 1e-3          # mm: a point this close to a trial line lies on it

Pt = tuple[float, float]


@dataclass
class LabelReq:
    kind: str                       # point, arrow, trial, polygon
    markup: str
    anchor: Pt
    mandatory: bool
    name: str
    r0: float = 0.0                 # radius of the symbol drawn at the anchor
    other: Pt | None = None         # arrow tail / trial far end
    pivot_digits: bool = False


@dataclass
class Drawing:
    layers: dict[int, list[Command]] = field(default_factory=dict)
    labels: list[LabelReq] = field(default_factory=list)
    hard: list[Rect] = field(default_factory=list)
    segments: list[tuple[Pt, Pt, bool]] = field(default_factory=list)     # (a, b, thick)

    def add(self, layer: int, cmd: Command) -> None:
        self.layers.setdefault(layer, []).append(cmd)
        thick = getattr(cmd, "style", "") in THICK_STYLES
        if isinstance(cmd, Line):
            self.segments.append(((cmd.x1, cmd.y1), (cmd.x2, cmd.y2), thick))
        elif isinstance(cmd, (Polyline, Polygon)) and cmd.style not in ("arrowhead", "dot"):
            pts = list(cmd.points) + ([cmd.points[0]] if isinstance(cmd, Polygon) else [])
            self.segments.extend((a, b, thick) for a, b in zip(pts[:-1], pts[1:]))

    @property
    def commands(self) -> list[Command]:
        return [c for k in sorted(self.layers) for c in self.layers[k]]

    def bbox(self) -> Rect | None:
        pts = [p for c in self.commands for p in command_points(c)]
        return Rect.bounding(pts) if pts else None

    def moved(self, dx: float, dy: float) -> "Drawing":
        d = Drawing({k: [translated(c, dx, dy) for c in v] for k, v in self.layers.items()})
        d.labels = [LabelReq(r.kind, r.markup, (r.anchor[0] + dx, r.anchor[1] + dy), r.mandatory, r.name, r.r0,
                             None if r.other is None else (r.other[0] + dx, r.other[1] + dy), r.pivot_digits)
                    for r in self.labels]
        d.hard = [h.translated(dx, dy) for h in self.hard]
        d.segments = [((a[0] + dx, a[1] + dy), (b[0] + dx, b[1] + dy), t) for a, b, t in self.segments]
        return d


THICK_STYLES = frozenset({"vector", "link", "guide"})

# layers, bottom to top
IMAGES, PATHS, TRIALS, LINKS, BLOCKS, SHAFTS, HEADS, PINS, DOTS = range(9)


def unit_vector(v: Pt) -> Pt:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def shifted(p: Pt, v: Pt, k: float = 1.0) -> Pt:
    return (p[0] + v[0] * k, p[1] + v[1] * k)


def _dist(a: Pt, b: Pt) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def angle_gap(a: float, b: float) -> float:
    d = abs(a - b) % (2 * math.pi)
    return min(d, 2 * math.pi - d)


def incident_directions(p: Pt, segments: Sequence[tuple], tol: float = 0.05) -> list[float]:
    """Paper angles (atan2 of y-down vectors) of the lines that leave ``p``."""
    out = []
    for a, b, *_ in segments:
        ab = (b[0] - a[0], b[1] - a[1])
        n = math.hypot(*ab)
        if n < 1e-9:
            continue
        t = ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / (n * n)
        if t < -tol / n or t > 1 + tol / n:
            continue
        foot = (a[0] + ab[0] * t, a[1] + ab[1] * t)
        if _dist(foot, p) > tol:
            continue
        if t * n > tol:
            out.append(math.atan2(a[1] - p[1], a[0] - p[0]))
        if (1 - t) * n > tol:
            out.append(math.atan2(b[1] - p[1], b[0] - p[0]))
    return out


def arrowhead(tail: Pt, tip: Pt, name: str) -> tuple[Polygon, Pt]:
    """A filled arrowhead with its apex exactly at ``tip``; returns it and where the shaft stops."""
    length = _dist(tail, tip)
    hl = min(ARROW_LEN, 0.5 * length)
    hw = ARROW_HALF * hl / ARROW_LEN
    u = unit_vector((tip[0] - tail[0], tip[1] - tail[1]))
    n = (-u[1], u[0])
    base = shifted(tip, u, -hl)
    poly = Polygon((tip, shifted(base, n, hw), shifted(base, n, -hw)), "arrowhead", f"{name}:head")
    return poly, shifted(tip, u, -0.8 * hl)


def model_points(entities: Sequence[Entity]) -> list[Vec]:
    pts: list[Vec] = []
    for e in entities:
        if isinstance(e, (Point, Pivot)):
            pts.append(e.at)
        elif isinstance(e, Arrow):
            pts += [e.tail, e.tip]
        elif isinstance(e, Bar):
            pts += [e.start, e.end]
        elif isinstance(e, (Plate, PolygonEntity)):
            pts += list(e.vertices)
        elif isinstance(e, TrialLine):
            pts.append(e.through)
        elif isinstance(e, Block):
            pts.append(e.at)
    return pts


def _nonzero(v: Vec) -> bool:
    return math.isfinite(v.x) and math.isfinite(v.y) and math.hypot(v.x, v.y) > 0


def draw_entities(entities: Sequence[Entity], k: float) -> Drawing:
    """Every entity of one diagram drawn at ``k`` paper mm per model unit, model origin at (0, 0)."""
    T = L.Transform(k)
    d = Drawing()
    model_pts = model_points(entities)
    paper_pts = [T(p) for p in model_pts]
    trials = [e for e in entities if isinstance(e, TrialLine) and _nonzero(e.direction)]
    # the crossings of trial lines are points of the diagram that lie on them
    for i, a in enumerate(trials):
        for b in trials[i + 1:]:
            s = a.direction.cross(b.direction)
            if abs(s) > 1e-12 * a.direction.norm() * b.direction.norm():
                t = (b.through - a.through).cross(b.direction) / s
                paper_pts.append(T(a.through + a.direction * t))
    pivots = [T(e.at) for e in entities if isinstance(e, Pivot)]
    bars = [(T(e.start), T(e.end)) for e in entities if isinstance(e, Bar)]
    centroid = (sum(p[0] for p in paper_pts) / len(paper_pts), sum(p[1] for p in paper_pts) / len(paper_pts)) \
        if paper_pts else (0.0, 0.0)
    pins: list[Pt] = []

    def add_pin(p: Pt) -> None:
        if all(_dist(p, q) > 0.01 for q in pins + pivots):
            pins.append(p)

    for e in entities:
        if isinstance(e, Bar):
            a, b = T(e.start), T(e.end)
            d.add(LINKS, Line(*a, *b, line_style_for(e.role), e.name))
            add_pin(a)
            add_pin(b)
        elif isinstance(e, Plate):
            d.add(LINKS, Polygon(tuple(T(v) for v in e.vertices), "link", e.name))
        elif isinstance(e, Block) and _nonzero(e.direction):
            c = T(e.at)
            u = T.direction(e.direction)
            n = (-u[1], u[0])
            corners = tuple(shifted(shifted(c, u, su * BLOCK_L / 2), n, sn * BLOCK_H / 2)
                            for su, sn in ((1, 1), (-1, 1), (-1, -1), (1, -1)))
            d.add(BLOCKS, Polygon(corners, "block", e.name))
            d.hard.append(Rect.bounding(corners))
            add_pin(c)
    for e in entities:
        if isinstance(e, Pivot):
            _draw_pivot(d, T(e.at), bars, e.name)
        elif isinstance(e, Guide) and _nonzero(e.direction):
            blocks = [T(b.at) for b in entities if isinstance(b, Block)]
            _draw_guide(d, T(e.through), T.direction(e.direction), blocks, paper_pts, centroid, e.name)
        elif isinstance(e, Arc):
            _draw_arc(d, e, T)
        elif isinstance(e, PolygonEntity):
            pts = tuple(T(v) for v in e.vertices)
            d.add(IMAGES, Polygon(pts, area_style_for(e.role), e.name))
            if e.label:
                c = (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
                d.labels.append(LabelReq("polygon", e.label, c, False, e.name))
        elif isinstance(e, TrialLine) and _nonzero(e.direction):
            _draw_trial(d, e, T, paper_pts)
        elif isinstance(e, Arrow):
            tail, tip = T(e.tail), T(e.tip)
            if _dist(tail, tip) < 1e-6:
                continue
            head, stop = arrowhead(tail, tip, e.name)
            d.add(SHAFTS, Line(*tail, *stop, line_style_for(e.role) if e.role in (Role.KNOWN, Role.RESULT)
                               else "vector", e.name))
            d.layers.setdefault(HEADS, []).append(head)
            d.hard.append(Rect.bounding(head.points))
            if e.label:
                d.labels.append(LabelReq("arrow", e.label, tip, False, e.name, other=tail))
    for p in pins:
        d.add(PINS, Circle(*p, PIN_R, "pin", "pin"))
        d.hard.append(Rect(p[0] - PIN_R, p[1] - PIN_R, 2 * PIN_R, 2 * PIN_R))
    marks = pins + pivots
    for e in entities:
        if isinstance(e, Point):
            p = T(e.at)
            r0 = DOT_R
            if any(_dist(p, q) < 0.01 for q in marks):
                r0 = PIN_R + 0.25
            else:
                d.add(DOTS, Circle(*p, DOT_R, "dot", e.name))
                d.hard.append(Rect(p[0] - DOT_R, p[1] - DOT_R, 2 * DOT_R, 2 * DOT_R))
            if e.label:
                d.labels.append(LabelReq("point", e.label, p, True, e.name, r0=r0, pivot_digits=True))
        elif isinstance(e, Pivot) and e.label:
            d.labels.append(LabelReq("point", e.label, T(e.at), True, e.name, r0=PIN_R + 0.25, pivot_digits=True))
    return d


def _draw_pivot(d: Drawing, p: Pt, bars: Sequence[tuple[Pt, Pt]], name: str) -> None:
    """A fixed pivot: pin, ground triangle, ground line and hatching, turned away from its links."""
    inc = incident_directions(p, bars)
    best, best_gap = (0.0, 1.0), -1.0
    for cand in ((0.0, 1.0), (-1.0, 0.0), (1.0, 0.0), (0.0, -1.0)):
        a = math.atan2(cand[1], cand[0])
        gap = min((angle_gap(a, b) for b in inc), default=math.pi)
        if gap > best_gap + 1e-9:
            best, best_gap = cand, gap
    u = best
    n = (-u[1], u[0])
    c = shifted(p, u, 4.0)
    tri = (p, shifted(c, n, 3.0), shifted(c, n, -3.0))
    d.add(PINS, Polygon(tri, "ground", f"{name}:ground"))
    a, b = shifted(c, n, -4.5), shifted(c, n, 4.5)
    d.add(PINS, Line(*a, *b, "link", f"{name}:ground line"))
    pts = list(tri) + [a, b]
    s = -4.5 + HATCH_STEP / 2
    while s <= 4.5:
        q = shifted(c, n, s)
        r = shifted(shifted(q, u, HATCH_LEN), n, -HATCH_LEN)
        d.add(PINS, Line(*q, *r, "hatch", f"{name}:hatch"))
        pts.append(r)
        s += HATCH_STEP
    d.add(PINS, Circle(*p, PIN_R, "pin", f"{name}:pin"))
    d.hard.append(Rect.bounding(pts))


def _hatched_line(d: Drawing, a: Pt, b: Pt, side: Pt, name: str) -> None:
    d.add(LINKS, Line(*a, *b, "guide", name))
    u = unit_vector((b[0] - a[0], b[1] - a[1]))
    length = _dist(a, b)
    s = HATCH_STEP / 2
    while s < length:
        q = shifted(a, u, s)
        r = shifted(shifted(q, side, HATCH_LEN), u, -HATCH_LEN)
        d.add(LINKS, Line(*q, *r, "hatch", f"{name}:hatch"))
        s += HATCH_STEP


def _draw_guide(d: Drawing, g: Pt, u: Pt, blocks: Sequence[Pt], pts: Sequence[Pt], centroid: Pt, name: str) -> None:
    n = (-u[1], u[0])

    def t_of(p: Pt) -> float:
        return (p[0] - g[0]) * u[0] + (p[1] - g[1]) * u[1]

    def off(p: Pt) -> float:
        return (p[0] - g[0]) * n[0] + (p[1] - g[1]) * n[1]

    on = [b for b in blocks if abs(off(b)) < 0.05]
    if on:
        ts = [t_of(b) for b in on] + [0.0]
        a, b = shifted(g, u, min(ts) - 8.0), shifted(g, u, max(ts) + BLOCK_L / 2 + 8.0)
        d.add(PATHS, Line(*a, *b, "centre", f"{name}:centre line"))
        for blk in on:
            t0 = t_of(blk)
            for sn in (1.0, -1.0):
                off_v = (n[0] * sn * BLOCK_H / 2, n[1] * sn * BLOCK_H / 2)
                p1 = shifted(shifted(g, u, t0 - BLOCK_L / 2 - RAIL_EXT), off_v)
                p2 = shifted(shifted(g, u, t0 + BLOCK_L / 2 + RAIL_EXT), off_v)
                _hatched_line(d, p1, p2, (n[0] * sn, n[1] * sn), f"{name}:rail")
    else:
        ts = [t_of(p) for p in pts] or [0.0]
        a, b = shifted(g, u, min(ts) - 8.0), shifted(g, u, max(ts) + 8.0)
        side = -1.0 if off(centroid) > 0 else 1.0
        _hatched_line(d, a, b, (n[0] * side, n[1] * side), name)


def _draw_arc(d: Drawing, e: Arc, T: L.Transform) -> None:
    span = e.end_angle - e.start_angle
    if not (e.radius > 0 and math.isfinite(span)):
        return
    segs = int(min(200, max(8, math.ceil(abs(span) * e.radius * T.k / 1.0))))
    pts = tuple(T(e.center + Vec.polar(e.radius, e.start_angle + span * i / segs)) for i in range(segs + 1))
    d.add(PATHS, Polyline(pts, line_style_for(e.role), e.name))


def _draw_trial(d: Drawing, e: TrialLine, T: L.Transform, pts: Sequence[Pt]) -> None:
    g = T(e.through)
    u = T.direction(e.direction)
    ts = [0.0]
    for p in pts:
        v = (p[0] - g[0], p[1] - g[1])
        if abs(u[0] * v[1] - u[1] * v[0]) < ON_LINE:
            ts.append(u[0] * v[0] + u[1] * v[1])
    lo, hi = min(ts), max(ts)
    if hi - lo < 1e-6:
        lo, hi = lo - TRIAL_LONE, hi + TRIAL_LONE
    else:
        lo, hi = lo - TRIAL_EXT, hi + TRIAL_EXT
    a, b = shifted(g, u, lo), shifted(g, u, hi)
    d.add(TRIALS, Line(*a, *b, line_style_for(e.role), e.name))
    if e.label:
        d.labels.append(LabelReq("trial", e.label, b, False, e.name, other=a))
