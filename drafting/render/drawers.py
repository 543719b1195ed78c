"""One drawer per entity type (see :mod:`drafting.layout.diagram` for the registry and the phases).

Mechanism entities: pivots (ground hatching turned away from their links), guides (rails
either side of a slider block, or a hatched line), blocks, path arcs (bars, plates and link numbers in
:mod:`drafting.render.link_drawers`).  Vector entities: arrows (thick
shaft, filled arrowhead with its apex at the tip), trial lines (thin, run past every point of the diagram
on them), images (light grey), points.  Drafting entities: circles (long-dash-dot centre lines and
pitch/base circles, thin loci, thick outlines), curves, segments; the drafting annotations (dimensions,
angle marks, notes) in :mod:`drafting.render.annotations`.  A scale bar is drawn by its viewport's
header, not here.  The symbols the mechanism is drawn with are :mod:`drafting.render.symbols`.
"""

from __future__ import annotations

import math
from typing import Sequence

from constructions.geometry import Line as ModelLine, Vec, intersect_lines
from constructions.tolerance import Tolerance
from constructions.entities import (Arc, Arrow, Bar, Block, Circle as CircleEntity, Curve, Entity, Guide, Pivot, Point, Polygon as PolygonEntity, Role, ScaleBar, Segment, TrialLine)

from .drawing import (BLOCKS, DOT_R, DOTS, HEADS, IMAGES, LINKS, PATHS, PIN_R, PINS,
                      SHAFTS, THICK_STYLES, TRIALS, DrawContext, Drawing, LabelReq, Pt, _dist, arrowhead, drawer,
                      incident_directions, nonzero, shifted, unit_vector)
from .paper import Circle, Line, Polygon, Polyline, Rect
from .style import area_style_for, line_style_for
from .symbols import BLOCK_H, BLOCK_L, ground_side, ground_symbol, hatching
from .transform import Transform
from . import annotations  # noqa: F401  (registers the drawers of dimensions, angle marks and notes)
from . import body_drawers  # noqa: F401  (registers the drawers of free bodies and couples)
from . import detail_mark  # noqa: F401  (registers the mark of a detail on its diagram)
from . import link_drawers  # noqa: F401  (registers the drawers of bars, plates and link numbers)
from . import machine_drawers  # noqa: F401  (registers the drawers of rotation arrows and followers)

TRIAL_EXT = 10.0        # trial lines run 10 mm past the furthest point of their diagram on them
TRIAL_LONE = 20.0
RAIL_EXT = 12.0
ON_LINE = 1e-3          # mm: a point this close to a trial line lies on it


# ---- what the whole diagram knows ---------------------------------------------------------------

CROSSING_REACH = 0.25
"""A crossing of two trial lines counts as a point of the diagram when it lies within this fraction of
the diagram's size around its points; lines of different dyads that happen to cross far away do not
stretch each other across the sheet."""


def trial_crossings(entities: Sequence[Entity], points: Sequence[Vec]) -> list[Vec]:
    """The crossings of the diagram's trial lines near the diagram (whose model points are ``points``):
    points of the diagram on them.  Lines parallel within the engine's tolerance
    (:class:`constructions.tolerance.Tolerance`, relative to the diagram's size) do not cross."""
    trials = [e for e in entities if isinstance(e, TrialLine) and nonzero(e.direction)]
    if len(trials) < 2 or not points:
        return []
    x0, x1 = min(p.x for p in points), max(p.x for p in points)
    y0, y1 = min(p.y for p in points), max(p.y for p in points)
    size = max(x1 - x0, y1 - y0)
    if not size > 0:                                  # every point one point: the lines cross there or not at all
        return []
    m = CROSSING_REACH * size
    tol = Tolerance(size)
    lines = [ModelLine(e.through, e.direction) for e in trials]
    out = []
    for i, a in enumerate(lines):
        for b in lines[i + 1:]:
            for p in intersect_lines(a, b, tol).points:
                if x0 - m <= p.x <= x1 + m and y0 - m <= p.y <= y1 + m:
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
    cmds, symbol = ground_symbol(p, ground_side(incident_directions(p, ctx.bars)), name)
    for c in cmds:
        d.add(PINS, c)
    d.hard.append(symbol)


@drawer(Pivot, phase=2)
def label_pivot(e: Pivot, ctx: DrawContext) -> None:
    if e.label:
        ctx.d.labels.append(LabelReq("point", e.label, ctx.T(e.at), True, e.name, r0=PIN_R + 0.25,
                                     pivot_digits=True))


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


_ARROW_OWN_STYLE = frozenset({Role.KNOWN, Role.RESULT, Role.LOAD, Role.DIMENSION})


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
        ctx.d.labels.append(LabelReq("arrow", ctx.text(e, e.label), tip, False, e.name, other=tail))


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


CIRCLE_NAME_AT = (45.0, 135.0, 225.0, 315.0, 90.0, 270.0, 0.0, 180.0)
"""Where a circle's name goes (degrees counter-clockwise from the right): the first place that is clear and
unambiguous; by the first, up and to the right, when none is."""
CURVE_NAME_AT = (0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875)
"""Where a curve's name goes, as a share of its points: the first place that is clear and unambiguous."""


@drawer(CircleEntity, points=_circle_points)
def draw_circle(e: CircleEntity, ctx: DrawContext) -> None:
    if not (e.radius > 0 and math.isfinite(e.radius)):
        return
    style = line_style_for(e.role)
    c = ctx.T(e.center)
    r = e.radius * ctx.T.k
    ctx.d.add(PATHS, Circle(c[0], c[1], r, style, e.name))
    if ctx.d.extent_only:
        return
    n = max(24, min(180, int(r)))
    ctx.d.add_segments([(c[0] + r * math.cos(2 * math.pi * i / n), c[1] + r * math.sin(2 * math.pi * i / n))
                        for i in range(n)], style in THICK_STYLES, closed=True)
    if e.label:
        at = [(c[0] + r * math.cos(math.radians(a)), c[1] - r * math.sin(math.radians(a))) for a in CIRCLE_NAME_AT]
        ctx.d.labels.append(LabelReq("point", e.label, at[0], False, e.name, alternates=tuple(at[1:])))


@drawer(Curve, points=lambda e: e.points)
def draw_curve(e: Curve, ctx: DrawContext) -> None:
    if ctx.d.extent_only:       # its extent: the paper transform keeps the order of each coordinate, bit for bit
        fin = e.points
        xs, ys = [p.x for p in fin], [p.y for p in fin]
        if not (math.isfinite(sum(xs)) and math.isfinite(sum(ys))):      # (a NaN or an infinity among them)
            fin = [p for p in fin if math.isfinite(p.x) and math.isfinite(p.y)]
            xs, ys = [p.x for p in fin], [p.y for p in fin]
        if len(fin) >= 2:
            ends = [fin[xs.index(min(xs))], fin[xs.index(max(xs))], fin[ys.index(min(ys))], fin[ys.index(max(ys))]]
            ctx.d.add(PATHS, Polyline(tuple(ctx.T.many(ends)), line_style_for(e.role), e.name))
        return
    pts = tuple(ctx.T.many(p for p in e.points if math.isfinite(p.x) and math.isfinite(p.y)))
    if len(pts) < 2:
        return
    if e.closed:
        ctx.d.add(PATHS, Polygon(pts, line_style_for(e.role), e.name))
    else:
        ctx.d.add(PATHS, Polyline(pts, line_style_for(e.role), e.name))
    if e.label:
        at = [pts[min(len(pts) - 1, int(f * len(pts)))] for f in CURVE_NAME_AT]
        ctx.d.labels.append(LabelReq("point", e.label, at[0], False, e.name, alternates=tuple(at[1:])))


@drawer(Segment, points=lambda e: (e.start, e.end))
def draw_segment(e: Segment, ctx: DrawContext) -> None:
    a, b = ctx.T(e.start), ctx.T(e.end)
    ctx.d.add(TRIALS if e.role in (Role.TRIAL, Role.PATH, Role.CENTRE_LINE) else LINKS,
              Line(*a, *b, line_style_for(e.role), e.name))
    if e.label and _dist(a, b) > 1e-6:
        ctx.d.labels.append(LabelReq("arrow", e.label, b, False, e.name, other=a))


__all__ = ["trial_crossings", "diagram_facts", "draw_pins", "TRIAL_EXT"]
