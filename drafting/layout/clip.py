"""Paper commands clipped to a circle: what an enlarged detail keeps of its diagram's drawing.

Lines, polylines, hatching strokes and outlines are cut where they cross the circle and only their
pieces inside are kept (as lines and polylines of the same style and name: the back ends draw them as
they draw any other); a circle or rectangle wholly inside is kept whole, one crossing the boundary is
cut as the polygon of its outline; lettering and filled figures (arrowheads, dots, grounds) are kept
only when wholly inside, never cut.
"""

from __future__ import annotations

import math

from ..render.paper import Circle, Command, Line, Polyline, Rectangle, Strokes, Text, command_points
from ..render.style import styles

Pt = tuple[float, float]

FILLED = frozenset(name for name, st in styles().items() if st.fill is not None)   # cut: left out
ARC_STEP = 0.5           # mm: the chord of a cut circle's outline


class Disc:
    """The circle of centre ``(cx, cy)`` and radius ``r`` (paper mm) commands are clipped to."""

    def __init__(self, cx: float, cy: float, r: float) -> None:
        self.cx, self.cy, self.r = cx, cy, r

    def inside(self, p: Pt, tol: float = 1e-9) -> bool:
        return math.hypot(p[0] - self.cx, p[1] - self.cy) <= self.r + tol

    def segment(self, a: Pt, b: Pt) -> tuple[float, float] | None:
        """The parameters ``(t0, t1)`` (0 <= t0 < t1 <= 1) of the part of ``a``-``b`` inside, or None."""
        dx, dy = b[0] - a[0], b[1] - a[1]
        fx, fy = a[0] - self.cx, a[1] - self.cy
        qa = dx * dx + dy * dy
        qb = 2 * (fx * dx + fy * dy)
        qc = fx * fx + fy * fy - self.r * self.r
        if qa == 0.0:
            return (0.0, 1.0) if qc <= 0 else None
        disc = qb * qb - 4 * qa * qc
        if disc <= 0:
            return None
        s = math.sqrt(disc)
        t0, t1 = max(0.0, (-qb - s) / (2 * qa)), min(1.0, (-qb + s) / (2 * qa))
        return (t0, t1) if t1 > t0 else None


def _at(a: Pt, b: Pt, t: float) -> Pt:
    return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))


def clip_path(points: list[Pt], disc: Disc) -> list[list[Pt]]:
    """The runs of the open path through ``points`` that lie inside ``disc``."""
    runs: list[list[Pt]] = []
    cur: list[Pt] = []
    for a, b in zip(points[:-1], points[1:]):
        got = disc.segment(a, b)
        if got is None:
            if cur:
                runs.append(cur)
                cur = []
            continue
        t0, t1 = got
        p, q = _at(a, b, t0), _at(a, b, t1)
        if not cur or t0 > 0.0:
            if cur:
                runs.append(cur)
            cur = [p]
        cur.append(q)
        if t1 < 1.0:
            runs.append(cur)
            cur = []
    if cur:
        runs.append(cur)
    return [r for r in runs if len(r) >= 2]


def _outline(cmd: Command) -> list[Pt]:
    if isinstance(cmd, Circle):
        n = max(24, int(2 * math.pi * cmd.r / ARC_STEP))
        return [(cmd.cx + cmd.r * math.cos(2 * math.pi * i / n), cmd.cy + cmd.r * math.sin(2 * math.pi * i / n))
                for i in range(n + 1)]
    if isinstance(cmd, Rectangle):
        x0, y0, x1, y1 = cmd.x, cmd.y, cmd.x + cmd.w, cmd.y + cmd.h
        return [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
    pts = list(cmd.points)
    return pts + pts[:1]


def _polylines(points: list[Pt], disc: Disc, style: str, name: str) -> list[Command]:
    return [Polyline(tuple(r), style, name) for r in clip_path(points, disc)]


def clip_command(cmd: Command, disc: Disc) -> list[Command]:
    """What of ``cmd`` lies inside ``disc`` (see the module's docstring)."""
    if isinstance(cmd, Text):
        b = cmd.box
        corners = ((b.left, b.top), (b.right, b.top), (b.left, b.bottom), (b.right, b.bottom))
        return [cmd] if all(disc.inside(p) for p in corners) else []
    if isinstance(cmd, Circle):
        d = math.hypot(cmd.cx - disc.cx, cmd.cy - disc.cy)
        if d + cmd.r <= disc.r + 1e-9:
            return [cmd]
        if d >= cmd.r + disc.r or d + disc.r <= cmd.r or cmd.style in FILLED:   # apart, or round the disc
            return []
        return _polylines(_outline(cmd), disc, cmd.style, cmd.name)
    if all(disc.inside(p) for p in (_outline(cmd) if isinstance(cmd, Rectangle) else command_points(cmd))):
        return [cmd]
    if isinstance(cmd, Line):
        got = disc.segment((cmd.x1, cmd.y1), (cmd.x2, cmd.y2))
        if got is None:
            return []
        (x1, y1), (x2, y2) = _at(cmd.points[0], cmd.points[1], got[0]), _at(cmd.points[0], cmd.points[1], got[1])
        return [Line(x1, y1, x2, y2, cmd.style, cmd.name)]
    if isinstance(cmd, Strokes):
        segs = []
        for a, b in cmd.segments:
            got = disc.segment(a, b)
            if got is not None:
                segs.append((_at(a, b, got[0]), _at(a, b, got[1])))
        return [Strokes(tuple(segs), cmd.style, cmd.name)] if segs else []
    if cmd.style in FILLED:
        return []
    if isinstance(cmd, Polyline):
        return _polylines(list(cmd.points), disc, cmd.style, cmd.name)
    return _polylines(_outline(cmd), disc, cmd.style, cmd.name)
