"""Word wrap: the range of widths wrap_range promises gives exactly the same lines, and its ends are
where the lines change."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from drafting.layout import wrap_range, wrap_words

words = st.lists(st.sampled_from(["V_CB", "the", "polygon", "ω_2", "=", "197.4", "mm/s,", "perpendicular",
                                  "O_1B", "a", "Draw", "through", "Coriolis", "2ω_3V_{A3A}"]), min_size=1, max_size=40)


@settings(max_examples=150, deadline=None)
@given(words, st.floats(20.0, 160.0), st.floats(0.0, 1.0), st.sampled_from([2.5, 3.0, 3.5]))
def test_every_width_in_the_range_wraps_the_same(ws, width, f, size):
    text = " ".join(ws)
    lines, lo, hi = wrap_range(text, width, size)
    assert lines == wrap_words(text, width, size)
    if lo == hi:                                         # a split word: only this width promised
        assert lo == width
        return
    assert lo <= width < hi
    inside = lo + f * (min(hi, lo + 200.0) - lo)
    if inside < hi:
        assert wrap_words(text, inside, size) == lines
    # the ends are tight: just below, a line no longer fits (it breaks earlier, or a word has to be
    # split); at hi, a break no longer happens
    below = math.nextafter(lo, -math.inf)
    got, lo2, hi2 = wrap_range(text, below, size)
    assert got != lines or lo2 == hi2 == below
    if math.isfinite(hi):
        assert wrap_words(text, hi, size) != lines


@settings(max_examples=150, deadline=None)
@given(words, st.floats(20.0, 160.0), st.sampled_from([2.5, 3.0, 3.25, 3.5]), st.sampled_from(["", "3.", "12."]))
def test_a_paragraph_s_height_without_commands_is_its_laid_out_height(ws, width, size, label):
    """Planning asks only how tall an item is: the word-table path gives the laid-out height exactly."""
    from drafting.layout import Paragraph, TooWide
    p = Paragraph(" ".join(ws), label=label, label_chars=label)
    try:
        placed = p.layout(width, size)
    except TooWide:
        with pytest.raises(TooWide):
            p.height(width, size)
        return
    assert p.height(width, size) == placed.height                 # bit for bit
