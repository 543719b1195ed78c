"""Styles and lettering: ISO 128 line types, ISO 3098 lettering, and role -> style.

A drawing command names a style; this module says what the name means on paper.  Nothing depends on
colour: every distinction (given / trial / path / result / image) is made by line width, dash pattern,
fill or arrowhead, so a sheet reads in black and white.

Lettering is measured with the bundled DejaVu Sans (Pillow reads the TrueType file), the only font a
sheet names.  cairosvg places text letter by letter with the font's advances and no kerning, so the
measurement sums per-character advances in the same way.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass
from pathlib import Path

from constructions.entities import Role

from .errors import StyleError
from .paper import Rect, Span

# ---- ISO 128 line widths (mm) and patterns -------------------------------------------------------

THICK = 0.5
THIN = 0.25
FRAME = 0.7


def dashed(d: float) -> tuple[float, ...]:
    """ISO 128 line type 02 (dashed): dash 12d, gap 3d (butt caps)."""
    return (12 * d, 3 * d)


def long_dash_dot(d: float) -> tuple[float, ...]:
    """ISO 128 line type 04 (long-dash-dot), long dash 24d, gap 3d, dot 0.5d.

    Drawn with round caps, which add d/2 at each end of every dash: the long dash is shortened and the
    gaps widened by d, and the dot is a zero-length dash that the round cap turns into a dot of
    diameter d, so the printed pattern matches the standard.
    """
    return (23 * d, 4 * d, 0.0, 4 * d)


@dataclass(frozen=True, slots=True)
class Style:
    """How a command looks.  ``stroke``/``fill`` are paint names or None; widths and dashes in mm."""

    name: str
    stroke: str | None = "black"
    width: float = THIN
    dash: tuple[float, ...] = ()
    fill: str | None = None
    cap: str = "round"
    join: str = "round"

    def __post_init__(self) -> None:
        if self.stroke is not None and not self.width > 0:
            raise ValueError(f"style {self.name!r}: a stroked line needs a positive width")
        if any(d < 0 for d in self.dash):
            raise ValueError(f"style {self.name!r}: dash lengths cannot be negative")
        if self.dash and not any(d > 0 for d in self.dash):
            raise ValueError(f"style {self.name!r}: a dash pattern needs a positive length")


LIGHT_GREY = "#d9d9d9"


def _styles() -> dict[str, Style]:
    s = [
        Style("frame", width=FRAME, cap="square", join="miter"),
        Style("title_block", width=FRAME, cap="square", join="miter"),
        Style("rule", width=THIN, cap="butt"),                      # table and title block rules
        Style("separator", width=THIN, cap="butt"),                 # between viewports
        Style("link", width=THICK),                                 # given bars, plates
        Style("guide", width=THICK, cap="butt"),
        Style("hatch", width=THIN, cap="butt"),
        Style("ground", width=THICK, fill="white"),                 # pivot triangle
        Style("block", width=THICK, fill="white", join="miter"),
        Style("pin", width=THICK, fill="white"),
        Style("dot", stroke=None, fill="black"),
        Style("trial", width=THIN, cap="butt"),                     # thin continuous, ISO type 01.2
        Style("path", width=THIN),                                   # construction arcs (loci), thin solid
        Style("centre", width=THIN, dash=long_dash_dot(THIN)),
        Style("hidden", width=THIN, dash=dashed(THIN), cap="butt"),
        Style("vector", width=THICK, cap="butt"),                   # known and result vectors
        Style("arrowhead", stroke=None, fill="black"),
        Style("image", width=THIN, fill=LIGHT_GREY, join="miter"),  # velocity images
        Style("label_bg", stroke=None, fill="white"),
        Style("bar_dark", width=THIN, fill="black", cap="butt", join="miter"),
        Style("bar_light", width=THIN, fill="white", cap="butt", join="miter"),
        Style("tick", width=THIN, cap="butt"),
        Style("mark", width=THIN),                                   # drawn tick/cross marks
        Style("dimension", width=THIN, cap="butt"),                  # ISO 129 dimension and extension lines
        Style("load", width=THICK, cap="butt"),                      # external and inertia forces
        Style("note_bg", stroke=None, fill="white"),                 # behind a note or dimension text
        # charts: axes and ticks thin; curves thick, told apart by dash pattern (black and white)
        Style("axis", width=THIN, cap="square"),
        Style("grid", width=THIN, stroke=LIGHT_GREY, cap="butt"),
        Style("band", stroke=None, fill=LIGHT_GREY),
        Style("series 1", width=THICK, fill=None),
        Style("series 2", width=THICK, dash=dashed(THICK), cap="butt"),
        Style("series 3", width=THICK, dash=long_dash_dot(THICK)),
        Style("series 4", width=THIN),
        # lettering: black fill, no stroke; the size travels with the text
        Style("text", stroke=None, fill="black"),
        Style("label", stroke=None, fill="black"),
        Style("heading", stroke=None, fill="black"),
        Style("title", stroke=None, fill="black"),
    ]
    return {x.name: x for x in s}


@functools.cache
def styles() -> dict[str, Style]:
    """The style table (built on first use)."""
    return _styles()


def style(name: str) -> Style:
    try:
        return styles()[name]
    except KeyError:
        raise StyleError(f"no style named {name!r}") from None


LINE_STYLES: dict[Role, str] = {
    Role.GIVEN: "link",            # links, guides: thick
    Role.KNOWN: "vector",          # vectors drawn to scale: thick
    Role.RESULT: "vector",
    Role.TRIAL: "trial",           # thin, continuous, extended past the crossing
    Role.AUXILIARY: "hidden",      # thin dashed (ISO 128 type 02): Culmann's line
    Role.PATH: "path",             # loci: thin
    Role.IMAGE: "image",
    Role.LABEL: "trial",
    Role.SCALE_BAR: "tick",
    Role.CENTRE_LINE: "centre",    # long-dash-dot (centre lines, pitch and base circles)
    Role.DIMENSION: "dimension",   # thin
    Role.NOTE: "dimension",        # a leader of a note: thin
    Role.LOAD: "load",             # forces: thick
    Role.CHART: "series 1",
}
"""The line style of a line-like entity (bar, trial line, path, circle, curve, vector shaft) of each role."""

AREA_STYLES: dict[Role, str] = {
    Role.GIVEN: "link",
    Role.KNOWN: "trial",
    Role.RESULT: "trial",
    Role.TRIAL: "trial",
    Role.AUXILIARY: "trial",
    Role.PATH: "trial",
    Role.IMAGE: "image",           # velocity / acceleration images: light grey with a thin outline
    Role.LABEL: "trial",
    Role.SCALE_BAR: "trial",
    Role.CENTRE_LINE: "centre",
    Role.DIMENSION: "dimension",
    Role.NOTE: "dimension",
    Role.LOAD: "trial",
    Role.CHART: "band",
}
"""The style of a closed figure (polygon, plate, closed curve) of each role."""


def _role_style(table: dict, role: Role, what: str) -> str:
    try:
        return table[role]
    except (KeyError, TypeError):
        name = role.name if isinstance(role, Role) else repr(role)
        raise StyleError(f"the role {name} has no {what} style; map it in drafting.render.style "
                         f"({'LINE_STYLES' if what == 'line' else 'AREA_STYLES'})") from None


def line_style_for(role: Role) -> str:
    """The style of a line-like entity (bar, trial line, path, vector shaft) of ``role``; a role without
    a style raises :class:`StyleError` naming it."""
    return _role_style(LINE_STYLES, role, "line")


def area_style_for(role: Role) -> str:
    """The style of a closed figure (polygon, plate) of ``role``."""
    return _role_style(AREA_STYLES, role, "area")


# ---- lettering (ISO 3098 type B) ----------------------------------------------------------------

FONT_FAMILY = "DejaVu Sans"
FONT_DIR = Path(__file__).resolve().parent / "fonts"
FONT_FILES = {False: "DejaVuSans.ttf", True: "DejaVuSans-Oblique.ttf"}

LABEL = 3.5
TITLE = 7.0
HEADING = 5.0
MIN_TEXT = 2.5
LETTER_SIZES = (2.5, 3.5, 5.0, 7.0, 10.0)
SUB_SCALE = 0.71          # sub/superscript size relative to its base, never below MIN_TEXT
SUB_SHIFT = 0.25          # subscript baseline drop, in units of the base size
SUP_SHIFT = -0.42         # superscript baseline rise
WIDTH_MARGIN = 1.02       # renderers hint advances slightly differently; measure 2 % wide

_EM = 2048                # font units per em of DejaVu Sans


@functools.cache
def _font(italic: bool):
    from PIL import ImageFont
    path = FONT_DIR / FONT_FILES[italic]
    if not path.exists():
        raise FileNotFoundError(f"the bundled font {path} is missing")
    return ImageFont.truetype(str(path), _EM, layout_engine=ImageFont.Layout.BASIC)


@functools.cache
def _advance(ch: str, italic: bool) -> float:
    """Advance of one character in em."""
    return _font(italic).getlength(ch) / _EM


_INK_SET = ("ABCDEFGHIJKLMNOPQRSTUVWXYZbdfhkltgjpqy0123456789()[]{}|/"
            "\u2713\u00d7\u22a5\u2225\u03c9\u03b1")


@functools.cache
def font_metrics() -> tuple[float, float]:
    """(ascent, descent) in em of the ink of the letters a sheet uses (Latin letters, digits,
    brackets, marks), rounded up to 0.01 em.  Tighter than the font's line metrics, which leave room
    for accented capitals; this is the box text collision tests use."""
    f = _font(False)
    a, _ = f.getmetrics()
    top = min(f.getbbox(ch)[1] for ch in _INK_SET)
    bottom = max(f.getbbox(ch)[3] for ch in _INK_SET)
    return math.ceil((a - top) / _EM * 100) / 100, math.ceil((bottom - a) / _EM * 100) / 100


def text_width(text: str, size: float, italic: bool = False) -> float:
    """Advance width in mm of ``text`` at ``size`` mm (sum of per-letter advances, as cairo draws)."""
    return _em_width(text, italic) * size * WIDTH_MARGIN


@functools.lru_cache(maxsize=16384)
def _em_width(text: str, italic: bool) -> float:
    return sum(_advance(ch, italic) for ch in text)


def sub_size(size: float) -> float:
    return max(MIN_TEXT, round(size * SUB_SCALE, 3))


@dataclass(frozen=True, slots=True)
class Extent:
    """Measured extent of spans relative to the start of the baseline: width, top (<0), bottom (>0)."""

    width: float
    top: float
    bottom: float

    @property
    def height(self) -> float:
        return self.bottom - self.top

    def box(self, x: float, y: float) -> Rect:
        return Rect(x, y + self.top, self.width, self.height)


def measure(spans: tuple[Span, ...] | list[Span]) -> Extent:
    """The extent of ``spans`` (measured once per distinct run of spans)."""
    return _measure(tuple(spans))


@functools.lru_cache(maxsize=8192)
def _measure(spans: tuple[Span, ...]) -> Extent:
    asc, desc = font_metrics()
    width = 0.0
    top = 0.0
    bottom = 0.0
    for s in spans:
        width += text_width(s.text, s.size, s.italic)
        top = min(top, s.shift - asc * s.size)
        bottom = max(bottom, s.shift + desc * s.size)
    return Extent(width, top, bottom)


def plain(text: str, size: float, italic: bool = False) -> tuple[Span, ...]:
    return (Span(text, size, 0.0, italic),)


_GROUP = r"(?:\{[^{}]*\}|[A-Za-z0-9\u0370-\u03ff']+)"
_TOKEN = re.compile(
    r"(?<![A-Za-z0-9\u0370-\u03ff])(?P<base>[A-Za-z\u0370-\u03ff]+)_(?P<sub>" + _GROUP + r")"
    r"(?:\^(?P<sup>" + _GROUP + r"))?")
_PIVOT = re.compile(r"^(?P<base>[A-Za-z])(?P<sub>[0-9]+)$")
_NAMED = re.compile(r"(?:(?<![A-Za-z0-9\u0370-\u03ff'\-/.])|(?<=/)(?=[A-Z]))(?P<chain>(?:[A-Za-z\u0370-\u03ff][0-9]{0,2})+)"
                    r"(?P<primes>'{1,2})?(?![0-9A-Za-z\u0370-\u03ff])")
_PAIR = re.compile(r"([A-Za-z\u0370-\u03ff])([0-9]*)")
"""Point and member names inside running text, set as the notes print them: the digits of "O4", "F14",
"O2G2", "omega2" ... as subscripts ("O4I" -> O with 4 below, then I), and a prime as a prime (b' ->
b\u2032, C'' -> C\u2033); words without digits or primes ("D'Alembert", "Kennedy's") stay as written."""
_PRIMES = {"'": "\u2032", "''": "\u2033"}
_NUMBER_PRIMED = re.compile(r"^[0-9]+'{1,2}$")
"""An unbraced subscript of digits with one or two primes after it (theta_1', the second solution): a
digit carries no prime, so the primes are the symbol's, set at full size after the subscript."""


def _strip(group: str | None) -> str:
    if not group:
        return ""
    return group[1:-1] if group.startswith("{") else group


def _symbol(base: str, sub: str, sup: str, size: float, italic_base: bool) -> list[Span]:
    out = [Span(base, size, 0.0, italic_base)]
    ss = sub_size(size)
    if sub:
        out.append(Span(sub, ss, round(SUB_SHIFT * size, 3)))
    if sup:
        out.append(Span(sup, ss, round(SUP_SHIFT * size, 3)))
    return out


@functools.lru_cache(maxsize=8192)
def rich(markup: str, size: float, *, pivot_digits: bool = False, italic_symbols: bool = False) -> tuple[Span, ...]:
    """Spans for ``markup`` with TeX-like sub/superscripts: "O_v", "V_CB^t", "V_{C}".

    With ``pivot_digits`` a label such as "O1" (one letter and digits) gets its digits as a subscript,
    as the notes print fixed pivots.  Subscripts are set with a baseline shift of the span (drawn with
    ``dy``), never with ``baseline-shift``.  Remembered: a sheet sets the same markup many times.
    """
    if pivot_digits:
        m = _PIVOT.match(markup)
        if m:
            return tuple(_symbol(m["base"], m["sub"], "", size, italic_symbols))
    spans: list[Span] = []
    pos = 0
    for m in _TOKEN.finditer(markup):
        if m.start() > pos:
            spans.append(Span(markup[pos:m.start()], size))
        sub, primes = _strip(m["sub"]), ""
        if not m["sup"] and _NUMBER_PRIMED.match(m["sub"]):     # theta_1': the symbol's prime, not the 1's
            sub, primes = sub.rstrip("'"), _PRIMES.get(sub[len(sub.rstrip("'")):], "")
        spans.extend(_symbol(m["base"], sub, _strip(m["sup"]), size, italic_symbols))
        if primes:
            spans.append(Span(primes, size, 0.0, italic_symbols))
        pos = m.end()
    if pos < len(markup):
        spans.append(Span(markup[pos:], size))
    return tuple(_merge([n for sp in spans for n in _names(sp)]))


_DASHES = ((re.compile(r"->"), "\u2192"), (re.compile(r"(?<![-!])--(?![->])"), "\u2013"))
"""ASCII a scene or a step may write, set as the sign it stands for: an arrow, a dash between clauses
(a word of its own when the text is wrapped word by word)."""


def _names(span: Span) -> list[Span]:
    """``span`` (a run outside any markup) with its point names set as symbols (see ``_NAMED``) and its
    ASCII arrows and dashes as their signs."""
    if span.shift:
        return [span]
    if "-" in span.text:
        text = span.text
        for ascii_, sign in _DASHES:
            text = ascii_.sub(sign, text)
        span = Span(text, span.size, span.shift, span.italic)
    if not any(c.isdigit() or c == "'" for c in span.text):
        return [span]
    out: list[Span] = []
    pos = 0
    for m in _NAMED.finditer(span.text):
        chain, primes, end = m["chain"], m["primes"], m.end()
        pairs = _PAIR.findall(chain)
        if primes and len(pairs) > 1:               # a word's apostrophe (the notes', drivers'): as written
            primes, end = None, end - len(primes)
        if not primes and not any(c.isdigit() for c in chain):
            continue
        out.append(Span(span.text[pos:m.start()], span.size, 0.0, span.italic))
        for base, sub in pairs:
            out.extend(_symbol(base, sub, "", span.size, span.italic))
        if primes:
            out.append(Span(_PRIMES[primes], span.size, 0.0, span.italic))
        pos = end
    out.append(Span(span.text[pos:], span.size, 0.0, span.italic))
    return out


def _merge(spans: list[Span]) -> list[Span]:
    out: list[Span] = []
    for s in spans:
        if not s.text:
            continue
        if out and (out[-1].size, out[-1].shift, out[-1].italic) == (s.size, s.shift, s.italic):
            out[-1] = Span(out[-1].text + s.text, s.size, s.shift, s.italic)
        else:
            out.append(s)
    return out


def scaled(spans: tuple[Span, ...], factor: float) -> tuple[Span, ...]:
    return tuple(Span(s.text, max(MIN_TEXT, s.size * factor), s.shift * factor, s.italic) for s in spans)
