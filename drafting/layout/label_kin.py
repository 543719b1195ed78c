"""Which entities a label could be mistaken for: its own entity and the others of its kind, so the label
placer keeps every label clearly nearer its own entity than any other of its kind.

The kinds are the sheet critic's (:func:`~drafting.layout.critic.labels.ambiguous_labels`): arrows (a
shaft with an arrowhead "<owner>:head"), points (dots and pins, one per place), a link number's link
parts against the other links', and otherwise the command type and style of the entity's own geometry
(trial lines with trial lines, angle arcs with angle arcs).  :meth:`Kin.test` gives, for one label, the
test a candidate box must pass: the nearest foreign entity of the kind farther from the label's text
than its own entity by more than the critic's margin.
"""

from __future__ import annotations

import math
import re
from collections import defaultdict
from typing import Callable

from ..render.drawing import Drawing, LabelReq
from ..render.paper import Circle, Line, Polygon, Polyline, Rect, Strokes

MARGIN = 1.0 + 0.1
"""mm: the critic's margin (``critic.labels.AMBIGUITY_MARGIN``) and a little more, so a label the placer
clears the critic clears too.  The critic is not imported: it imports the layout that imports this."""

MARK_STYLES = frozenset({"dot", "pin"})
NUMBER = "number "          # a link number's entity: "number link 3" numbers "link 3", "link 3 AB"...

_PART = re.compile(r":(?! )")


def _owner_part(name: str) -> tuple[str, str]:
    """The owner and part of a command's name, as the critic splits them."""
    got = _PART.split(name, 1)
    return got[0], got[1] if len(got) > 1 else ""


def _outline(c) -> list:
    """The segments of a Line, Polyline, Polygon (closed) or Strokes."""
    t = type(c)
    if t is Line:
        return [c.points]
    if t is Strokes:
        return list(c.segments)
    pts = list(c.points)
    return list(zip(pts, pts[1:] + pts[:1] if t is Polygon else pts[1:]))

_SHAPES = (Line, Polyline, Polygon, Strokes, Circle)

Test = Callable[[float, float, float, float], bool]
"""A label's test of a candidate text box (left, top, right, bottom): True when it is unambiguous."""


def _element_bounds(g: tuple) -> tuple[float, float, float, float]:
    if len(g) == 2 and not isinstance(g[0], tuple):             # a point
        return g[0], g[1], g[0], g[1]
    if len(g) == 3:                                              # a circle (cx, cy, r)
        return g[0] - g[2], g[1] - g[2], g[0] + g[2], g[1] + g[2]
    (a0, a1), (b0, b1) = g
    return min(a0, b0), min(a1, b1), max(a0, b0), max(a1, b1)


def clip_fraction(a0: float, a1: float, dx: float, dy: float, left: float, top: float, right: float,
          bottom: float) -> float:
    """The fraction of the segment from (a0, a1) along (dx, dy) inside a box (Liang-Barsky)."""
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, a0 - left), (dx, right - a0), (-dy, a1 - top), (dy, bottom - a1)):
        if abs(p) < 1e-12:                      # parallel to this edge: outside, or no limit
            if q < 0:
                return 0.0
            continue
        t = q / p
        if p < 0:
            if t > t0:
                t0 = t
        elif t < t1:
            t1 = t
        if t0 > t1:
            return 0.0
    return t1 - t0


def _point_distance(x: float, y: float, le: float, to: float, ri: float, bo: float) -> float:
    return math.hypot(max(le - x, 0.0, x - ri), max(to - y, 0.0, y - bo))


def _segment_distance(a0: float, a1: float, b0: float, b1: float, le: float, to: float, ri: float,
                      bo: float) -> float:
    """The least distance between a segment and a box (0 when they meet)."""
    dx, dy = b0 - a0, b1 - a1
    if clip_fraction(a0, a1, dx, dy, le, to, ri, bo) > 0.0:
        return 0.0                                      # it runs through the box
    n2 = dx * dx + dy * dy
    best = min(_point_distance(a0, a1, le, to, ri, bo), _point_distance(b0, b1, le, to, ri, bo))
    if n2 > 1e-18:
        for cx, cy in ((le, to), (ri, to), (ri, bo), (le, bo)):
            t = ((cx - a0) * dx + (cy - a1) * dy) / n2
            if 0.0 < t < 1.0:
                best = min(best, math.hypot(cx - a0 - t * dx, cy - a1 - t * dy))
    return best


def _distance(g: tuple, le: float, to: float, ri: float, bo: float) -> float:
    """From a box to a point (x, y), a circle's curve (cx, cy, r) or a segment ((x, y), (x, y))."""
    if len(g) == 2 and not isinstance(g[0], tuple):
        return _point_distance(g[0], g[1], le, to, ri, bo)
    if len(g) == 3:
        cx, cy, r = g
        far = max(math.hypot(x - cx, y - cy) for x in (le, ri) for y in (to, bo))
        return max(0.0, _point_distance(cx, cy, le, to, ri, bo) - r, r - far)
    (a0, a1), (b0, b1) = g
    return _segment_distance(a0, a1, b0, b1, le, to, ri, bo)


class Kin:
    """A drawing's entities by kind: each owner's kind and geometry (segments, circles), and the marks."""

    __slots__ = ("kind", "geometry", "marks", "marked")

    def __init__(self, d: Drawing) -> None:
        own: dict[str, list] = defaultdict(list)
        heads: set[str] = set()
        first: dict[str, str] = {}
        self.marks: list[tuple[float, float]] = []
        self.marked: set[str] = set()
        for c in d.commands:
            if type(c) not in _SHAPES:
                continue
            o, p = _owner_part(c.name)
            if type(c) is Circle and c.style in MARK_STYLES and p in ("", "pin"):
                self.marked.add(o)
                if all(math.hypot(c.cx - x, c.cy - y) > 0.01 for x, y in self.marks):
                    self.marks.append((c.cx, c.cy))
                continue
            if p == "head" and type(c) is Polygon:
                heads.add(o)
            elif p != "":
                continue
            else:
                first.setdefault(o, f"{type(c).__name__} {c.style}")
            own[o].extend([(c.cx, c.cy, c.r)] if type(c) is Circle else _outline(c))
        self.kind = {o: "arrow" if o in heads and k.startswith("Line ") else k for o, k in first.items()}
        self.geometry = dict(own)

    def test(self, req: LabelReq, reach: Rect, pad: float) -> Test | None:
        """The test of ``req``'s candidate boxes (grounds ``pad`` wider than the text each side, all within
        ``reach``), or None when no foreign entity of its kind can be near enough to matter."""
        o = _owner_part(req.name)[0]
        if o.startswith(NUMBER):
            link = o[len(NUMBER):]
            ours = [g for k, gs in self.geometry.items() if k == link or k.startswith(link + " ") for g in gs]
            theirs = [g for k, gs in self.geometry.items() if k.startswith("link ")
                      and not (k == link or k.startswith(link + " ")) for g in gs]
            if not ours:
                return None
        elif o in self.marked or o not in self.kind:
            ax, ay = req.anchor
            ours = [req.anchor]
            theirs = [m for m in self.marks if math.hypot(m[0] - ax, m[1] - ay) > 0.01]
        else:
            kind = self.kind[o]
            ours = self.geometry[o]
            theirs = [g for k, gs in self.geometry.items() if k != o and self.kind.get(k) == kind for g in gs]
        grow = req.r0 + 18.0                 # no candidate is farther than this from its own entity
        le, to, ri, bo = reach.left - grow, reach.top - grow, reach.right + grow, reach.bottom + grow
        near = []
        for g in theirs:
            x0, y0, x1, y1 = _element_bounds(g)
            if x0 <= ri and x1 >= le and y0 <= bo and y1 >= to:
                near.append((x0, y0, x1, y1, g))
        if not near:
            return None
        return _Clear(ours, near, pad)


class _Clear:
    """A label's test: the text box (the ground inset by ``pad``) nearer its own geometry than any foreign
    element by more than :data:`MARGIN`; the foreign elements are measured only when their bounds are
    near enough."""

    __slots__ = ("ours", "theirs", "pad")

    def __init__(self, ours: list, theirs: list, pad: float) -> None:
        self.ours, self.theirs, self.pad = ours, theirs, pad

    def with_ours(self, ours: list) -> "_Clear":
        """The same test with ``ours`` as the label's own geometry (a leader drawn to it)."""
        return _Clear(ours, self.theirs, self.pad)

    def __call__(self, le: float, to: float, ri: float, bo: float) -> bool:
        p = self.pad
        bl, bt, br, bb = le + p, to + p, ri - p, bo - p
        limit = min((_distance(g, bl, bt, br, bb) for g in self.ours), default=math.inf) + MARGIN
        for x0, y0, x1, y1, g in self.theirs:
            if math.hypot(max(x0 - br, 0.0, bl - x1), max(y0 - bb, 0.0, bt - y1)) > limit:
                continue                     # its bounds, and so all of it, are farther than the limit
            if _distance(g, bl, bt, br, bb) <= limit:
                return False
        return True
