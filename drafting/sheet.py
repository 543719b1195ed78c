"""A sheet: a Construction laid out on paper as drawing commands.

``compose_sheet(construction, info, results)`` is the whole pipeline up to the recording back end:
it draws every entity of every diagram in its viewport (the space diagram at an ISO 5455 scale chosen
to fit, each vector polygon at the scale its construction chose), places the labels, sets the vector
equations, the numbered steps, the results table and the notes, and fills in the title block.  The
result is a :class:`Sheet`: the paper, a tuple of drawing commands in paper mm (y down) and named
regions, so tests can check what is drawn without rendering.  :mod:`drafting.svg` renders it.
"""

from __future__ import annotations

import datetime as _dt
import functools
import math
import re
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping, Sequence

from constructions.geometry import Vec
from constructions.record import (Arc, Arrow, Bar, Block, Construction, Diagram, Entity, Guide, Pivot,
                                  Plate, Point, Polygon as PolygonEntity, Role, ScaleBar, TrialLine)

from . import layout as L
from .layout import LayoutError
from .paper import (Circle, Command, Line, Paper, Polygon, Polyline, Rect, Rectangle, Text, command_points,
                    paper as make_paper, translated)
from .style import LABEL, area_style_for, line_style_for, measure, rich

__all__ = ["ResultRow", "SheetInfo", "Sheet", "compose_sheet", "LayoutError"]


@dataclass(frozen=True)
class ResultRow:
    """One line of the results table: the value read off the construction and the analytic one."""

    quantity: str
    graphical: str
    analytic: str
    difference: str
    note: str = ""


def _today() -> str:
    return _dt.date.today().isoformat()


@dataclass(frozen=True)
class SheetInfo:
    """What the title block says, and the sheet's paper."""

    title: str
    drawing_number: str
    paper: str = "A4"
    orientation: str = "landscape"
    date: str = field(default_factory=_today)
    sheet: tuple[int, int] = (1, 1)
    units: str = "mm, mm/s, rad/s"
    created_by: str = "drafting"
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        n, m = self.sheet
        if not (1 <= n <= m):
            raise ValueError(f"sheet {n} of {m} is not a sheet number")


@dataclass(frozen=True)
class Sheet:
    """A composed sheet: paper, drawing commands (paper mm, y down) and named regions."""

    paper: Paper
    commands: tuple[Command, ...]
    regions: Mapping[str, Rect] = field(default_factory=dict, compare=False)
    scales: tuple[tuple[str, str], ...] = ()
    text_size: float = LABEL
    transforms: Mapping[str, L.Transform] = field(default_factory=dict, compare=False)
    """Model -> paper transform of each viewport ("space", "velocity" ...)."""

    @property
    def width(self) -> float:
        return self.paper.width

    @property
    def height(self) -> float:
        return self.paper.height

    def texts(self) -> tuple[Text, ...]:
        return tuple(c for c in self.commands if isinstance(c, Text))

    def named(self, prefix: str) -> tuple[Command, ...]:
        return tuple(c for c in self.commands if c.name.startswith(prefix))


# ---- units --------------------------------------------------------------------------------------

_VECTOR = {
    Diagram.VELOCITY: ("velocity", "Velocity polygon", "m/s", "mm/s"),
    Diagram.ACCELERATION: ("acceleration", "Acceleration polygon", "m/s^2", "mm/s^2"),
    Diagram.FORCE: ("force", "Force polygon", "N", "N"),
}
_ACCEL = re.compile(r"/\s*s\s*(\^\s*2|\*\*\s*2|2|\u00b2)")


def display_unit(units: str, kind: str) -> str:
    """The unit a vector scale is written in, taken from SheetInfo.units."""
    tokens = [t.strip() for t in re.split(r"[,;]", units) if t.strip()]
    for t in tokens:
        if "rad" in t:
            continue
        if kind == "velocity" and "/s" in t and not _ACCEL.search(t):
            return t
        if kind == "acceleration" and _ACCEL.search(t):
            return t
        if kind == "force" and re.fullmatch(r"[kMm]?N", t):
            return t
    return {"velocity": "mm/s", "acceleration": "mm/s^2", "force": "N"}[kind]


@functools.cache
def _unit_factor(si_unit: str, unit: str) -> float:
    """How many ``unit`` make one ``si_unit``."""
    from .units import registry
    q = registry().Quantity(1.0, si_unit)
    try:
        return float(q.to(unit.replace("\u00b2", "^2")).magnitude)
    except Exception as e:
        raise ValueError(f"the sheet unit {unit!r} cannot express a {si_unit} quantity") from e


# ---- drawing the entities of a diagram -----------------------------------------------------------

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
VIEW_PAD = 7.0          # room around a drawing for its labels
LABEL_PAD = 0.4         # white margin of a label's background
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


def _unit(v: Pt) -> Pt:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def _add(p: Pt, v: Pt, k: float = 1.0) -> Pt:
    return (p[0] + v[0] * k, p[1] + v[1] * k)


def _dist(a: Pt, b: Pt) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def _angle_gap(a: float, b: float) -> float:
    d = abs(a - b) % (2 * math.pi)
    return min(d, 2 * math.pi - d)


def _incident(p: Pt, segments: Sequence[tuple], tol: float = 0.05) -> list[float]:
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
    u = _unit((tip[0] - tail[0], tip[1] - tail[1]))
    n = (-u[1], u[0])
    base = _add(tip, u, -hl)
    poly = Polygon((tip, _add(base, n, hw), _add(base, n, -hw)), "arrowhead", f"{name}:head")
    return poly, _add(tip, u, -0.8 * hl)


def _model_points(entities: Sequence[Entity]) -> list[Vec]:
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
    model_pts = _model_points(entities)
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
            corners = tuple(_add(_add(c, u, su * BLOCK_L / 2), n, sn * BLOCK_H / 2)
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
    inc = _incident(p, bars)
    best, best_gap = (0.0, 1.0), -1.0
    for cand in ((0.0, 1.0), (-1.0, 0.0), (1.0, 0.0), (0.0, -1.0)):
        a = math.atan2(cand[1], cand[0])
        gap = min((_angle_gap(a, b) for b in inc), default=math.pi)
        if gap > best_gap + 1e-9:
            best, best_gap = cand, gap
    u = best
    n = (-u[1], u[0])
    c = _add(p, u, 4.0)
    tri = (p, _add(c, n, 3.0), _add(c, n, -3.0))
    d.add(PINS, Polygon(tri, "ground", f"{name}:ground"))
    a, b = _add(c, n, -4.5), _add(c, n, 4.5)
    d.add(PINS, Line(*a, *b, "link", f"{name}:ground line"))
    pts = list(tri) + [a, b]
    s = -4.5 + HATCH_STEP / 2
    while s <= 4.5:
        q = _add(c, n, s)
        r = _add(_add(q, u, HATCH_LEN), n, -HATCH_LEN)
        d.add(PINS, Line(*q, *r, "hatch", f"{name}:hatch"))
        pts.append(r)
        s += HATCH_STEP
    d.add(PINS, Circle(*p, PIN_R, "pin", f"{name}:pin"))
    d.hard.append(Rect.bounding(pts))


def _hatched_line(d: Drawing, a: Pt, b: Pt, side: Pt, name: str) -> None:
    d.add(LINKS, Line(*a, *b, "guide", name))
    u = _unit((b[0] - a[0], b[1] - a[1]))
    length = _dist(a, b)
    s = HATCH_STEP / 2
    while s < length:
        q = _add(a, u, s)
        r = _add(_add(q, side, HATCH_LEN), u, -HATCH_LEN)
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
        a, b = _add(g, u, min(ts) - 8.0), _add(g, u, max(ts) + BLOCK_L / 2 + 8.0)
        d.add(PATHS, Line(*a, *b, "centre", f"{name}:centre line"))
        for blk in on:
            t0 = t_of(blk)
            for sn in (1.0, -1.0):
                off_v = (n[0] * sn * BLOCK_H / 2, n[1] * sn * BLOCK_H / 2)
                p1 = _add(_add(g, u, t0 - BLOCK_L / 2 - RAIL_EXT), off_v)
                p2 = _add(_add(g, u, t0 + BLOCK_L / 2 + RAIL_EXT), off_v)
                _hatched_line(d, p1, p2, (n[0] * sn, n[1] * sn), f"{name}:rail")
    else:
        ts = [t_of(p) for p in pts] or [0.0]
        a, b = _add(g, u, min(ts) - 8.0), _add(g, u, max(ts) + 8.0)
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
    a, b = _add(g, u, lo), _add(g, u, hi)
    d.add(TRIALS, Line(*a, *b, line_style_for(e.role), e.name))
    if e.label:
        d.labels.append(LabelReq("trial", e.label, b, False, e.name, other=a))


# ---- labels -------------------------------------------------------------------------------------

def _clip_len(a: Pt, b: Pt, r: Rect) -> float:
    """Length of segment ab inside rectangle r (Liang-Barsky)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, a[0] - r.left), (dx, r.right - a[0]), (-dy, a[1] - r.top), (dy, r.bottom - a[1])):
        if abs(p) < 1e-12:
            if q < 0:
                return 0.0
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return 0.0
    return (t1 - t0) * math.hypot(dx, dy)


def _edge(u: Pt, hw: float, hh: float) -> float:
    """Distance from a box centre to its edge along unit ``u``."""
    cands = []
    if abs(u[0]) > 1e-9:
        cands.append(hw / abs(u[0]))
    if abs(u[1]) > 1e-9:
        cands.append(hh / abs(u[1]))
    return min(cands)


def _candidates(req: LabelReq, hw: float, hh: float, incident: list[float], relax: int):
    """(centre, cost) candidates for a label box of half sizes hw, hh."""
    dists = (0.7, 1.6, 3.0, 4.5) if relax == 0 else (6.0, 8.0, 11.0, 15.0)
    p = req.anchor
    if req.kind in ("point", "polygon"):
        if req.kind == "polygon" and relax == 0:
            yield p, 0.0
        for di, dist in enumerate(dists):
            for i in range(16):
                a = 2 * math.pi * i / 16
                u = (math.cos(a), -math.sin(a))                # a measured CCW as seen on paper
                ap = math.atan2(u[1], u[0])
                gap = min((_angle_gap(ap, b) for b in incident), default=math.pi)
                t = req.r0 + dist + _edge(u, hw, hh)
                cost = 2.0 * (math.pi - gap) + 0.8 * dist + 0.05 * _angle_gap(a, math.pi / 4)
                yield _add(p, u, t), cost
    elif req.kind == "arrow":
        tail, tip = req.other, req.anchor
        v = (tip[0] - tail[0], tip[1] - tail[1])
        u = _unit(v)
        n = (-u[1], u[0])
        for dist in dists[:3] if relax == 0 else dists:
            for f in (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8):
                a = _add(tail, v, f)
                for side in (1.0, -1.0):
                    nn = (n[0] * side, n[1] * side)
                    yield _add(a, nn, dist + 0.3 + _edge(nn, hw, hh)), 3.0 * abs(f - 0.5) + 0.8 * dist + (side < 0) * 0.1
    elif req.kind == "trial":
        end, start = req.anchor, req.other
        v = _unit((start[0] - end[0], start[1] - end[1]))
        n = (-v[1], v[0])
        for dist in dists[:3] if relax == 0 else dists:
            for s in (3.0, 6.0, 10.0, 15.0, 22.0):
                a = _add(end, v, s)
                for side in (1.0, -1.0):
                    nn = (n[0] * side, n[1] * side)
                    yield _add(a, nn, dist + _edge(nn, hw, hh)), 0.1 * s + 0.8 * dist
                    # the other end of the line as well
                    b = _add(start, v, -s)
                    yield _add(b, nn, dist + _edge(nn, hw, hh)), 0.1 * s + 0.8 * dist + 1.0


def place_labels(d: Drawing, plot: Rect, region: str, size: float = LABEL) -> list[Command]:
    """Put every label where it overlaps no other label, arrowhead or symbol, inside ``plot``.

    A small candidate search: positions around the anchor are scored by how much line they would
    cover (a white background hides it) and how well they sit in the widest gap between the lines at
    the anchor; overlaps with labels, arrowheads, pins and dots are forbidden.  Optional labels
    (on arrows, trial lines and images) are left out when no free place exists.
    """
    placed: list[Rect] = []
    out: list[Command] = []
    order = sorted(range(len(d.labels)), key=lambda i: (not d.labels[i].mandatory,
                                                        ["point", "arrow", "trial", "polygon"].index(d.labels[i].kind)))
    for i in order:
        req = d.labels[i]
        spans = rich(req.markup, size, pivot_digits=req.pivot_digits)
        ext = measure(spans)
        hw, hh = ext.width / 2 + LABEL_PAD, ext.height / 2 + LABEL_PAD
        incident = _incident(req.anchor, d.segments) if req.kind == "point" else []
        best = None
        for relax in (0, 1):
            for centre, cost in _candidates(req, hw, hh, incident, relax):
                box = Rect(centre[0] - hw, centre[1] - hh, 2 * hw, 2 * hh)
                if not plot.contains(box):
                    continue
                if any(box.overlaps(o, 0.3) for o in placed) or any(box.overlaps(o, 0.2) for o in d.hard):
                    continue
                thin = thick = 0.0
                for a, b, heavy in d.segments:
                    ln = _clip_len(a, b, box)
                    if heavy:
                        thick += ln
                    else:
                        thin += ln
                if thick > 0 and not req.mandatory:
                    continue                      # an optional label never hides part of a thick line
                total = cost + 3.0 * thin + 20.0 * thick
                if best is None or total < best[0]:
                    best = (total, centre, box)
            if best is not None:
                break
        if best is None:
            if not req.mandatory:
                continue
            # last resort: the nearest position inside the plot that overlaps no other label
            for relax in (0, 1):
                for centre, cost in _candidates(req, hw, hh, incident, relax):
                    box = Rect(centre[0] - hw, centre[1] - hh, 2 * hw, 2 * hh)
                    if plot.contains(box) and not any(box.overlaps(o, 0.3) for o in placed):
                        if best is None or cost < best[0]:
                            best = (cost, centre, box)
            if best is None:
                raise LayoutError(f"no room for the label {req.markup!r} in the {region} viewport; use A3")
        _, centre, box = best
        placed.append(box)
        x = centre[0] - ext.width / 2
        y = centre[1] - (ext.top + ext.bottom) / 2
        out.append(Rectangle(box.x, box.y, box.w, box.h, "label_bg", f"{req.name}:label bg"))
        out.append(Text(x, y, spans, "label", ext.box(x, y), region, f"{req.name}:label"))
    return out


# ---- viewports ----------------------------------------------------------------------------------

@dataclass(frozen=True)
class DiagramSpec:
    key: str                        # region key: "space", "velocity" ...
    heading: str
    entities: tuple[Entity, ...]
    scale_text: str                 # for the title block
    unit: str                       # unit of the scale bar
    paper_per_unit: float           # paper mm per unit of the scale bar
    k: float                        # paper mm per model (SI) unit


def _fit_space(entities: tuple[Entity, ...], w: float, h: float):
    """The largest ISO 5455 scale at which the space diagram fits a w x h viewport."""
    for ratio in L.ISO_5455:
        k = 1000.0 * L.ratio_factor(ratio)
        dr = draw_entities(entities, k)
        bb = dr.bbox()
        if bb is None:
            continue
        heading = f"Space diagram {L.ratio_text(ratio)}"
        try:
            hh = L.header_height(w, heading, L.ratio_factor(ratio), "mm")
        except LayoutError:
            continue
        need_w = bb.w + 2 * VIEW_PAD + 2
        need_h = bb.h + 2 * VIEW_PAD + 2 + hh
        if need_w <= w and need_h <= h:
            return ratio, need_h
    return None


def _vector_spec(diagram: Diagram, entities: tuple[Entity, ...], units: str) -> DiagramSpec:
    kind, heading, si_unit, _ = _VECTOR[diagram]
    scale = next((e for e in entities if isinstance(e, ScaleBar)), None)
    if scale is not None and scale.units_per_mm > 0 and math.isfinite(scale.units_per_mm):
        upm = scale.units_per_mm
    else:
        pts = _model_points(entities) or [Vec(0, 0)]
        ext = max(max(p.x for p in pts) - min(p.x for p in pts), max(p.y for p in pts) - min(p.y for p in pts), 1e-300)
        upm = next(v for v in L.nice_values(ext / 110.0, ext / 110.0 * 10.1))
    unit = display_unit(units, kind)
    f = _unit_factor(si_unit, unit)
    per_mm = upm * f
    shown = re.sub(r"\^\s*2|\*\*\s*2", "\u00b2", unit)          # mm/s^2 is printed mm/s²
    return DiagramSpec(diagram.value, heading, entities, f"{kind} 1 mm = {L.number_text(per_mm)} {shown}",
                       shown, 1.0 / per_mm, 1.0 / upm)


def _render_viewport(spec: DiagramSpec, rect: Rect, region: str) -> tuple[list[Command], L.Transform]:
    header = L.viewport_header(rect, spec.heading, spec.paper_per_unit, spec.unit, region=region, name=spec.key)
    plot = Rect.from_edges(rect.x + 1.0, rect.y + header.height, rect.right - 1.0, rect.bottom - 1.0)
    dr = draw_entities(spec.entities, spec.k)
    bb = dr.bbox()
    cmds: list[Command] = list(header.commands)
    if bb is None:
        return cmds, L.Transform(spec.k, plot.center[0], plot.center[1])
    if bb.w + 2 * VIEW_PAD > plot.w + 1e-6 or bb.h + 2 * VIEW_PAD > plot.h + 1e-6:
        raise LayoutError(f"the {spec.heading.lower()} needs {bb.w + 2 * VIEW_PAD:.0f} x "
                          f"{bb.h + 2 * VIEW_PAD:.0f} mm and its viewport has {plot.w:.0f} x {plot.h:.0f} mm; "
                          f"use A3")
    dx = plot.center[0] - (bb.x + bb.w / 2)
    dy = plot.center[1] - (bb.y + bb.h / 2)
    moved = dr.moved(dx, dy)
    cmds.extend(moved.commands)
    cmds.extend(place_labels(moved, plot, region))
    return cmds, L.Transform(spec.k, dx, dy)


# ---- the sheet ----------------------------------------------------------------------------------

def _sections(construction: Construction, results: Sequence[ResultRow], notes: Sequence[str]) -> list[L.Section]:
    secs: list[L.Section] = []
    eqs = []
    for eq in construction.equations:
        if eq not in eqs:
            eqs.append(eq)
    if eqs:
        items: list[L.Item] = [L.EquationItem(eq, name=f"equation {i + 1}") for i, eq in enumerate(eqs)]
        items.append(L.Paragraph(f"Marks over each vector: magnitude, then direction; "
                                 f"{L.MARK_YES} known, {L.MARK_NO} unknown.", name="equation legend"))
        secs.append(L.Section("Vector equations", tuple(items)))
    steps = [s for s in construction.steps if s.caption.strip()]
    if steps:
        n = len(steps)
        secs.append(L.Section("Construction", tuple(
            L.Paragraph(s.caption.strip(), label=f"{i + 1}.", label_chars=f"{n}.", name=f"step {i + 1}")
            for i, s in enumerate(steps))))
    if results:
        has_note = any(r.note for r in results)
        header = ("Quantity", "Graphical", "Analytic", "Difference") + (("Note",) if has_note else ())
        rows = tuple((r.quantity, r.graphical, r.analytic, r.difference) + ((r.note,) if has_note else ())
                     for r in results)
        align = ("l", "r", "r", "r") + (("l",) if has_note else ())
        secs.append(L.Section("Results", (L.TableItem(header, rows, align, wrap_last=has_note),)))
    if notes:
        secs.append(L.Section("Notes", tuple(
            L.Paragraph(t, label="\u2013", label_chars="\u2013", name=f"note {i + 1}") for i, t in enumerate(notes))))
    return secs


def compose_sheet(construction: Construction, info: SheetInfo, results: Sequence[ResultRow] = ()) -> Sheet:
    """Lay out ``construction`` with its ``results`` on the sheet described by ``info``.

    Raises :class:`LayoutError` when the content does not fit even with 2.5 mm lettering; on A4 the
    message says to use A3.
    """
    pp = make_paper(info.paper, info.orientation)
    try:
        return _compose(construction, info, results, pp)
    except LayoutError as e:
        msg = str(e)
        if pp.name != "A4":                       # A3 is the largest sheet: advise what is left
            msg = re.sub(r"use A3( or landscape)?$", "it does not fit even on A3; split the content over "
                         "more sheets or draw the polygon at a coarser scale", msg)
        raise LayoutError(msg[:1].upper() + msg[1:] + ("" if msg.endswith(".") else ".")) from None


COMFORTABLE_LETTERING = 3.0
"""Lettering below this is taken only when nothing else fits."""


def _best_plan(pp: Paper, tb_height, space_need, vec_needs, space_entities, sections, construction, results):
    """The layout plan and its space scale and text flow.

    Landscape sheets try the default text column and the narrowest one: a narrower column can let the
    space diagram go up an ISO scale (1:2 -> 1:1 on A4 for the notes' slider-crank), which is worth it
    when the text keeps its lettering size, or -- to bring a reduced space diagram up towards true
    scale -- when it stays at least COMFORTABLE_LETTERING.
    """
    if pp.orientation == "landscape":
        plans = [L.plan_landscape(pp, tb_height, space_need, vec_needs),
                 L.plan_landscape(pp, tb_height, space_need, vec_needs, text_width=L.TEXT_COL_MIN)]
    else:
        plans = [L.plan_portrait(pp, tb_height, space_need, vec_needs)]
    options = []
    space_misfit = None
    for plan in plans:
        ratio = None
        if space_entities:
            r = plan.viewports["space"]  # the scale is the same if the viewport later takes an empty slot
            got = _fit_space(space_entities, r.w, r.h)
            if got is None:
                space_misfit = space_misfit or (f"the space diagram does not fit its {r.w:.0f} x {r.h:.0f} mm "
                                                f"viewport on {pp.name} {pp.orientation}; use A3")
                continue
            ratio = got[0]
        # text: equations, steps, results, notes -- shrunk from 3.5 to 2.5 mm until they fit
        slots = [(name, r) for name, r in plan.text_slots if r.w > 20 and r.h > 10]
        flowed = L.flow_shrinking(sections, slots)
        if flowed is None:
            continue
        options.append((plan, ratio, slots, flowed))
    if not options and space_misfit:
        raise LayoutError(space_misfit)
    if not options:
        raise LayoutError(f"the equations, {len(construction.steps)} steps and {len(results)} result rows do "
                          f"not fit on {pp.name} {pp.orientation} even with 2.5 mm lettering; use A3")
    first = options[0]
    first_size = first[3][1]
    reduced = first[1] is not None and L.ratio_factor(first[1]) < 1.0

    def acceptable(o) -> bool:
        size = o[3][1]
        return o is first or size >= first_size - 1e-9 or (reduced and size >= COMFORTABLE_LETTERING - 1e-9)
    readable = [o for o in options if acceptable(o)]
    return max(readable, key=lambda o: (L.ratio_factor(o[1]) if o[1] else 0.0, o[3][1]))


def _compose(construction: Construction, info: SheetInfo, results: Sequence[ResultRow], pp: Paper) -> Sheet:
    frame = pp.frame
    space_entities = tuple(e for e in construction.entities(Diagram.SPACE) if not isinstance(e, ScaleBar))
    vector_specs = [
        _vector_spec(dg, tuple(construction.entities(dg)), info.units)
        for dg in (Diagram.VELOCITY, Diagram.ACCELERATION, Diagram.FORCE)
        if any(not isinstance(e, ScaleBar) for e in construction.entities(dg))
    ]
    # what each vector viewport needs at its fixed scale
    vec_needs = []
    for spec in vector_specs:
        bb = draw_entities(spec.entities, spec.k).bbox()
        w = (bb.w if bb else 0.0) + 2 * VIEW_PAD + 2
        h = (bb.h if bb else 0.0) + 2 * VIEW_PAD + 2
        w = max(w, 90.0)
        hh = L.header_height(w, spec.heading, spec.paper_per_unit, spec.unit)
        vec_needs.append(L.ViewportNeed(spec.key, size=(w, h + hh)))
    space_need = None
    if space_entities:
        def size_for_width(w: float, h: float):
            got = _fit_space(space_entities, w, h)
            return None if got is None else (w, got[1])
        space_need = L.ViewportNeed("space", size_for_width=size_for_width)

    def tb_fields(scale_text: str):
        return [[("Scale", scale_text), ("Units", info.units)],
                [("Drawing no.", info.drawing_number), ("Created by", info.created_by), ("Date", info.date),
                 ("Sheet", f"{info.sheet[0]}/{info.sheet[1]}")]]

    # the scale text is not known before the space scale is; size the title block with a long stand-in
    probe_scale = "; ".join(["Space 1:10000"] + [s.scale_text for s in vector_specs])

    def tb_height(width: float) -> float:
        return L.title_block(frame, width, info.title, tb_fields(probe_scale)).rect.h

    sections = _sections(construction, results, info.notes)
    plan, ratio, slots, (text_cmds, size) = _best_plan(pp, tb_height, space_need, vec_needs, space_entities,
                                                       sections, construction, results)

    specs: dict[str, DiagramSpec] = {s.key: s for s in vector_specs}
    scales: list[tuple[str, str]] = []
    if space_entities:
        specs["space"] = DiagramSpec("space", f"Space diagram {L.ratio_text(ratio)}", space_entities,
                                     f"Space {L.ratio_text(ratio)}", "mm", L.ratio_factor(ratio),
                                     1000.0 * L.ratio_factor(ratio))
        scales.append(("space", f"Space {L.ratio_text(ratio)}"))
    scales += [(s.key, s.scale_text) for s in vector_specs]
    scale_text = "; ".join(t for _, t in scales) or "none"

    tb = L.title_block(frame, plan.title_block.w, info.title, tb_fields(scale_text))
    regions: dict[str, Rect] = {"page": pp.page, "frame": frame, "title_block": tb.rect}
    cmds: list[Command] = [Rectangle(frame.x, frame.y, frame.w, frame.h, "frame", "frame")]
    used = {c.region for c in text_cmds if isinstance(c, Text)}
    viewports = dict(plan.viewports)
    separators = list(plan.separators)
    for slot, key, whole, sep in plan.reclaim:
        if slot in used:
            separators.append(sep)
        else:                                    # an empty slot goes back to its viewport
            viewports[key] = whole
            slots = [(n, r) for n, r in slots if n != slot]
    for x1, y1, x2, y2 in separators:
        cmds.append(Line(x1, y1, x2, y2, "separator", "separator"))
    transforms: dict[str, L.Transform] = {}
    for key, rect in viewports.items():
        region = f"viewport:{key}"
        regions[region] = rect
        vc, transforms[key] = _render_viewport(specs[key], rect, region)
        cmds.extend(vc)
    for name, r in slots:
        regions[name] = r
    cmds.extend(text_cmds)
    cmds.extend(tb.commands)
    return Sheet(pp, tuple(cmds), MappingProxyType(regions), tuple(scales), size, MappingProxyType(transforms))
