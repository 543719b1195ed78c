"""Text items that flow into text slots: headings, paragraphs, vector equations with their marks and the
results table, grouped in sections.

Each item sets itself at a width and lettering size as drawing commands from its top-left corner
(:class:`Placed`), or raises :class:`TooWide`; :meth:`Item.height` may find its height without making
the commands.  Where the items go is :mod:`drafting.layout.flow`'s business.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

from constructions.record import Term, VectorEquation

from ..render.paper import Command, Line, Span, translated
from ..render.style import HEADING, LABEL, Extent, measure, plain, rich, sub_size, text_width
from .wrap import line_baselines, stack_lines, text_at, wrap_words, wrapped_extents, wrapped_height


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
    keep_with_next: bool = False  # set in the same slot as the next item (a step with its table under it)

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


@functools.lru_cache(maxsize=8192)
def table_cell(text: str, size: float) -> tuple[tuple[Span, ...], Extent]:
    """A table cell's spans and extent (a table is measured at every width its page plans try)."""
    spans = rich(text, size)
    return spans, measure(spans)



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
        cells = [[table_cell(c, size) for c in row] for row in (self.header,) + self.rows]
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
                    bottom = max(bottom, line_baselines(ext, y_row, size)[1])
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
