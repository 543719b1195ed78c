"""One drawer per entity type (see :mod:`drafting.layout.diagram` for the registry and the phases).

Mechanism entities: bars, plates, pivots (ground hatching turned away from their links), guides (rails
either side of a slider block, or a hatched line), blocks, path arcs.  Vector entities: arrows (thick
shaft, filled arrowhead with its apex at the tip), trial lines (thin, run past every point of the diagram
on them), images (light grey), points.  Drafting entities: circles (long-dash-dot centre lines and
pitch/base circles, thin loci, thick outlines), curves, segments, ISO 129 dimensions (extension lines,
dimension line with filled arrowheads, horizontal text), angle marks (arc with an arrowhead and text)
and notes (text on a white ground).  A scale bar is drawn by its viewport's header, not here.
"""

from __future__ import annotations

import math
from typing import Sequence

from constructions.entities import (AngleMark, Arc, Arrow, Bar, Block, Circle as CircleEntity, Curve, Dimension,
                                    Entity, Guide, Note, Pivot, Plate, Point, Polygon as PolygonEntity, Role,
                                    ScaleBar, Segment, TrialLine)
from constructions.geometry import Vec

from .drawing import (ARROW_LEN, BLOCKS, DOT_R, DOTS, HEADS, IMAGES, LINKS, NOTES, PATHS, PIN_R, PINS,
                      SHAFTS, THICK_STYLES, TRIALS, DrawContext, Drawing, LabelReq, Pt, _dist, angle_gap,
                      arrowhead, drawer, incident_directions, nonzero, shifted, unit_vector)
from .paper import Circle, Command, Line, Polygon, Polyline, Rect, Rectangle, Strokes, Text
from .style import LABEL, area_style_for, line_style_for, measure, rich
from .transform import Transform

TRIAL_EXT = 10.0        # trial lines run 10 mm past the furthest point of their diagram on them
TRIAL_LONE = 20.0
BLOCK_L = 10.0
BLOCK_H = 6.0
RAIL_EXT = 12.0
HATCH_STEP = 1.6
HATCH_LEN = 1.8
ON_LINE = 1e-3          # mm: a point this close to a trial line lies on it
NOTE_PAD = 0.4          # white margin around a note or dimension text
DIM_EXT_GAP = 1.0       # ISO 129: a small gap between the feature and its extension line ...
DIM_EXT_OVER = 2.0      # ... which runs this far past the dimension line
DIM_TEXT = LABEL        # lettering of dimensions, angle marks and notes
ANGLE_MIN_R = 6.0       # an angle mark's arc is at least this radius on paper


# ---- what the whole diagram knows ---------------------------------------------------------------

CROSSING_REACH = 0.25
"""A crossing of two trial lines counts as a point of the diagram when it lies within this fraction of
the diagram's size around its points; lines of different dyads that happen to cross far away do not
stretch each other across the sheet."""


def trial_crossings(entities: Sequence[Entity], points: Sequence[Vec] | None = None) -> list[Vec]:
    """The crossings of the diagram's trial lines near the diagram: points of the diagram on them."""
    trials = [e for e in entities if isinstance(e, TrialLine) and nonzero(e.direction)]
    if len(trials) < 2:
        return []
    pts = list(points) if points is not None else []
    if pts:
        x0, x1 = min(p.x for p in pts), max(p.x for p in pts)
        y0, y1 = min(p.y for p in pts), max(p.y for p in pts)
        m = CROSSING_REACH * max(x1 - x0, y1 - y0)
        box = (x0 - m, y0 - m, x1 + m, y1 + m)
    else:
        box = None
    out = []
    for i, a in enumerate(trials):
        for b in trials[i + 1:]:
            s = a.direction.cross(b.direction)
            if abs(s) > 1e-12 * a.direction.norm() * b.direction.norm():
                t = (b.through - a.through).cross(b.direction) / s
                p = a.through + a.direction * t
                if box is None or (box[0] <= p.x <= box[2] and box[1] <= p.y <= box[3]):
                    out.append(p)
    return out


def diagram_facts(entities: Sequence[Entity], T: Transform):
    """Pivots, bars and blocks on paper: what pivots and guides are drawn around."""
    pivots = [T(e.at) for e in entities if isinstance(e, Pivot)]
    bars = [(T(e.start), T(e.end)) for e in entities if isinstance(e, Bar)]
    blocks = [T(b.at) for b in entities if isinstance(b, Block)]
    return pivots, bars, blocks


def draw_pins(ctx: DrawContext) -> None:
    """The pins of the joints found while drawing the links (after phase 1)."""
    for p, owner in ctx.pins.items():
        ctx.d.add(PINS, Circle(*p, PIN_R, "pin", f"{owner}:pin"))
        ctx.d.hard.append(Rect(p[0] - PIN_R, p[1] - PIN_R, 2 * PIN_R, 2 * PIN_R))


# ---- the mechanism --------------------------------------------------------------------------------

@drawer(Bar, phase=0, points=lambda e: (e.start, e.end))
def draw_bar(e: Bar, ctx: DrawContext) -> None:
    a, b = ctx.T(e.start), ctx.T(e.end)
    ctx.d.add(LINKS, Line(*a, *b, line_style_for(e.role), e.name))
    ctx.add_pin(a, e.name)
    ctx.add_pin(b, e.name)


@drawer(Plate, phase=0, points=lambda e: e.vertices)
def draw_plate(e: Plate, ctx: DrawContext) -> None:
    ctx.d.add(LINKS, Polygon(tuple(ctx.T(v) for v in e.vertices), "link", e.name))


@drawer(Block, phase=0, points=lambda e: (e.at,))
def draw_block(e: Block, ctx: DrawContext) -> None:
    if not nonzero(e.direction):
        return
    c = ctx.T(e.at)
    u = ctx.T.direction(e.direction)
    n = (-u[1], u[0])
    corners = tuple(shifted(shifted(c, u, su * BLOCK_L / 2), n, sn * BLOCK_H / 2)
                    for su, sn in ((1, 1), (-1, 1), (-1, -1), (1, -1)))
    ctx.d.add(BLOCKS, Polygon(corners, "block", e.name))
    ctx.d.hard.append(Rect.bounding(corners))
    ctx.add_pin(c, e.name)


@drawer(Pivot, points=lambda e: (e.at,))
def draw_pivot(e: Pivot, ctx: DrawContext) -> None:
    """A fixed pivot: pin, ground triangle, ground line and hatching, turned away from its links."""
    d, p, name = ctx.d, ctx.T(e.at), e.name
    inc = incident_directions(p, ctx.bars)
    best, best_gap = (0.0, 1.0), -1.0
    for cand in ((0.0, 1.0), (-1.0, 0.0), (1.0, 0.0), (0.0, -1.0)):
        a = math.atan2(cand[1], cand[0])
        gap = min((angle_gap(a, b) for b in inc), default=math.pi)
        if gap > best_gap + 1e-9:
            best, best_gap = cand, gap
    cmds, symbol = ground_symbol(p, best, name)
    for c in cmds:
        d.add(PINS, c)
    d.hard.append(symbol)


def ground_symbol(p: Pt, u: Pt, name: str) -> tuple[list[Command], Rect]:
    """A fixed pivot at paper point ``p`` grounded on the side of unit ``u``: ground triangle, ground line,
    hatching and pin, and the box of the ground (which labels must not cover).  The sweep page draws
    its pivots with it too."""
    n = (-u[1], u[0])
    c = shifted(p, u, 4.0)
    tri = (p, shifted(c, n, 3.0), shifted(c, n, -3.0))
    a, b = shifted(c, n, -4.5), shifted(c, n, 4.5)
    pts = list(tri) + [a, b]
    strokes = []
    s = -4.5 + HATCH_STEP / 2
    while s <= 4.5:
        q = shifted(c, n, s)
        r = shifted(shifted(q, u, HATCH_LEN), n, -HATCH_LEN)
        strokes.append((q, r))
        pts.append(r)
        s += HATCH_STEP
    return ([Polygon(tri, "ground", f"{name}:ground"), Line(*a, *b, "link", f"{name}:ground line"),
             Strokes(tuple(strokes), "hatch", f"{name}:hatch"), Circle(*p, PIN_R, "pin", f"{name}:pin")],
            Rect.bounding(pts))


@drawer(Pivot, phase=2)
def label_pivot(e: Pivot, ctx: DrawContext) -> None:
    if e.label:
        ctx.d.labels.append(LabelReq("point", e.label, ctx.T(e.at), True, e.name, r0=PIN_R + 0.25,
                                     pivot_digits=True))


def hatching(a: Pt, u: Pt, length: float, side: Pt, name: str) -> Strokes | None:
    """The hatching of a line ``length`` mm long from ``a`` along the unit vector ``u``: a stroke every
    HATCH_STEP, leaning back from the line towards the unit vector ``side``; None when the line is too
    short for one.  The sweep page hatches its rails with it too."""
    s = HATCH_STEP / 2
    ux, uy, sx, sy = u[0], u[1], side[0] * HATCH_LEN, side[1] * HATCH_LEN
    back_x, back_y = ux * -HATCH_LEN, uy * -HATCH_LEN
    strokes = []
    while s < length:
        qx, qy = a[0] + ux * s, a[1] + uy * s                    # shifted(a, u, s)
        strokes.append(((qx, qy), (qx + sx + back_x, qy + sy + back_y)))
        s += HATCH_STEP
    return Strokes(tuple(strokes), "hatch", name) if strokes else None


def _hatched_line(d: Drawing, a: Pt, b: Pt, side: Pt, name: str) -> None:
    d.add(LINKS, Line(*a, *b, "guide", name))
    h = hatching(a, unit_vector((b[0] - a[0], b[1] - a[1])), _dist(a, b), side, f"{name}:hatch")
    if h is not None:
        d.add(LINKS, h)


@drawer(Guide)
def draw_guide(e: Guide, ctx: DrawContext) -> None:
    if not nonzero(e.direction):
        return
    d, g, u, name = ctx.d, ctx.T(e.through), ctx.T.direction(e.direction), e.name
    n = (-u[1], u[0])

    def t_of(p: Pt) -> float:
        return (p[0] - g[0]) * u[0] + (p[1] - g[1]) * u[1]

    def off(p: Pt) -> float:
        return (p[0] - g[0]) * n[0] + (p[1] - g[1]) * n[1]

    on = [b for b in ctx.blocks if abs(off(b)) < 0.05]
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
        ts = [t_of(p) for p in ctx.paper_pts] or [0.0]
        a, b = shifted(g, u, min(ts) - 8.0), shifted(g, u, max(ts) + 8.0)
        side = -1.0 if off(ctx.centroid) > 0 else 1.0
        _hatched_line(d, a, b, (n[0] * side, n[1] * side), name)


@drawer(Arc)
def draw_arc(e: Arc, ctx: DrawContext) -> None:
    span = e.end_angle - e.start_angle
    if not (e.radius > 0 and math.isfinite(span)):
        return
    T = ctx.T
    segs = int(min(200, max(8, math.ceil(abs(span) * e.radius * T.k / 1.0))))
    # T(centre + Vec.polar(radius, angle)), written out with the same arithmetic
    cx, cy, r, a0, k, ox, oy = e.center.x, e.center.y, e.radius, e.start_angle, T.k, T.ox, T.oy
    pts = tuple((ox + k * (cx + r * math.cos(a)), oy - k * (cy + r * math.sin(a)))
                for a in (a0 + span * i / segs for i in range(segs + 1)))
    ctx.d.add(PATHS, Polyline(pts, line_style_for(e.role), e.name))


# ---- vector diagrams ------------------------------------------------------------------------------

@drawer(PolygonEntity, points=lambda e: e.vertices)
def draw_polygon(e: PolygonEntity, ctx: DrawContext) -> None:
    pts = tuple(ctx.T(v) for v in e.vertices)
    ctx.d.add(IMAGES, Polygon(pts, area_style_for(e.role), e.name))
    if e.label:
        c = (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
        ctx.d.labels.append(LabelReq("polygon", e.label, c, False, e.name))


@drawer(TrialLine, points=lambda e: (e.through,))
def draw_trial(e: TrialLine, ctx: DrawContext) -> None:
    if not nonzero(e.direction):
        return
    T = ctx.T
    g = T(e.through)
    u = T.direction(e.direction)
    ts = [0.0]
    for p in ctx.paper_pts:
        v = (p[0] - g[0], p[1] - g[1])
        if abs(u[0] * v[1] - u[1] * v[0]) < ON_LINE:
            ts.append(u[0] * v[0] + u[1] * v[1])
    lo, hi = min(ts), max(ts)
    if hi - lo < 1e-6:
        lo, hi = lo - TRIAL_LONE, hi + TRIAL_LONE
    else:
        lo, hi = lo - TRIAL_EXT, hi + TRIAL_EXT
    a, b = shifted(g, u, lo), shifted(g, u, hi)
    ctx.d.add(TRIALS, Line(*a, *b, line_style_for(e.role), e.name))
    if e.label:
        ctx.d.labels.append(LabelReq("trial", e.label, b, False, e.name, other=a))


_ARROW_OWN_STYLE = frozenset({Role.KNOWN, Role.RESULT, Role.LOAD})


@drawer(Arrow, points=lambda e: (e.tail, e.tip))
def draw_arrow(e: Arrow, ctx: DrawContext) -> None:
    tail, tip = ctx.T(e.tail), ctx.T(e.tip)
    if _dist(tail, tip) < 1e-6:
        return
    head, stop = arrowhead(tail, tip, e.name)
    ctx.d.add(SHAFTS, Line(*tail, *stop, line_style_for(e.role) if e.role in _ARROW_OWN_STYLE else "vector",
                           e.name))
    ctx.d.layers.setdefault(HEADS, []).append(head)
    ctx.d.hard.append(Rect.bounding(head.points))
    if e.label:
        ctx.d.labels.append(LabelReq("arrow", e.label, tip, False, e.name, other=tail))


@drawer(Point, phase=2, points=lambda e: (e.at,))
def draw_point(e: Point, ctx: DrawContext) -> None:
    p = ctx.T(e.at)
    r0 = DOT_R
    if any(_dist(p, q) < 0.01 for q in ctx.marks):
        r0 = PIN_R + 0.25
    else:
        ctx.d.add(DOTS, Circle(*p, DOT_R, "dot", e.name))
        ctx.d.hard.append(Rect(p[0] - DOT_R, p[1] - DOT_R, 2 * DOT_R, 2 * DOT_R))
    if e.label:
        ctx.d.labels.append(LabelReq("point", e.label, p, True, e.name, r0=r0, pivot_digits=True))


@drawer(ScaleBar)
def draw_scale_bar(e: ScaleBar, ctx: DrawContext) -> None:
    """Nothing in the figure: the viewport's header draws the scale bar of the scale the diagram is
    drawn at."""


# ---- circles, curves, segments --------------------------------------------------------------------

def _circle_points(e: CircleEntity) -> tuple[Vec, ...]:
    c, r = e.center, abs(e.radius)
    return (c + Vec(r, 0), c + Vec(-r, 0), c + Vec(0, r), c + Vec(0, -r))


@drawer(CircleEntity, points=_circle_points)
def draw_circle(e: CircleEntity, ctx: DrawContext) -> None:
    if not (e.radius > 0 and math.isfinite(e.radius)):
        return
    style = line_style_for(e.role)
    c = ctx.T(e.center)
    r = e.radius * ctx.T.k
    ctx.d.add(PATHS, Circle(c[0], c[1], r, style, e.name))
    n = max(24, min(180, int(r)))
    ctx.d.add_segments([(c[0] + r * math.cos(2 * math.pi * i / n), c[1] + r * math.sin(2 * math.pi * i / n))
                        for i in range(n)], style in THICK_STYLES, closed=True)
    if e.label:
        a = math.radians(45.0)
        at = (c[0] + r * math.cos(a), c[1] - r * math.sin(a))
        ctx.d.labels.append(LabelReq("point", e.label, at, False, e.name))


@drawer(Curve, points=lambda e: e.points)
def draw_curve(e: Curve, ctx: DrawContext) -> None:
    pts = tuple(ctx.T(p) for p in e.points if math.isfinite(p.x) and math.isfinite(p.y))
    if len(pts) < 2:
        return
    if e.closed:
        ctx.d.add(PATHS, Polygon(pts, line_style_for(e.role), e.name))
    else:
        ctx.d.add(PATHS, Polyline(pts, line_style_for(e.role), e.name))
    if e.label:
        ctx.d.labels.append(LabelReq("point", e.label, pts[len(pts) // 2], False, e.name))


@drawer(Segment, points=lambda e: (e.start, e.end))
def draw_segment(e: Segment, ctx: DrawContext) -> None:
    a, b = ctx.T(e.start), ctx.T(e.end)
    ctx.d.add(TRIALS if e.role in (Role.TRIAL, Role.PATH, Role.CENTRE_LINE) else LINKS,
              Line(*a, *b, line_style_for(e.role), e.name))
    if e.label and _dist(a, b) > 1e-6:
        ctx.d.labels.append(LabelReq("arrow", e.label, b, False, e.name, other=a))


# ---- drafting annotations: dimensions, angle marks, notes -------------------------------------------

def _boxed_text(ctx: DrawContext, centre: Pt, words: str, name: str) -> Rect:
    """Horizontal lettering centred on ``centre`` over a white ground (it may cross lines)."""
    spans = rich(words, DIM_TEXT)
    ext = measure(spans)
    x = centre[0] - ext.width / 2
    y = centre[1] - (ext.top + ext.bottom) / 2
    box = ext.box(x, y)
    bg = Rect(box.x - NOTE_PAD, box.y - NOTE_PAD, box.w + 2 * NOTE_PAD, box.h + 2 * NOTE_PAD)
    ctx.d.add(NOTES, Rectangle(bg.x, bg.y, bg.w, bg.h, "note_bg", f"{name}:text bg"))
    ctx.d.add(NOTES, Text(x, y, spans, "label", box, "", f"{name}:text"))
    ctx.d.hard.append(bg)
    return bg


def _text_half(words: str) -> tuple[float, float]:
    ext = measure(rich(words, DIM_TEXT))
    return ext.width / 2 + NOTE_PAD, ext.height / 2 + NOTE_PAD


def _dimension_points(e: Dimension) -> tuple[Vec, ...]:
    d = e.end - e.start
    if not nonzero(d):
        return (e.start, e.end)
    off = d.perp().unit() * e.offset
    return (e.start, e.end, e.start + off, e.end + off)


@drawer(Dimension, points=_dimension_points)
def draw_dimension(e: Dimension, ctx: DrawContext) -> None:
    """ISO 129: extension lines from the feature (with a small gap) to just past the dimension line,
    the dimension line with filled arrowheads touching the extension lines, the value horizontal
    (unidirectional) on a white ground at the middle of the dimension line."""
    T = ctx.T
    a, b = T(e.start), T(e.end)
    if _dist(a, b) < 1e-6:
        return
    u = unit_vector((b[0] - a[0], b[1] - a[1]))
    n = (u[1], -u[0])                     # paper normal that is "left of start -> end" in the model (y up)
    off = e.offset * T.k
    side = 1.0 if off >= 0 else -1.0
    da, db = shifted(a, n, off), shifted(b, n, off)
    for p, q, tag in ((a, da, "a"), (b, db, "b")):
        if abs(off) > DIM_EXT_GAP:
            p0 = shifted(p, n, side * DIM_EXT_GAP)
            p1 = shifted(q, n, side * DIM_EXT_OVER)
            ctx.d.add(TRIALS, Line(*p0, *p1, "dimension", f"{e.name}:extension {tag}"))
    length = _dist(da, db)
    words = ctx.text(e, e.text)
    if length >= 2 * ARROW_LEN + 1.0:
        h1, _ = arrowhead(db, da, f"{e.name}:start")
        h2, _ = arrowhead(da, db, f"{e.name}:end")
        ctx.d.add(TRIALS, Line(*da, *db, "dimension", e.name))
    else:                                  # too short: arrows outside, pointing in
        h1, _ = arrowhead(shifted(da, u, -ARROW_LEN - 2.0), da, f"{e.name}:start")
        h2, _ = arrowhead(shifted(db, u, ARROW_LEN + 2.0), db, f"{e.name}:end")
        ctx.d.add(TRIALS, Line(*shifted(da, u, -ARROW_LEN - 2.0), *shifted(db, u, ARROW_LEN + 2.0),
                               "dimension", e.name))
    for h in (h1, h2):
        ctx.d.layers.setdefault(HEADS, []).append(h)
        ctx.d.hard.append(Rect.bounding(h.points))
    if words:
        mid = ((da[0] + db[0]) / 2, (da[1] + db[1]) / 2)
        hw, hh = _text_half(words)
        if length < 2 * hw + 2 * ARROW_LEN + 1.0 or abs(u[1]) < 0.5:
            # beside the dimension line, away from the feature: the text box just clears the line
            reach = abs(n[0]) * hw + abs(n[1]) * hh + 0.6
            mid = shifted(mid, n, side * reach)
        _boxed_text(ctx, mid, words, e.name)


@drawer(AngleMark, points=lambda e: (e.vertex,))
def draw_angle_mark(e: AngleMark, ctx: DrawContext) -> None:
    """An arc about the vertex from the start direction CCW to the end direction, an arrowhead at its
    end, and the text just outside the middle of the arc."""
    T = ctx.T
    span = e.end_angle - e.start_angle
    if not math.isfinite(span) or abs(span) < 1e-9:
        return
    v = T(e.vertex)
    r = max(abs(e.radius) * T.k, ANGLE_MIN_R)
    segs = int(min(180, max(8, math.ceil(abs(span) * r / 0.8))))

    def at(angle: float, rr: float = r) -> Pt:
        return (v[0] + rr * math.cos(angle), v[1] - rr * math.sin(angle))
    pts = tuple(at(e.start_angle + span * i / segs) for i in range(segs + 1))
    # the arrowhead: its apex at the end of the arc, along the chord of the last ~ARROW_LEN of arc
    back = min(abs(span), ARROW_LEN / r) * (1 if span > 0 else -1)
    head, _ = arrowhead(at(e.end_angle - back), pts[-1], e.name)
    clear = 0.8 * min(ARROW_LEN, 0.5 * _dist(at(e.end_angle - back), pts[-1]))     # of the arrowhead
    keep = [p for p in pts if _dist(p, pts[-1]) >= clear]
    if len(keep) >= 2:
        ctx.d.add(TRIALS, Polyline(tuple(keep), "dimension", e.name))
    ctx.d.layers.setdefault(HEADS, []).append(head)
    ctx.d.hard.append(Rect.bounding(head.points))
    words = ctx.text(e, e.text)
    if words:
        # the value is a label at the middle of the arc: the label placer keeps it off the lines around
        # (a short crank, a lever crossing the arc) as it does every other label
        mid = e.start_angle + span / 2
        ctx.d.labels.append(LabelReq("point", words, at(mid), True, e.name, r0=0.6))


NOTE_GAP = 0.3
"""The least room between the grounds of two notes, mm."""


@drawer(Note, points=lambda e: (e.at,))
def draw_note(e: Note, ctx: DrawContext) -> None:
    """The words on a white ground centred at the note's point -- where they would cover a note set
    before (names of circles a few mm apart, say), moved up or down just clear of it, the least way."""
    words = ctx.text(e, e.text)
    if not words:
        return
    x, y0 = ctx.T(e.at)
    hw, hh = _text_half(words)

    def free(y: float) -> bool:
        return not any(Rect(x - hw, y - hh, 2 * hw, 2 * hh).overlaps(o, NOTE_GAP) for o in ctx.notes)
    clear = NOTE_GAP + hh + 1e-6                # (a hair more: the test is strict)
    ys = [y0] + [v for o in ctx.notes for v in (o.top - clear, o.bottom + clear)]
    y = min((v for v in ys if free(v)), key=lambda v: (abs(v - y0), v))
    ctx.notes.append(_boxed_text(ctx, (x, y), words, e.name))


__all__ = ["trial_crossings", "diagram_facts", "draw_pins", "TRIAL_EXT", "BLOCK_L", "BLOCK_H"]
