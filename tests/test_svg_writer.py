"""The SVG writer: well-formed XML whatever the text, attributes and text read back exactly as given."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from drafting.render.paper import Line, Rect, Span, Text
from drafting.layout.sheet import Sheet
from drafting.backends.svg import sheet_to_svg

NS = "{http://www.w3.org/2000/svg}"


def _sheet(commands) -> Sheet:
    from drafting.study.worked import builtin_example, sheets_for
    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    from dataclasses import replace
    base = sheets_for(Study(load_scene(builtin_example())).run())[0]
    return replace(base, commands=tuple(commands))


def test_text_and_attributes_read_back_exactly():
    tricky = 'a < b & "c" > d\t\'e\''
    spans = (Span(tricky, 3.5), Span("", 2.5, shift=0.875), Span("x_1 & <y>", 2.5, shift=0.875, italic=True))
    cmds = [Text(10, 20, spans, "text", Rect(10, 17, 40, 4), "r", "t"), Line(0, 0, 5, 5, "link", "l")]
    svg = sheet_to_svg(_sheet(cmds), attrs=lambda c: {"data-e": 'name "with" <quotes>\nand a line'})
    root = ET.fromstring(svg)
    text = root.find(f".//{NS}text")
    assert text.text == tricky
    tspans = text.findall(f"{NS}tspan")
    assert [t.text for t in tspans] == [None, "x_1 & <y>"]
    assert tspans[1].get("font-style") == "italic" and tspans[0].get("dy") == "0.875"
    assert text.get("data-e") == 'name "with" <quotes>\nand a line'
    line = root.find(f".//{NS}line")
    assert (line.get("x2"), line.get("stroke-width"), line.get("data-e")) == ("5", "0.5", text.get("data-e"))


def test_an_empty_text_is_an_empty_element():
    svg = sheet_to_svg(_sheet([Text(1, 2, (), "text", Rect(1, 0, 1, 2), "r", "t")]))
    assert '<text font-size="3.5" x="1" xml:space="preserve" y="2" />' in svg
    root = ET.fromstring(svg)
    assert root.get("font-family") == "DejaVu Sans"               # every text inherits it; black is the default fill


def test_a_hatching_is_one_path_of_separate_strokes():
    from drafting.render.paper import Strokes
    svg = sheet_to_svg(_sheet([Strokes((((0.0, 0.0), (1.0, 1.5)), ((2.25, -0.5), (3.0, 4.0))), "hatch", "h")]))
    paths = ET.fromstring(svg).findall(f".//{NS}path")
    assert len(paths) == 1 and paths[0].get("d") == "M0 0L1 1.5 M2.25 -0.5L3 4"
    assert paths[0].get("fill") == "none" and paths[0].get("stroke-width") == "0.25"


def _fmt_by_round(v: float) -> str:
    """The coordinate format as first written: round to 3 decimals, then print."""
    r = round(float(v), 3)
    if r == 0:
        r = 0.0
    s = f"{r:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("", "-0") else s


def test_a_coordinate_prints_as_its_rounding_prints():
    """``.3f`` rounds correctly, as ``round(v, 3)`` does, ties to even included: the shorter format
    writes every coordinate as the first one did."""
    from hypothesis import given, settings, strategies as st
    from drafting.backends.svg import fmt

    @settings(max_examples=2000, deadline=None)
    @given(st.floats(-1e7, 1e7, allow_nan=False) | st.integers(-10**7, 10**7).map(lambda i: i / 2000)
           | st.integers(-10**6, 10**6).map(lambda i: i / 16))
    def check(v):
        assert fmt(v) == _fmt_by_round(v)
    check()
    ties = (-0.0004, 0.0005, 0.0015, 0.0625, -0.0625, 2.5e-7, -12.3456, 1e20)
    assert [fmt(v) for v in ties] == [_fmt_by_round(v) for v in ties]
    assert [fmt(v) for v in (-0.0004, 0.0625, -12.3456)] == ["0", "0.062", "-12.346"]


def _svgwrite_own(dwg) -> str:
    """The document as svgwrite writes it (through ElementTree), made safe in one pass over the whole."""
    from drafting.scene.textsafe import xml_safe
    return xml_safe(ET.tostring(dwg.get_xml(), encoding="unicode"))


def _held_to_svgwrite(monkeypatch) -> list:
    """Every document the writer writes is compared with svgwrite's own writing of the same tree."""
    from drafting.backends import svg
    write = svg._document
    written: list = []

    def both(dwg):
        got = write(dwg)
        assert got == _svgwrite_own(dwg)
        written.append(got)
        return got
    monkeypatch.setattr(svg, "_document", both)
    return written


def test_the_writer_writes_what_svgwrite_writes_for_every_gallery_sheet(monkeypatch):
    from pathlib import Path

    from drafting.scene.reader import load_scene
    from drafting.study.study import Study
    from drafting.study.worked import sheets_for
    written = _held_to_svgwrite(monkeypatch)
    gallery = Path(__file__).resolve().parent.parent / "gallery"
    for path in sorted(gallery.glob("*.toml")):
        for sheet in sheets_for(Study(load_scene(path)).run()):
            sheet_to_svg(sheet)
    assert len(written) >= 50


def test_the_writer_writes_what_svgwrite_writes_for_hostile_text_and_every_element(monkeypatch):
    from drafting.render.paper import Circle, Polygon, Polyline, Rectangle, Strokes
    written = _held_to_svgwrite(monkeypatch)
    nasty = 'tab\there, cr\rlf\n "q" \'a\' <&> \x00\x1b\ud800\ufffe \u22a5 \U0001f600'
    spans = (Span(nasty, 3.5), Span(nasty, 2.5, shift=0.875, italic=True), Span("", 2.5))
    cmds = [Text(10, 20, spans, "text", Rect(10, 17, 40, 4), "r", "t"),
            Text(1, 2, (Span("plain", 3.5),), "text", Rect(1, 0, 1, 2), "r", "t"),
            Text(1, 2, (), "text", Rect(1, 0, 1, 2), "r", "t"),
            Line(0, -0.0004, 5, 5, "link", "l"), Polyline(((0, 0), (1, 2), (3, 1)), "link", "p"),
            Polygon(((0, 0), (1, 2), (3, 1)), "image", "g"), Circle(5, 5, 1.25, "link", "c"),
            Rectangle(1, 1, 2, 3, "trial", "r"), Strokes((((0.0, 0.0), (1.0, 1.5)),), "hatch", "h")]
    sheet_to_svg(_sheet(cmds), attrs=lambda c: {"data-e": nasty, "data-n": "", "data-x": None})
    svg = sheet_to_svg(_sheet(cmds))
    assert len(written) == 2
    root = ET.fromstring(written[0])
    text = root.find(f".//{NS}text")
    assert "\ufffd" in text.text and "\x00" not in text.text and text.get("data-e").startswith("tab\there, cr\rlf\n")
    assert "data-n" not in text.attrib and "data-x" not in text.attrib    # empty and None: left out, as in svgwrite
    assert "\ud800" not in svg and "\U0001f600" in svg
