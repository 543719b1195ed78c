"""Enlarged details (ISO 128, ISO 5455): a region of a diagram too small to read at the diagram's
scale, drawn again in a panel of its own at an enlargement.

The construction records a :class:`~constructions.entities.Detail` in the diagram it enlarges: the
region (centre and radius, model units) and its letter.  The diagram draws it as its mark, a thin circle
and the letter (:mod:`drafting.render.detail_mark`); the :class:`DetailPanel` draws the diagram's own
entities (nothing of the record is drawn twice over: the same entities, through the same drawers) at an
ISO 5455 scale chosen to fit, clipped to the region's circle (:mod:`drafting.layout.clip`), with the
circle drawn thin round it, lettered, and the scale in its heading ("Detail A 5:1"); several details of
one diagram share a panel and its scale, one over the other ("Details A and B 10:1").
"""

from __future__ import annotations

import math
from typing import Sequence

from constructions.entities import Detail, Entity

from ..render.drawing import Drawing, LabelReq, TextFn
from ..render.errors import LayoutError
from ..render.paper import Circle, Command, Line, Rect
from ..render.scales import ISO_5455, ratio_factor, ratio_text
from ..render.transform import Transform
from .clip import Disc, clip_command
from .formats import DiagramScale, per_si, symbol_of
from .header import Header, viewport_header
from .labels import place_labels
from .panel import VIEW_PAD, Figure, Panel, PanelCache, Size

DETAIL_MIN_MM = 30.0     # a detail's circle is at least this across on paper ...
DETAIL_MAX_MM = 160.0    # ... and at most this
GAP_MM = 6.0             # between the circles of several details in one panel
BOUNDARY = "dimension"   # the thin line round a detail


class DetailPanel(Panel):
    """The :class:`Detail` regions of one diagram, enlarged one over the other at one scale (each circle
    lettered): its rungs are the ISO 5455 scales at which the largest region's circle is DETAIL_MIN_MM
    to DETAIL_MAX_MM across, the smallest drawing first."""

    kind = "space"
    priority = 1

    def __init__(self, details: Sequence[Detail], entities: Sequence[Entity], units, cache: PanelCache,
                 text: TextFn | None = None) -> None:
        self.details = tuple(details)
        letters = [d.letter for d in self.details]
        self.title = "Detail " + letters[0] if len(letters) == 1 else \
            "Details " + ", ".join(letters[:-1]) + " and " + letters[-1]
        self.key = f"{self.details[0].diagram.key}: {self.title.lower()}"
        self.figure = Figure([e for e in entities if not isinstance(e, Detail)], text)
        self.units, self.cache = units, cache
        self.unit = symbol_of(units, "length")
        self.per_m = per_si(units, "length")
        d = 2.0 * max(x.radius for x in self.details) * 1000.0
        fits = [r for r in reversed(ISO_5455) if DETAIL_MIN_MM <= d * ratio_factor(r) <= DETAIL_MAX_MM]
        self.ratios = tuple(fits) or (min(ISO_5455, key=lambda r: abs(d * ratio_factor(r) - DETAIL_MIN_MM)),)
        self.ks = tuple(1000.0 * ratio_factor(r) for r in self.ratios)       # paper mm per metre, by rung
        self.headings = tuple(f"{self.title} {ratio_text(r)}" for r in self.ratios)

    def rungs(self) -> int:
        return len(self.ks)

    def k(self, rung: int) -> float:
        return self.ks[rung]

    def heading(self, rung: int) -> str:
        return self.headings[rung]

    def ppu(self, rung: int) -> float:
        """Paper mm per display length unit."""
        return self.ks[rung] / self.per_m

    def drawn_size(self, rung: int) -> Size:
        """The circles one over the other on paper, mm."""
        k = self.k(rung)
        return (max(2 * d.radius * k for d in self.details),
                sum(2 * d.radius * k for d in self.details) + GAP_MM * (len(self.details) - 1))

    def measure(self, rung: int, width: float) -> Size | None:
        w, h = self.drawn_size(rung)
        w, h = w + 2 * VIEW_PAD + 2, h + 2 * VIEW_PAD + 2
        if w > width + 1e-9:
            return None
        hh = self.cache.header_height(w, self.heading(rung), self.ppu(rung), self.unit)   # (as narrow as given)
        return None if hh is None else (w, h + hh)

    def min_width(self) -> float:
        return self.drawn_size(0)[0] + 2 * VIEW_PAD + 2

    def scale_text(self, rung: int) -> str:
        return self.heading(rung)

    def scale(self, rung: int) -> DiagramScale:
        return DiagramScale(self.key, "length", 1.0 / self.k(rung), self.per_m / self.k(rung), self.unit)

    def header(self, rung: int, rect: Rect, region: str) -> Header:
        return viewport_header(rect, self.heading(rung), self.ppu(rung), self.unit, region=region, name=self.key)

    def discs(self, rung: int, plot: Rect) -> list[Disc]:
        """The details' circles on paper, one over the other centred in ``plot``."""
        k = self.k(rung)
        _, h = self.drawn_size(rung)
        y = plot.center[1] - h / 2
        out = []
        for d in self.details:
            r = d.radius * k
            out.append(Disc(plot.center[0], y + r, r))
            y += 2 * r + GAP_MM
        return out

    def draw(self, rung: int, rect: Rect, region: str, header: Header) -> tuple[list[Command], Transform]:
        k = self.k(rung)
        plot = Rect.from_edges(rect.x + 1.0, rect.y + header.height, rect.right - 1.0, rect.bottom - 1.0)
        w, h = self.drawn_size(rung)
        if w + 2 * VIEW_PAD > plot.w + 1e-6 or h + 2 * VIEW_PAD > plot.h + 1e-6:
            raise LayoutError(f"the {self.heading(rung).lower()} needs {w + 2 * VIEW_PAD:.0f} x "
                              f"{h + 2 * VIEW_PAD:.0f} mm and its viewport has {plot.w:.0f} x {plot.h:.0f} mm")
        cmds: list[Command] = list(header.commands)
        drawn, labels = Drawing(), Drawing()
        T = Transform(k)
        for det, disc in zip(self.details, self.discs(rung, plot)):
            c = T(det.centre)
            part = clipped_drawing(self.figure.drawing(k).moved(disc.cx - c[0], disc.cy - c[1], region), disc)
            for layer, got in part.layers.items():
                for cmd in got:
                    drawn.add(layer, cmd)
            drawn.add(0, Circle(disc.cx, disc.cy, disc.r, BOUNDARY, f"{det.name}: boundary"))
            drawn.labels.extend(part.labels)
            a = math.radians(45.0)
            drawn.labels.append(LabelReq("point", det.letter, (disc.cx + disc.r * math.cos(a), disc.cy - disc.r * math.sin(a)),
                                         True, f"{det.name}: boundary"))
            drawn.hard.extend(part.hard)
        cmds.extend(drawn.commands)
        cmds.extend(place_labels(drawn, plot, region))
        first = self.discs(rung, plot)[0]
        c = T(self.details[0].centre)
        return cmds, Transform(k, first.cx - c[0], first.cy - c[1])


def clipped_drawing(d: Drawing, disc: Disc) -> Drawing:
    """The drawing's commands clipped to ``disc``, with the labels anchored inside it and the symbols
    labels must keep off that lie inside it."""
    out = Drawing()
    for layer in sorted(d.layers):
        for cmd in d.layers[layer]:
            for piece in clip_command(cmd, disc):
                out.add(layer, piece)
    out.labels = [q for q in d.labels if disc.inside(q.anchor)]
    out.hard = [h for h in d.hard if disc.inside(h.center)]
    return out


def detail_panels(entities: Sequence[Entity], units, cache: PanelCache, text: TextFn | None = None) -> list[Panel]:
    """One :class:`DetailPanel` holding the :class:`Detail` regions among one diagram's ``entities``
    (none without)."""
    details = [e for e in entities if isinstance(e, Detail)]
    return [DetailPanel(details, entities, units, cache, text)] if details else []




class DetailsBeside:
    """A space panel with the panel of its diagram's details beside it, on its right, as one block:
    the details take the room the diagram leaves in the width of its panel (a diagram seldom fills a
    sheet's width), at the largest of their scales that fits there, no taller than the diagram's panel
    (or than the details' smallest scale needs)."""

    def __init__(self, space, details: DetailPanel) -> None:
        self.space, self.details = space, details

    def detail_rung(self, width: float, height: float) -> tuple[int, Size] | None:
        best = None
        for r in range(self.details.rungs()):
            got = self.details.need(r, width)
            if got is not None and (best is None or got[1] <= height + 1e-9):
                best = (r, got)
        return best

    def need(self, rung: int, width: float, got: Size | None) -> Size | None:
        if got is None:
            return None
        w, h = got
        beside = self.detail_rung(width - w, h)
        if beside is None:
            return None
        dw, dh = beside[1]
        return w + dw, max(h, dh)

    def min_width(self, rung: int) -> float:
        got = self.details.need(0, 10_000.0)
        return got[0] if got else 0.0

    def split(self, rung: int, rect: Rect) -> tuple[Rect, Rect, int]:
        """The diagram's part of ``rect``, the details' part (on the right) and the details' rung."""
        got = self.space.own_need(rung, rect.w - self.min_width(rung))
        w = got[0] if got else rect.w / 2
        r, (dw, _) = self.detail_rung(rect.w - w, rect.h) or (0, self.details.need(0, 10_000.0))
        dw = max(dw, min(rect.w - w, dw * 1.5))
        main = Rect(rect.x, rect.y, rect.w - dw, rect.h)
        return main, Rect(main.right, rect.y, dw, rect.h), r

    def render(self, rung: int, rect: Rect, region: str, draw_space):
        main, side, r = self.split(rung, rect)
        cmds, T = draw_space(main)
        dcmds, _ = self.details.render(r, side, region)
        cmds.append(Line(side.x, side.y, side.x, side.bottom, "separator", "separator"))
        return cmds + dcmds, T


__all__ = ["DetailPanel", "DetailsBeside", "detail_panels", "clipped_drawing"]
