"""Charts: series against a common x quantity (s-v-a-j of a cam, values over a crank sweep).

A chart is not drawn to a model scale: it fills a chart panel of its own.  Axes carry ticks and numbers
at 1-2-5 steps in the sheet's units, every series is one polyline (broken at NaN), bands are shaded y
ranges with their label, and a legend above the axes tells the series apart by line pattern (solid,
dashed, long-dash-dot, thin), so the chart reads in black and white.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Sequence

from constructions.entities import Chart

from ..render.drawing import panel_drawer
from ..render.errors import LayoutError
from ..render.paper import Command, Line, Polyline, Rect, Rectangle, Text
from ..render.scales import nice_step, number_text
from ..render.style import MIN_TEXT, measure, plain, rich

SERIES_STYLES = ("series 1", "series 2", "series 3", "series 4")
TICK = 1.5
NUM = MIN_TEXT + 0.5          # 3.0 mm numbers
LEGEND_SAMPLE = 12.0
CHART_MIN = (90.0, 60.0)      # the smallest chart panel that stays readable (w, h in mm)


@dataclass(frozen=True)
class AxisUnits:
    """How the chart writes SI values: ``convert(kind, si)`` -> number, ``symbol(kind)`` -> unit."""

    convert: Callable[[str, float], float]
    symbol: Callable[[str], str]


def _si(kind: str, v: float) -> float:
    return v


def _si_symbol(kind: str) -> str:
    return {"length": "m", "velocity": "m/s", "acceleration": "m/s\u00b2", "angle": "rad", "force": "N",
            "angular velocity": "rad/s", "angular acceleration": "rad/s\u00b2", "time": "s"}.get(kind, "")


SI_AXES = AxisUnits(_si, _si_symbol)


DEGREE_STEPS = (1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 90.0, 180.0, 360.0)
"""Tick steps of an axis in degrees: the divisions of a turn a drafter uses, not 1-2-5 (0, 90, 180 ...)."""


def _step_at_least(x: float, steps: Sequence[float] | None) -> float:
    if steps is None or not x <= steps[-1]:
        return nice_step(x)
    return next(v for v in steps if v >= x * (1 - 1e-12))


def ticks(lo: float, hi: float, length_mm: float, spacing_mm: float,
          steps: Sequence[float] | None = None) -> tuple[float, float, float]:
    """(first, last, step): the axis range widened to multiples of a 1-2-5 step (or of one of ``steps``,
    e.g. DEGREE_STEPS) with ticks at least ``spacing_mm`` apart on an axis ``length_mm`` long."""
    if not (math.isfinite(lo) and math.isfinite(hi)):
        lo, hi = 0.0, 1.0
    if hi - lo <= 1e-12 * max(abs(lo), abs(hi), 1.0):
        pad = abs(lo) * 0.1 or 1.0
        lo, hi = lo - pad, hi + pad
    n = max(1, int(length_mm // spacing_mm))
    step = _step_at_least((hi - lo) / n, steps)
    while True:
        first = math.floor(lo / step + 1e-9) * step
        last = math.ceil(hi / step - 1e-9) * step
        if (last - first) / step <= n:
            return first, last, step
        step = _step_at_least(step * 1.01, steps)


def _runs(xs: Sequence[float], ys: Sequence[float]) -> list[list[tuple[float, float]]]:
    """The finite stretches of a series: NaN (or inf) marks a gap."""
    runs: list[list[tuple[float, float]]] = [[]]
    for x, y in zip(xs, ys):
        if math.isfinite(x) and math.isfinite(y):
            runs[-1].append((x, y))
        elif runs[-1]:
            runs.append([])
    return [r for r in runs if len(r) >= 2]


@panel_drawer(Chart)
@dataclass(frozen=True)
class ChartAxes:
    """Where a drawn chart puts its values: paper x of a display x value, paper y of a display y value,
    and the plot's top and bottom on paper (a cursor spans them)."""

    x: Callable[[float], float]
    y: Callable[[float], float]
    top: float
    bottom: float


def draw_chart(e: Chart, rect: Rect, units: AxisUnits = SI_AXES, region: str = "") -> list[Command]:
    """The chart ``e`` filling ``rect`` (paper mm)."""
    return chart_with_axes(e, rect, units, region)[0]


def chart_with_axes(e: Chart, rect: Rect, units: AxisUnits = SI_AXES,
                    region: str = "") -> tuple[list[Command], ChartAxes]:
    """:func:`draw_chart`, and the chart's :class:`ChartAxes` (what a cursor over it needs)."""
    out: list[Command] = []
    name = e.name
    cx = lambda v: units.convert(e.x_kind, v)                              # noqa: E731
    y_kind = e.series[0].y_kind if e.series else "number"
    cy = lambda v: units.convert(y_kind, v)                                # noqa: E731
    # legend rows at the top
    y_top = rect.y
    row_h = measure(plain("Xg", NUM)).height + 1.0
    legend_rows = 0
    cur = rect.right + 1                     # force a new row for the first entry
    for i, s in enumerate(e.series):
        label = s.label + ("" if s.y_kind == y_kind else f" ({units.symbol(s.y_kind)})")
        spans = rich(label, NUM)
        w = LEGEND_SAMPLE + 1.5 + measure(spans).width + 4.0
        if cur + w > rect.right:
            legend_rows += 1
            cur = rect.x
        yy = y_top + (legend_rows - 1) * row_h + row_h / 2
        st = SERIES_STYLES[i % len(SERIES_STYLES)]
        out.append(Line(cur, yy, cur + LEGEND_SAMPLE, yy, st, f"{name}:legend {i + 1} sample"))
        ext = measure(spans)
        ty = yy - (ext.top + ext.bottom) / 2
        out.append(Text(cur + LEGEND_SAMPLE + 1.5, ty, spans, "text", ext.box(cur + LEGEND_SAMPLE + 1.5, ty),
                        region, f"{name}:legend {i + 1}"))
        cur += w
    top = y_top + legend_rows * row_h + 1.0
    # data ranges in display units
    xs = [cx(v) for s in e.series for v in s.x if math.isfinite(v)]
    ys = [units.convert(s.y_kind, v) for s in e.series for v in s.y if math.isfinite(v)]
    for lo, hi, _ in e.bands:
        ys += [cy(v) for v in (lo, hi) if math.isfinite(v)]
    x_lo, x_hi = (min(xs), max(xs)) if xs else (0.0, 1.0)
    y_lo, y_hi = (min(ys), max(ys)) if ys else (0.0, 1.0)
    unit_y = units.symbol(y_kind)
    num_h = measure(plain("0", NUM)).height
    # y axis: unit over the numbers; x axis: numbers and title under it
    title_y = rich(unit_y, NUM) if unit_y else ()
    x_unit = units.symbol(e.x_kind)
    x_title = rich(f"{e.x_label} ({x_unit})" if x_unit else e.x_label, NUM)
    plot_top = top + (num_h + 1.5 if title_y else 0.0) + num_h / 2
    plot_bottom = rect.bottom - (TICK + 1.0 + num_h + 1.5 + num_h + 0.5)
    y0, y1, ys_step = ticks(y_lo, y_hi, max(plot_bottom - plot_top, 1.0), 8.0,
                            DEGREE_STEPS if unit_y == "\u00b0" else None)
    y_labels = []
    v = y0
    while v <= y1 + ys_step * 1e-6:
        y_labels.append((v, number_text(_clean(v, ys_step))))
        v += ys_step
    left_w = max(measure(plain(t, NUM)).width for _, t in y_labels) + TICK + 1.0
    plot_left = rect.x + left_w
    plot_right = rect.right - 2.0
    x0, x1, xs_step = ticks(x_lo, x_hi, max(plot_right - plot_left, 1.0), 14.0,
                            DEGREE_STEPS if x_unit == "\u00b0" else None)
    if plot_right - plot_left < 20 or plot_bottom - plot_top < 15:
        raise LayoutError(f"the chart {name!r} needs at least {CHART_MIN[0]:.0f} x {CHART_MIN[1]:.0f} mm")

    def px(v: float) -> float:
        return plot_left + (v - x0) / (x1 - x0) * (plot_right - plot_left)

    def py(v: float) -> float:
        return plot_bottom - (v - y0) / (y1 - y0) * (plot_bottom - plot_top)

    # bands first (under everything), then grid, axes, series
    for i, (lo, hi, label) in enumerate(e.bands):
        a, b = sorted((cy(lo), cy(hi)))
        a, b = max(a, y0), min(b, y1)
        if b <= a:
            continue
        out.append(Rectangle(plot_left, py(b), plot_right - plot_left, py(a) - py(b), "band", f"{name}:band {i + 1}"))
        if label:
            spans = rich(label, MIN_TEXT)
            ext = measure(spans)
            if ext.height + 0.4 <= py(a) - py(b) and ext.width + 2 <= plot_right - plot_left:
                tx, ty = plot_right - 1.0 - ext.width, py(b) + 0.4 - ext.top
                out.append(Text(tx, ty, spans, "text", ext.box(tx, ty), region, f"{name}:band {i + 1} label"))
    for v, t in y_labels:
        yy = py(v)
        if v not in (y0,):
            out.append(Line(plot_left, yy, plot_right, yy, "grid", f"{name}:grid y"))
        out.append(Line(plot_left - TICK, yy, plot_left, yy, "axis", f"{name}:tick y"))
        ext = measure(plain(t, NUM))
        tx, ty = plot_left - TICK - 0.8 - ext.width, yy - (ext.top + ext.bottom) / 2
        out.append(Text(tx, ty, plain(t, NUM), "text", ext.box(tx, ty), region, f"{name}:number y"))
    v = x0
    last_right = -math.inf
    while v <= x1 + xs_step * 1e-6:
        xx = px(v)
        if v != x0:
            out.append(Line(xx, plot_top, xx, plot_bottom, "grid", f"{name}:grid x"))
        out.append(Line(xx, plot_bottom, xx, plot_bottom + TICK, "axis", f"{name}:tick x"))
        t = number_text(_clean(v, xs_step))
        ext = measure(plain(t, NUM))
        tx, ty = xx - ext.width / 2, plot_bottom + TICK + 0.8 - ext.top
        tx = min(tx, rect.right - ext.width)
        if tx > last_right + 1.0:
            out.append(Text(tx, ty, plain(t, NUM), "text", ext.box(tx, ty), region, f"{name}:number x"))
            last_right = tx + ext.width
        v += xs_step
    if y0 < 0 < y1:
        out.append(Line(plot_left, py(0.0), plot_right, py(0.0), "axis", f"{name}:zero"))
    out.append(Line(plot_left, plot_top, plot_left, plot_bottom, "axis", f"{name}:axis y"))
    out.append(Line(plot_left, plot_bottom, plot_right, plot_bottom, "axis", f"{name}:axis x"))
    if title_y:
        ext = measure(title_y)
        tx, ty = rect.x, top - ext.top
        out.append(Text(tx, ty, title_y, "text", ext.box(tx, ty), region, f"{name}:unit y"))
    ext = measure(x_title)
    tx, ty = plot_right - ext.width, rect.bottom - 0.5 - ext.bottom
    out.append(Text(tx, ty, x_title, "text", ext.box(tx, ty), region, f"{name}:title x"))
    for i, s in enumerate(e.series):
        st = SERIES_STYLES[i % len(SERIES_STYLES)]
        conv = (lambda k: (lambda v: units.convert(k, v)))(s.y_kind)
        for j, run in enumerate(_runs(s.x, s.y)):
            pts = tuple((round(px(cx(a)), 4), round(py(conv(b)), 4)) for a, b in run)
            out.append(Polyline(pts, st, f"{name}:series {i + 1} run {j + 1}"))
    return out, ChartAxes(px, py, plot_top, plot_bottom)


def _clean(v: float, step: float) -> float:
    """A tick value without float noise (0.30000000000000004 -> 0.3)."""
    digits = max(0, -int(math.floor(math.log10(step))) + 1) if step > 0 else 6
    return round(v, digits)
