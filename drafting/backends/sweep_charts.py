"""The sweep card's charts and words: the cycle charts of the sweep two by two beside the mechanism, each
with a cursor and a dot on each series at the slider's angle; the readout of their values in the scene's
units; and the positions the sweep names (gaps, change points, a four-bar's limit positions and the
transmission angle's extremes) as a status line at every angle and a jump list.
"""

from __future__ import annotations

import math

from constructions.entities import Chart

from ..layout.chart import AxisUnits, chart_with_axes
from ..layout.formats import per_si, symbol_of
from ..layout.header import viewport_header
from ..render.paper import Circle, Line, Rect
from .html_markup import markup_html
from .sweep_canvas import HEIGHT, MECH_W, WIDTH

CURSOR_DOT = 1.0


def charts(card) -> tuple[list[dict], list[str], list[list[str]]]:
    """The sweep's charts two by two beside the mechanism, each with a cursor and a dot on each series;
    the readout's headings and its text at every angle (scene units)."""
    u, th, count = card.u, card.th, card.count
    axes = AxisUnits(lambda kind, v: v * per_si(u, kind), lambda kind: symbol_of(u, kind))
    charts = [e for e in card.rec.entities() if isinstance(e, Chart)][:4]
    cw, ch = (WIDTH - MECH_W) / 2, HEIGHT / 2
    cursors: list[dict] = []
    heads = [f"\u03b8<sub>{card.m.crank}</sub>"]
    cols = [[u.format("angle", float(th[i]) % (2 * math.pi)) for i in range(count)]]
    # a chart runs over one turn from 0 (the analysis' chart order): where each slider angle is in it
    where: dict[int, int] = {}
    for j, i in enumerate(card.chart_order):
        where.setdefault(i, j)
    for ci, chart in enumerate(charts):
        r = Rect(MECH_W + (ci % 2) * cw, (ci // 2) * ch, cw, ch)
        if ci % 2:
            card.static.append(Line(r.x, r.y, r.x, r.bottom, "separator", "sweep separator"))
        elif ci:
            card.static.append(Line(MECH_W, r.y, WIDTH, r.y, "separator", "sweep separator"))
        hd = viewport_header(r, chart.diagram.name, None, "", region="sweep", name=f"sweep {chart.name}")
        card.static += hd.commands
        cmds, at = chart_with_axes(chart, Rect(r.x + 2.0, r.y + hd.height, r.w - 4.0, r.h - hd.height - 1.5),
                                   axes, "sweep")
        card.static += cmds
        for ser in chart.series:
            col = []
            for i in range(count):
                v = float(ser.y[where[i]]) if where.get(i, len(ser.y)) < len(ser.y) else math.nan
                text = u.format(ser.y_kind, v) if math.isfinite(v) else "\u2014"
                for lo, hi, band in chart.bands:
                    if math.isfinite(v) and not min(lo, hi) <= v <= max(lo, hi):
                        text += f" (outside {band})"
                col.append(text)
            heads.append(markup_html(ser.label))
            cols.append(col)
        xs = [round(at.x(axes.convert(chart.x_kind, chart.series[0].x[where[i]])), 3) for i in range(count)]
        cid = f"sw-cursor-{ci}"
        card.tag(Line(xs[0], at.top, xs[0], at.bottom, "series 4", f"sweep cursor {ci}"), cid, "sw-cursor")
        dots = []
        for si, ser in enumerate(chart.series):
            did = f"sw-dot-{ci}-{si}"
            ys = [round(at.y(axes.convert(ser.y_kind, float(ser.y[where[i]]))), 3)
                  if math.isfinite(ser.y[where[i]]) else None for i in range(count)]
            card.tag(Circle(xs[0], ys[0] if ys[0] is not None else at.bottom, CURSOR_DOT, "dot",
                            f"sweep dot {ci} {si}"), did, "sw-dot")
            dots.append({"id": did, "y": ys})
        cursors.append({"id": cid, "x": xs, "dots": dots})
    return cursors, heads, cols

# -- what the sweep names -----------------------------------------------------------------------------
def named(card) -> tuple[list[str], dict[int, list[str]]]:
    """The status line at every angle and the jump list: gaps, change points, and for a four-bar its
    limit positions and the transmission angle's extremes, each at its nearest slider angle."""
    u, th, count = card.u, card.th, card.count
    turn = 2 * math.pi
    step = float(th[1] - th[0]) if th.size > 1 else turn

    def angle(a: float) -> str:
        return u.format("angle", a % turn)

    def index_of(a: float) -> int:
        return int(round(((a - th[0]) % turn) / step)) % count if step > 0 else 0
    status = ["" for _ in range(count)]
    events: list[tuple[int, str]] = []
    for a, b in card.s.gaps():
        a, b = min(a, count), min(b, count)
        if a >= b:
            continue
        span = f"{angle(float(th[a]))} to {angle(float(th[b - 1]))}"
        for i in range(a, b):
            status[i] = (f"The linkage cannot be assembled at this crank angle (a gap, {span})"
                         + (": only the crank is drawn." if card.crank_names else "."))
        events.append((a, f"gap from {angle(float(th[a]))}"))
    named: list[tuple[float, str, str]] = []
    for a in card.s.change_points:
        named.append((a, f"change point at {angle(a)}", f"Change point at {angle(a)}: all the links lie in line "
                      f"and the two assemblies meet; the linkage keeps to its branch."))
    k = card.study.get("classification")
    if k is not None:
        c = k.joints[2]
        turns_back = k.grashof != "change point" and "rocker" not in k.turns_fully
        for lp, mark in zip(k.limit_positions, ("'", "''")):
            named.append((lp.crank_angle, f"{c}{mark} at {angle(lp.crank_angle)}",
                          f"Limit position {c}{mark} at {angle(lp.crank_angle)}: crank and coupler in line "
                          f"({'extended' if lp.extended else 'folded'})"
                          + ("; the rocker stops and turns back." if turns_back else ".")))
        for a, val, word in ((k.transmission_min_at, k.transmission_min, "least"),
                             (k.transmission_max_at, k.transmission_max, "greatest")):
            if a is not None and val is not None:
                named.append((a, f"\u03bc {word} at {angle(a)}",
                              f"Transmission angle at its {word}, {u.format('angle', val)}, at {angle(a)}: "
                              f"the crank lies along the frame."))
    for a, short, long in named:
        i = index_of(a)
        status[i] = (status[i] + " " if status[i] else "") + long
        events.append((i, short))
    merged: dict[int, list[str]] = {}
    for i, text in sorted(events):
        merged.setdefault(i, []).append(text)
    return status, merged
