"""Diagram panels: one diagram drawn, centred and labelled in its rectangle of the sheet.

A :class:`Panel` knows the scales it may be drawn at, as a ladder of *rungs* from the smallest drawing
to the largest, and the room each rung needs for a given panel width (the drawing with room for its
labels, under the heading and scale bar).  The page packer (:mod:`drafting.layout.pages`) climbs the rungs of
every panel while they fit, then :meth:`Panel.render` draws the chosen rung into the rectangle.

- :class:`SpacePanel`: the space diagram (and any diagram drawn to a length scale) at an ISO 5455 scale.
- :class:`VectorPanel`: a vector polygon at the scale its construction fixed (``ScaleBar.units_per_mm``)
  or, when that is None, at a 1-2-5 scale of the sheet's unit (1 mm = 10 mm/s): the largest that fits
  the panel.
- :class:`ChartPanel`: charts, filling whatever room they get.

A diagram is drawn only at the scales actually tried, once each (the drawings are kept by scale:
:class:`~drafting.layout.panel.Figure`), and its size at a scale is read off that drawing.  The Panel
every kind is, and the placing of a drawing in its rectangle, are in :mod:`drafting.layout.panel`.
"""

from __future__ import annotations

import copy
import math
from typing import Sequence

from constructions.entities import Arrow, Chart, Entity, Role, ScaleBar

from ..render.drawing import TextFn, is_panel_entity
from ..render.paper import Command, Rect
from ..render.scales import ISO_5455, nice_values, number_text, ratio_factor, ratio_text
from ..render.style import LABEL
from ..scene.unitset import Units
from .chart import CHART_MIN, AxisUnits, draw_chart
from .detail_panel import DetailsBeside, detail_panels
from .formats import DiagramScale, per_si, symbol_of
from .header import Header, viewport_header
from .panel import Figure, Panel, PanelCache, Size, render_drawing

VECTOR_MIN_W = 90.0     # a vector panel is at least this wide (heading and scale bar side by side)
SPACE_MIN_MM = 25.0     # the space diagram's larger side is at least this long at a legible scale
LABEL_GAP_MM = LABEL    # ... and its labelled points a letter height apart on paper (a label each),
LABEL_ROOM_MAX_MM = 150.0   # as long as that keeps its larger side within this
POLYGON_MIN_MM = 40.0   # a polygon drawn at a scale the sheet chooses is at least this large
POLYGON_AIM_MM = 50.0   # ... and aims at a known vector at least this long


class SpacePanel(Panel):
    """A diagram drawn to a length scale (the space diagram) at an ISO 5455 scale (with its enlarged
    details beside it when it has some: :class:`~drafting.layout.detail_panel.DetailsBeside`)."""

    kind = "space"
    priority = 0
    beside: DetailsBeside | None = None

    def __init__(self, key: str, title: str, entities: Sequence[Entity], units, cache: PanelCache,
                 text: TextFn | None = None) -> None:
        self.key, self.title = key, title
        self.figure = Figure(entities, text)
        self.units, self.cache = units, cache
        self.unit = symbol_of(units, "length")
        self.per_m = per_si(units, "length")                  # display length units per metre
        self.ratios = tuple(reversed(ISO_5455))               # smallest drawing first

    def rungs(self) -> int:
        return len(self.ratios)

    def k(self, rung: int) -> float:
        return 1000.0 * ratio_factor(self.ratios[rung])

    def heading(self, rung: int) -> str:
        return f"{self.title} {ratio_text(self.ratios[rung])}"

    def first_legible_rung(self) -> int:
        """The first rung at which the diagram is at least SPACE_MIN_MM and its labelled points at least
        LABEL_GAP_MM apart (a crowd of labels, as in a diagram of instant centres, needs room to be read),
        the second only as long as the diagram stays within LABEL_ROOM_MAX_MM."""
        size = self.figure.size
        if size <= 0:               # a single point (a problem's frame): the rung nearest full size
            return min(range(len(self.ratios)), key=lambda i: abs(math.log(ratio_factor(self.ratios[i]))))
        gap = self.figure.label_gap
        first = len(self.ratios) - 1
        for i in range(len(self.ratios)):
            if size * self.k(i) >= SPACE_MIN_MM:
                first = i
                break
        i = first
        while (gap * self.k(i) < LABEL_GAP_MM and i + 1 < len(self.ratios)
               and size * self.k(i + 1) <= LABEL_ROOM_MAX_MM):
            i += 1
        return i

    def ppu(self, rung: int) -> float:
        return self.k(rung) / self.per_m                      # paper mm per display length unit

    def measure(self, rung: int, width: float) -> Size | None:
        if self.beside is not None:
            return self.beside.need(rung, width, self.own_need(rung, width - self.beside.min_width(rung)))
        return self.own_need(rung, width)

    def own_need(self, rung: int, width: float) -> Size | None:
        got = self.figure.fit(self.k(rung), width)
        if got is None:
            return None
        w, h = got
        hh = self.cache.header_height(width, self.heading(rung), self.ppu(rung), self.unit)
        if hh is None:
            return None
        return w, h + hh

    def scale_text(self, rung: int) -> str:
        return f"Space {ratio_text(self.ratios[rung])}" if self.key == "space" else \
            f"{self.title} {ratio_text(self.ratios[rung])}"

    def scale(self, rung: int) -> DiagramScale:
        return DiagramScale(self.key, "length", 1.0 / self.k(rung), self.per_m / self.k(rung), self.unit)

    def drawn_size(self, rung: int) -> Size:
        k = self.k(rung)
        return self.figure.extent[0] * k, self.figure.extent[1] * k

    def header(self, rung: int, rect: Rect, region: str) -> Header:
        return viewport_header(rect, self.heading(rung), self.ppu(rung), self.unit, region=region, name=self.key)

    def draw(self, rung: int, rect: Rect, region: str, header: Header):
        return render_drawing(self.figure, self.k(rung), header, rect, region,
                               self.heading(rung))

    def render(self, rung: int, rect: Rect, region: str):
        if self.beside is None or self.blank:
            return super().render(rung, rect, region)
        return self.beside.render(rung, rect, region, lambda main: super(SpacePanel, self).render(rung, main, region))


VECTOR_TITLES = {"velocity": "Velocity polygon", "acceleration": "Acceleration polygon", "force": "Force polygon"}


class VectorPanel(Panel):
    """A vector polygon at the scale its construction fixed, or at the largest 1-2-5 scale (in the
    sheet's unit) that fits its panel when the construction leaves the scale to the drawing."""

    kind = "vector"

    def __init__(self, key: str, title: str, label: str, quantity: str, entities: Sequence[Entity],
                 fixed: float | None, units, cache: PanelCache, text: TextFn | None = None) -> None:
        self.key, self.title, self.label, self.quantity = key, title, label, quantity
        self.figure = Figure(entities, text)
        self.units, self.cache = units, cache
        self.unit = symbol_of(units, quantity)
        self.f = per_si(units, quantity)                      # display units per SI unit
        self.fixed = fixed
        if fixed is not None:
            self.values = (fixed * self.f,)
        else:
            size = self.figure.size * self.f
            if size > 0 and math.isfinite(size):
                # display units per mm, from a drawing 10 mm large to one 2 m large: largest value first
                self.values = tuple(reversed(nice_values(size / 2000.0, size / 10.0)))
            else:
                self.values = (1.0,)
        self.known = max(((e.tip - e.tail).norm() for e in entities
                          if isinstance(e, Arrow) and e.role is Role.KNOWN), default=0.0)

    @property
    def free(self) -> bool:
        return self.fixed is None

    def rungs(self) -> int:
        return len(self.values)

    def upm(self, rung: int) -> float:
        """SI units per paper mm."""
        return self.fixed if self.fixed is not None else self.values[rung] / self.f

    def k(self, rung: int) -> float:
        return 1.0 / self.upm(rung)

    def first_legible_rung(self) -> int:
        if self.fixed is not None:
            return 0
        for i in range(len(self.values)):
            if self.figure.size * self.k(i) >= POLYGON_MIN_MM - 1e-9:
                return i
        return len(self.values) - 1

    def measure(self, rung: int, width: float) -> Size | None:
        got = self.figure.fit(self.k(rung), width, VECTOR_MIN_W)
        if got is None:
            return None
        w, h = got
        hh = self.cache.header_height(width, self.title, self.k(rung) / self.f, self.unit)
        if hh is None:
            return None
        return w, h + hh

    def min_width(self) -> float:
        return VECTOR_MIN_W

    def scale_text(self, rung: int) -> str:
        return f"{self.label} 1 mm = {number_text(self.upm(rung) * self.f)} {self.unit}"

    def scale(self, rung: int) -> DiagramScale:
        return DiagramScale(self.key, self.quantity, self.upm(rung), self.upm(rung) * self.f, self.unit)

    def drawn_size(self, rung: int) -> Size:
        k = self.k(rung)
        return self.figure.extent[0] * k, self.figure.extent[1] * k

    def known_mm(self, rung: int) -> float:
        return self.known * self.k(rung)

    def header(self, rung: int, rect: Rect, region: str) -> Header:
        return viewport_header(rect, self.title, self.k(rung) / self.f, self.unit, region=region, name=self.key)

    def draw(self, rung: int, rect: Rect, region: str, header: Header):
        return render_drawing(self.figure, self.k(rung), header, rect, region, self.title)


class ChartPanel(Panel):
    """One or more charts stacked in a panel of their own; they fill whatever room they get."""

    kind = "chart"
    priority = 2

    def __init__(self, key: str, title: str, charts: Sequence[Chart], units, cache: PanelCache) -> None:
        self.key, self.title, self.charts = key, title, tuple(charts)
        self.units, self.cache = units, cache
        self.axes = AxisUnits(lambda kind, v: v * per_si(units, kind), lambda kind: symbol_of(units, kind))

    def rungs(self) -> int:
        return 1

    def measure(self, rung: int, width: float) -> Size | None:
        if width < CHART_MIN[0]:
            return None
        hh = self.cache.header_height(width, self.title, None, "")
        if hh is None:
            return None
        return CHART_MIN[0], hh + CHART_MIN[1] * len(self.charts)

    def min_width(self) -> float:
        return CHART_MIN[0]

    def header(self, rung: int, rect: Rect, region: str) -> Header:
        return viewport_header(rect, self.title, None, "", region=region, name=self.key)

    def draw(self, rung: int, rect: Rect, region: str, header: Header):
        cmds: list[Command] = list(header.commands)
        area = Rect.from_edges(rect.x + 2.0, rect.y + header.height, rect.right - 2.0, rect.bottom - 2.0)
        n = len(self.charts)
        h = area.h / n
        for i, c in enumerate(self.charts):
            sub = Rect(area.x, area.y + i * h, area.w, h - (2.0 if i < n - 1 else 0.0))
            cmds.extend(draw_chart(c, sub, self.axes, region))
        return cmds, None


# ---- building the panels of a construction ------------------------------------------------------------

def _title(kind: str, name: str) -> str:
    base = VECTOR_TITLES.get(kind, kind[:1].upper() + kind[1:] + " diagram")
    return f"{base}, {name}" if name else base


def _label(kind: str, name: str) -> str:
    return f"{kind} ({name})" if name else kind


def panels_for(construction, units, cache: PanelCache, text: TextFn | None = None) -> list[Panel]:
    """One panel per diagram of ``construction`` (in the order space, velocity, acceleration, force,
    the others as they first appear), and one chart panel per diagram holding charts."""
    by_diagram: dict = {}
    for e in construction.entities():
        by_diagram.setdefault(e.diagram, []).append(e)
    order = {"space": 0, "velocity": 1, "acceleration": 2, "force": 3}
    diagrams = sorted(by_diagram, key=lambda d: order.get(d.kind, 4))       # stable: first appearance
    panels: list[Panel] = []
    charts: list[Panel] = []
    for dg in diagrams:
        ents = by_diagram[dg]
        chart_ents = [e for e in ents if is_panel_entity(e)]
        drawn = [e for e in ents if not is_panel_entity(e)]
        if chart_ents:
            title = dg.name if dg.kind == "chart" and dg.name else _title(dg.kind, dg.name) if dg.kind != "chart" \
                else "Chart"
            charts.append(ChartPanel(dg.key if not drawn else f"{dg.key} (chart)", title, chart_ents, units, cache))
        if not any(not isinstance(e, ScaleBar) for e in drawn):
            continue
        bar = next((e for e in drawn if isinstance(e, ScaleBar)), None)
        quantity = bar.quantity if bar is not None else dg.kind
        if quantity not in VECTOR_TITLES:          # drawn to a length scale: space, free body ...
            title = "Space diagram" if dg.kind == "space" and not dg.name else _title(dg.kind, dg.name)
            panels.append(SpacePanel(dg.key, title, drawn, units, cache, text))
            for d in detail_panels(drawn, units, cache, text):
                panels[-1].beside = DetailsBeside(panels[-1], d)
        else:
            upm = bar.units_per_mm if bar is not None else None
            fixed = upm if upm is not None and upm > 0 and math.isfinite(upm) else None
            panels.append(VectorPanel(dg.key, _title(dg.kind, dg.name), _label(dg.kind, dg.name), quantity, drawn,
                                      fixed, units, cache, text))
    out = panels + charts
    for i, p in enumerate(out):
        p.index = i
    return out


__all__ = ["SpacePanel", "VectorPanel", "ChartPanel", "panels_for", "POLYGON_MIN_MM", "POLYGON_AIM_MM"]


def fit_space(entities: tuple[Entity, ...], w: float, h: float, units=None):
    """The largest ISO 5455 scale at which a space diagram fits a ``w`` x ``h`` viewport, and the
    height it needs: ``(ratio, height)`` or None."""
    p = SpacePanel("space", "Space diagram", entities, units or Units(), PanelCache())
    for r in range(p.rungs() - 1, -1, -1):
        got = p.need(r, w)
        if got is not None and got[1] <= h:
            return p.ratios[r], got[1]
    return None



def held_to(panel: Panel, upm: float) -> Panel:
    """``panel`` drawn at one scale only, ``upm`` SI units per paper mm: a scene's stated scale, or a problem
    sheet held to its worked sheet's.  A length diagram takes the ISO 5455 ratio it names (or the ratio
    itself, 1:2.5), a polygon that many units a millimetre; other panels are returned as they are."""
    held = copy.copy(panel)
    if isinstance(panel, SpacePanel):
        same = [r for r in panel.ratios if math.isclose(1.0 / (1000.0 * ratio_factor(r)), upm, rel_tol=1e-9)]
        if same:
            held.ratios = (same[0],)
        else:
            factor = 1.0 / (1000.0 * upm)                    # paper per true length
            held.ratios = ((_plain(factor), 1) if factor >= 1 else (1, _plain(1.0 / factor)),)
        return held
    if isinstance(panel, VectorPanel):
        held.fixed, held.values = upm, (upm * panel.f,)
        return held
    return panel


def _plain(x: float) -> float | int:
    """A ratio's term as written: 2 not 2.0, 2.5 as it is."""
    r = round(x, 9)
    return int(r) if r == int(r) else r
