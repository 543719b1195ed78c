"""The drawers of free bodies: a body drawn free of the others (:class:`~constructions.entities.BodyOutline`)
and a couple or torque on it (:class:`~constructions.entities.MomentArc`).

A free body is drawn thin against the forces on it (ISO 128: the forces are the result, thick): a link as a
slender outline around the line of its pins, a ternary link as a shaded plate, a block as its rectangle;
each pin a small circle, every point lettered, and the body's caption ("link 3: two-force member") below
it.  A couple is an arc three quarters of a turn about its point, thick like a force, its arrowhead in the
couple's sense.  Registered with the other drawers when :mod:`drafting.render.drawers` is imported.
"""

from __future__ import annotations

import math

from constructions.entities import BodyOutline, MomentArc
from constructions.geometry import Vec

from .annotations import _boxed_text, _text_half
from .drawing import (DOT_R, DOTS, HEADS, LINKS, PINS, DrawContext, LabelReq, Pt, _dist, arrowhead, drawer,
                      nonzero, shifted, unit_vector)
from .paper import Circle, Polygon, Polyline, Rect
from .symbols import BLOCK_H, BLOCK_L

BODY_HALF = 1.6
"""Half the width of a slender link's outline on paper, mm (its pins' circles fit inside)."""
BODY_PIN_R = 1.0
"""The radius of a pin on a free body, mm: a small circle, thin."""
ROUND = 12
"""Segments of each half circle closing a slender link's outline."""
CAPTION_GAP = 3.0
"""The room between a body (with its forces) and its caption under it, mm."""
MOMENT_MIN_R = 5.0
"""A couple's arc is at least this radius on paper, mm."""
MOMENT_TURN = 1.5 * math.pi
"""A couple's arc turns three quarters of a turn."""


def _slender(a: Pt, b: Pt, half: float) -> tuple[Pt, ...]:
    """The outline of a slender link from ``a`` to ``b`` on paper: two sides ``half`` off the centre line,
    closed by half circles about the end pins."""
    u = unit_vector((b[0] - a[0], b[1] - a[1]))
    base = math.atan2(u[1], u[0])
    pts = []
    for c, start in ((b, base - math.pi / 2), (a, base + math.pi / 2)):
        pts += [(c[0] + half * math.cos(start + math.pi * i / ROUND), c[1] + half * math.sin(start + math.pi * i / ROUND))
                for i in range(ROUND + 1)]
    return tuple(pts)


def _body_points(e: BodyOutline) -> tuple[Vec, ...]:
    return tuple(e.outline) + tuple(p for _, p in e.pins) + tuple(p for _, p in e.points) + \
        ((e.caption_at,) if e.caption_at is not None else ())


@drawer(BodyOutline, phase=0, points=_body_points)
def draw_body(e: BodyOutline, ctx: DrawContext) -> None:
    """The body thin, its pins as small circles on top."""
    T, d = ctx.T, ctx.d
    pts = tuple(T(v) for v in e.outline)
    if len(pts) >= 3:
        d.add(LINKS, Polygon(pts, "image", e.name))
    elif len(pts) == 2 and _dist(*pts) > 1e-6:
        d.add(LINKS, Polygon(_slender(pts[0], pts[1], BODY_HALF), "path", e.name))
    elif pts and e.direction is not None and nonzero(e.direction):
        c = pts[0]
        u = T.direction(e.direction)
        n = (-u[1], u[0])
        corners = tuple(shifted(shifted(c, u, su * BLOCK_L / 2), n, sn * BLOCK_H / 2)
                        for su, sn in ((1, 1), (-1, 1), (-1, -1), (1, -1)))
        d.add(LINKS, Polygon(corners, "bar_light", e.name))
    for name, v in e.pins:
        p = T(v)
        d.add(PINS, Circle(*p, BODY_PIN_R, "bar_light", f"{e.name}:pin {name}"))
        d.hard.append(Rect(p[0] - BODY_PIN_R, p[1] - BODY_PIN_R, 2 * BODY_PIN_R, 2 * BODY_PIN_R))
    for name, v in e.points:
        p = T(v)
        d.add(DOTS, Circle(*p, DOT_R, "dot", f"{e.name}:point {name}"))
        d.hard.append(Rect(p[0] - DOT_R, p[1] - DOT_R, 2 * DOT_R, 2 * DOT_R))


@drawer(BodyOutline, phase=2)
def letter_body(e: BodyOutline, ctx: DrawContext) -> None:
    """Every pin and point lettered; the caption centred under the body (under any caption in its way)."""
    T = ctx.T
    for (name, v), r0 in [(x, BODY_PIN_R + 0.25) for x in e.pins] + [(x, DOT_R) for x in e.points]:
        ctx.d.labels.append(LabelReq("point", name, T(v), True, f"{e.name}:{name}", r0=r0, pivot_digits=True))
    if e.caption and e.caption_at is not None:
        x, y = T(e.caption_at)
        hw, hh = _text_half(e.caption)
        y += CAPTION_GAP + hh
        for o in sorted(ctx.notes, key=lambda r: r.top):          # clear of the captions set before
            if Rect(x - hw, y - hh, 2 * hw, 2 * hh).overlaps(o, CAPTION_GAP):
                y = o.bottom + CAPTION_GAP + hh
        ctx.notes.append(_boxed_text(ctx, (x, y), e.caption, f"{e.name}:caption"))


def moment_arc_points(e: MomentArc) -> tuple[Vec, ...]:
    """The arc's circle's extreme points (the diagram is sized to hold it)."""
    r, c = abs(e.radius), e.centre
    return (c + Vec(r, 0.0), c + Vec(-r, 0.0), c + Vec(0.0, r), c + Vec(0.0, -r))


def moment_arc_paper(e: MomentArc, ctx: DrawContext) -> tuple[Pt, ...]:
    """The arc on paper, from its start to its arrowhead, turning the couple's way."""
    v = ctx.T(e.centre)
    r = max(abs(e.radius) * ctx.T.k, MOMENT_MIN_R)
    span = math.copysign(MOMENT_TURN, e.moment)
    segs = int(min(180, max(12, math.ceil(abs(span) * r / 0.8))))
    return tuple((v[0] + r * math.cos(a), v[1] - r * math.sin(a))
                 for a in (e.start_angle + span * i / segs for i in range(segs + 1)))


@drawer(MomentArc, points=moment_arc_points)
def draw_moment_arc(e: MomentArc, ctx: DrawContext) -> None:
    """Thick like a force: the arc, the arrowhead at its end pointing the couple's way, the label at the
    middle of the arc."""
    if not (e.moment != 0.0 and math.isfinite(e.moment)):
        return
    pts = moment_arc_paper(e, ctx)
    back = next(p for p in reversed(pts) if _dist(p, pts[-1]) >= 3.0)
    head, stop = arrowhead(back, pts[-1], e.name)
    keep = [p for p in pts if _dist(p, pts[-1]) >= _dist(stop, pts[-1])]
    ctx.d.add(LINKS, Polyline(tuple(keep) + (stop,), "load", e.name))
    ctx.d.layers.setdefault(HEADS, []).append(head)
    ctx.d.hard.append(Rect.bounding(head.points))
    if e.label:
        ctx.d.labels.append(LabelReq("point", e.label, pts[len(pts) // 2], True, f"{e.name}:label", r0=0.6))


__all__ = ["draw_body", "letter_body", "draw_moment_arc", "moment_arc_paper"]
