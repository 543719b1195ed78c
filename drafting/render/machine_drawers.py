"""The drawers of the machine elements a cam or gear sheet shows beside its construction.

A rotation arrow (a body's sense of rotation, labelled omega) is drawn as an angle mark about the body's
centre: an arc with its arrowhead at the end of the sweep and its label at the middle.  A translating
follower is drawn in true size at its station: its stem (two thick edges, square-ended), its end -- a
roller (thick circle on its pin), a knife edge (a wedge coming to a point on the cam) or a flat face (a
thick line square to the stem) -- and its guide, a bearing either side of the stem hatched away from it.
"""

from __future__ import annotations

import math

from constructions.entities import AngleMark, FollowerBody, RotationArrow

from .annotations import draw_angle_mark
from .drawing import LINKS, PIN_R, PINS, DrawContext, Pt, drawer, shifted
from .paper import Circle, Line, Polygon, Rect
from .symbols import hatching

__all__ = ["draw_rotation_arrow", "draw_follower"]

GUIDE_GAP = 0.6
"""mm between the stem and its guide on paper: the bearing's clearance, drawn so the lines stay apart."""


@drawer(RotationArrow, points=lambda e: (e.center,))
def draw_rotation_arrow(e: RotationArrow, ctx: DrawContext) -> None:
    """The arc about the centre through the sweep, its arrowhead showing the sense, the label at its middle."""
    if not (math.isfinite(e.sweep) and abs(e.sweep) > 1e-9 and e.radius > 0):
        return
    draw_angle_mark(AngleMark(e.name, e.role, e.diagram, e.center, e.radius, e.start_angle,
                              e.start_angle + e.sweep, e.label), ctx)


def _follower_points(e: FollowerBody):
    u = e.direction
    n = math.hypot(u.x, u.y) or 1.0
    return (e.at, e.at + u * (e.stem / n))


@drawer(FollowerBody, points=_follower_points)
def draw_follower(e: FollowerBody, ctx: DrawContext) -> None:
    """The follower's stem, its end (roller, knife, face) and the guide it slides in."""
    T, d, name = ctx.T, ctx.d, e.name
    u = T.direction(e.direction)
    un = math.hypot(*u)
    if not un > 0:
        return
    u = (u[0] / un, u[1] / un)
    n = (-u[1], u[0])
    end = T(e.at)
    hw = e.width * T.k / 2
    top = shifted(end, u, e.stem * T.k)
    base = end
    if e.kind == "knife":
        base = shifted(end, u, 2 * hw)                   # the wedge runs from the edge up to the full stem
        d.add(LINKS, Polygon((end, shifted(base, n, hw), shifted(base, n, -hw)), "link", f"{name}:edge"))
    for s in (1.0, -1.0):
        a, b = shifted(base, n, s * hw), shifted(top, n, s * hw)
        d.add(LINKS, Line(*a, *b, "link", f"{name}:stem"))
    d.add(LINKS, Line(*shifted(top, n, hw), *shifted(top, n, -hw), "link", f"{name}:stem end"))
    if e.kind == "roller":
        r = e.radius * T.k
        d.add(LINKS, Circle(end[0], end[1], r, "link", f"{name}:roller"))
        d.add_segments([(end[0] + r * math.cos(2 * math.pi * i / 48), end[1] + r * math.sin(2 * math.pi * i / 48))
                        for i in range(48)], True, closed=True)
        d.add(PINS, Circle(end[0], end[1], PIN_R, "pin", f"{name}:pin"))
        d.hard.append(Rect(end[0] - PIN_R, end[1] - PIN_R, 2 * PIN_R, 2 * PIN_R))
    elif e.kind == "flat":
        f = e.face * T.k
        d.add(LINKS, Line(*shifted(end, n, f), *shifted(end, n, -f), "link", f"{name}:face"))
    _guide(ctx, shifted(end, u, e.guide_at * T.k), u, n, hw, e.guide * T.k, f"{name}:guide")


def _guide(ctx: DrawContext, mid: Pt, u: Pt, n: Pt, hw: float, length: float, name: str) -> None:
    """The bearing: a thick line either side of the stem over ``length``, hatched away from it."""
    for s in (1.0, -1.0):
        off = hw + GUIDE_GAP
        a = shifted(shifted(mid, u, -length / 2), n, s * off)
        b = shifted(a, u, length)
        ctx.d.add(LINKS, Line(*a, *b, "guide", name))
        h = hatching(a, u, length, (n[0] * s, n[1] * s), f"{name}:hatch")
        if h is not None:
            ctx.d.add(LINKS, h)
