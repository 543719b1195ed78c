"""A diagram panel in general: the :class:`Panel` a page packer places (a ladder of scales, smallest
drawing first, and the room each needs), the :class:`Figure` it draws (a diagram's drawings, one per
scale tried) and the placing of a drawing, centred and labelled, in the panel's rectangle.  The kinds of
panel are in :mod:`drafting.layout.panels`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Sequence

from constructions.entities import BodyOutline, Entity, Point

from ..render.errors import LayoutError
from ..render.paper import Command, Rect, Rectangle
from ..render.transform import Transform
from ..render.drawing import Drawing, TextFn
from .diagram import draw_entities, model_points
from .formats import DiagramScale
from .header import Header, header_height
from .labels import place_labels

VIEW_PAD = 7.0          # room around a drawing for its labels

Size = tuple[float, float]
_UNMEASURED = object()


@dataclass
class PanelCache:
    """What a compose run remembers: drawings by scale, header heights by width."""

    headers: dict[tuple, float] = field(default_factory=dict)
    fills: dict[tuple, object] = field(default_factory=dict)

    def header_height(self, width: float, heading: str, ppu: float | None, unit: str) -> float | None:
        key = (round(width, 6), heading, ppu, unit)
        got = self.headers.get(key)
        if got is None:
            try:
                got = header_height(width, heading, ppu, unit)
            except LayoutError:
                got = math.inf
            self.headers[key] = got
        return None if got == math.inf else got


class Figure:
    """A diagram's entities and their drawings, one per scale tried (``k`` paper mm per model unit)."""

    def __init__(self, entities: Sequence[Entity], text: TextFn | None = None) -> None:
        self.entities = tuple(entities)
        self.text = text
        self._draws: dict[float, Drawing] = {}
        self._boxes: dict[float, Rect | None] = {}
        pts = model_points(self.entities)
        if pts:
            self.extent = (max(p.x for p in pts) - min(p.x for p in pts), max(p.y for p in pts) - min(p.y for p in pts))
        else:
            self.extent = (0.0, 0.0)

    @property
    def size(self) -> float:
        """The larger side of the model points' bounding box (model units)."""
        return max(self.extent)

    @property
    def label_gap(self) -> float:
        """The least distance between two labelled points at different places (model units; inf when
        fewer than two): points with a label, and a free body's lettered pins and points and its caption."""
        pts = {(e.at.x, e.at.y) for e in self.entities if isinstance(e, Point) and e.label}
        for e in self.entities:
            if isinstance(e, BodyOutline):          # a free body's lettered pins and points, and its caption
                pts.update((q.x, q.y) for _, q in e.pins + e.points)
                if e.caption and e.caption_at is not None:
                    pts.add((e.caption_at.x, e.caption_at.y))
        if len(pts) < 2:
            return math.inf
        tiny = 1e-9 * max(self.size, 1e-300)
        best = math.inf
        pts = sorted(pts)
        for i, (x, y) in enumerate(pts):
            for u, v in pts[i + 1:]:
                d = math.hypot(u - x, v - y)
                if tiny < d < best:
                    best = d
        return best

    def drawing(self, k: float) -> Drawing:
        d = self._draws.get(k)
        if d is None:
            d = draw_entities(self.entities, k, text=self.text)
            self._draws[k] = d
        return d

    def least_width(self, k: float) -> float:
        """The least width :func:`fit_drawing` can give the drawing at ``k``, known without drawing it:
        the drawing covers its model points (every drawer draws at the points it names), so its extent
        is at least theirs at ``k`` (less a micrometre, so a rounding in the last bit cannot turn a fit
        into a skip)."""
        return self.extent[0] * k + 2 * VIEW_PAD + 2 - 1e-3

    def fit(self, k: float, width: float, least: float = 0.0) -> Size | None:
        """The room (width, height) the drawing at ``k`` needs in a panel, at least ``least`` wide; None
        when that is wider than ``width``.  A scale whose model points alone are too wide is rejected
        without drawing it (:meth:`least_width`)."""
        if max(self.least_width(k), least) > width + 1e-9:
            return None
        w, h = fit_drawing(self.bbox(k))
        w = max(w, least)
        return None if w > width + 1e-9 else (w, h)

    def bbox(self, k: float) -> Rect | None:
        """The drawing's extent at ``k`` (measured once per scale: the packer asks many times), from a
        drawing made for its extent only unless the whole drawing is made already."""
        if k not in self._boxes:
            d = self._draws.get(k)
            self._boxes[k] = (d if d is not None else
                              draw_entities(self.entities, k, text=self.text, extent_only=True)).bbox()
        return self._boxes[k]


class RoomFigure(Figure):
    """A figure that draws some of its entities in the room of all of them: a problem sheet's space
    diagram of an inverse position problem draws the frame alone, where the worked sheet draws the whole
    mechanism at the crank angle the student is to find -- at the same place, with the room to draw the
    rest.  Its extent, legibility and box are the whole's; its drawing is ``shown``'s."""

    def __init__(self, shown: Sequence[Entity], room: Sequence[Entity], text: TextFn | None = None) -> None:
        super().__init__(room, text)
        self.shown = tuple(shown)

    def drawing(self, k: float) -> Drawing:
        d = self._draws.get(k)
        if d is None:
            d = self._draws[k] = draw_entities(self.shown, k, text=self.text, among=self.entities)
        return d

    def bbox(self, k: float) -> Rect | None:
        if k not in self._boxes:
            boxes = [b for b in (draw_entities(self.entities, k, text=self.text, extent_only=True).bbox(),
                                 draw_entities(self.shown, k, text=self.text, among=self.entities, extent_only=True).bbox())
                     if b is not None]
            self._boxes[k] = boxes[0].union(boxes[-1]) if boxes else None
        return self._boxes[k]


class Panel:
    """One diagram block: a ladder of scales (rungs, smallest drawing first) and what each needs."""

    key: str
    kind: str                    # "space", "vector", "chart"
    priority: int = 1
    blank: bool = False          # framed empty: heading, scale and scale bar, nothing drawn (a problem sheet)

    def rungs(self) -> int:
        raise NotImplementedError

    _first: int | None = None

    def min_rung(self) -> int:
        """The first rung at which the diagram is legible (found once: the packer asks many times)."""
        if self._first is None:
            self._first = self.first_legible_rung()
        return self._first

    def first_legible_rung(self) -> int:
        return 0

    def need(self, rung: int, width: float) -> Size | None:
        """(width, height) of the panel the diagram needs at ``rung`` in a panel ``width`` wide, or None
        when it does not fit that width: :meth:`measure`'d once per rung and width (the packer asks the
        same some twenty times over its arrangements and climbs).  The memo is this panel's own: a copy
        (a lab sheet's held or blank panel) starts its own."""
        memo = self.__dict__.get("_needs")
        if memo is None or memo[0] != id(self):
            memo = self._needs = (id(self), {})
        got = memo[1].get((rung, width), _UNMEASURED)
        if got is _UNMEASURED:
            got = memo[1][(rung, width)] = self.measure(rung, width)
        return got

    def measure(self, rung: int, width: float) -> Size | None:
        """:meth:`need`, measured."""
        raise NotImplementedError

    def min_width(self) -> float:
        return 0.0

    def scale_text(self, rung: int) -> str | None:
        return None

    def scale(self, rung: int) -> DiagramScale | None:
        return None

    def drawn_size(self, rung: int) -> Size:
        """The extent of the diagram's own figure (model points) on paper at ``rung``, mm."""
        return (0.0, 0.0)

    def header(self, rung: int, rect: Rect, region: str) -> Header:
        """The panel's heading (with its scale and scale bar where it has one) at the top of ``rect``."""
        raise NotImplementedError

    def render(self, rung: int, rect: Rect, region: str) -> tuple[list[Command], Transform | None]:
        header = self.header(rung, rect, region)
        if self.blank:
            return _empty_frame(self.key, header, rect), None
        return self.draw(rung, rect, region, header)

    def draw(self, rung: int, rect: Rect, region: str, header: Header) -> tuple[list[Command], Transform | None]:
        raise NotImplementedError


def _empty_frame(key: str, header: Header, rect: Rect) -> list[Command]:
    """The header over an empty framed drawing area (where a student draws)."""
    plot = Rect.from_edges(rect.x + 2.0, rect.y + header.height + 1.0, rect.right - 2.0, rect.bottom - 2.0)
    cmds = list(header.commands)
    if plot.w > 0 and plot.h > 0:
        cmds.append(Rectangle(plot.x, plot.y, plot.w, plot.h, "path", f"{key} drawing area"))
    return cmds


def fit_drawing(bb: Rect | None) -> Size:
    w = (bb.w if bb else 0.0) + 2 * VIEW_PAD + 2
    h = (bb.h if bb else 0.0) + 2 * VIEW_PAD + 2
    return w, h


def render_drawing(fig: Figure, k: float, header: Header, rect: Rect, region: str,
                    heading: str) -> tuple[list[Command], Transform]:
    plot = Rect.from_edges(rect.x + 1.0, rect.y + header.height, rect.right - 1.0, rect.bottom - 1.0)
    d, bb = fig.drawing(k), fig.bbox(k)               # (the extent the packer measured at this scale)
    cmds: list[Command] = list(header.commands)
    if bb is None:
        return cmds, Transform(k, plot.center[0], plot.center[1])
    if bb.w + 2 * VIEW_PAD > plot.w + 1e-6 or bb.h + 2 * VIEW_PAD > plot.h + 1e-6:
        raise LayoutError(f"the {heading.lower()} needs {bb.w + 2 * VIEW_PAD:.0f} x "
                          f"{bb.h + 2 * VIEW_PAD:.0f} mm and its viewport has {plot.w:.0f} x {plot.h:.0f} mm; "
                          f"use A3")
    dx = plot.center[0] - (bb.x + bb.w / 2)
    dy = plot.center[1] - (bb.y + bb.h / 2)
    moved = d.moved(dx, dy, region)
    cmds.extend(moved.commands)
    cmds.extend(place_labels(moved, plot, region))
    return cmds, Transform(k, dx, dy)
