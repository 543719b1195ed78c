"""PDF and PNG drawn with cairo straight from the commands show what the SVG shows.

cairosvg, reading the SVG (the document of record), is the reference: the line art must be the same
pixels, the lettering the same ink, and every letter inside the box the layout measured for it (so
the collision tests the layout made hold on the PNG and the PDF too).
"""

from __future__ import annotations

import io
import os
import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from drafting.backends import cairo as cairo_out
from drafting.backends.files import PNG_DPI
from drafting.render.paper import Text
from drafting.scene.reader import load_scene
from drafting.study.study import Study
from drafting.backends.svg import sheet_to_svg
from drafting.study.worked import builtin_example, sheets_for

from paths import GALLERY


@pytest.fixture(scope="module")
def sheets():
    out = list(sheets_for(Study(load_scene(builtin_example())).run()))
    out += list(sheets_for(Study(load_scene(GALLERY / "notes-acceleration-example-4.toml")).run()))
    return out


def _grey(png: bytes) -> np.ndarray:
    with Image.open(io.BytesIO(png)) as im:
        return np.asarray(im.convert("L"), dtype=float)


def _via_cairosvg(sheet) -> np.ndarray:
    os.environ.setdefault("FONTCONFIG_FILE", str(cairo_out.FONTS_CONF))
    import cairosvg
    return _grey(cairosvg.svg2png(bytestring=sheet_to_svg(sheet).encode(), dpi=PNG_DPI))


def test_line_art_is_the_same_pixels_as_the_svg(sheets):
    for sh in sheets:
        art = replace(sh, commands=tuple(c for c in sh.commands if not isinstance(c, Text)))
        a, b = _grey(cairo_out.sheet_to_png(art, PNG_DPI)), _via_cairosvg(art)
        assert a.shape == b.shape
        d = np.abs(a - b)
        # the SVG rounds coordinates to 1 um: anti-aliased edges may differ by a shade, nothing more
        assert d.mean() < 0.05 and np.percentile(d, 99.9) < 24, (d.mean(), np.percentile(d, 99.9))


def test_lettering_is_the_same_ink_and_stays_in_its_measured_box(sheets):
    k = PNG_DPI / 25.4
    for sh in sheets:
        texts = [c for c in sh.commands if isinstance(c, Text)]
        lettering = replace(sh, commands=tuple(texts))
        a, b = 255 - _grey(cairo_out.sheet_to_png(lettering, PNG_DPI)), 255 - _via_cairosvg(lettering)
        assert abs(a.sum() - b.sum()) < 0.03 * b.sum()           # the same letters, the same weight
        inside = np.zeros(a.shape, dtype=bool)
        for t in texts:
            r = t.box
            inside[max(0, int((r.top - 0.3) * k)):int((r.bottom + 0.3) * k) + 1,
                   max(0, int((r.left - 0.3) * k)):int((r.right + 0.3) * k) + 1] = True
        assert a[~inside].max(initial=0) < 40, "a letter is drawn outside the box the layout measured"


def test_pdf_pages_are_the_paper_and_the_text_is_text(sheets, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1795392000")
    pdf = cairo_out.sheets_to_pdf(sheets[1:])
    assert pdf == cairo_out.sheets_to_pdf(sheets[1:])                 # reproducible
    n = len(sheets[1:])
    assert len(re.findall(rb"/Type /Page\b(?!s)", pdf)) == n and b"/Count %d" % n in pdf
    assert pdf.count(b"/MediaBox [ 0 0 841.889764 595.275591 ]") == n    # A4 landscape, exactly
    assert b"DejaVuSans" in pdf and b"/FontFile2" in pdf               # set as text, the font embedded
    assert b"/CreationDate (D:20261123000000Z)" in pdf


def test_an_unknown_paint_is_refused():
    with pytest.raises(ValueError, match="paint"):
        cairo_out._rgb("rgb(1,2,3)")


def test_a_png_is_the_same_bytes_whatever_was_drawn_before_it():
    """The PNG of a sheet does not depend on what the process drew before (cairo keeps scaled fonts
    between surfaces: a PDF drawn first used to leave its unhinted glyphs for the PNG, so `--format png`
    and the default formats gave different pixels).  Each order runs in a fresh process."""
    import subprocess
    import sys
    code = ("import hashlib, sys; from drafting.backends import cairo as cairo_out; from drafting.scene.reader import load_scene; "
            "from drafting.study.study import Study; from drafting.study.worked import builtin_example, sheets_for; "
            "sh = sheets_for(Study(load_scene(builtin_example())).run()); "
            "sys.argv[1] == 'pdf' and cairo_out.sheets_to_pdf(sh); "
            "print(hashlib.sha256(cairo_out.sheet_to_png(sh[0], 150.0)).hexdigest())")
    got = {first: subprocess.run([sys.executable, "-c", code, first], capture_output=True, text=True, check=True,
                                 cwd=Path(__file__).resolve().parents[1]).stdout.strip() for first in ("png", "pdf")}
    assert got["png"] == got["pdf"] and len(got["png"]) == 64
