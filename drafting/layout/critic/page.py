"""The critic's checks of a page as a whole: how much of its panel each diagram fills, how much of the
frame is left blank, the size of the lettering and how many lines each title-block cell takes.  Each
check takes a :class:`~drafting.layout.sheet.Sheet` and returns its findings."""

from __future__ import annotations

from collections import defaultdict

from ...render.paper import Rect, Text
from ...render.scales import ISO_5455, nice_floor, ratio_factor
from ...render.style import MIN_TEXT
from ..panel import VIEW_PAD
from .geometry import bounding, covered_area
from .parts import Finding, part, viewport_commands, viewport_keys

LEAST_FILL = 0.6
"""A diagram should fill at least this share of its drawing area in its binding dimension."""

BLOCK_MARGIN = 2.0
"""Each content block of a page is grown by this much (mm, each side) before the blank is measured: the
white a block needs around it to read as one."""

MOST_BLANK = 0.5
"""A page whose frame is more than this share blank is flagged."""

MOST_CELL_LINES = 2
"""A title-block cell should hold its value in at most this many lines."""


def _drawing_area(rect: Rect, header: list) -> Rect:
    """A viewport's room for its drawing: below its header (heading and scale bar), to its edges."""
    top = max([rect.top] + [b.bottom for b in (bounding([c]) for c in header) if b is not None])
    return Rect.from_edges(rect.left, top, rect.right, rect.bottom)


def larger_scale_growth(scale) -> float | None:
    """How many times larger the diagram would be drawn at the next larger scale of its series -- ISO 5455
    for a drawing of lengths (a space diagram, a free body, a cam), 1-2-5 for the others (a vector
    polygon's "1 mm = x units") -- or None when the series has none larger."""
    if scale.quantity == "length":
        factor = 0.001 / scale.units_per_mm                 # paper mm per model mm
        larger = [ratio_factor(r) for r in ISO_5455 if ratio_factor(r) > factor * (1 + 1e-9)]
        return min(larger) / factor if larger else None
    if not scale.per_mm > 0:
        return None
    return scale.per_mm / nice_floor(scale.per_mm * (1 - 1e-9))


def diagram_fill(sheet) -> list[Finding]:
    """diagram-fill: a diagram (a viewport with a drawing scale) whose drawn extent -- the box of
    everything drawn in its viewport below the header, labels included -- fills less than
    :data:`LEAST_FILL` of its drawing area (the viewport below its header) in the binding dimension:
    max(extent width / area width, extent height / area height) < 0.6; unless the next larger scale of its
    series (:func:`larger_scale_growth`) would not fit: the figure (labels left out) grown by that factor,
    with :data:`~drafting.layout.panel.VIEW_PAD` of room for labels each side, wider or taller than the
    area less 1 mm each side (the layout's own rule).  Value: the fill ratio."""
    out = []
    for key in viewport_keys(sheet.regions):
        scale = sheet.diagram_scales.get(key)
        if scale is None:
            continue
        rect = sheet.regions[f"viewport:{key}"]
        header, drawing = viewport_commands(sheet.commands, rect)
        ext = bounding(drawing)
        if ext is None:
            continue
        area = _drawing_area(rect, header)
        if area.w <= 0 or area.h <= 0:
            continue
        ratio = max(ext.w / area.w, ext.h / area.h)
        if ratio >= LEAST_FILL:
            continue
        growth = larger_scale_growth(scale)
        fig = bounding(c for c in drawing if part(c.name) not in ("label", "label bg"))
        if growth is None or fig is None:
            continue
        plot = area.inset(1.0)
        if fig.w * growth + 2 * VIEW_PAD > plot.w or fig.h * growth + 2 * VIEW_PAD > plot.h:
            continue
        out.append(Finding("diagram-fill", sheet.number, f"the {key} diagram fills {ratio:.0%} of its panel "
                           f"({ext.w:.0f} x {ext.h:.0f} mm in {area.w:.0f} x {area.h:.0f} mm) and would fit "
                           f"{growth:g} times larger", ext, ratio))
    return out


def content_blocks(sheet) -> list[Rect]:
    """The page's content: each viewport's drawn extent (header included), each line of text outside the
    viewports and the title block (text blocks and tables, line by line), each table rule, and the title
    block -- not yet grown by :data:`BLOCK_MARGIN`."""
    blocks = []
    keys = viewport_keys(sheet.regions)
    for key in keys:
        header, drawing = viewport_commands(sheet.commands, sheet.regions[f"viewport:{key}"])
        ext = bounding(header + drawing)
        if ext is not None:
            blocks.append(ext)
    for c in sheet.commands:
        if type(c) is Text and not c.region.startswith("viewport:") and c.region != "title_block":
            blocks.append(c.box)
        elif c.style == "rule" and not c.name.startswith("title block"):
            blocks.append(bounding([c]))
    if "title_block" in sheet.regions:
        blocks.append(sheet.regions["title_block"])
    return blocks


def blank_fraction(sheet) -> float:
    """The share of the frame not covered by the page's content blocks, each grown by
    :data:`BLOCK_MARGIN` (see :func:`content_blocks`)."""
    frame = sheet.regions.get("frame", sheet.paper.frame)
    covered = covered_area((b.expanded(BLOCK_MARGIN) for b in content_blocks(sheet)), frame)
    return 1.0 - covered / (frame.w * frame.h)


def blank_page(sheet) -> list[Finding]:
    """blank-page: a page whose :func:`blank_fraction` is more than :data:`MOST_BLANK`.  Value: the
    blank fraction."""
    blank = blank_fraction(sheet)
    if blank <= MOST_BLANK:
        return []
    frame = sheet.regions.get("frame", sheet.paper.frame)
    return [Finding("blank-page", sheet.number, f"{blank:.0%} of the frame is blank", frame, blank)]


def small_lettering(sheet) -> list[Finding]:
    """lettering: a text with a main run -- a span set on the baseline (shift 0), not a subscript or
    superscript -- smaller than MIN_TEXT (2.5 mm, ISO 3098's least height).  The size is the span's font
    size in mm as the command carries it (the em, as the SVG's font-size).  Value: the smallest such
    size, mm."""
    out = []
    for t in sheet.commands:
        if type(t) is not Text:
            continue
        sizes = [s.size for s in t.spans if s.shift == 0 and s.text.strip()]
        if sizes and min(sizes) < MIN_TEXT - 1e-9:
            out.append(Finding("lettering", sheet.number, f"{t.plain!r} ({t.name}) is lettered "
                               f"{min(sizes):g} mm high", t.box, min(sizes)))
    return out


def title_cells(sheet) -> list[Finding]:
    """title-cell: a title-block cell whose value takes more than :data:`MOST_CELL_LINES` lines: the
    texts of the title block (region "title_block") of one name, its caption apart ("title", "title block
    Scale" ...; each Text is one line).  Value: the number of lines."""
    cells: dict[str, list[Text]] = defaultdict(list)
    for t in sheet.commands:
        if type(t) is Text and t.region == "title_block" and not t.name.startswith("title block caption "):
            cells[t.name].append(t)
    out = []
    for name, lines in cells.items():
        if len(lines) > MOST_CELL_LINES:
            where = bounding(lines)
            out.append(Finding("title-cell", sheet.number, f"the title block's {name!r} takes {len(lines)} lines",
                               where, float(len(lines))))
    return out
