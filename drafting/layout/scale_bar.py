"""Scale bars: alternate black and white segments standing for a 1-2-5 value, numbers above, the unit after.

:func:`choose_bar` picks the longest 1-2-5 bar that fits, :func:`scale_bar` draws it.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

from ..render.paper import Command, Line, Rect, Rectangle, Text
from ..render.scales import nice_values, number_text
from ..render.style import MIN_TEXT, Extent, measure, plain
from .wrap import text_at


SCALE_BAR_HEIGHT = 1.6
SCALE_TICK = 1.0
SCALE_TEXT = MIN_TEXT


@dataclass(frozen=True)
class _BarPlan:
    """Where a scale bar's parts go (see :func:`scale_bar`), found without making a command."""

    divisions: int
    seg: float
    y_num: float
    y_tick0: float
    y_bar: float
    labels: tuple[str, ...]
    shown: tuple[int, ...]
    unit_x: float
    box: Rect


@functools.lru_cache(maxsize=1024)
def _bar_numbers(value: float) -> tuple[int, tuple[str, ...], tuple[Extent, ...]]:
    """A bar standing for ``value``: its divisions, and the number at every division with its extent."""
    divisions = _divisions(value)
    labels = tuple(number_text(value * i / divisions) for i in range(divisions + 1))
    return divisions, labels, tuple(measure(plain(t, SCALE_TEXT)) for t in labels)


def _bar_rows(top: float, unit: str) -> tuple[float, float, float, float]:
    """A scale bar's rows under ``top``: the numbers' baseline, the ticks' top, the bar's top, and the
    bottom of the bar and its unit (the same whatever the bar's length and value)."""
    num_ext = measure(plain("0", SCALE_TEXT))
    y_num = top - num_ext.top
    y_tick0 = y_num + num_ext.bottom + 0.4
    y_bar = y_tick0 + SCALE_TICK
    return y_num, y_tick0, y_bar, max(y_bar + SCALE_BAR_HEIGHT,
                                      measure(plain(unit, SCALE_TEXT)).box(0.0, y_bar + SCALE_BAR_HEIGHT).bottom)


def bar_bottom(top: float, unit: str) -> float:
    """The bottom of the box :func:`_bar_plan` gives a bar under ``top`` (as that Rect computes it)."""
    return Rect.from_edges(0.0, top, 1.0, _bar_rows(top, unit)[3]).bottom


def _bar_plan(x: float, top: float, length: float, value: float, unit: str) -> _BarPlan:
    divisions, labels, exts = _bar_numbers(value)
    seg = length / divisions
    ts = SCALE_TEXT
    y_num, y_tick0, y_bar, bottom = _bar_rows(top, unit)
    widths = [e.width for e in exts]
    every = 1
    while every < divisions and any(
            (widths[i] + widths[min(i + every, divisions)]) / 2 + 1.0 > seg * every
            for i in range(0, divisions, every)):
        every += 1
        while divisions % every:
            every += 1
    shown = sorted(set(range(0, divisions + 1, every)) | {0, divisions})
    if len(shown) > 2 and shown[-2] + every > divisions:
        # the last regular number may crowd the end number
        gap = (widths[shown[-2]] + widths[-1]) / 2 + 1.0
        if (divisions - shown[-2]) * seg < gap:
            shown.pop(-2)
    unit_x = x + length + 1.2
    unit_box = measure(plain(unit, ts)).box(unit_x, y_bar + SCALE_BAR_HEIGHT)
    # the boxes text_at gives the first and the last number
    first = exts[shown[0]].box(x + shown[0] * seg - widths[shown[0]] / 2, y_num)
    last = exts[shown[-1]].box(x + shown[-1] * seg - widths[shown[-1]] / 2, y_num)
    box = Rect.from_edges(min(x, first.left), top, max(unit_box.right, last.right), bottom)
    return _BarPlan(divisions, seg, y_num, y_tick0, y_bar, labels, tuple(shown), unit_x, box)


def scale_bar(x: float, top: float, length: float, value: float, unit: str, *, region: str = "",
              name: str = "scale bar") -> tuple[list[Command], Rect]:
    """A scale bar ``length`` mm long standing for ``value`` ``unit``, numbers above, top at ``top``.

    Alternate black and white segments (reads in black and white), a tick and number at every
    division where the numbers fit, the unit after the bar.  Returns the commands and the bounding box.
    """
    bp = _bar_plan(x, top, length, value, unit)
    seg, ts = bp.seg, SCALE_TEXT
    cmds: list[Command] = []
    for i in range(bp.divisions):
        cmds.append(Rectangle(x + i * seg, bp.y_bar, seg, SCALE_BAR_HEIGHT,
                              "bar_dark" if i % 2 == 0 else "bar_light", f"{name} segment {i}"))
    cmds.append(Rectangle(x, bp.y_bar, length, SCALE_BAR_HEIGHT, "tick", f"{name} outline"))
    texts: list[Text] = []
    for i in range(bp.divisions + 1):
        xi = x + i * seg
        cmds.append(Line(xi, bp.y_tick0, xi, bp.y_bar, "tick", f"{name} tick {i}"))
        if i in bp.shown:
            texts.append(text_at(xi, bp.y_num, plain(bp.labels[i], ts), anchor="middle", region=region,
                                 name=f"{name} number {i}"))
    texts.append(text_at(bp.unit_x, bp.y_bar + SCALE_BAR_HEIGHT, plain(unit, ts), region=region,
                         name=f"{name} unit"))
    cmds.extend(texts)
    return cmds, bp.box


def _divisions(value: float) -> int:
    lead = round(value / 10 ** math.floor(math.log10(value) + 1e-12), 6)
    return {1.0: 5, 2.0: 4, 5.0: 5}.get(lead, 4)


def choose_bar(paper_per_unit: float, max_len: float, *, min_len: float = 20.0,
               pref_len: float = 80.0) -> tuple[float, float] | None:
    """(value, paper length) of the longest 1-2-5 bar no longer than min(max_len, pref_len)."""
    limit = min(max_len, pref_len)
    if limit <= 0:
        return None
    if not (paper_per_unit > 0 and math.isfinite(paper_per_unit)) or limit < min_len:
        return None
    vals = nice_values(min_len / paper_per_unit, limit / paper_per_unit)
    if not vals:
        return None
    v = vals[-1]
    return v, v * paper_per_unit
