"""The drawers of a linkage's links as textbooks draw them: bars (a slotted lever run on through the block
that slides in it, wherever the block sits: beyond the pivot too, as in the Whitworth quick-return),
ternary links as shaded plates with their outline, and each link's number beside it (the frame's beside a
ground symbol).  Registered with the other drawers when :mod:`drafting.render.drawers` is imported.
"""

from __future__ import annotations

import math

from constructions.entities import Bar, Block, LinkNumber, Plate

from .drawing import LINKS, PIN_R, DrawContext, LabelReq, Pt, _dist, drawer, incident_directions, nonzero, shifted
from .paper import Line, Polygon
from .style import line_style_for
from .symbols import BLOCK_H, BLOCK_L, ground_side

ON_BAR = 0.05
"""mm: a block whose centre lies this close to a bar's line, along it, slides on that bar (a slotted lever)."""
PARALLEL = 1e-3
"""sine: a block's direction this close to a bar's is along it."""
LEVER_PAST = 0.5 * BLOCK_L + 3.0
"""A slotted lever runs this far past the centre of a block outside its two joints: through the block."""
NUMBER_GAP = 1.0
"""mm between a link and its number."""


def lever_reach(a: Pt, b: Pt, ctx: DrawContext) -> tuple[Pt, Pt]:
    """The ends of the bar ``a``-``b`` as drawn: its joints, run on through every block that slides along
    it outside them (a slot in the lever)."""
    ab = (b[0] - a[0], b[1] - a[1])
    n = math.hypot(*ab)
    if n < 1e-9:
        return a, b
    u = (ab[0] / n, ab[1] / n)
    lo, hi = 0.0, n
    for e in ctx.entities:
        if not (isinstance(e, Block) and nonzero(e.direction)):
            continue
        c, d = ctx.T(e.at), ctx.T.direction(e.direction)
        v = (c[0] - a[0], c[1] - a[1])
        if abs(u[0] * v[1] - u[1] * v[0]) > ON_BAR or abs(u[0] * d[1] - u[1] * d[0]) > PARALLEL:
            continue
        t = u[0] * v[0] + u[1] * v[1]
        if t < 0:
            lo = min(lo, t - LEVER_PAST)
        elif t > n:
            hi = max(hi, t + LEVER_PAST)
    return shifted(a, u, lo), shifted(a, u, hi)


@drawer(Bar, phase=0, points=lambda e: (e.start, e.end))
def draw_bar(e: Bar, ctx: DrawContext) -> None:
    a, b = ctx.T(e.start), ctx.T(e.end)
    p, q = lever_reach(a, b, ctx)
    ctx.d.add(LINKS, Line(*p, *q, line_style_for(e.role), e.name))
    ctx.add_pin(a, e.name)
    ctx.add_pin(b, e.name)


@drawer(Plate, phase=0, points=lambda e: e.vertices)
def draw_plate(e: Plate, ctx: DrawContext) -> None:
    """A ternary (or larger) link: the plate shaded light grey under its outline."""
    pts = tuple(ctx.T(v) for v in e.vertices)
    ctx.d.add(LINKS, Polygon(pts, "band", f"{e.name}:plate"))
    ctx.d.add(LINKS, Polygon(pts, "link", e.name))


def _at_pivot(p: Pt, ctx: DrawContext) -> bool:
    return any(_dist(p, q) < 0.01 for q in ctx.pivots)


@drawer(LinkNumber, phase=2)
def draw_link_number(e: LinkNumber, ctx: DrawContext) -> None:
    """The number beside the link's middle, clear of its line (the label placer keeps it off every line);
    at a fixed pivot (the frame) beside the ground symbol's hatching; at a block, beside the block."""
    p = ctx.T(e.at)
    r0 = NUMBER_GAP
    if _at_pivot(p, ctx):
        u = ground_side(incident_directions(p, ctx.bars))
        n = (-u[1], u[0])
        p = shifted(shifted(p, u, 5.0), n, 7.0)
        r0 = 0.5
    elif any(_dist(p, q) < 0.01 for q in ctx.blocks):
        r0 = 0.5 * math.hypot(BLOCK_L, BLOCK_H) + NUMBER_GAP
    elif any(_dist(p, q) < 0.01 for q in ctx.marks):
        r0 = PIN_R + NUMBER_GAP
    ctx.d.labels.append(LabelReq("point", str(e.number), p, True, e.name, r0=r0))


__all__ = ["lever_reach"]
