"""The peer for the sheet benchmark: the same line art drawn through matplotlib.

What a user would otherwise script: every command of a laid-out sheet becomes a matplotlib artist on
one figure the size of the paper (an axes filling it, 1 data unit = 1 mm, y down) -- lines and
polylines as ``Line2D``, a hatching's strokes as one ``LineCollection``, polygons, rectangles and
circles as patches, each span of lettering as a
``text`` at the position the sheet's layout gave it (matplotlib has no layout of its own to offer
here) -- and saved with matplotlib's own SVG, PDF and Agg (PNG) back ends.  Only the drawing stage has
a peer: solving and laying out a sheet are this engine's.  matplotlib is optional (``pip install
'.[bench]'``); without it :func:`available` is None and the benchmark says so.  ``drafting bench`` loads
this file from the checkout (:func:`drafting.app.bench.benchmark`).
"""

from __future__ import annotations

import io
from typing import Sequence

from drafting.render.paper import Circle, Line, Polygon, Polyline, Rectangle, Strokes, Text
from drafting.layout.sheet import Sheet
from drafting.render.style import FONT_FAMILY, measure, style

PT_PER_MM = 72.0 / 25.4
_CAPS = {"butt": "butt", "round": "round", "square": "projecting"}
_JOINS = {"miter": "miter", "round": "round", "bevel": "bevel"}


def available() -> str | None:
    """matplotlib's version, or None when it is not installed."""
    try:
        import matplotlib
    except ImportError:
        return None
    return matplotlib.__version__


def figure_for(sheet: Sheet):
    """A matplotlib figure holding every command of ``sheet`` as an artist."""
    from matplotlib.figure import Figure          # no pyplot, no backend switched: savefig picks by format
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D
    from matplotlib import patches

    fig = Figure(figsize=(sheet.width / 25.4, sheet.height / 25.4))
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    ax.set_xlim(0.0, sheet.width)
    ax.set_ylim(sheet.height, 0.0)
    ax.set_axis_off()

    def stroke_kw(name: str) -> dict:
        st = style(name)
        if st.stroke is None:
            return {"linewidth": 0.0, "edgecolor": "none"}
        kw = {"linewidth": st.width * PT_PER_MM, "capstyle": _CAPS[st.cap], "joinstyle": _JOINS[st.join]}
        if st.dash:
            kw["linestyle"] = (0.0, tuple(d * PT_PER_MM / (st.width * PT_PER_MM) for d in st.dash))
        return kw

    for c in sheet.commands:
        if isinstance(c, Text):
            x = c.x
            for s in c.spans:
                ax.text(x, c.y + s.shift, s.text, fontsize=s.size * PT_PER_MM, family=FONT_FAMILY,
                        style="italic" if s.italic else "normal", va="baseline", ha="left")
                x += measure((s,)).width
            continue
        st = style(c.style)
        kw = stroke_kw(c.style)
        if isinstance(c, (Line, Polyline)):
            pts = c.points
            line = Line2D([p[0] for p in pts], [p[1] for p in pts], color=st.stroke or "none",
                          linewidth=kw["linewidth"], solid_capstyle=kw.get("capstyle", "butt"),
                          dash_capstyle=kw.get("capstyle", "butt"), solid_joinstyle=kw.get("joinstyle", "miter"),
                          linestyle=kw.get("linestyle", "-"))
            ax.add_line(line)
            continue
        if isinstance(c, Strokes):
            ax.add_collection(LineCollection([list(seg) for seg in c.segments], colors=st.stroke or "none",
                                             linewidths=kw["linewidth"], capstyle=kw.get("capstyle", "butt"),
                                             linestyles=kw.get("linestyle", "-")))
            continue
        pkw = {"facecolor": st.fill or "none", "edgecolor": st.stroke or "none", "linewidth": kw["linewidth"]}
        if "linestyle" in kw:
            pkw["linestyle"] = kw["linestyle"]
        if isinstance(c, Polygon):
            ax.add_patch(patches.Polygon(c.points, closed=True, **pkw))
        elif isinstance(c, Rectangle):
            ax.add_patch(patches.Rectangle((c.x, c.y), c.w, c.h, **pkw))
        elif isinstance(c, Circle):
            ax.add_patch(patches.Circle((c.cx, c.cy), c.r, **pkw))
        else:                                                      # pragma: no cover - Command is closed
            raise TypeError(f"not a drawing command: {c!r}")
    return fig


def save(sheet: Sheet, fmt: str, dpi: float = 150.0) -> bytes:
    """The sheet drawn by matplotlib and saved as ``fmt`` (svg, pdf or png)."""
    out = io.BytesIO()
    figure_for(sheet).savefig(out, format=fmt, dpi=dpi)
    return out.getvalue()


def artists(sheets: Sequence[Sheet]) -> int:
    """How many artists the figures hold (lines, collections, patches and texts): what the peer draws."""
    n = 0
    for sh in sheets:
        ax = figure_for(sh).axes[0]
        n += len(ax.lines) + len(ax.collections) + len(ax.patches) + len(ax.texts)
    return n


def command_count(sheets: Sequence[Sheet]) -> int:
    """What the engine draws, counted the way :func:`artists` counts (a span of lettering each)."""
    return sum(len(c.spans) if isinstance(c, Text) else 1 for sh in sheets for c in sh.commands)

