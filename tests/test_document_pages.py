"""A document of several sheets as a whole: one title block for all its sheets, and no sheet left mostly
white when its content could be packed (the sheet critic's blank-page check, :mod:`drafting.layout.critic`).

The scenes are gallery scenes whose second sheet was a few lines of text on a white page (watt-six-bar,
cycle-four-bar, notes-velocity-example-3) or whose sheets had title blocks of two widths (133 and 180 mm:
notes-velocity-example-3, notes-dynamic-example-3).
"""

from __future__ import annotations

import pytest

import drafting
from drafting.layout.critic.page import MOST_BLANK, blank_fraction

from paths import GALLERY

SPREAD = ("watt-six-bar", "cycle-four-bar", "notes-velocity-example-3")
TWO_BLOCKS = ("notes-velocity-example-3", "notes-dynamic-example-3", "instant-centres-slider-crank")


@pytest.mark.parametrize("name", SPREAD)
def test_no_sheet_of_a_document_is_mostly_blank(name):
    sheets = drafting.load(GALLERY / f"{name}.toml").sheets()
    assert len(sheets) == 2
    blank = [round(blank_fraction(s), 3) for s in sheets]
    assert max(blank) <= MOST_BLANK, blank


@pytest.mark.parametrize("name", TWO_BLOCKS)
def test_every_sheet_of_a_document_has_the_same_title_block(name):
    sheets = drafting.load(GALLERY / f"{name}.toml").sheets()
    assert len(sheets) >= 2
    rects = [s.regions["title_block"] for s in sheets]
    assert len({round(r.w, 6) for r in rects}) == 1, [r.w for r in rects]
    assert len({round(r.h, 6) for r in rects}) == 1, [r.h for r in rects]
    for s, r in zip(sheets, rects):                  # at the frame's bottom right
        assert r.right == pytest.approx(s.paper.frame.right) and r.bottom == pytest.approx(s.paper.frame.bottom)
