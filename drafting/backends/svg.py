"""SVG: the only module that imports svgwrite.

One user unit is one millimetre (``width="297mm" viewBox="0 0 297 210"``).  Every command becomes one
element with its style written out as presentation attributes (stroke, width, dashes, fill), which
cairosvg reads reliably.  Coordinates are rounded to 3 decimals so the output is stable.  Nothing here
uses what cairosvg cannot render: arrowheads are filled polygons (no markers), subscripts are tspans
moved with ``dy`` (no ``baseline-shift``), label backgrounds are white rectangles (no ``paint-order``).

svgwrite holds the document; :func:`_write` writes its tree out in one pass, to the same characters as
svgwrite's own writer (its ``get_xml`` builds an ElementTree of the whole document first, which took
half of the SVG's time).  The elements this module makes -- shapes, paths, texts and their tspans --
are written directly; anything else (the ``<defs>`` with the font's style sheet) by svgwrite itself.
A test holds every gallery sheet to svgwrite's own output, character for character.

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
from xml.etree import ElementTree

import svgwrite
from svgwrite import path as svg_path, shapes, text as svg_text
from svgwrite.base import Title
from svgwrite.utils import strlist

from .fonts import css_for
from ..render.paper import Circle, Command, Line, Polygon, Polyline, Rectangle, Strokes, Text
from ..layout.parts import Ids, Part, part_of
from ..layout.sheet import Sheet
from ..render.style import FONT_FAMILY, style
from ..scene.textsafe import xml_safe


def fmt(v: float) -> str:
    """A coordinate in mm with at most 3 decimals and no '-0' (``.3f`` rounds as ``round(v, 3)`` does:
    both are correctly rounded)."""
    s = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("", "-0") else s


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


def _line(dwg, c: Line):
    return shapes.Line((fmt(c.x1), fmt(c.y1)), (fmt(c.x2), fmt(c.y2)), factory=dwg)


def _polyline(dwg, c: Polyline):
    return shapes.Polyline([(fmt(x), fmt(y)) for x, y in c.points], factory=dwg)


def _polygon(dwg, c: Polygon):
    return shapes.Polygon([(fmt(x), fmt(y)) for x, y in c.points], factory=dwg)


def _strokes(dwg, c: Strokes):
    """One path of separate strokes: "M x y L x y" for each."""
    return svg_path.Path([f"M{fmt(a[0])} {fmt(a[1])}L{fmt(b[0])} {fmt(b[1])}" for a, b in c.segments], factory=dwg)


def _rect(dwg, c: Rectangle):
    return shapes.Rect((fmt(c.x), fmt(c.y)), (fmt(c.w), fmt(c.h)), factory=dwg)


def _circle(dwg, c: Circle):
    return shapes.Circle((fmt(c.cx), fmt(c.cy)), fmt(c.r), factory=dwg)


def _element(dwg: svgwrite.Drawing, c: Command, attrs: Callable[[Command], dict[str, str]] | None = None):
    make = _MAKERS.get(type(c))
    if make is None:
        raise TypeError(f"not a drawing command: {c!r}")
    el = make(dwg, c)
    if make is not _text:
        el.attribs.update(_paint(c.style))
    if attrs is not None:
        el.attribs.update(attrs(c))
    return el


def _text(dwg: svgwrite.Drawing, c: Text):
    base = c.spans[0].size if c.spans else 3.5
    el = svg_text.Text("", factory=dwg)
    el.attribs.update({"x": fmt(c.x), "y": fmt(c.y), "font-size": fmt(base), "xml:space": "preserve"})
    shift = 0.0
    for i, s in enumerate(c.spans):
        if i == 0 and s.shift == 0 and not s.italic:
            el.text = s.text
            continue
        ts = svg_text.TSpan(s.text, factory=dwg)
        dy = s.shift - shift
        if abs(dy) > 5e-4:
            ts.attribs["dy"] = fmt(dy)
        shift = s.shift
        if abs(s.size - base) > 5e-4:
            ts.attribs["font-size"] = fmt(s.size)
        if s.italic:
            ts.attribs["font-style"] = "italic"
        el.add(ts)
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
    dwg = svgwrite.Drawing(size=(f"{fmt(w)}mm", f"{fmt(h)}mm"), profile="full", debug=False)
    dwg.attribs["viewBox"] = f"0 0 {fmt(w)} {fmt(h)}"
    dwg.attribs["font-family"] = FONT_FAMILY          # every text's (black, the default fill)
    page = dwg.rect()
    page.attribs.update({"x": "0", "y": "0", "width": fmt(w), "height": fmt(h), "fill": "white", "stroke": "none"})
    dwg.add(page)
    dwg.defs.add(dwg.style(css_for(s.text for c in sheet.commands if isinstance(c, Text) for s in c.spans)))
    if not grouped:
        for c in sheet.commands:
            dwg.add(_element(dwg, c, attrs))
        return _document(dwg)
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
                dwg.elements.append(run)
        run.elements.append(_element(dwg, c, attrs))
    return _document(dwg)


class _Run:
    """One group of the document: a run of one part's commands (see the module's words).  It is
    written as :func:`_run_head` and its elements; ``get_xml`` is svgwrite's tree of the same (a
    ``Group`` holding a ``Title``), which a test holds the writer to."""

    __slots__ = ("attribs", "title", "elements")

    def __init__(self, attribs: dict[str, str], title: str | None) -> None:
        self.attribs, self.title, self.elements = attribs, title, []

    def get_xml(self):
        xml = ElementTree.Element("g", dict(sorted(self.attribs.items())))
        if self.title is not None:
            xml.append(Title(self.title).get_xml())
        for el in self.elements:
            xml.append(el.get_xml())
        return xml


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


# ---- the writer: svgwrite's tree as svgwrite (through ElementTree) writes it ------------------------

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


def _write(el, out: list[str]) -> None:
    """One element and what it holds (ElementTree's layout: ``<x a="1" />`` when empty)."""
    kind = type(el)
    if kind is _Run:
        out.append(_run_head(tuple(el.attribs.items()), el.title))
        for sub in el.elements:
            _write(sub, out)
        out.append("</g>")
        return
    if kind in _POINTS:
        el.attribs["points"] = el.points_to_string(el.points)
    elif kind is svg_path.Path:
        el.attribs["d"] = strlist(el.commands, " ")
    elif kind not in _PLAIN:
        out.append(_by_svgwrite(el))
        return
    _start(el.elementname, el.attribs, out)
    text = str(el.text) if kind in _TEXTS else ""
    if text or el.elements:
        out.append(">")
        if text:
            out.append(_escaped(text, attribute=False))
        for sub in el.elements:
            _write(sub, out)
        out.append(f"</{el.elementname}>")
    else:
        out.append(" />")


_POINTS = (shapes.Polyline, shapes.Polygon)
_TEXTS = (svg_text.Text, svg_text.TSpan)
_PLAIN = frozenset(_TEXTS + (shapes.Line, shapes.Rect, shapes.Circle))
"""The element kinds whose ``get_xml`` is svgwrite's plain one (after the points and path data above)."""


def _by_svgwrite(el) -> str:
    """An element svgwrite writes itself (the defs with the font's style sheet)."""
    return _made_safe(ElementTree.tostring(el.get_xml(), encoding="unicode"))


@functools.lru_cache(maxsize=16)
def _made_safe(xml: str) -> str:
    """:func:`xml_safe`, remembered: the style sheet embeds the font (~36 kB), the same for many sheets."""
    return xml_safe(xml)


def _document(dwg: svgwrite.Drawing) -> str:
    """The whole document, as ``ElementTree.tostring(dwg.get_xml(), encoding="unicode")`` writes it
    (svgwrite's tostring() encodes to UTF-8 and decodes again: the same text)."""
    held, dwg.elements = dwg.elements, []
    try:
        root = dwg.get_xml()                          # the root's attributes as svgwrite sets them
    finally:
        dwg.elements = held
    out: list[str] = []
    _start(root.tag, dict(root.attrib), out)
    out.append(">")
    for el in held:
        _write(el, out)
    out.append("</svg>")
    return "".join(out)
