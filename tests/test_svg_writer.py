"""The SVG writer: well-formed XML whatever the text, attributes and text read back exactly as given."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from drafting.paper import Line, Rect, Span, Text
from drafting.sheet import Sheet
from drafting.svg import sheet_to_svg

NS = "{http://www.w3.org/2000/svg}"


def _sheet(commands) -> Sheet:
    from drafting.worked import builtin_example, sheets_for
    from drafting.scene import load_scene
    from drafting.study import Study
    from dataclasses import replace
    base = sheets_for(Study(load_scene(builtin_example())).run())[0]
    return replace(base, commands=tuple(commands))


def test_text_and_attributes_read_back_exactly():
    tricky = 'a < b & "c" > d\t\'e\''
    spans = (Span(tricky, 3.5), Span("", 2.5, shift=0.875), Span("x_1 & <y>", 2.5, shift=0.875, italic=True))
    cmds = [Text(10, 20, spans, "text", Rect(10, 17, 40, 4), "r", "t"), Line(0, 0, 5, 5, "link", "l")]
    svg = sheet_to_svg(_sheet(cmds), attrs=lambda c: {"data-e": 'name "with" <quotes>\nand a line'})
    root = ET.fromstring(svg)
    text = root.find(f"{NS}text")
    assert text.text == tricky
    tspans = text.findall(f"{NS}tspan")
    assert [t.text for t in tspans] == [None, "x_1 & <y>"]
    assert tspans[1].get("font-style") == "italic" and tspans[0].get("dy") == "0.875"
    assert text.get("data-e") == 'name "with" <quotes>\nand a line'
    line = root.find(f"{NS}line")
    assert (line.get("x2"), line.get("stroke-width"), line.get("data-e")) == ("5", "0.5", text.get("data-e"))


def test_an_empty_text_is_an_empty_element():
    svg = sheet_to_svg(_sheet([Text(1, 2, (), "text", Rect(1, 0, 1, 2), "r", "t")]))
    assert '<text fill="black" font-family="DejaVu Sans" font-size="3.5" x="1" xml:space="preserve" y="2" />' in svg
    ET.fromstring(svg)
