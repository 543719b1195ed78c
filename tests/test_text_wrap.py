"""Word wrap: the word-table wrap and the letter-splitting wrap agree wherever nothing is split, and the
height planning reads off the word table is the laid-out height (as is a scale bar's, read off its rows)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st


words = st.lists(st.sampled_from(["V_CB", "the", "polygon", "ω_2", "=", "197.4", "mm/s,", "perpendicular",
                                  "O_1B", "a", "Draw", "through", "Coriolis", "2ω_3V_{A3A}"]), min_size=1, max_size=40)


@settings(max_examples=150, deadline=None)
@given(words, st.floats(4.0, 160.0), st.sampled_from([2.5, 3.0, 3.5]))
def test_the_two_greedy_wraps_agree(ws, width, size):
    """wrap_words takes its breaks from the word table and falls back to splitting a word only when one is
    longer than the line; the splitting wrap, on text where nothing needs splitting, breaks the same."""
    from drafting.layout.wrap import _breaks, _word_columns, _words, _wrap_splitting, wrap_words
    from drafting.render.style import text_width
    text = " ".join(ws)
    split = _breaks(_word_columns(text, size)[0], width, text_width(" ", size)) is None
    assert split == any(w[1] > width for w in _words(text, size))
    assert wrap_words(text, width, size) == _wrap_splitting(text, width, size)


@settings(max_examples=100, deadline=None)
@given(words, st.lists(st.floats(4.0, 160.0), min_size=1, max_size=12), st.sampled_from([2.5, 3.0, 3.5]))
def test_a_wrap_remembered_for_a_range_of_widths_is_the_wrap_at_each_width(ws, widths, size):
    """Line extents are remembered per range of widths that break the lines alike: asked at widths in any
    order (and at the edges of the ranges found), each answer is the greedy wrap at that very width."""
    from drafting.layout.wrap import _breaks, _line_extents, _word_columns, _wrap_ranges, wrapped_extents
    from drafting.render.style import text_width
    text = " ".join(ws)
    _wrap_ranges.cache_clear()
    edges = []
    for w in widths:
        wrapped_extents(text, w, size)
        edges += [e for lo, hi, _ in _wrap_ranges(text, size) for e in (lo, hi) if 0 < e < 1e6]
    col_w, tops, bottoms = _word_columns(text, size)
    for w in widths + edges + [math.nextafter(e, 0.0) for e in edges]:
        got = _breaks(col_w, w, text_width(" ", size))
        assert wrapped_extents(text, w, size) == (None if got is None else _line_extents(got, tops, bottoms, size))


def assert_height_is_laid_out_height(item, width: float, size: float) -> None:
    """The height planning reads without commands is the laid-out height bit for bit, and an item too
    wide to lay out is too wide to measure."""
    from drafting.layout.items import TooWide
    try:
        placed = item.layout(width, size)
    except TooWide:
        with pytest.raises(TooWide):
            item.height(width, size)
        return
    assert item.height(width, size) == placed.height


@settings(max_examples=150, deadline=None)
@given(words, st.floats(20.0, 160.0), st.sampled_from([2.5, 3.0, 3.25, 3.5]), st.sampled_from(["", "3.", "12."]))
def test_a_paragraph_s_height_without_commands_is_its_laid_out_height(ws, width, size, label):
    """Planning asks only how tall an item is: the word-table path gives the laid-out height exactly."""
    from drafting.layout.items import Paragraph
    assert_height_is_laid_out_height(Paragraph(" ".join(ws), label=label, label_chars=label), width, size)


cell = st.lists(st.sampled_from(["V_CB", "197.4", "mm/s", "0.0%", "ω_2", "perpendicular to O_1B", "", "—",
                                 "the Coriolis component 2ω_3V_{A3A}", "1.2e-09"]), min_size=1, max_size=3).map(" ".join)


@settings(max_examples=150, deadline=None)
@given(st.integers(2, 5).flatmap(lambda n: st.tuples(st.lists(cell, min_size=n, max_size=n),
                                                      st.lists(st.lists(cell, min_size=n, max_size=n), max_size=8),
                                                      st.booleans())),
       st.floats(20.0, 200.0), st.sampled_from([2.5, 3.0, 3.25, 3.5]))
def test_a_table_s_height_without_commands_is_its_laid_out_height(table, width, size):
    """The results table's height row by row from the word table is its laid-out height exactly, wrapped
    last column included."""
    from drafting.layout.items import TableItem
    header, rows, wrap_last = table
    assert_height_is_laid_out_height(
        TableItem(tuple(header), tuple(tuple(r) for r in rows), ("l",) + ("r",) * (len(header) - 1), wrap_last),
        width, size)


@settings(max_examples=300, deadline=None)
@given(st.floats(-50.0, 400.0), st.floats(-50.0, 300.0), st.floats(10.0, 150.0),
       st.sampled_from([0.01, 0.2, 0.5, 1.0, 2.0, 5.0, 25.0, 1000.0, 2e5]),
       st.sampled_from(["mm", "m/s", "m/s²", "N", "kN·m", "in/s", "rad/s²", ""]))
def test_a_scale_bar_s_bottom_without_its_plan_is_its_laid_out_bottom(x, top, length, value, unit):
    """A viewport header is planned with the bar's bottom alone (the same for every length and value):
    it is the bottom of the bar's full plan, bit for bit."""
    from drafting.layout.scale_bar import _bar_plan, bar_bottom
    assert bar_bottom(top, unit) == _bar_plan(x, top, length, value, unit).box.bottom


@settings(max_examples=150, deadline=None)
@given(words, st.floats(20.0, 160.0), st.sampled_from([2.5, 3.5, 5.0]))
def test_a_balanced_wrap_keeps_the_line_count_and_cannot_be_narrower(ws, width, size):
    """balanced_width: no wider than asked, the same number of lines as there (no word split), and a
    hundredth of a millimetre narrower would take another line -- so the lines are as even as a greedy
    wrap makes them."""
    from drafting.layout.wrap import _breaks, _word_columns, balanced_width
    from drafting.render.style import text_width
    text = " ".join(ws)
    widths, space = _word_columns(text, size)[0], text_width(" ", size)
    whole = _breaks(widths, width, space)
    got = balanced_width(text, width, size)
    assert got <= width
    if whole is None or len(whole) < 2:
        assert got == width
        return
    assert len(_breaks(widths, got, space)) == len(whole)
    assert got - 0.011 < max(widths) or len(_breaks(widths, got - 0.011, space)) > len(whole)


def test_a_title_of_two_lines_is_broken_into_lines_of_about_one_length():
    """The acceleration example's title took a full line and "1)" under it; balanced, its two lines are
    within a word of each other."""
    from drafting.layout.wrap import balanced_width, wrap_words
    from drafting.render.style import measure
    title = "Slider-crank: acceleration polygon (notes, acceleration Example 1)"
    greedy = [measure(line).width for line in wrap_words(title, 115.0, 3.5)]
    even = [measure(line).width for line in wrap_words(title, balanced_width(title, 115.0, 3.5), 3.5)]
    assert len(greedy) == len(even) == 2
    assert greedy[1] < 0.1 * greedy[0] and abs(even[0] - even[1]) < 0.2 * even[0]
