"""The slider over the crank angle on the step-through page of a swept scene (``analyses = ["sweep"]``).

One more card on the page, above the sheets: the mechanism drawn at an ISO 5455 scale in a panel of its
own, the cycle charts of the sweep beside it (output motion, angular velocities and accelerations, the
transmission angle with its 40-140 deg band), each with a cursor, and a readout of the charts' values at
the slider's angle in the scene's units.  A range slider (the arrow keys when it has focus, Home/End), a
play/pause button and a jump list of the positions the sweep names (limit positions, change points, the
transmission angle's extremes, where gaps begin) move the crank.

Every state is read here, in Python, from the study's own sweep analysis (one turn in steps of 1 deg,
:data:`drafting.families.linkage.family.SWEEP_STEPS`): the positions of every point in the scene's length unit,
the slider blocks' directions, the chart cursor and dot positions on paper, the readout text.  They
travel as JSON; the page's script only moves elements.  At a gap (the linkage cannot be assembled) only
the crank is drawn -- its points at the gaps are the analysis' own -- greyed, with a note; nothing is
borrowed from a neighbouring angle.  The card is built in :mod:`.sweep_canvas` (states and scale),
:mod:`.sweep_mechanism` and :mod:`.sweep_charts`; its style sheet and script are ``html/sweep.css`` and
``html/sweep.js``.

``#angle=150`` opens at crank angle 150 (scene's angle unit).  ``#selftest-sweep`` (after the page has
loaded) checks that an arrow key on the slider leaves the construction's steps alone, that play and pause
start and stop the crank, that at the first gap only the crank stands with the note, then moves the
slider a quarter turn through its input event and checks that every moved pin stands where the JSON
puts it, the first chart's cursor has moved and the readout changed; it writes the outcome and the
pins' SVG coordinates into the page title for a headless browser to read.
"""

from __future__ import annotations

import html
import math
from dataclasses import dataclass

import numpy as np

from ..render.scales import ratio_text
from ..layout.sheet import Sheet
from ..render.paper import Command, Paper
from .html_markup import asset, script_json
from .svg import sheet_to_svg
from .sweep_canvas import HEIGHT, WIDTH, SweepCanvas
from .sweep_charts import charts, named
from .sweep_mechanism import bodies, guides, traces


@dataclass(frozen=True)
class SweepSection:
    """The card: its HTML (controls, SVG, readout, JSON, script), the JSON it carries and the drawing
    commands of its SVG (for tests)."""

    html: str
    data: dict
    commands: tuple[Command, ...]


def _sub_digits(n: int) -> str:
    return str(n).translate(str.maketrans("0123456789", "\u2080\u2081\u2082\u2083\u2084\u2085\u2086\u2087\u2088\u2089"))


def _build(card: SweepCanvas) -> SweepSection:
    """The card's drawing, its JSON and its markup."""
    guides(card)
    paths = traces(card)
    parts = bodies(card)
    cursors, heads, cols = charts(card)
    status, merged = named(card)
    u, count = card.u, card.count
    data = {"count": count, "k": card.k, "ox": card.ox, "oy": card.oy, "scale": ratio_text(card.ratio),
            "turn": u.convert("angle", 2 * math.pi),
            "value": [u.convert("angle", float(card.th[i]) % (2 * math.pi)) for i in range(count)],
            "angle": [f"\u03b8{_sub_digits(card.m.crank)} = {t}" for t in cols[0]],
            "ok": [bool(x) for x in card.ok], "status": status, "pts": card.pos, **parts, "traces": paths,
            "charts": cursors, "readout": [[col[i] for col in cols] for i in range(count)]}
    commands = tuple(card.static + card.moving)

    def attrs(cmd: Command) -> dict[str, str]:
        if cmd.name in card.ids:
            ident, cls = card.ids[cmd.name]
            return {"id": ident, "class": cls}
        return {}
    svg = sheet_to_svg(Sheet(Paper("sweep", "landscape", WIDTH, HEIGHT), commands), attrs, grouped=False)
    dot = " \u00b7 "
    marks = "".join(f'<option value="{i}"></option>' for i in merged)
    jumps = "".join(f'<button data-i="{i}">{html.escape(dot.join(t))}</button>' for i, t in merged.items())
    readout = "".join(f'<span>{h} = <span class="v" id="sweep-v{j}"></span></span>' for j, h in enumerate(heads))
    payload = script_json(data, allow_nan=False)
    body = (f'<div id="sweep"><h3>Over the cycle: turn the crank</h3>'
            f'<div id="sweep-controls"><button id="sweep-play">&#9654; play</button>'
            f'<input type="range" id="sweep-slider" min="0" max="{count - 1}" step="1" value="0" '
            f'list="sweep-marks" aria-label="crank angle"><span id="sweep-angle"></span></div>'
            f'<datalist id="sweep-marks">{marks}</datalist>'
            + (f'<div id="sweep-events">Named positions: {jumps}</div>' if merged else "")
            + f'<div id="sweep-status"></div>{svg}<div id="sweep-readout">{readout}</div>'
            f'<script type="application/json" id="sweep-data">{payload}</script>'
            f'<script>{asset("sweep.js")}</script></div>')
    return SweepSection(body, data, commands)


def sweep_section(study) -> SweepSection | None:
    """The slider card of a solved study whose scene asked for the sweep; None for any other study (its
    page stays as it was)."""
    sw = study.computed("sweep")
    if sw is None or np.asarray(sw.result.thetas).size == 0:
        return None
    return _build(SweepCanvas(study, sw))


__all__ = ["SweepSection", "sweep_section"]
