"""The log-log chart of the accuracy-against-time benchmarks: error against cost, one line and marker per
method, black on white in the sheets' font (svgwrite; the PNG beside it through cairosvg).

:func:`axes` draws the ground, the decades' grid and the frame; :func:`lines` a series each; :func:`legend`
and :func:`titles` the rest; :func:`chart` all of them for a plain chart.  ``benchmarks/cam_profile.py``
composes the same pieces with its own marks (the 1 ms line, its default circled).
"""

from __future__ import annotations

import math
from pathlib import Path

W, H = 180.0, 140.0                     # mm
X0, X1, Y0, Y1 = 24.0, 172.0, 8.0, 104.0  # the plot area
FONT = "DejaVu Sans"
MARKS = ("circle", "square", "triangle", "diamond", "down", "cross")
DASHES = (None, "4,1.2", "1.2,1", "6,1.2,1.2,1.2", "2.4,1.2", "0.6,0.9")


def ranges(xs, ys) -> tuple[tuple[int, int], tuple[int, int]]:
    """The whole decades that hold every x and every y."""
    return ((math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))),
            (math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))))


def pos(x, y, xr, yr):
    """Paper coordinates (mm) of the value (x, y)."""
    px = X0 + (math.log10(x) - xr[0]) / (xr[1] - xr[0]) * (X1 - X0)
    py = Y1 - (math.log10(y) - yr[0]) / (yr[1] - yr[0]) * (Y1 - Y0)
    return px, py


def mark(dwg, g, kind, x, y, r=1.3):
    st = dict(fill="white", stroke="black", stroke_width=0.3)
    if kind == "circle":
        g.add(dwg.circle((x, y), r, **st))
    elif kind == "square":
        g.add(dwg.rect((x - r, y - r), (2 * r, 2 * r), **st))
    elif kind == "triangle":
        g.add(dwg.polygon([(x, y - 1.25 * r), (x - 1.15 * r, y + 0.8 * r), (x + 1.15 * r, y + 0.8 * r)], **st))
    elif kind == "down":
        g.add(dwg.polygon([(x, y + 1.25 * r), (x - 1.15 * r, y - 0.8 * r), (x + 1.15 * r, y - 0.8 * r)], **st))
    elif kind == "cross":
        for d in (1, -1):
            g.add(dwg.line((x - r, y - d * r), (x + r, y + d * r), stroke="black", stroke_width=0.35))
    else:
        g.add(dwg.polygon([(x, y - 1.35 * r), (x + r, y), (x, y + 1.35 * r), (x - r, y)], **st))


SUPERSCRIPT = str.maketrans("-0123456789", "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079")


def _power(dwg, x, y, k, anchor):
    """10^k with the exponent in superscript digits (one text run: no shifted tspan to drift)."""
    return dwg.text("10" + str(k).translate(SUPERSCRIPT), insert=(x, y), font_size=3.0, font_family=FONT,
                    text_anchor=anchor)


def label(dwg, g, text, x, y, anchor="start", size=3.0):
    """A label on a white ground (it crosses grid lines)."""
    w = 0.56 * size * len(text)
    left = x - (w if anchor == "end" else w / 2 if anchor == "middle" else 0.0)
    g.add(dwg.rect((left - 0.6, y - size * 0.85), (w + 1.2, size * 1.15), fill="white"))
    g.add(dwg.text(text, insert=(x, y), font_size=size, font_family=FONT, text_anchor=anchor))


def axes(path: Path, xr, yr):
    """(drawing, group): the white ground, the decades' grid lines and numbers, the frame."""
    import svgwrite
    dwg = svgwrite.Drawing(str(path), size=(f"{W}mm", f"{H}mm"), viewBox=f"0 0 {W} {H}", profile="full")
    dwg.add(dwg.rect((0, 0), (W, H), fill="white"))
    g = dwg.g()
    dwg.add(g)
    for k in range(xr[0], xr[1] + 1):                       # decades: grid lines and numbers
        for m in range(1, 10):
            v = math.log10(m) + k
            if v > xr[1]:
                break
            x = pos(10 ** v, 10 ** yr[0], xr, yr)[0]
            g.add(dwg.line((x, Y0), (x, Y1), stroke="#bbbbbb" if m == 1 else "#e4e4e4", stroke_width=0.2))
        x = pos(10 ** k, 10 ** yr[0], xr, yr)[0]
        g.add(_power(dwg, x, Y1 + 5.0, k, "middle"))
    for k in range(yr[0], yr[1] + 1):
        y = pos(10 ** xr[0], 10 ** k, xr, yr)[1]
        g.add(dwg.line((X0, y), (X1, y), stroke="#bbbbbb", stroke_width=0.2))
        g.add(_power(dwg, X0 - 1.5, y + 1.0, k, "end"))
    g.add(dwg.rect((X0, Y0), (X1 - X0, Y1 - Y0), fill="none", stroke="black", stroke_width=0.35))
    return dwg, g


def lines(dwg, g, series, xr, yr) -> None:
    """Each series (name, [(x, y), ...]) as a polyline with its marker at every point."""
    for i, (_, points) in enumerate(series):
        pts = sorted([pos(x, y, xr, yr) for x, y in points], key=lambda q: -q[1])
        line = dwg.polyline(pts, fill="none", stroke="black", stroke_width=0.35)
        if DASHES[i]:
            line["stroke-dasharray"] = DASHES[i]
        g.add(line)
        for x, y in pts:
            mark(dwg, g, MARKS[i], x, y)


def legend(dwg, g, names) -> None:
    """Under the chart, two columns."""
    rows = (len(names) + 1) // 2
    for i, name in enumerate(names):
        lx, y = X0 + (i % 2) * 76.0, H - 3.0 - 5.0 * rows + 5.0 * (i // 2)
        line = dwg.line((lx, y - 1.0), (lx + 14.0, y - 1.0), stroke="black", stroke_width=0.35)
        if DASHES[i]:
            line["stroke-dasharray"] = DASHES[i]
        g.add(line)
        mark(dwg, g, MARKS[i], lx + 7.0, y - 1.0, 1.1)
        g.add(dwg.text(name, insert=(lx + 16.0, y), font_size=3.0, font_family=FONT))


def titles(dwg, g, x_title: str, y_title: str) -> None:
    """The axes' titles, the y one turned."""
    g.add(dwg.text(x_title, insert=((X0 + X1) / 2, Y1 + 12.0), font_size=3.5, font_family=FONT,
                   text_anchor="middle"))
    yl = dwg.text(y_title, insert=(6.0, (Y0 + Y1) / 2), font_size=3.5, font_family=FONT, text_anchor="middle")
    yl.rotate(-90, center=(6.0, (Y0 + Y1) / 2))
    g.add(yl)


def chart(series, path: Path, x_title: str, y_title: str) -> None:
    """A plain chart of ``series`` (name, [(x, y), ...]) at ``path`` (SVG) and a PNG beside it."""
    xr, yr = ranges([x for _, p in series for x, _ in p], [y for _, p in series for _, y in p])
    dwg, g = axes(path, xr, yr)
    lines(dwg, g, series, xr, yr)
    legend(dwg, g, [name for name, _ in series])
    titles(dwg, g, x_title, y_title)
    dwg.save()             # not pretty: whitespace between a number and its exponent would show
    png(path)


def png(path: Path) -> None:
    import cairosvg
    cairosvg.svg2png(url=str(path), write_to=str(path.with_suffix(".png")), dpi=150)
