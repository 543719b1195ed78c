"""Paper: sheet sizes, the frame, rectangles, and the recording back end.

Everything here is in millimetres on paper with the origin at the top-left corner of the sheet and y
pointing down, as in SVG.  The drawing commands are plain frozen dataclasses carrying a *style name*
(see :mod:`drafting.render.style`), never a colour or a line width, so a test can read what would be drawn
without rendering anything, and :mod:`drafting.backends.svg` is the only module that turns them into markup.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, NamedTuple, Union

# ISO 216 sizes, landscape (width, height) in mm.
PAPER_SIZES: dict[str, tuple[float, float]] = {
    "A4": (297.0, 210.0),
    "A3": (420.0, 297.0),
}
ORIENTATIONS = ("landscape", "portrait")

# ISO 5457 borders: 20 mm filing margin on the left, 10 mm elsewhere; frame line 0.7.
FRAME_LEFT = 20.0
FRAME_OTHER = 10.0
FRAME_LINE = 0.7
TITLE_BLOCK_MAX_WIDTH = 180.0


class PaperError(ValueError):
    """An unknown paper size or orientation."""


class Rect(NamedTuple):
    """An axis-aligned rectangle on paper: top-left corner ``(x, y)``, width ``w``, height ``h`` (a named
    tuple: layout makes and compares thousands)."""

    x: float
    y: float
    w: float
    h: float

    @classmethod
    def from_edges(cls, left: float, top: float, right: float, bottom: float) -> "Rect":
        return cls(left, top, right - left, bottom - top)

    @property
    def left(self) -> float:
        return self.x

    @property
    def top(self) -> float:
        return self.y

    @property
    def right(self) -> float:
        return self.x + self.w

    @property
    def bottom(self) -> float:
        return self.y + self.h

    @property
    def center(self) -> tuple[float, float]:
        return (self.x + self.w / 2, self.y + self.h / 2)

    def inset(self, dx: float, dy: float | None = None) -> "Rect":
        dy = dx if dy is None else dy
        return Rect(self.x + dx, self.y + dy, self.w - 2 * dx, self.h - 2 * dy)

    def expanded(self, d: float) -> "Rect":
        return self.inset(-d)

    def translated(self, dx: float, dy: float) -> "Rect":
        return Rect(self.x + dx, self.y + dy, self.w, self.h)

    def contains(self, other: "Rect", tol: float = 1e-6) -> bool:
        return (other.left >= self.left - tol and other.right <= self.right + tol
                and other.top >= self.top - tol and other.bottom <= self.bottom + tol)

    def contains_point(self, x: float, y: float, tol: float = 1e-6) -> bool:
        return self.left - tol <= x <= self.right + tol and self.top - tol <= y <= self.bottom + tol

    def overlaps(self, other: "Rect", gap: float = 0.0) -> bool:
        """True when the interiors (grown by ``gap`` / 2 each) share area; touching edges do not."""
        return (self.left < other.right + gap and other.left < self.right + gap
                and self.top < other.bottom + gap and other.top < self.bottom + gap)

    def union(self, other: "Rect") -> "Rect":
        return Rect.from_edges(min(self.left, other.left), min(self.top, other.top),
                               max(self.right, other.right), max(self.bottom, other.bottom))

    @staticmethod
    def bounding(points: Iterable[tuple[float, float]]) -> "Rect":
        pts = points if isinstance(points, (list, tuple)) else list(points)
        if not pts:
            raise ValueError("no points to bound")
        xs = [p[0] for p in pts]
        ys = [p[1] for p in pts]
        return Rect.from_edges(min(xs), min(ys), max(xs), max(ys))


@dataclass(frozen=True, slots=True)
class Paper:
    """A sheet of paper: ISO name, orientation and size in mm."""

    name: str
    orientation: str
    width: float
    height: float

    @property
    def page(self) -> Rect:
        return Rect(0.0, 0.0, self.width, self.height)

    @property
    def frame(self) -> Rect:
        """The drawing frame: 20 mm from the left edge, 10 mm from the others."""
        return Rect.from_edges(FRAME_LEFT, FRAME_OTHER, self.width - FRAME_OTHER, self.height - FRAME_OTHER)

    @property
    def title_block_max_width(self) -> float:
        return min(TITLE_BLOCK_MAX_WIDTH, self.frame.w)


def paper(name: str = "A4", orientation: str = "landscape") -> Paper:
    """The ISO sheet ``name`` ("A4", "A3") in ``orientation`` ("landscape" or "portrait")."""
    key = name.strip().upper()
    if key not in PAPER_SIZES:
        raise PaperError(f"unknown paper size {name!r}; use one of {', '.join(PAPER_SIZES)}")
    o = orientation.strip().lower()
    if o not in ORIENTATIONS:
        raise PaperError(f"unknown orientation {orientation!r}; use 'landscape' or 'portrait'")
    w, h = PAPER_SIZES[key]
    if o == "portrait":
        w, h = h, w
    return Paper(key, o, w, h)


# --------------------------------------------------------------------------------------------------
# The recording back end: what is drawn, in paper mm, y down.
# --------------------------------------------------------------------------------------------------

Pt = tuple[float, float]


@dataclass(frozen=True, slots=True)
class Line:
    x1: float
    y1: float
    x2: float
    y2: float
    style: str
    name: str = ""

    @property
    def points(self) -> tuple[Pt, Pt]:
        return ((self.x1, self.y1), (self.x2, self.y2))

    @property
    def length(self) -> float:
        return math.hypot(self.x2 - self.x1, self.y2 - self.y1)


@dataclass(frozen=True, slots=True)
class Polyline:
    points: tuple[Pt, ...]
    style: str
    name: str = ""


@dataclass(frozen=True, slots=True)
class Polygon:
    """A closed figure; an arrowhead is a filled Polygon whose first point is the apex (the tip)."""

    points: tuple[Pt, ...]
    style: str
    name: str = ""


@dataclass(frozen=True, slots=True)
class Strokes:
    """Separate straight strokes of one style drawn as one path: a hatching, ``segments`` as (start,
    end) pairs."""

    segments: tuple[tuple[Pt, Pt], ...]
    style: str
    name: str = ""

    @property
    def points(self) -> tuple[Pt, ...]:
        return tuple(p for seg in self.segments for p in seg)


@dataclass(frozen=True, slots=True)
class Rectangle:
    x: float
    y: float
    w: float
    h: float
    style: str
    name: str = ""

    @property
    def rect(self) -> Rect:
        return Rect(self.x, self.y, self.w, self.h)


@dataclass(frozen=True, slots=True)
class Circle:
    cx: float
    cy: float
    r: float
    style: str
    name: str = ""


class Span(NamedTuple):
    """A run of text: its size in mm and its baseline shift in mm (positive = down, a subscript).  A named
    tuple: text is measured by its runs, and a tuple hashes and compares in C."""

    text: str
    size: float
    shift: float = 0.0
    italic: bool = False


@dataclass(frozen=True, slots=True)
class Text:
    """A line of lettering starting at ``(x, y)`` on the baseline (text-anchor start).

    ``spans`` are drawn one after the other; ``box`` is the measured extent (advance width by the
    font's ascent and descent) used for collision tests; ``region`` names the sheet region it must
    stay in.
    """

    x: float
    y: float
    spans: tuple[Span, ...]
    style: str
    box: Rect
    region: str
    name: str = ""

    @property
    def plain(self) -> str:
        return "".join(s.text for s in self.spans)

    @property
    def sizes(self) -> tuple[float, ...]:
        return tuple(s.size for s in self.spans)


Command = Union[Line, Polyline, Polygon, Strokes, Rectangle, Circle, Text]


def translated(cmd: Command, dx: float, dy: float, region: str | None = None) -> Command:
    """The same command moved by ``(dx, dy)`` mm (a text put in ``region`` when given)."""
    t = type(cmd)
    if t is Text:
        b = cmd.box
        return Text(cmd.x + dx, cmd.y + dy, cmd.spans, cmd.style, Rect(b.x + dx, b.y + dy, b.w, b.h),
                    cmd.region if region is None else region, cmd.name)
    if t is Line:
        return Line(cmd.x1 + dx, cmd.y1 + dy, cmd.x2 + dx, cmd.y2 + dy, cmd.style, cmd.name)
    if t is Polyline or t is Polygon:
        return t(tuple((x + dx, y + dy) for x, y in cmd.points), cmd.style, cmd.name)
    if t is Strokes:
        return Strokes(tuple(((a[0] + dx, a[1] + dy), (b[0] + dx, b[1] + dy)) for a, b in cmd.segments), cmd.style,
                       cmd.name)
    if t is Rectangle:
        return Rectangle(cmd.x + dx, cmd.y + dy, cmd.w, cmd.h, cmd.style, cmd.name)
    if t is Circle:
        return Circle(cmd.cx + dx, cmd.cy + dy, cmd.r, cmd.style, cmd.name)
    raise TypeError(f"not a drawing command: {cmd!r}")


def command_points(cmd: Command) -> tuple[Pt, ...]:
    """The points that bound a command's geometry (stroke width not included)."""
    if isinstance(cmd, Line):
        return cmd.points
    if isinstance(cmd, (Polyline, Polygon, Strokes)):
        return cmd.points
    if isinstance(cmd, Rectangle):
        return ((cmd.x, cmd.y), (cmd.x + cmd.w, cmd.y + cmd.h))
    if isinstance(cmd, Circle):
        return ((cmd.cx - cmd.r, cmd.cy - cmd.r), (cmd.cx + cmd.r, cmd.cy + cmd.r))
    if isinstance(cmd, Text):
        b = cmd.box
        return ((b.left, b.top), (b.right, b.bottom))
    raise TypeError(f"not a drawing command: {cmd!r}")
