"""The title block at the bottom right of a sheet's frame: the title over rows of captioned fields
(scale, units, drawing number, date, sheet n/m), sized to its width before anything is drawn."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

from ..render.errors import LayoutError
from ..render.paper import Command, Line, Rect, Rectangle, Span, translated
from ..render.style import LABEL, MIN_TEXT, TITLE, measure, plain, rich
from .wrap import balanced_width, line_baselines, stack_lines, text_at, wrap_words


TB_PAD = 1.2
TB_CAPTION = MIN_TEXT


@dataclass(frozen=True)
class TitleBlock:
    commands: tuple[Command, ...]
    rect: Rect


def _cell_value_lines(value: str, width: float) -> tuple[list[tuple[Span, ...]], float]:
    for size in (3.5, 3.0, 2.5):
        spans = rich(value, size)
        if measure(spans).width <= width:
            return [spans], size
    return wrap_words(value, width, 2.5), 2.5


@dataclass(frozen=True)
class _BlockPlan:
    """What :func:`title_block` sets where, found without making a command: the title's size and
    lines, and per row of fields its cells (caption x, caption baseline, value lines and size, value
    top) and column rules; the height of every row."""

    size: float
    title_lines: tuple
    rows: tuple
    heights: tuple[float, ...]


def _block_plan(width: float, title: str, fields: Sequence[Sequence[tuple[str, str]]]) -> _BlockPlan:
    # the title row: 7 mm, shrunk to 3.5, then wrapped
    inner = width - 2 * TB_PAD
    size = TITLE
    tw = measure(rich(title, 1.0)).width
    if tw * size > inner:
        size = max(LABEL, math.floor(inner / tw * 4) / 4)
    if tw * size <= inner:
        title_lines = [rich(title, size)]
    else:
        title_lines = wrap_words(title, balanced_width(title, inner, size), size)     # lines of one length
    t_bottom = line_baselines([(m.top, m.bottom) for m in map(measure, title_lines)], TB_PAD + 0.6, size)[1]
    heights: list[float] = [max(12.0, t_bottom + TB_PAD + 0.6)]
    cap_ext = measure(plain("Xg", TB_CAPTION))
    rows = []
    for row in fields:
        n = len(row)
        caps = [measure(plain(c, TB_CAPTION)).width for c, _ in row]
        vals = [measure(rich(v, 3.5)).width for _, v in row]
        nat = [max(c, v) + 2 * TB_PAD for c, v in zip(caps, vals)]
        if sum(nat) <= width:
            spare = width - sum(nat)
            widths = [w + spare / n for w in nat]
            if n == 2:   # a scale/units row: the first (scale) cell takes the spare
                widths = [nat[0] + spare, nat[1]]
        else:
            mins = [c + 2 * TB_PAD for c in caps]
            rest = width - sum(mins)
            if rest <= 0:
                raise LayoutError("the title block is too narrow for its field names; use A3")
            extra = [max(v + 2 * TB_PAD - m, 0.0) for v, m in zip(vals, mins)]
            tot = sum(extra) or 1.0
            widths = [m + rest * e / tot for m, e in zip(mins, extra)]
        x = 0.0
        row_h = 0.0
        cells, col_x = [], []
        for (cap, val), w in zip(row, widths):
            cap_spans = plain(cap, TB_CAPTION)
            cap_y = 0.5 - cap_ext.top
            lines, vs = _cell_value_lines(val, w - 2 * TB_PAD)
            v_top = measure(cap_spans).box(x + TB_PAD, cap_y).bottom + 0.6    # under the caption (text_at's box)
            vb = line_baselines([(m.top, m.bottom) for m in map(measure, lines)], v_top, vs)[1]
            cells.append((cap, x, cap_spans, cap_y, lines, vs, v_top))
            row_h = max(row_h, vb + 0.7)
            if x > 0:
                col_x.append(x)
            x += w
        row_h = max(row_h, 9.0)
        rows.append((tuple(cells), tuple(col_x)))
        heights.append(row_h)
    return _BlockPlan(size, tuple(title_lines), tuple(rows), tuple(heights))


def title_block_height(width: float, title: str, fields: Sequence[Sequence[tuple[str, str]]]) -> float:
    """The height of :func:`title_block` ``width`` wide, without making its commands."""
    return sum(_block_plan(width, title, fields).heights)


def title_block(frame: Rect, width: float, title: str, fields: Sequence[Sequence[tuple[str, str]]], *,
                region: str = "title_block") -> TitleBlock:
    """The title block at the bottom right of ``frame``: the title over rows of captioned fields."""
    bp = _block_plan(width, title, fields)
    rows_cmds: list[list[Command]] = [list(stack_lines(bp.title_lines, TB_PAD, TB_PAD + 0.6, bp.size,
                                                       style="title", name="title")[0])]
    for (cells, col_x), row_h in zip(bp.rows, bp.heights[1:]):
        cmds: list[Command] = []
        for cap, x, cap_spans, cap_y, lines, vs, v_top in cells:
            cmds.append(text_at(x + TB_PAD, cap_y, cap_spans, name=f"title block caption {cap}"))
            cmds.extend(stack_lines(lines, x + TB_PAD, v_top, vs, name=f"title block {cap}")[0])
        cmds.extend(Line(cx, 0.0, cx, row_h, "rule", "title block column") for cx in col_x)
        rows_cmds.append(cmds)
    total_h = sum(bp.heights)
    rect = Rect(frame.right - width, frame.bottom - total_h, width, total_h)
    out: list[Command] = [Rectangle(rect.x, rect.y, rect.w, rect.h, "title_block", "title block")]
    y = rect.y
    for i, (cmds, h) in enumerate(zip(rows_cmds, bp.heights)):
        if i:
            out.append(Line(rect.x, y, rect.right, y, "rule", "title block row"))
        out.extend(translated(c, rect.x, y, region) for c in cmds)
        y += h
    return TitleBlock(tuple(out), rect)


def scale_cell(scales: Sequence[str]) -> str:
    """The title block's scale: the one scale of the sheet's drawings, "As shown" when each of several
    carries its own (in its heading or scale bar), a dash on a sheet of text."""
    if not scales:
        return "\u2014 (no drawing on this sheet)"
    return scales[0] if len(scales) == 1 else "As shown"
