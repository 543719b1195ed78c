"""Layout: text flow, tables, scale bars, viewport headers and the title block.

Text items (headings, paragraphs, vector equations with their marks, the results table) are set into
text slots in order at one lettering size, shrunk step by step from 3.5 mm to no less than 2.5 mm
until they fit (:func:`flow_shrinking`); the slots may lie on several pages.  Where the slots and the
diagram panels go is :mod:`drafting.layout.pages`' business.

Everything returned is drawing commands (:mod:`drafting.render.paper`) in paper mm, y down.  ``Transform``
and ``LayoutError`` used to live here and are still importable from here.
"""

from __future__ import annotations

import functools
import itertools
import math
from dataclasses import dataclass
from typing import MutableMapping, Sequence

from constructions.record import Term, VectorEquation

from ..render.errors import LayoutError  # re-exported: its old home
from ..render.paper import Command, Line, Rect, Rectangle, Span, Text, translated
from ..render.scales import ISO_5455, nice_values, number_text, ratio_factor, ratio_text  # noqa: F401 (re-exported)
from ..render.style import (HEADING, LABEL, MIN_TEXT, SUB_SHIFT, TITLE, Extent, font_metrics, measure, plain,
                    rich, sub_size, text_width)
from ..render.transform import Transform  # noqa: F401 (re-exported: its old home)


# ---- text primitives ----------------------------------------------------------------------------

def text_at(x: float, y: float, spans: Sequence[Span], *, style: str = "text", region: str = "",
            name: str = "", anchor: str = "start") -> Text:
    """A Text command with its measured box; ``anchor`` 'middle'/'end' shifts x (start anchor in SVG)."""
    spans = tuple(spans)
    ext = measure(spans)
    if anchor == "middle":
        x -= ext.width / 2
    elif anchor == "end":
        x -= ext.width
    return Text(x, y, spans, style, ext.box(x, y), region, name)


def wrap_words(markup: str, width: float, size: float) -> list[tuple[Span, ...]]:
    """Greedy word wrap of rich text into lines no wider than ``width`` mm; neighbouring runs of one
    size, shift and slant are joined into one span as the line is built."""
    words = _words(markup, size)
    if not words:
        return []
    breaks = _breaks(_word_columns(markup, size)[0], width, text_width(" ", size))
    if breaks is None:
        return _wrap_splitting(markup, width, size)
    space = Span(" ", size)
    plain_words = _plain_words(markup, size)
    lines = []
    for i0, i1 in breaks:
        texts = plain_words[i0:i1]
        if None not in texts:                  # plain words only: the runs merge into one span
            lines.append((Span(" ".join(texts), size),))
            continue
        flat: list[Span] = list(words[i0][0])
        for i in range(i0 + 1, i1):
            flat.append(space)
            flat.extend(words[i][0])
        # neighbouring runs of one size, shift and slant joined (as _add joins them)
        lines.append(tuple(Span("".join(sp.text for sp in group), *key)
                           for key, group in itertools.groupby(flat, key=_run_key)))
    return lines


def _run_key(s: Span) -> tuple[float, float, bool]:
    return s[1:]


@functools.lru_cache(maxsize=4096)
def _plain_words(markup: str, size: float) -> list[str | None]:
    """Each word of ``markup`` at ``size`` as its text when it is one upright span on the baseline at
    ``size`` (a space joins such words into the same run), else None (never changed: remembered)."""
    return [sp[0].text if len(sp) == 1 and sp[0].size == size and sp[0].shift == 0.0 and not sp[0].italic
            else None for sp, _, _, _ in _words(markup, size)]


@functools.lru_cache(maxsize=4096)
def _words(markup: str, size: float) -> tuple[tuple[tuple[Span, ...], float, float, float], ...]:
    """Each word of ``markup`` at ``size``: (spans, width, top, bottom), its extent as :func:`measure`
    takes it (from the baseline, 0 included)."""
    return tuple(_word(w, size) for w in markup.split())


@functools.lru_cache(maxsize=4096)
def _word_columns(markup: str, size: float) -> tuple[list[float], list[float], list[float]]:
    """The widths, tops and bottoms of the words of ``markup`` at ``size`` (see :func:`_words`), as
    lists (never changed: they are remembered)."""
    words = _words(markup, size)
    return [w[1] for w in words], [w[2] for w in words], [w[3] for w in words]


def _breaks(widths: Sequence[float], width: float, space: float) -> list[tuple[int, int]] | None:
    """The greedy wrap of words of the given ``widths`` into lines no wider than ``width``: the lines as
    (first, end) word indices; None when a word is longer than the line (it must be split:
    :func:`_wrap_splitting`)."""
    lines: list[tuple[int, int]] = []
    start, cur_w = 0, 0.0
    for i, w in enumerate(widths):
        if w > width:
            return None
        if i > start and cur_w + space + w > width:
            lines.append((start, i))
            start, cur_w = i, 0.0
        if i > start:
            cur_w += space
        cur_w += w
    lines.append((start, len(widths)))
    return lines


def _add(run: list[list], s: Span) -> None:
    if run and run[-1][1] == s.size and run[-1][2] == s.shift and run[-1][3] == s.italic:
        run[-1][0] += s.text
    else:
        run.append([s.text, s.size, s.shift, s.italic])


def _wrap_splitting(markup: str, width: float, size: float) -> list[tuple[Span, ...]]:
    """The greedy wrap when some word is longer than the line: that word is split letter by letter."""
    space = text_width(" ", size)
    lines: list[list[list]] = []
    cur: list[list] = []
    cur_w = 0.0
    for word in markup.split():
        spans, w, _, _ = _word(word, size)
        if w > width:
            for piece in _split_long(word, width, size):
                if cur:
                    lines.append(cur)
                cur = []
                for sp in rich(piece, size):
                    _add(cur, sp)
                cur_w = measure(rich(piece, size)).width
            continue
        if cur and cur_w + space + w > width:
            lines.append(cur)
            cur, cur_w = [], 0.0
        if cur:
            _add(cur, Span(" ", size))
            cur_w += space
        for sp in spans:
            _add(cur, sp)
        cur_w += w
    if cur:
        lines.append(cur)
    return [tuple(Span(*r) for r in line) for line in lines]


@functools.lru_cache(maxsize=8192)
def _cell(text: str, size: float) -> tuple[tuple[Span, ...], Extent]:
    """A table cell's spans and extent (a table is measured at every width its page plans try)."""
    spans = rich(text, size)
    return spans, measure(spans)


@functools.lru_cache(maxsize=16384)
def _word(word: str, size: float) -> tuple[tuple[Span, ...], float, float, float]:
    """A word's spans, width, top and bottom (measured once per word and size)."""
    spans = rich(word, size)
    m = measure(spans)
    return spans, m.width, m.top, m.bottom


def _split_long(word: str, width: float, size: float) -> list[str]:
    out, cur = [], ""
    for ch in word:
        if cur and text_width(cur + ch, size) > width:
            out.append(cur)
            cur = ""
        cur += ch
    if cur:
        out.append(cur)
    return out


def stack_lines(lines: Sequence[tuple[Span, ...]], x: float, top: float, size: float, *,
                style: str = "text", name: str = "") -> tuple[list[Text], float]:
    """Lines one under the other, the first box top at ``top``; returns texts and the bottom."""
    ms = [measure(line) for line in lines]
    ys, bottom = _baselines([(m.top, m.bottom) for m in ms], top, size)
    return [Text(x, y, tuple(line), style, m.box(x, y), "", name) for line, m, y in zip(lines, ms, ys)], bottom


@functools.lru_cache(maxsize=64)
def _line_room(size: float) -> tuple[float, float]:
    """The top and bottom every line at ``size`` is given room for (a subscript included)."""
    asc, desc = font_metrics()
    return -asc * size, SUB_SHIFT * size + desc * sub_size(size)


def _baselines(extents: Sequence[tuple[float, float]], top: float, size: float) -> tuple[list[float], float]:
    """The baselines of lines of the given (top, bottom) extents stacked from ``top``, and the bottom.
    Every line is given room for a subscript, so lines with and without one are evenly spaced."""
    n_top, n_bottom = _line_room(size)
    ys: list[float] = []
    y_prev = prev_bottom = 0.0
    for t, b in extents:
        e_top, e_bottom = min(t, n_top), max(b, n_bottom)
        y = top - e_top if not ys else y_prev + max(1.35 * size, prev_bottom - e_top + 0.1 * size)
        ys.append(y)
        y_prev, prev_bottom = y, e_bottom
    return ys, (top if not ys else y_prev + prev_bottom)


def wrapped_extents(markup: str, width: float, size: float) -> list[tuple[float, float]] | None:
    """The (top, bottom) extent of each line of ``markup`` wrapped to ``width``, as :func:`measure` takes
    the line :func:`wrap_words` makes, found from the word table without making a span; None when a
    word would have to be split."""
    widths, tops, bottoms = _word_columns(markup, size)
    got = _breaks(widths, width, text_width(" ", size)) if widths else []
    if got is None:
        return None
    asc, desc = font_metrics()
    sp_top, sp_bottom = -asc * size, desc * size              # the space between words
    ext = []
    for i0, i1 in got:
        if i1 - i0 > 1:
            ext.append((min(min(tops[i0:i1]), sp_top), max(max(bottoms[i0:i1]), sp_bottom)))
        else:
            ext.append((min(tops[i0], 0.0), max(bottoms[i0], 0.0)))
    return ext


def wrapped_height(markup: str, width: float, size: float) -> float | None:
    """The height :func:`stack_lines` gives ``markup`` wrapped to ``width`` (from 0), found from the word
    table without making a span or a command; None when a word would have to be split."""
    ext = wrapped_extents(markup, width, size)
    return None if ext is None else _baselines(ext, 0.0, size)[1]


# ---- text blocks: items that flow into slots -------------------------------------------------------

class TooWide(Exception):
    """An item cannot be set in the width it was given at this lettering size."""


@dataclass(frozen=True)
class Placed:
    """An item set at one width: its commands (from its top-left corner) and height."""

    commands: tuple[Command, ...]
    height: float


class Item:
    keep_with_next = False

    def layout(self, width: float, size: float) -> Placed:  # pragma: no cover - interface
        raise NotImplementedError

    def height(self, width: float, size: float) -> float:
        """``layout(width, size).height``; an item may find it without making its commands."""
        return self.layout(width, size).height


def heading_size(size: float) -> float:
    return min(HEADING, max(LABEL, round(size * HEADING / LABEL, 2)))


@dataclass(frozen=True)
class Heading(Item):
    text: str
    keep_with_next = True

    def layout(self, width: float, size: float) -> Placed:
        hs = heading_size(size)
        spans = plain(self.text, hs)
        lines = wrap_words(self.text, width, hs) if measure(spans).width > width else [spans]
        texts, bottom = stack_lines(lines, 0.0, 0.0, hs, style="heading", name=f"heading {self.text}")
        return Placed(tuple(texts), bottom)


@dataclass(frozen=True)
class Paragraph(Item):
    """Wrapped rich text with an optional hanging label ("3.") in a column ``label_width`` wide."""

    markup: str
    label: str = ""
    label_chars: str = ""         # the widest label of the list, to size the label column
    name: str = ""

    def _indent(self, size: float) -> float:
        return text_width(self.label_chars or self.label, size) + 0.6 * size if self.label or self.label_chars else 0.0

    def height(self, width: float, size: float) -> float:
        indent = self._indent(size)
        if width - indent < 8 * size:
            raise TooWide(self.markup)
        h = wrapped_height(self.markup, width - indent, size)
        return self.layout(width, size).height if h is None else h

    def layout(self, width: float, size: float) -> Placed:
        indent = self._indent(size)
        cmds: list[Command] = []
        if width - indent < 8 * size:
            raise TooWide(self.markup)
        lines = wrap_words(self.markup, width - indent, size)
        texts, bottom = stack_lines(lines, indent, 0.0, size, name=self.name)
        cmds.extend(texts)
        if self.label:
            y = texts[0].y if texts else -measure(plain(self.label, size)).top
            cmds.append(text_at(indent - 0.6 * size, y, plain(self.label, size), anchor="end",
                                name=f"{self.name} number"))
        return Placed(tuple(cmds), bottom)


MARK_YES = "\u2713"   # check mark: known
MARK_NO = "\u00d7"    # cross: unknown


def term_spans(term: Term, size: float) -> tuple[Span, ...]:
    sup = f"^{{{term.superscript}}}" if term.superscript else ""
    return rich(f"{term.quantity}_{{{term.subscript}}}{sup}", size, italic_symbols=True)


def marks_text(term: Term) -> str:
    return (MARK_YES if term.magnitude_known else MARK_NO) + (MARK_YES if term.direction_known else MARK_NO)


@dataclass(frozen=True)
class EquationItem(Item):
    """A vector equation with the notes' marks over every term: first magnitude, then direction."""

    equation: VectorEquation
    name: str = "equation"

    def layout(self, width: float, size: float) -> Placed:
        size = min(LABEL, size + 0.5)           # equations a little larger than the body text
        ms = sub_size(size)
        # tokens: (spans, term or None)
        tokens: list[tuple[tuple[Span, ...], Term | None]] = []
        for side_i, side in enumerate((self.equation.left, self.equation.right)):
            if side_i == 1:
                tokens.append((plain(" = ", size), None))
            for i, t in enumerate(side):
                if i:
                    tokens.append((plain(" + ", size), None))
                tokens.append((term_spans(t, size), t))
            if side_i == 1 and not side:           # an equilibrium: the left-hand terms sum to zero
                tokens.append((plain("0", size), None))
        # greedy wrap at operators; continuation lines indented
        lines: list[list[tuple[tuple[Span, ...], Term | None]]] = [[]]
        cur_w = 0.0
        indent = 2.0 * size
        for spans, term in tokens:
            w = measure(spans).width
            limit = width - (indent if len(lines) > 1 else 0.0)
            if term is not None and lines[-1] and cur_w + w > limit:
                lines.append([])
                cur_w = 0.0
            if term is None and not lines[-1]:
                continue
            lines[-1].append((spans, term))
            cur_w += w
            if term is not None and cur_w > width - (indent if len(lines) > 1 else 0.0):
                raise TooWide(str(self.equation))
        cmds: list[Command] = []
        top = 0.0
        mark_ext = measure(plain(MARK_YES + MARK_NO, ms))
        for li, line in enumerate(lines):
            all_spans = tuple(s for spans, _ in line for s in spans)
            eq_ext = measure(all_spans)
            y_mark = top - mark_ext.top
            y_eq = y_mark + mark_ext.bottom + 0.25 * size - eq_ext.top
            x = indent if li else 0.0
            first = next((spans for spans, term in line if term is not None), None)
            if first is not None:        # keep the marks over the first symbol inside the column
                x += max(0.0, (measure(plain(MARK_YES + MARK_NO, ms)).width - measure(first[:1]).width) / 2)
            cmds.append(text_at(x, y_eq, all_spans, name=self.name))
            for spans, term in line:
                w = measure(spans).width
                if term is not None:
                    base_w = measure(spans[:1]).width
                    cx = x + base_w / 2 if len(spans) > 1 else x + w / 2
                    cmds.append(text_at(cx, y_mark, plain(marks_text(term), ms), anchor="middle",
                                        name=f"{self.name} marks {term.symbol}"))
                x += w
            top = y_eq + eq_ext.bottom + 0.35 * size
        return Placed(tuple(cmds), top - 0.35 * size)


@dataclass(frozen=True)
class TableItem(Item):
    """The results table: quantity, graphical, analytic, difference (and a note column if any)."""

    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    align: tuple[str, ...]         # 'l' or 'r' per column
    wrap_last: bool = False
    name: str = "results"

    def _columns(self, width: float, size: float) -> tuple[list[list[tuple[tuple[Span, ...], Extent]]], list[float]]:
        """Every cell's spans and extent (the header row first) and the column widths at ``width``."""
        pad = 0.45 * size
        ncol = len(self.header)
        cells = [[_cell(c, size) for c in row] for row in (self.header,) + self.rows]
        nat = [max(r[i][1].width for r in cells) + 2 * pad for i in range(ncol)]
        widths = list(nat)
        if sum(widths) > width:
            if self.wrap_last:
                rest = width - sum(widths[:-1])
                if rest < 8 * size:
                    raise TooWide("results table")
                widths[-1] = rest
            else:
                raise TooWide("results table")
        else:
            # spread the spare width over the value columns, but keep the table compact
            spare = min(width - sum(widths), 6 * size * ncol)
            for i in range(1, ncol):
                widths[i] += spare / max(ncol - 1, 1)
        return cells, widths

    def height(self, width: float, size: float) -> float:
        """:meth:`layout`'s height, row by row with the same arithmetic, without making a command."""
        pad, vpad = 0.45 * size, 0.25 * size
        cells, widths = self._columns(width, size)
        y = 0.0
        for ri, row in enumerate(cells):
            y_row = y + vpad
            bottom = y_row
            for ci, (_, m) in enumerate(row):
                if m.width > widths[ci] - 2 * pad + 1e-9:
                    ext = wrapped_extents(((self.header,) + self.rows)[ri][ci], widths[ci] - 2 * pad, size)
                    if ext is None:                          # a word split letter by letter
                        return self.layout(width, size).height
                else:
                    ext = [(m.top, m.bottom)]
                if ext:
                    bottom = max(bottom, _baselines(ext, y_row, size)[1])
            y = bottom + vpad
        return y

    def layout(self, width: float, size: float) -> Placed:
        pad = 0.45 * size
        vpad = 0.25 * size
        ncol = len(self.header)
        columns, widths = self._columns(width, size)
        cells = [[spans for spans, _ in row] for row in columns]
        cmds: list[Command] = []
        y = 0.0
        xs = [sum(widths[:i]) for i in range(ncol)]
        total = sum(widths)
        cmds.append(Line(0.0, y, total, y, "rule", f"{self.name} top rule"))
        for ri, row in enumerate(cells):
            y_row = y + vpad
            cell_lines: list[list[tuple[Span, ...]]] = []
            for ci, spans in enumerate(row):
                text = ((self.header,) + self.rows)[ri][ci]
                if measure(spans).width > widths[ci] - 2 * pad + 1e-9:
                    cell_lines.append(wrap_words(text, widths[ci] - 2 * pad, size))
                else:
                    cell_lines.append([spans])
            bottom = y_row
            for ci, lines in enumerate(cell_lines):
                if not lines:
                    continue
                texts, b = stack_lines(lines, 0.0, y_row, size,
                                       name=f"{self.name} {'header' if ri == 0 else f'row {ri}'} col {ci}")
                for t in texts:
                    if self.align[ci] == "r":
                        dx = xs[ci] + widths[ci] - pad - t.box.w
                    else:
                        dx = xs[ci] + pad
                    cmds.append(translated(t, dx, 0.0))
                bottom = max(bottom, b)
            y = bottom + vpad
            if ri == 0:
                cmds.append(Line(0.0, y, total, y, "rule", f"{self.name} header rule"))
        cmds.append(Line(0.0, y, total, y, "rule", f"{self.name} bottom rule"))
        return Placed(tuple(cmds), y)


@dataclass(frozen=True)
class Section:
    heading: str
    items: tuple[Item, ...]


LayoutCache = MutableMapping[tuple, "Placed | TooWide"]


def _remembered(cache: LayoutCache, key: tuple, make):
    """``make()`` remembered in ``cache`` under ``key``, a TooWide it raises included (raised again)."""
    got = cache.get(key)
    if got is None:
        try:
            got = make()
        except TooWide as e:
            got = e
        cache[key] = got
    if isinstance(got, TooWide):
        raise got
    return got


def layout_item(item: Item, width: float, size: float, cache: LayoutCache | None = None, *,
                w: float | None = None) -> Placed:
    """``item.layout(width, size)``, remembered in ``cache`` (items are immutable): the same text is
    set once per width and size however many plans are tried.  ``w`` is ``round(width, 6)`` when the
    caller has it already."""
    if cache is None:
        return item.layout(width, size)
    return _remembered(cache, (item, round(width, 6) if w is None else w, size), lambda: item.layout(width, size))


def item_height(item: Item, width: float, size: float, cache: LayoutCache | None = None, *,
                w: float | None = None) -> float:
    """The height ``item`` takes at ``width`` and ``size`` (raises :class:`TooWide`), without making its
    commands when the item can; remembered in ``cache`` beside :func:`layout_item`'s results (``w`` as
    there)."""
    if cache is None:
        return item.height(width, size)
    if w is None:
        w = round(width, 6)
    got = cache.get((item, w, size))                      # set in full already
    if isinstance(got, Placed):
        return got.height
    if isinstance(got, TooWide):
        raise got
    return _remembered(cache, ("height", item, w, size), lambda: item.height(width, size))


class FlowText:
    """Sections made ready to flow many times (a page planner tries many plans): their items in order,
    each section's heading made once, and every item's height remembered per slot width, lettering
    size and kind of measure, in lists (no hashing of items on the way)."""

    def __init__(self, sections: Sequence[Section]) -> None:
        self.sections = tuple(sections)
        self.groups = [tuple([Heading(sec.heading), *sec.items]) if sec.heading else tuple(sec.items)
                       for sec in self.sections]
        self._heights: dict[tuple, list[list]] = {}

    def __len__(self) -> int:
        return len(self.sections)

    def __iter__(self):
        return iter(self.sections)

    def heights(self, w: float, size: float, plan: bool) -> list[list]:
        """Per section, per item: the height at width key ``w`` and ``size`` (a float or the TooWide
        raised), or None while unasked."""
        key = (w, size, plan)
        got = self._heights.get(key)
        if got is None:
            got = self._heights[key] = [[None] * len(g) for g in self.groups]
        return got


def flow(sections: Sequence[Section] | FlowText, slots: Sequence[tuple[str, Rect]], size: float,
         cache: LayoutCache | None = None, *, tagged: bool = False, plan: bool = False) -> list | None:
    """Set the sections into the slots in order at lettering ``size``; None when they do not fit.
    Each text command's region is the name of the slot it went into; with ``tagged`` the result is
    ``(slot name, command)`` pairs (a rule of a table has no region of its own).  With ``plan`` no
    command is made: the result is the name of the slot each item went into, in order (what a page
    planner needs to know of a trial).  A planner that flows the same sections many times passes them
    as one :class:`FlowText`."""
    if not sections:
        return []
    if not slots:
        return None
    text = sections if isinstance(sections, FlowText) else FlowText(sections)
    out: list[Command] = []
    si = 0
    name, slot = slots[si]
    y = slot.top
    section_gap = 1.0 * size
    item_gap = 0.35 * size
    used = False

    def next_slot() -> bool:
        nonlocal si, name, slot, y, used
        si += 1
        if si >= len(slots):
            return False
        name, slot = slots[si]
        y = slot.top
        used = False
        return True

    placements: list[tuple[str, float, float, Item, float]] = []
    measure_item = item_height if plan else (lambda it, wd, sz, c, w: layout_item(it, wd, sz, c, w=w).height)
    widths = [round(r.w, 6) for _, r in slots]
    tables = [text.heights(w, size, plan) for w in widths]

    def height_of(k: int, i: int, item: Item) -> float:
        row = tables[si][k]
        got = row[i]
        if got is None:
            try:
                got = measure_item(item, slot.w, size, cache, w=widths[si])
            except TooWide as e:
                got = e
            row[i] = got
        if isinstance(got, TooWide):
            raise got
        return got

    for k, items in enumerate(text.groups):
        if used:
            y += section_gap
        i = 0
        while i < len(items):
            item = items[i]
            try:
                height = height_of(k, i, item)
                need = height
                if item.keep_with_next and i + 1 < len(items):
                    need += item_gap + height_of(k, i + 1, items[i + 1])
            except TooWide:
                height = None
                need = math.inf
            if height is None or y + need > slot.bottom + 1e-9:
                # too wide or too tall for what is left of this slot: go on in the next one
                if not next_slot():
                    return None
                continue
            placements.append((name, slot.x, y, item, slot.w))
            y += height + item_gap
            used = True
            i += 1
    if plan:
        return [name for name, _, _, _, _ in placements]
    # everything fits: now make the commands
    for name, x, y, item, w in placements:
        placed = layout_item(item, w, size, cache)      # (set in full already when measured so)
        region = slot_region(name)
        moved = [translated(c, x, y, region) for c in placed.commands]
        out.extend(((name, c) for c in moved) if tagged else moved)
    return out


# A document's text slot is named "<page>#<region>": the page's number and the region on that page (the
# commands set in it carry the region).  Made and read only here.

def page_slot(page: int, region: str) -> str:
    return f"{page}#{region}"


def slot_page(name: str) -> str:
    """The page number of a slot named by :func:`page_slot`, as text."""
    return name.partition("#")[0]


def slot_region(name: str) -> str:
    """The region of a slot named by :func:`page_slot` (a name without a page is its own region)."""
    return name.partition("#")[2] or name


TEXT_SIZES = (3.5, 3.25, 3.0, 2.75, 2.5)


def flow_shrinking(sections: Sequence[Section], slots: Sequence[tuple[str, Rect]], *,
                   sizes: Sequence[float] = TEXT_SIZES, cache: LayoutCache | None = None,
                   tagged: bool = False, plan: bool = False) -> tuple[list, float] | None:
    """The largest lettering size (3.5 down to 2.5) at which everything fits, and its commands (with
    ``plan``, the slots the items went into: see :func:`flow`)."""
    # (a lower bound of the height, set at the widest slot, used to skip sizes first: it cost more than it
    # saved -- each plan's slots have their own widths -- and never changed a sheet)
    text = sections if isinstance(sections, FlowText) else FlowText(sections)
    for size in sizes:
        out = flow(text, slots, size, cache, tagged=tagged, plan=plan)
        if out is not None:
            return out, size
    return None


# ---- scale bars -------------------------------------------------------------------------------------

SCALE_BAR_HEIGHT = 1.6
SCALE_TICK = 1.0
SCALE_TEXT = MIN_TEXT


@dataclass(frozen=True)
class _BarPlan:
    """Where a scale bar's parts go (see :func:`scale_bar`), found without making a command."""

    divisions: int
    seg: float
    y_num: float
    y_tick0: float
    y_bar: float
    labels: tuple[str, ...]
    shown: tuple[int, ...]
    unit_x: float
    box: Rect


@functools.lru_cache(maxsize=1024)
def _bar_numbers(value: float) -> tuple[int, tuple[str, ...], tuple[Extent, ...]]:
    """A bar standing for ``value``: its divisions, and the number at every division with its extent."""
    divisions = _divisions(value)
    labels = tuple(number_text(value * i / divisions) for i in range(divisions + 1))
    return divisions, labels, tuple(measure(plain(t, SCALE_TEXT)) for t in labels)


def _bar_rows(top: float, unit: str) -> tuple[float, float, float, float]:
    """A scale bar's rows under ``top``: the numbers' baseline, the ticks' top, the bar's top, and the
    bottom of the bar and its unit (the same whatever the bar's length and value)."""
    num_ext = measure(plain("0", SCALE_TEXT))
    y_num = top - num_ext.top
    y_tick0 = y_num + num_ext.bottom + 0.4
    y_bar = y_tick0 + SCALE_TICK
    return y_num, y_tick0, y_bar, max(y_bar + SCALE_BAR_HEIGHT,
                                      measure(plain(unit, SCALE_TEXT)).box(0.0, y_bar + SCALE_BAR_HEIGHT).bottom)


def _bar_bottom(top: float, unit: str) -> float:
    """The bottom of the box :func:`_bar_plan` gives a bar under ``top`` (as that Rect computes it)."""
    return Rect.from_edges(0.0, top, 1.0, _bar_rows(top, unit)[3]).bottom


def _bar_plan(x: float, top: float, length: float, value: float, unit: str) -> _BarPlan:
    divisions, labels, exts = _bar_numbers(value)
    seg = length / divisions
    ts = SCALE_TEXT
    y_num, y_tick0, y_bar, bottom = _bar_rows(top, unit)
    widths = [e.width for e in exts]
    every = 1
    while every < divisions and any(
            (widths[i] + widths[min(i + every, divisions)]) / 2 + 1.0 > seg * every
            for i in range(0, divisions, every)):
        every += 1
        while divisions % every:
            every += 1
    shown = sorted(set(range(0, divisions + 1, every)) | {0, divisions})
    if len(shown) > 2 and shown[-2] + every > divisions:
        # the last regular number may crowd the end number
        gap = (widths[shown[-2]] + widths[-1]) / 2 + 1.0
        if (divisions - shown[-2]) * seg < gap:
            shown.pop(-2)
    unit_x = x + length + 1.2
    unit_box = measure(plain(unit, ts)).box(unit_x, y_bar + SCALE_BAR_HEIGHT)
    # the boxes text_at gives the first and the last number
    first = exts[shown[0]].box(x + shown[0] * seg - widths[shown[0]] / 2, y_num)
    last = exts[shown[-1]].box(x + shown[-1] * seg - widths[shown[-1]] / 2, y_num)
    box = Rect.from_edges(min(x, first.left), top, max(unit_box.right, last.right), bottom)
    return _BarPlan(divisions, seg, y_num, y_tick0, y_bar, labels, tuple(shown), unit_x, box)


def scale_bar(x: float, top: float, length: float, value: float, unit: str, *, region: str = "",
              name: str = "scale bar") -> tuple[list[Command], Rect]:
    """A scale bar ``length`` mm long standing for ``value`` ``unit``, numbers above, top at ``top``.

    Alternate black and white segments (reads in black and white), a tick and number at every
    division where the numbers fit, the unit after the bar.  Returns the commands and the bounding box.
    """
    bp = _bar_plan(x, top, length, value, unit)
    seg, ts = bp.seg, SCALE_TEXT
    cmds: list[Command] = []
    for i in range(bp.divisions):
        cmds.append(Rectangle(x + i * seg, bp.y_bar, seg, SCALE_BAR_HEIGHT,
                              "bar_dark" if i % 2 == 0 else "bar_light", f"{name} segment {i}"))
    cmds.append(Rectangle(x, bp.y_bar, length, SCALE_BAR_HEIGHT, "tick", f"{name} outline"))
    texts: list[Text] = []
    for i in range(bp.divisions + 1):
        xi = x + i * seg
        cmds.append(Line(xi, bp.y_tick0, xi, bp.y_bar, "tick", f"{name} tick {i}"))
        if i in bp.shown:
            texts.append(text_at(xi, bp.y_num, plain(bp.labels[i], ts), anchor="middle", region=region,
                                 name=f"{name} number {i}"))
    texts.append(text_at(bp.unit_x, bp.y_bar + SCALE_BAR_HEIGHT, plain(unit, ts), region=region,
                         name=f"{name} unit"))
    cmds.extend(texts)
    return cmds, bp.box


def _divisions(value: float) -> int:
    lead = round(value / 10 ** math.floor(math.log10(value) + 1e-12), 6)
    return {1.0: 5, 2.0: 4, 5.0: 5}.get(lead, 4)


def choose_bar(paper_per_unit: float, max_len: float, *, min_len: float = 20.0,
               pref_len: float = 80.0) -> tuple[float, float] | None:
    """(value, paper length) of the longest 1-2-5 bar no longer than min(max_len, pref_len)."""
    limit = min(max_len, pref_len)
    if limit <= 0:
        return None
    if not (paper_per_unit > 0 and math.isfinite(paper_per_unit)) or limit < min_len:
        return None
    vals = nice_values(min_len / paper_per_unit, limit / paper_per_unit)
    if not vals:
        return None
    v = vals[-1]
    return v, v * paper_per_unit


# ---- viewport header: heading and scale bar ------------------------------------------------------

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
        top = rect.y + HEADER_GAP + max(0.0, (hbox.h - _bar_bottom(0.0, unit)) / 2)
        return _HeaderPlan(head, x0, y0, (bx, top, length, v),
                           max(hbox.bottom, _bar_bottom(top, unit)) - rect.y + HEADER_GAP)
    bar = choose_bar(paper_per_unit, rect.w - 3.0 - unit_w - overhang, min_len=10.0)
    if bar is None:
        raise LayoutError(f"the {name} viewport is too narrow for its scale bar; use A3")
    v, length = bar                         # under the heading
    top = hbox.bottom + 1.5
    return _HeaderPlan(head, x0, y0, (x0 + 1.5, top, length, v), _bar_bottom(top, unit) - rect.y + HEADER_GAP)


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


# ---- title block --------------------------------------------------------------------------------

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
    tw = measure(plain(title, 1.0)).width
    if tw * size > inner:
        size = max(LABEL, math.floor(inner / tw * 4) / 4)
    if tw * size <= inner:
        title_lines = [plain(title, size)]
    else:
        title_lines = wrap_words(title, inner, size)
    t_bottom = _baselines([(m.top, m.bottom) for m in map(measure, title_lines)], TB_PAD + 0.6, size)[1]
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
            vb = _baselines([(m.top, m.bottom) for m in map(measure, lines)], v_top, vs)[1]
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
