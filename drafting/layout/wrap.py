"""Lettering: a text command with its measured box, greedy word wrap and lines stacked under each other.

:func:`wrap_words` wraps rich text (:func:`drafting.render.style.rich`) into lines no wider than a width,
splitting a word letter by letter only when it is longer than the line; :func:`stack_lines` sets lines
one under the other, each given room for a subscript so lines with and without one are evenly spaced.
:func:`wrapped_extents` and :func:`wrapped_height` find what wrapping would give from a remembered table
of the words, without making a span (a page planner asks many times).
"""

from __future__ import annotations

import functools
import itertools
import math
import re
from typing import Sequence

from ..render.paper import Span, Text
from ..render.style import SUB_SHIFT, font_metrics, measure, rich, sub_size, text_width


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
    return tuple(_word(w, size) for w in words_of(markup))


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


def balanced_width(markup: str, width: float, size: float) -> float:
    """The least width, down to a hundredth of a millimetre, at which ``markup`` wraps greedily into no
    more lines than at ``width``: a title wrapped to it has lines of about one length (as a typesetter
    breaks a heading), not a full line and a word left over.  ``width`` itself when a word would have to
    be split there or the text takes one line."""
    widths = _word_columns(markup, size)[0]
    space = text_width(" ", size)
    got = _breaks(widths, width, space) if widths else None
    if got is None or len(got) < 2:
        return width
    n = len(got)
    lo, hi = max(widths), width                  # the greedy wrap's line count only grows as it narrows
    while hi - lo > 0.01:
        mid = (lo + hi) / 2
        if len(_breaks(widths, mid, space)) <= n:
            hi = mid
        else:
            lo = mid
    return hi


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
    for word in words_of(markup):
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


_NUMBER = re.compile(r"^[(\[]?[-\u2212]?\d[\d.]*(?:e[-+]?\d+)?$")
_UNIT = re.compile(r"^(?:mm|cm|m|km|\u00b5m|um|in|ft|N|kN|lbf|kg|g|s|rad|rpm|deg|Hz)(?:/[a-z]+)?[\u00b2\u00b3]?"
                   r"(?:/s[\u00b2]?)?[.,;:)\]]*$")
_PRODUCT = re.compile(r"^(?:m|mm|in|ft)(?:[\u00b2]|/s)?[.,;:)\]]*$")


@functools.lru_cache(maxsize=4096)
def words_of(markup: str) -> tuple[str, ...]:
    """The words a line may break between: the text's words, but a number kept with its unit and a
    unit's parts together ("0.6417 N m", "500 mm/s"), as ISO 80000-1 sets them (never a unit alone at a
    line's start)."""
    out: list[str] = []
    for w in markup.split():
        if out and _UNIT.match(w) and _NUMBER.match(out[-1]):
            out[-1] += " " + w
        elif out and _PRODUCT.match(w) and re.search(r"\d (?:N|kN|lbf)$", out[-1]):
            out[-1] += " " + w
        else:
            out.append(w)
    return tuple(out)


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
    ys, bottom = line_baselines([(m.top, m.bottom) for m in ms], top, size)
    return [Text(x, y, tuple(line), style, m.box(x, y), "", name) for line, m, y in zip(lines, ms, ys)], bottom


@functools.lru_cache(maxsize=64)
def _line_room(size: float) -> tuple[float, float]:
    """The top and bottom every line at ``size`` is given room for (a subscript included)."""
    asc, desc = font_metrics()
    return -asc * size, SUB_SHIFT * size + desc * sub_size(size)


def line_baselines(extents: Sequence[tuple[float, float]], top: float, size: float) -> tuple[list[float], float]:
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


def _same_breaks(widths: Sequence[float], lines: list[tuple[int, int]], space: float) -> tuple[float, float]:
    """The widths [lo, hi) at which :func:`_breaks` breaks ``widths`` into ``lines`` again, from the very sums
    it compares: every line fits (its running width, the largest of its sums, is at most the width; no
    word longer) and none could take the next line's first word (its width plus a space and that word is
    over the width).  Greedy breaking makes each line's end depend only on where it starts, so in that
    range every line ends where it did."""
    lo, hi = max(widths), math.inf
    for n, (i0, i1) in enumerate(lines):
        cur = widths[i0]
        for w in widths[i0 + 1:i1]:
            cur += space
            cur += w
        lo = max(lo, cur)
        if n + 1 < len(lines):
            hi = min(hi, cur + space + widths[i1])
    return lo, hi


@functools.lru_cache(maxsize=4096)
def _wrap_ranges(markup: str, size: float) -> list:
    """The wraps of ``markup`` at ``size`` found so far, as [lo, hi, line extents] (filled by
    :func:`wrapped_extents`)."""
    return []


def wrapped_extents(markup: str, width: float, size: float) -> list[tuple[float, float]] | None:
    """The (top, bottom) extent of each line of ``markup`` wrapped to ``width``, as :func:`measure` takes
    the line :func:`wrap_words` makes, found from the word table without making a span; None when a
    word would have to be split.  Remembered per range of widths that wrap alike (a page planner asks
    at many widths, most of which break the lines where another did)."""
    ranges = _wrap_ranges(markup, size)
    for lo, hi, ext in ranges:
        if lo <= width < hi:
            return ext
    widths, tops, bottoms = _word_columns(markup, size)
    space = text_width(" ", size)
    got = _breaks(widths, width, space) if widths else []
    if got is None:
        ranges.append((-math.inf, max(widths), None))
        return None
    ext = _line_extents(got, tops, bottoms, size)
    ranges.append(_same_breaks(widths, got, space) + (ext,) if widths else (-math.inf, math.inf, ext))
    return ext


def _line_extents(got: list[tuple[int, int]], tops: list[float], bottoms: list[float],
                  size: float) -> list[tuple[float, float]]:
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
    return None if ext is None else line_baselines(ext, 0.0, size)[1]
