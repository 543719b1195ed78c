"""SVG: the one module that writes the sheets' markup.

One user unit is one millimetre (``width="297mm" viewBox="0 0 297 210"``).  Every command becomes one
element with its style written out as presentation attributes (stroke, width, dashes, fill), which
cairosvg reads reliably.  Coordinates are rounded to 3 decimals so the output is stable.  Nothing here
uses what cairosvg cannot render: arrowheads are filled polygons (no markers), subscripts are tspans
moved with ``dy`` (no ``baseline-shift``), label backgrounds are white rectangles (no ``paint-order``).

The document is a small tree of :class:`_Element` (tag, attributes, text, children) written out in
one pass by :func:`_write`, to the characters svgwrite writes for the same document through
ElementTree (attributes sorted by name, None and empty values left out, ``<x a="1" />`` when empty,
the style sheet as CDATA): the sheets were first written with svgwrite, whose import alone (its
validator's regular expressions, and urllib) took a tenth of a cold ``drafting render``.  A test holds
every gallery sheet to svgwrite's own writing of the same tree, character for character.

Every text that reaches the document -- titles, drawing numbers, names, labels, file names -- passes
:func:`drafting.scene.textsafe.xml_safe` here, the one place that writes SVG: every text and attribute value
is made safe as it is written, so characters XML 1.0 forbids become U+FFFD wherever they came from,
and ``&``, ``<``, ``>``, quotes and (in attributes) tabs and line ends are escaped as ElementTree
escapes them.  The document stays inert: plain shapes and text only, no scripts, no links or external
references, no DOCTYPE or entities.

Each drawn thing is a group, so that a sheet can be styled, searched and read aloud: the commands are
written in their order (the z-order is the sheet's, exactly), and each run of consecutive commands of one
part (:func:`drafting.layout.parts.part_of`: an entity of the record, the label naming it, or a piece of
the sheet's furniture -- frame, title block, results table, a step's words, a scale bar) is one
``<g class="KIND" data-entity="ID">``.  ``KIND`` comes from the record's entity type (``vector``,
``trial-line``, ``point``, ``link`` ...) or the furniture (``title-block``, ``table``, ``step-text`` ...);
``ID`` is the entity's name as an XML id (:class:`drafting.layout.parts.Ids`: stable, unique).  An entity
drawn on several layers (a link below the arrows, its pin above them) is several runs: every run has the
same class and ``data-entity``; the first carries ``id="ID"`` and the ``<title>`` ("V_B -- known velocity
vector"), the later ones neither, so each id is written once.  The label naming an entity is a run of its
own (labels lie above every line): ``class="KIND label"`` and ``data-for="ID"``, the entity it names
(and it is the one carrying the id and title when the entity draws nothing before its label, as a joint
named on the space diagram).  Nothing of this changes what is drawn: groups carry no style.
"""

from __future__ import annotations

import functools
from typing import Callable

from .fonts import css_for
from ..render.paper import Circle, Command, Line, Polygon, Polyline, Rectangle, Strokes, Text
from ..layout.parts import Ids, Part, part_of
from ..layout.sheet import Sheet
from ..render.style import FONT_FAMILY, style
from ..scene.textsafe import xml_safe

SVG_NAMESPACES = {"xmlns": "http://www.w3.org/2000/svg", "xmlns:xlink": "http://www.w3.org/1999/xlink",
                  "xmlns:ev": "http://www.w3.org/2001/xml-events"}
"""The root's namespaces, as svgwrite's full profile declares them (with ``baseProfile="full"``)."""


def fmt(v: float) -> str:
    """A coordinate in mm with at most 3 decimals and no '-0' (``.3f`` rounds as ``round(v, 3)`` does:
    both are correctly rounded)."""
    s = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("", "-0") else s


class _Element:
    """One element of the document: ``tag``, ``attribs`` (values as strings; written sorted, None and
    empty ones left out), ``text`` and the ``elements`` it holds."""

    __slots__ = ("tag", "attribs", "text", "elements")

    def __init__(self, tag: str, attribs: dict[str, str], text: str = "") -> None:
        self.tag, self.attribs, self.text, self.elements = tag, attribs, text, []


@functools.lru_cache(maxsize=None)
def _paint(name: str) -> dict[str, str]:
    st = style(name)
    a: dict[str, str] = {"fill": st.fill or "none"}
    if st.stroke is None:
        a["stroke"] = "none"
        return a
    a["stroke"] = st.stroke
    a["stroke-width"] = fmt(st.width)
    a["stroke-linecap"] = st.cap
    a["stroke-linejoin"] = st.join
    if st.dash:
        a["stroke-dasharray"] = ",".join(fmt(d) for d in st.dash)
    return a


def _points(points) -> str:
    return " ".join(f"{fmt(x)},{fmt(y)}" for x, y in points)


def _line(c: Line) -> _Element:
    return _Element("line", {"x1": fmt(c.x1), "y1": fmt(c.y1), "x2": fmt(c.x2), "y2": fmt(c.y2)})


def _polyline(c: Polyline) -> _Element:
    return _Element("polyline", {"points": _points(c.points)})


def _polygon(c: Polygon) -> _Element:
    return _Element("polygon", {"points": _points(c.points)})


def _strokes(c: Strokes) -> _Element:
    """One path of separate strokes: "M x y L x y" for each."""
    return _Element("path", {"d": " ".join(f"M{fmt(a[0])} {fmt(a[1])}L{fmt(b[0])} {fmt(b[1])}"
                                           for a, b in c.segments)})


def _rect(c: Rectangle) -> _Element:
    return _Element("rect", {"x": fmt(c.x), "y": fmt(c.y), "width": fmt(c.w), "height": fmt(c.h)})


def _circle(c: Circle) -> _Element:
    return _Element("circle", {"cx": fmt(c.cx), "cy": fmt(c.cy), "r": fmt(c.r)})


def _element(c: Command, attrs: Callable[[Command], dict[str, str]] | None = None) -> _Element:
    make = _MAKERS.get(type(c))
    if make is None:
        raise TypeError(f"not a drawing command: {c!r}")
    el = make(c)
    if make is not _text:
        el.attribs.update(_paint(c.style))
    if attrs is not None:
        el.attribs.update(attrs(c))
    return el


def _text(c: Text) -> _Element:
    base = c.spans[0].size if c.spans else 3.5
    el = _Element("text", {"x": fmt(c.x), "y": fmt(c.y), "font-size": fmt(base), "xml:space": "preserve"})
    shift = 0.0
    for i, s in enumerate(c.spans):
        if i == 0 and s.shift == 0 and not s.italic:
            el.text = s.text
            continue
        ts = _Element("tspan", {}, s.text)
        dy = s.shift - shift
        if abs(dy) > 5e-4:
            ts.attribs["dy"] = fmt(dy)
        shift = s.shift
        if abs(s.size - base) > 5e-4:
            ts.attribs["font-size"] = fmt(s.size)
        if s.italic:
            ts.attribs["font-style"] = "italic"
        el.elements.append(ts)
    return el


_MAKERS = {Line: _line, Polyline: _polyline, Polygon: _polygon, Strokes: _strokes, Rectangle: _rect, Circle: _circle,
           Text: _text}


def sheet_to_svg(sheet: Sheet, attrs: Callable[[Command], dict[str, str]] | None = None, *,
                 grouped: bool = True, ids: Ids | None = None) -> str:
    """The sheet as an SVG document, 1 user unit = 1 mm, each part a group (see the module's words);
    ``attrs(command)`` adds attributes to each element; ``grouped=False`` writes the elements bare (the
    sweep card, which names its own); ``ids`` shares the ids of several documents on one page (each id is
    then written once over all of them)."""
    w, h = sheet.width, sheet.height
    root = {"width": f"{fmt(w)}mm", "height": f"{fmt(h)}mm", "viewBox": f"0 0 {fmt(w)} {fmt(h)}",
            "font-family": FONT_FAMILY,                  # every text's (black, the default fill)
            **SVG_NAMESPACES, "baseProfile": "full", "version": "1.1"}
    css = css_for(s.text for c in sheet.commands if isinstance(c, Text) for s in c.spans)
    page = _Element("rect", {"x": "0", "y": "0", "width": fmt(w), "height": fmt(h), "fill": "white", "stroke": "none"})
    elements: list = [page]
    if not grouped:
        elements += [_element(c, attrs) for c in sheet.commands]
        return _document(root, css, elements)
    entities = sheet.entities
    ids = Ids(entities) if ids is None else ids
    run, key, name = None, None, None
    for c in sheet.commands:
        if c.name != name:
            name = c.name
            part = part_of(name, entities)
            if (part.owner, part.label) != key:
                key = (part.owner, part.label)
                run = _run(part, ids)
                elements.append(run)
        run.elements.append(_element(c, attrs))
    return _document(root, css, elements)


class _Run:
    """One group of the document: a run of one part's commands (see the module's words), written as
    :func:`_run_head` (a ``<g>`` and its ``<title>``) and its elements."""

    __slots__ = ("attribs", "title", "elements")

    def __init__(self, attribs: dict[str, str], title: str | None) -> None:
        self.attribs, self.title, self.elements = attribs, title, []


def _run(part: Part, ids: Ids) -> _Run:
    """The group of one run of ``part``'s commands: its class and entity; the id and title on the
    part's first run in the document."""
    owner = ids(part.owner)
    if part.label:
        attribs = {"class": f"{part.kind} label", "data-entity": owner, "data-for": owner}
    else:
        attribs = {"class": part.kind, "data-entity": owner}
    if ids.claim(owner):
        attribs["id"] = owner
        return _Run(attribs, part.title)
    return _Run(attribs, None)


@functools.lru_cache(maxsize=4096)
def _run_head(attribs: tuple[tuple[str, str], ...], title: str | None) -> str:
    """A group's start tag and title, as ElementTree writes them (the same few for every sheet)."""
    out: list[str] = []
    _start("g", dict(attribs), out)
    out.append(">")
    if title is not None:
        out.append(f"<title>{_escaped(title, attribute=False)}</title>" if title else "<title />")
    return "".join(out)


def svg_inline(sheet: Sheet, width: str = "100%") -> str:
    """The sheet as an SVG element that scales to ``width`` (for HTML and notebooks)."""
    text = sheet_to_svg(sheet)
    head, rest = text.split("<svg", 1)
    tag, body = rest.split(">", 1)
    tag = tag.replace(f'width="{sheet.paper.width:g}mm"', f'width="{width}"')
    tag = tag.replace(f'height="{sheet.paper.height:g}mm"', 'height="auto"')
    return f"<svg{tag}>{body}"


# ---- the writer: the tree as svgwrite (through ElementTree) writes it --------------------------------

def _escaped(v: str, *, attribute: bool) -> str:
    """``v`` made safe (:func:`xml_safe`) and escaped as ElementTree escapes text or an attribute."""
    if not (v.isascii() and v.isprintable()):       # only then can it hold a forbidden character, or a tab or line end
        v = xml_safe(v)
    if "&" in v:
        v = v.replace("&", "&amp;")
    if "<" in v:
        v = v.replace("<", "&lt;")
    if ">" in v:
        v = v.replace(">", "&gt;")
    if attribute:
        for c, e in _ATTRIBUTE_ESCAPES:
            if c in v:
                v = v.replace(c, e)
    return v


_ATTRIBUTE_ESCAPES = (('"', "&quot;"), ("\r", "&#13;"), ("\n", "&#10;"), ("\t", "&#09;"))
_attribute = functools.lru_cache(maxsize=4096)(functools.partial(_escaped, attribute=True))
"""An attribute value escaped (most are coordinates and paints the sheet repeats: remembered)."""


def _start(tag: str, attribs: dict, out: list[str]) -> None:
    """``<tag`` and its attributes as svgwrite's ``get_xml`` sets them: sorted by name, None and empty
    values left out, values as ``str`` (svgwrite's ``value_to_string`` without validation)."""
    out.append("<" + tag)
    for k, v in sorted(attribs.items()):
        if v is not None:
            v = str(v)
            if v:
                out.append(f' {k}="{_attribute(v)}"')


def _write(el: _Element | _Run, out: list[str]) -> None:
    """One element and what it holds (ElementTree's layout: ``<x a="1" />`` when empty)."""
    if type(el) is _Run:
        out.append(_run_head(tuple(el.attribs.items()), el.title))
        for sub in el.elements:
            _write(sub, out)
        out.append("</g>")
        return
    _start(el.tag, el.attribs, out)
    text = str(el.text)
    if text or el.elements:
        out.append(">")
        if text:
            out.append(_escaped(text, attribute=False))
        for sub in el.elements:
            _write(sub, out)
        out.append(f"</{el.tag}>")
    else:
        out.append(" />")


@functools.lru_cache(maxsize=16)
def _defs(css: str) -> str:
    """The ``<defs>`` holding the style sheet as CDATA (svgwrite's ``<style>``), made safe
    (:func:`xml_safe`) and remembered: it embeds the font (~36 kB), the same for many sheets."""
    return xml_safe(f'<defs><style type="text/css"><![CDATA[{css}]]></style></defs>' if css
                    else '<defs><style type="text/css" /></defs>')


def _document(root: dict[str, str], css: str, elements: list) -> str:
    """The whole document: the ``<svg>`` with ``root``'s attributes, the style sheet's ``<defs>``, then
    ``elements`` (as ``ElementTree.tostring(drawing.get_xml(), encoding="unicode")`` writes svgwrite's
    drawing of the same)."""
    out: list[str] = []
    _start("svg", root, out)
    out.append(">")
    out.append(_defs(css))
    for el in elements:
        _write(el, out)
    out.append("</svg>")
    return "".join(out)
