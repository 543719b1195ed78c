"""Every SVG carries its font: a DejaVu Sans subset (regular and oblique) holding every character the
sheet writes, so it looks the same on a machine without the font; PDF and PNG are not touched by it."""

from __future__ import annotations

import base64
import io
import re

from fontTools.ttLib import TTFont

import drafting
from drafting.backends.fonts import REPERTOIRE



def _faces(svg: str) -> dict[str, set[int]]:
    out = {}
    for style, data in re.findall(r'font-style:(\w+);src:url\(data:font/woff;base64,([A-Za-z0-9+/=]+)\)', svg):
        font = TTFont(io.BytesIO(base64.b64decode(data)))
        out[style] = set(font.getBestCmap())
    return out


def test_the_sheet_carries_every_glyph_it_writes():
    from pathlib import Path
    study = drafting.load(Path(__file__).resolve().parent.parent / "gallery" / "notes-acceleration-example-1.toml")
    for sheet in study.sheets():
        svg = sheet.svg()
        faces = _faces(svg)
        assert set(faces) == {"normal", "italic"}
        used = {ord(ch) for t in sheet.texts() for s in t.spans for ch in s.text}
        assert used <= faces["normal"] and used <= faces["italic"]
        assert not re.search(r"url\((?!data:)", svg)              # nothing fetched from elsewhere


def test_a_title_beyond_the_repertoire_brings_its_glyphs():
    from pathlib import Path
    text = (Path(__file__).resolve().parent.parent / "gallery" / "notes-velocity-example-1.toml").read_text()
    extra = "Кривошипно-шатунный механизм"
    assert not set(extra) <= REPERTOIRE
    study = drafting.loads(text.replace('title = "Slider-crank: velocity polygon (notes, velocity Example 1)"',
                                        f'title = "{extra}"'))
    faces = _faces(study.sheets()[0].svg())
    assert {ord(c) for c in extra} <= faces["normal"]


def test_the_subset_is_the_same_bytes_whatever_the_clock(monkeypatch):
    """The font keeps its own date (no timestamp of the run): a sheet's SVG is reproducible, and an empty
    SOURCE_DATE_EPOCH does not break it."""
    from drafting.backends.fonts import FONTS, _subset
    chars = frozenset("Space diagram 1:5")
    got = []
    for epoch in ("", "0", "1795392000", None):
        if epoch is None:
            monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
        else:
            monkeypatch.setenv("SOURCE_DATE_EPOCH", epoch)
        got.append(_subset(FONTS / "DejaVuSans.ttf", chars))
    assert len(set(got)) == 1


def test_the_shipped_repertoire_subsets_are_what_subsetting_makes_now():
    """The ready-made subsets in drafting/render/fonts (so a one-sheet render does not subset) are current:
    remake them with ``python -m drafting.backends.fonts`` when this fails."""
    from drafting.backends.fonts import FONT_FILES, FONTS, REPERTOIRE, _subset, shipped
    for name in FONT_FILES.values():
        assert shipped(name).read_bytes() == _subset(FONTS / name, REPERTOIRE), name
