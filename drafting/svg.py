"""SVG: the sheet's document of record, written element by element.

One user unit is one millimetre (``width="297mm" viewBox="0 0 297 210"``).  Every command becomes one
element with its style written out as presentation attributes (stroke, width, dashes, fill), which
cairosvg reads reliably.  Coordinates are rounded to 3 decimals so the output is stable.  Nothing here
uses what cairosvg cannot render: arrowheads are filled polygons (no markers), subscripts are tspans
moved with ``dy`` (no ``baseline-shift``), label backgrounds are white rectangles (no ``paint-order``).

Every text that reaches the document -- titles, drawing numbers, names, labels, file names -- passes
:func:`drafting.textsafe.xml_safe` here, the one place that writes SVG: characters XML 1.0 forbids
become U+FFFD, and svgwrite escapes ``&``, ``<``, ``>`` and quotes.  The document stays inert: plain
shapes and text only, no scripts, no links or external references, no DOCTYPE or entities.
"""

from __future__ import annotations

import functools
import re
from typing import Callable

from .font_embed import css_for
from .paper import Circle, Command, Line, Polygon, Polyline, Rectangle, Text
from .sheet import Sheet
from .style import FONT_FAMILY, style
from .textsafe import xml_safe


def fmt(v: float) -> str:
    """A coordinate in mm with at most 3 decimals and no '-0'."""
    r = round(float(v), 3)
    if r == 0:
        r = 0.0
    s = f"{r:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("", "-0") else s


@functools.cache
def _paint(name: str) -> tuple[tuple[str, str], ...]:
    st = style(name)
    a: dict[str, str] = {"fill": st.fill or "none"}
    if st.stroke is None:
        a["stroke"] = "none"
        return tuple(a.items())
    a["stroke"] = st.stroke
    a["stroke-width"] = fmt(st.width)
    a["stroke-linecap"] = st.cap
    a["stroke-linejoin"] = st.join
    if st.dash:
        a["stroke-dasharray"] = ",".join(fmt(d) for d in st.dash)
    return tuple(a.items())


_ATTR_SPECIAL = re.compile('[&<>"\n\r\t]')
_DATA_SPECIAL = re.compile("[&<>]")


def _attr(value: str) -> str:
    """An attribute value escaped as XML's serializers escape it."""
    if _ATTR_SPECIAL.search(value):
        value = (value.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")
                 .replace("\r", "&#13;").replace("\n", "&#10;").replace("\t", "&#09;"))
    return value


def _data(text: str) -> str:
    """Character data escaped (&, <, >)."""
    if _DATA_SPECIAL.search(text):
        text = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return text


def _tag(name: str, attrs: dict[str, str], inner: str | None = None) -> str:
    """``<name a="..." ...>inner</name>``, the attributes in name order; an element with nothing inside
    is closed at once (``<name ... />``)."""
    head = "<" + name + "".join(f' {k}="{_attr(v)}"' for k, v in sorted(attrs.items()))
    return head + " />" if inner is None else f"{head}>{inner}</{name}>"


def _points(pts) -> str:
    return " ".join(f"{fmt(x)},{fmt(y)}" for x, y in pts)


def _element(c: Command, extra: dict[str, str] | None) -> str:
    if isinstance(c, Text):
        return _text(c, extra)
    if isinstance(c, Line):
        a = {"x1": fmt(c.x1), "y1": fmt(c.y1), "x2": fmt(c.x2), "y2": fmt(c.y2)}
        name = "line"
    elif isinstance(c, Polyline):
        a, name = {"points": _points(c.points)}, "polyline"
    elif isinstance(c, Polygon):
        a, name = {"points": _points(c.points)}, "polygon"
    elif isinstance(c, Rectangle):
        a, name = {"x": fmt(c.x), "y": fmt(c.y), "width": fmt(c.w), "height": fmt(c.h)}, "rect"
    elif isinstance(c, Circle):
        a, name = {"cx": fmt(c.cx), "cy": fmt(c.cy), "r": fmt(c.r)}, "circle"
    else:
        raise TypeError(f"not a drawing command: {c!r}")
    a.update(_paint(c.style))
    if extra:
        a.update(extra)
    return _tag(name, a)


def _text(c: Text, extra: dict[str, str] | None) -> str:
    base = c.spans[0].size if c.spans else 3.5
    a = {"x": fmt(c.x), "y": fmt(c.y), "font-family": FONT_FAMILY, "font-size": fmt(base), "fill": "black",
         "xml:space": "preserve"}
    if extra:
        a.update(extra)
    parts: list[str] = []
    shift = 0.0
    for i, s in enumerate(c.spans):
        if i == 0 and s.shift == 0 and not s.italic:
            parts.append(_data(xml_safe(s.text)))
            continue
        ta: dict[str, str] = {}
        dy = s.shift - shift
        if abs(dy) > 5e-4:
            ta["dy"] = fmt(dy)
        shift = s.shift
        if abs(s.size - base) > 5e-4:
            ta["font-size"] = fmt(s.size)
        if s.italic:
            ta["font-style"] = "italic"
        parts.append(_tag("tspan", ta, _data(xml_safe(s.text)) or None))
    inner = "".join(parts)
    return _tag("text", a, inner if inner else None)


_ROOT = ('<svg baseProfile="full" height="{h}mm" version="1.1" viewBox="0 0 {w} {h}" width="{w}mm" '
         'xmlns="http://www.w3.org/2000/svg" xmlns:ev="http://www.w3.org/2001/xml-events" '
         'xmlns:xlink="http://www.w3.org/1999/xlink">')


def sheet_to_svg(sheet: Sheet, attrs: Callable[[Command], dict[str, str]] | None = None) -> str:
    """The sheet as an SVG document, 1 user unit = 1 mm; ``attrs(command)`` adds attributes to each
    element (the step-through page tags each with its entity)."""
    w, h = fmt(sheet.width), fmt(sheet.height)
    css = css_for(s.text for c in sheet.commands if isinstance(c, Text) for s in c.spans)
    out = [_ROOT.format(w=w, h=h), f'<defs><style type="text/css"><![CDATA[{css}]]></style></defs>',
           _tag("rect", {"x": "0", "y": "0", "width": w, "height": h, "fill": "white", "stroke": "none"})]
    out.extend(_element(c, None if attrs is None else attrs(c)) for c in sheet.commands)
    out.append("</svg>")
    return xml_safe("".join(out))        # and once more over the whole: nothing unsafe gets through
