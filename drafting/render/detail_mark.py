"""The mark of a detail on its diagram (ISO 128): a thin circle round the region drawn enlarged
elsewhere, and the detail's letter beside it.  The enlarged drawing itself is a panel of its own
(:mod:`drafting.layout.detail_panel`)."""

from __future__ import annotations

import math

from constructions.entities import Detail
from constructions.geometry import Vec

from .drawing import PATHS, DrawContext, LabelReq, drawer
from .paper import Circle
from .style import line_style_for


def _detail_points(e: Detail) -> tuple[Vec, ...]:
    c, r = e.centre, e.radius
    return (Vec(c.x - r, c.y), Vec(c.x + r, c.y), Vec(c.x, c.y - r), Vec(c.x, c.y + r))


@drawer(Detail, points=_detail_points)
def draw_detail_mark(e: Detail, ctx: DrawContext) -> None:
    if not (e.radius > 0 and math.isfinite(e.radius)):
        return
    c = ctx.T(e.centre)
    r = e.radius * ctx.T.k
    style = line_style_for(e.role)
    ctx.d.add(PATHS, Circle(c[0], c[1], r, style, e.name))
    n = max(24, min(180, int(r)))
    ctx.d.add_segments([(c[0] + r * math.cos(2 * math.pi * i / n), c[1] + r * math.sin(2 * math.pi * i / n))
                        for i in range(n)], False, closed=True)
    a = math.radians(45.0)
    ctx.d.labels.append(LabelReq("point", e.letter, (c[0] + r * math.cos(a), c[1] - r * math.sin(a)), True, e.name))
