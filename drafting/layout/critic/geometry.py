"""The plane geometry the sheet critic measures with: the ink of a drawing command as straight segments,
a segment against a box, distances from a box, and the area a set of boxes covers.  Paper mm, y down."""

from __future__ import annotations

import math
from typing import Iterable, Sequence

from ...render.paper import Circle, Command, Line, Polygon, Polyline, Pt, Rect, Rectangle, Strokes, Text, \
    command_points
from ...render.style import THICK, styles
from ..label_kin import clip_fraction

Segment = tuple[Pt, Pt]

ARC_SAGITTA = 0.01
"""A circle is measured as the inscribed polygon whose chords stray at most this far (mm) from the arc."""


def _closed(points: Sequence[Pt]) -> list[Segment]:
    pts = list(points)
    return list(zip(pts, pts[1:] + pts[:1])) if len(pts) > 1 else []


def circle_points(cx: float, cy: float, r: float) -> list[Pt]:
    """The corners of the polygon inscribed in a circle, chords within :data:`ARC_SAGITTA` of the arc."""
    if r <= ARC_SAGITTA:
        n = 8
    else:
        n = max(16, math.ceil(math.pi / math.acos(1.0 - ARC_SAGITTA / r)))
    return [(cx + r * math.cos(2 * math.pi * i / n), cy + r * math.sin(2 * math.pi * i / n)) for i in range(n)]


def outline(cmd: Command) -> list[Segment]:
    """The segments of a command's path (a closed figure closed, a circle as its inscribed polygon); a
    Text has none."""
    t = type(cmd)
    if t is Line:
        return [cmd.points]
    if t is Polyline:
        return list(zip(cmd.points[:-1], cmd.points[1:]))
    if t is Polygon:
        return _closed(cmd.points)
    if t is Strokes:
        return list(cmd.segments)
    if t is Rectangle:
        x, y, w, h = cmd.x, cmd.y, cmd.w, cmd.h
        return _closed(((x, y), (x + w, y), (x + w, y + h), (x, y + h)))
    if t is Circle:
        return _closed(circle_points(cmd.cx, cmd.cy, cmd.r))
    return []


def is_stroked(cmd: Command) -> bool:
    """True when the command's style draws a line along its path (a fill-only style does not)."""
    s = styles().get(cmd.style)
    return s is not None and s.stroke is not None and type(cmd) is not Text


def is_black_fill(cmd: Command) -> bool:
    """True when the command's style fills its figure black (an arrowhead, a dot, a dark scale-bar cell)."""
    s = styles().get(cmd.style)
    return s is not None and s.fill == "black" and type(cmd) in (Polygon, Rectangle, Circle)


def is_heavy(cmd: Command) -> bool:
    """True for the drawing's objects: a stroke of the thick width (a link, a vector, a load, a guide, a
    block, a pin) or a black fill (an arrowhead, a dot); thin construction lines are not heavy."""
    s = styles().get(cmd.style)
    if s is None or type(cmd) is Text:
        return False
    return (s.stroke is not None and s.width >= THICK) or is_black_fill(cmd)


def clip_length(seg: Segment, box: Rect) -> float:
    """The length of the part of ``seg`` strictly inside ``box`` (Liang-Barsky, the placer's own
    :func:`~drafting.layout.label_kin.clip_fraction`; a touch is 0)."""
    (a0, a1), (b0, b1) = seg
    le, to = box.x, box.y
    ri, bo = le + box.w, to + box.h
    if (a0 <= le and b0 <= le) or (a0 >= ri and b0 >= ri) or (a1 <= to and b1 <= to) or (a1 >= bo and b1 >= bo):
        return 0.0
    dx, dy = b0 - a0, b1 - a1
    return clip_fraction(a0, a1, dx, dy, le, to, ri, bo) * math.hypot(dx, dy)


def circle_box_distance(cx: float, cy: float, r: float, box: Rect) -> float:
    """The least distance between a circle (the curve) and a box (0 when the curve enters it): the
    curve stays clear of the box when the box is wholly outside the circle or wholly inside it."""
    near = point_box_distance((cx, cy), box)
    far = max(math.hypot(x - cx, y - cy) for x in (box.left, box.right) for y in (box.top, box.bottom))
    return max(0.0, near - r, r - far)


def inside_polygon(p: Pt, poly: Sequence[Pt]) -> bool:
    """Even-odd test of point ``p`` against the closed polygon ``poly``."""
    x, y = p
    inside = False
    n = len(poly)
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            inside = not inside
    return inside


def fill_meets(cmd: Command, box: Rect) -> bool:
    """True when the filled figure of ``cmd`` (Polygon, Rectangle, Circle) shares area with ``box``."""
    if type(cmd) is Rectangle:
        return cmd.rect.overlaps(box)
    pts = circle_points(cmd.cx, cmd.cy, cmd.r) if type(cmd) is Circle else list(cmd.points)
    if any(clip_length(s, box) > 0 for s in _closed(pts)):
        return True
    if any(box.contains_point(x, y, -1e-9) for x, y in pts):
        return True
    return inside_polygon(box.center, pts)


def point_box_distance(p: Pt, box: Rect) -> float:
    """The distance from ``p`` to the nearest point of ``box`` (0 inside it)."""
    dx = max(box.left - p[0], 0.0, p[0] - box.right)
    dy = max(box.top - p[1], 0.0, p[1] - box.bottom)
    return math.hypot(dx, dy)


def segment_box_distance(seg: Segment, box: Rect) -> float:
    """The least distance between a segment and a box (0 when they meet)."""
    if clip_length(seg, box) > 0 or box.contains_point(*seg[0]) or box.contains_point(*seg[1]):
        return 0.0
    corners = ((box.left, box.top), (box.right, box.top), (box.right, box.bottom), (box.left, box.bottom))
    best = min(point_box_distance(seg[0], box), point_box_distance(seg[1], box))
    return min(best, min(point_segment_distance(c, seg) for c in corners))


def point_segment_distance(p: Pt, seg: Segment) -> float:
    (a0, a1), (b0, b1) = seg
    dx, dy = b0 - a0, b1 - a1
    n2 = dx * dx + dy * dy
    t = 0.0 if n2 < 1e-18 else max(0.0, min(1.0, ((p[0] - a0) * dx + (p[1] - a1) * dy) / n2))
    return math.hypot(p[0] - a0 - t * dx, p[1] - a1 - t * dy)


def covered_area(boxes: Iterable[Rect], within: Rect) -> float:
    """The area of the union of ``boxes`` inside ``within`` (exact: a sweep over the boxes' x edges)."""
    clipped = []
    for b in boxes:
        le, to = max(b.left, within.left), max(b.top, within.top)
        ri, bo = min(b.right, within.right), min(b.bottom, within.bottom)
        if ri > le and bo > to:
            clipped.append((le, to, ri, bo))
    xs = sorted({v for le, _, ri, _ in clipped for v in (le, ri)})
    area = 0.0
    for x0, x1 in zip(xs, xs[1:]):
        spans = sorted((to, bo) for le, to, ri, bo in clipped if le <= x0 and ri >= x1)
        covered, top, bottom = 0.0, None, None
        for to, bo in spans:
            if bottom is None or to > bottom:
                if bottom is not None:
                    covered += bottom - top
                top, bottom = to, bo
            else:
                bottom = max(bottom, bo)
        if bottom is not None:
            covered += bottom - top
        area += covered * (x1 - x0)
    return area


def bounding(cmds: Iterable[Command]) -> Rect | None:
    """The box holding every command's geometry (a text's measured box), or None when there is none."""
    pts = [p for c in cmds for p in command_points(c)]
    return Rect.bounding(pts) if pts else None
