"""PDF and PNG drawn straight from a sheet's commands with cairo: the only module that draws with cairo.

The SVG is the sheet's document of record (:mod:`drafting.backends.svg`); the PDF and PNG are the same commands
drawn onto a cairo surface directly, rather than by writing the SVG and parsing it back (cairosvg sets
every letter as an outline, one cairo call per letter, which made the PDF several times slower than the
whole layout).  What each command means on paper is the one style table (:func:`drafting.render.style.style`),
the same as the SVG's presentation attributes:

- 1 user unit is 1 mm: the PDF page is exactly the paper (mm scaled to points, 72 / 25.4), the PNG is
  ``dpi / 25.4`` pixels a millimetre, rounded to whole pixels as cairosvg did, stored as 8-bit grey;
- paint as SVG paints it: fill first, then stroke; the non-zero fill rule; the miter limit 4 of SVG
  (cairo's own default is 10); dashes in mm with their zero-length dots drawn by round caps;
- text is set as text (the PDF's lettering is searchable and selectable, its font embedded as a
  subset), in the bundled DejaVu Sans, spans one after the other from the baseline point, each span's
  baseline moved by its shift (a subscript) and at its own size, as the SVG's tspans are; font metrics
  are not hinted, so the advances are the font's own, the ones the layout measured with.

With ``SOURCE_DATE_EPOCH`` set (or a moment given) the PDF's creation date is that moment, so the same
sheet gives the same bytes.
"""

from __future__ import annotations

import io
import os
import re
import time
from typing import Sequence

from . import cairo_ffi
from ..render.paper import Circle, Command, Line, Polygon, Polyline, Rectangle, Strokes, Text
from ..layout.sheet import Sheet, source_date_epoch
from ..render.style import FONT_DIR, FONT_FAMILY, style

MM_TO_PT = 72.0 / 25.4
FONTS_CONF = FONT_DIR / "fonts.conf"
SVG_MITER_LIMIT = 4.0
_COLOURS = {"black": (0.0, 0.0, 0.0), "white": (1.0, 1.0, 1.0)}


def _cairo():
    """cairocffi, with fontconfig told about the bundled DejaVu Sans before cairo first looks for fonts,
    so the PDF/PNG are set in the font the layout measured with (a user's FONTCONFIG_FILE wins)."""
    os.environ.setdefault("FONTCONFIG_FILE", str(FONTS_CONF))
    prebuilt = cairo_ffi.install()      # its declarations prebuilt, not parsed on every start
    try:
        with cairo_ffi.loading():       # and libcairo.so.2 opened without running ldconfig
            import cairocffi
    except Exception:
        cairo_ffi.uninstall()           # cairocffi's own parse and search, as it always did
        import cairocffi
    return cairocffi


def _rgb(paint: str) -> tuple[float, float, float]:
    if paint in _COLOURS:
        return _COLOURS[paint]
    if re.fullmatch(r"#[0-9a-fA-F]{6}", paint):
        return tuple(int(paint[i:i + 2], 16) / 255.0 for i in (1, 3, 5))      # type: ignore[return-value]
    raise ValueError(f"the paint {paint!r} is not one the sheets use (black, white or #rrggbb)")


class _Painter:
    """Draws commands onto one cairo context whose user unit is 1 mm."""

    def __init__(self, cairo, ctx) -> None:
        self.cairo, self.ctx = cairo, ctx
        ctx.set_miter_limit(SVG_MITER_LIMIT)
        ctx.set_fill_rule(cairo.FILL_RULE_WINDING)
        opts = cairo.FontOptions()
        opts.set_hint_metrics(cairo.HINT_METRICS_OFF)
        opts.set_antialias(cairo.ANTIALIAS_GRAY)           # no coloured sub-pixel fringes: a grey page
        opts.set_hint_style(cairo.HINT_STYLE_NONE)         # outlines as drawn, whatever rendered before
        ctx.set_font_options(opts)
        self._caps = {"butt": cairo.LINE_CAP_BUTT, "round": cairo.LINE_CAP_ROUND, "square": cairo.LINE_CAP_SQUARE}
        self._joins = {"miter": cairo.LINE_JOIN_MITER, "round": cairo.LINE_JOIN_ROUND, "bevel": cairo.LINE_JOIN_BEVEL}
        self._faces = {italic: cairo.ToyFontFace(FONT_FAMILY, cairo.FONT_SLANT_ITALIC if italic else
                                                 cairo.FONT_SLANT_NORMAL, cairo.FONT_WEIGHT_NORMAL)
                       for italic in (False, True)}

    def page(self, width: float, height: float, commands: Sequence[Command]) -> None:
        ctx = self.ctx
        ctx.rectangle(0, 0, width, height)
        ctx.set_source_rgb(1.0, 1.0, 1.0)
        ctx.fill()
        for c in commands:
            self.command(c)

    def command(self, c: Command) -> None:
        ctx = self.ctx
        if isinstance(c, Text):
            self.text(c)
            return
        if isinstance(c, Line):
            ctx.move_to(c.x1, c.y1)
            ctx.line_to(c.x2, c.y2)
        elif isinstance(c, Strokes):
            for a, b in c.segments:
                ctx.move_to(*a)
                ctx.line_to(*b)
        elif isinstance(c, (Polyline, Polygon)):
            if not c.points:
                return
            ctx.move_to(*c.points[0])
            for p in c.points[1:]:
                ctx.line_to(*p)
            if isinstance(c, Polygon):
                ctx.close_path()
        elif isinstance(c, Rectangle):
            ctx.rectangle(c.x, c.y, c.w, c.h)
        elif isinstance(c, Circle):
            ctx.new_sub_path()
            ctx.arc(c.cx, c.cy, c.r, 0.0, 2 * 3.141592653589793)
            ctx.close_path()
        else:
            raise TypeError(f"not a drawing command: {c!r}")
        self.paint(c.style, fillable=not isinstance(c, (Line, Strokes)))

    def paint(self, name: str, fillable: bool) -> None:
        st, ctx = style(name), self.ctx
        if st.fill and fillable:
            ctx.set_source_rgb(*_rgb(st.fill))
            if st.stroke:
                ctx.fill_preserve()
            else:
                ctx.fill()
        if st.stroke:
            ctx.set_source_rgb(*_rgb(st.stroke))
            ctx.set_line_width(st.width)
            ctx.set_line_cap(self._caps[st.cap])
            ctx.set_line_join(self._joins[st.join])
            ctx.set_dash(list(st.dash) if st.dash else [], 0.0)
            ctx.stroke()
        ctx.new_path()

    def text(self, c: Text) -> None:
        ctx = self.ctx
        ctx.set_source_rgb(0.0, 0.0, 0.0)
        x = c.x
        for s in c.spans:
            ctx.set_font_face(self._faces[s.italic])
            ctx.set_font_size(s.size)
            ctx.move_to(x, c.y + s.shift)
            if s.text.strip():
                ctx.show_text(s.text)
            x += ctx.text_extents(s.text)[4] if s.text else 0.0
        ctx.new_path()


def sheets_to_pdf(sheets: Sequence[Sheet], epoch: int | None = None) -> bytes:
    """One PDF with a page per sheet, each page exactly its paper, created at ``epoch`` (see
    :func:`dated_pdf`)."""
    cairo = _cairo()
    out = io.BytesIO()
    first = sheets[0]
    surface = cairo.PDFSurface(out, first.width * MM_TO_PT, first.height * MM_TO_PT)
    try:
        for i, sh in enumerate(sheets):
            if i:
                surface.set_size(sh.width * MM_TO_PT, sh.height * MM_TO_PT)
            ctx = cairo.Context(surface)
            ctx.scale(MM_TO_PT, MM_TO_PT)
            _Painter(cairo, ctx).page(sh.width, sh.height, sh.commands)
            ctx.show_page()
    finally:
        surface.finish()
    return dated_pdf(out.getvalue(), epoch)


def sheet_to_png(sheet: Sheet, dpi: float) -> bytes:
    """The sheet as a PNG at ``dpi`` pixels an inch: 8-bit grey (a sheet is black, white and grey only,
    so nothing is lost) through Pillow, several times quicker to encode than cairo's 32-bit PNG and half
    the size."""
    cairo = _cairo()
    import numpy as np
    from PIL import Image

    k = dpi / 25.4
    w, h = int(round(sheet.width * k)), int(round(sheet.height * k))
    surface = cairo.ImageSurface(cairo.FORMAT_RGB24, w, h)
    ctx = cairo.Context(surface)
    ctx.scale(k, k)
    _Painter(cairo, ctx).page(sheet.width, sheet.height, sheet.commands)
    surface.flush()
    stride = surface.get_stride()
    pixels = np.frombuffer(surface.get_data(), dtype=np.uint8).reshape(h, stride // 4, 4)
    grey = np.ascontiguousarray(pixels[:, :w, 1])          # the green byte: r = g = b on every pixel
    surface.finish()
    out = io.BytesIO()
    Image.fromarray(grey, mode="L").save(out, format="PNG")
    return out.getvalue()


def dated_pdf(pdf: bytes, epoch: int | None = None) -> bytes:
    """The PDF with its creation date set to ``epoch`` (seconds since 1970; a batch passes one moment to
    every worker), else to SOURCE_DATE_EPOCH when set, so the same sheet gives the same bytes; cairo
    itself stamps the wall clock.  The stamp keeps its length, so the cross-reference offsets stay
    valid."""
    epoch = source_date_epoch() if epoch is None else epoch
    if epoch is None:
        return pdf
    stamp = time.strftime("D:%Y%m%d%H%M%SZ", time.gmtime(int(epoch))).encode()
    return re.sub(rb"/CreationDate \(D:\d{14}Z\)", b"/CreationDate (" + stamp + b")", pdf, count=1)
