"""A viewport's header: its heading at the top left and its scale bar beside the heading (or under it)."""

from __future__ import annotations

from dataclasses import dataclass

from ..render.errors import LayoutError
from ..render.paper import Command, Rect, Span
from ..render.style import HEADING, LABEL, measure, plain
from .scale_bar import SCALE_TEXT, bar_bottom, choose_bar, scale_bar
from .wrap import text_at


HEADER_GAP = 1.5


@dataclass(frozen=True)
class Header:
    commands: tuple[Command, ...]
    height: float


@dataclass(frozen=True)
class _HeaderPlan:
    """Where a viewport header's heading and scale bar go (see :func:`viewport_header`)."""

    head: tuple[Span, ...]
    x: float
    y: float
    bar: tuple[float, float, float, float] | None    # x, top, length and value of the scale bar
    height: float


def _header_plan(rect: Rect, heading: str, paper_per_unit: float | None, unit: str, name: str) -> _HeaderPlan:
    hs = HEADING
    head = plain(heading, hs)
    hext = measure(head)
    if hext.width > rect.w - 2:
        hs = LABEL
        head = plain(heading, hs)
        hext = measure(head)
        if hext.width > rect.w - 2:
            raise LayoutError(f"the {name} viewport is too narrow for its heading")
    x0 = rect.x + 1.5
    y0 = rect.y + HEADER_GAP - hext.top
    hbox = hext.box(x0, y0)
    if paper_per_unit is None:
        return _HeaderPlan(head, x0, y0, None, hbox.bottom - rect.y + HEADER_GAP)
    unit_w = measure(plain(unit, SCALE_TEXT)).width + 1.2
    overhang = 4.0
    side_room = rect.right - 1.5 - unit_w - overhang - (hbox.right + 6.0)
    bar = choose_bar(paper_per_unit, side_room, min_len=25.0)
    if bar is not None:                     # beside the heading, centred on it
        v, length = bar
        bx = rect.right - 1.5 - unit_w - length
        top = rect.y + HEADER_GAP + max(0.0, (hbox.h - bar_bottom(0.0, unit)) / 2)
        return _HeaderPlan(head, x0, y0, (bx, top, length, v),
                           max(hbox.bottom, bar_bottom(top, unit)) - rect.y + HEADER_GAP)
    bar = choose_bar(paper_per_unit, rect.w - 3.0 - unit_w - overhang, min_len=10.0)
    if bar is None:
        raise LayoutError(f"the {name} viewport is too narrow for its scale bar; use A3")
    v, length = bar                         # under the heading
    top = hbox.bottom + 1.5
    return _HeaderPlan(head, x0, y0, (x0 + 1.5, top, length, v), bar_bottom(top, unit) - rect.y + HEADER_GAP)


def viewport_header(rect: Rect, heading: str, paper_per_unit: float | None, unit: str, *, region: str,
                    name: str) -> Header:
    """Heading at the top left of a viewport and the scale bar at the top right (or under it); a panel
    without a scale (a chart: ``paper_per_unit`` None) has the heading only."""
    hp = _header_plan(rect, heading, paper_per_unit, unit, name)
    cmds: list[Command] = [text_at(hp.x, hp.y, hp.head, style="heading", region=region, name=f"heading {name}")]
    if hp.bar is not None:
        bx, top, length, v = hp.bar
        cmds.extend(scale_bar(bx, top, length, v, unit, region=region, name=f"scale bar {name}")[0])
    return Header(tuple(cmds), hp.height)


def header_height(width: float, heading: str, paper_per_unit: float | None, unit: str) -> float:
    """The height :func:`viewport_header` gives a viewport ``width`` wide, without making its commands."""
    return _header_plan(Rect(0, 0, width, 100), heading, paper_per_unit, unit, "probe").height
