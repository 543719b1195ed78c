"""The sweep card's drawing as it is being built: every point's position at every slider angle (read from
the study's sweep analysis), the ISO 5455 scale of the mechanism's panel, and the paper commands -- the
static ones and the moving ones, each moving one with the element id and class the page's script moves it
by.  :mod:`.sweep_mechanism` and :mod:`.sweep_charts` draw into it; :mod:`.html_sweep` writes it out.
"""

from __future__ import annotations

import math

import numpy as np

from ..layout.formats import symbol_of
from ..render.scales import ISO_5455, ratio_factor, ratio_text
from ..layout.header import viewport_header
from ..render.errors import LayoutError
from ..render.paper import Command, Line, Rect, Rectangle

WIDTH, HEIGHT = 310.0, 150.0          # the card's drawing, mm
MECH_W = 120.0                        # the mechanism panel; the charts share the rest, two by two
MARGIN = 9.0                          # room around the swept mechanism for blocks, ground symbols, labels


class SweepCanvas:
    """The states, the scale and the drawing of one study's card.

    ``analysis`` is the study's sweep analysis (:class:`drafting.families.linkage.family.SweepAnalysis`):
    the solved turn, its record of charts, the order the charts draw its samples in and the crank's points
    at the gaps.  Its last sample closes the turn when the chart order leaves it out: the slider then runs
    over the others (``count``)."""

    def __init__(self, study, analysis) -> None:
        self.study, self.s, self.rec = study, analysis.result, analysis.record
        self.chart_order = analysis.chart_order
        self.m = study.scene.mechanism
        self.u = study.scene.units
        self.per_m = self.u.convert("length", 1.0)
        th = np.asarray(self.s.thetas, dtype=float)
        self.count = len(set(self.chart_order))                     # the closing angle is the first again
        self.th, self.closed = th, self.count < th.size
        self.ok = np.asarray(self.s.assembles, dtype=bool)[:self.count]
        self.first = next((i for i in range(self.count) if self.ok[i]), 0)
        self.static: list[Command] = []
        self.moving: list[Command] = []
        self.ids: dict[str, tuple[str, str]] = {}
        self._states(analysis.crank_at_gaps)
        self._scale()

    # -- the states -------------------------------------------------------------------------------------
    def _states(self, crank_at_gaps) -> None:
        """Every point's position at every slider angle, scene length units (None where it does not
        stand); at a gap the crank's points, turned to the crank angle."""
        count, per_m = self.count, self.per_m
        self.pos: dict[str, list] = {}
        for name, (x, y) in self.s.positions.items():
            x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
            self.pos[name] = [[float(x[i]) * per_m, float(y[i]) * per_m]
                              if math.isfinite(x[i]) and math.isfinite(y[i]) else None for i in range(count)]
        self.crank_names: list[str] = []
        for i in np.flatnonzero(~self.ok):
            cp = crank_at_gaps.get(int(i))
            if cp is None:
                break
            for name, p in cp.items():
                if name in self.pos and name not in self.m.ground:
                    self.pos[name][i] = [p.x * per_m, p.y * per_m]
                    if name not in self.crank_names:
                        self.crank_names.append(name)

    def _scale(self) -> None:
        """The largest ISO 5455 scale at which every position of the turn fits the space panel."""
        pts = [p for v in self.pos.values() for p in v if p is not None]
        lo_x, hi_x = min(p[0] for p in pts), max(p[0] for p in pts)
        lo_y, hi_y = min(p[1] for p in pts), max(p[1] for p in pts)
        self.panel = mech = Rect(0.0, 0.0, MECH_W, HEIGHT)
        unit = symbol_of(self.u, "length")
        ratio, head = ISO_5455[-1], None
        for r in ISO_5455:                                           # largest first
            kr = 1000.0 * ratio_factor(r) / self.per_m               # paper mm per scene length unit
            try:
                hr = viewport_header(mech, f"Space diagram {ratio_text(r)}", kr, unit, region="sweep",
                                     name="sweep space")
            except LayoutError:
                continue
            if (hi_x - lo_x) * kr <= mech.w - 2 * MARGIN and (hi_y - lo_y) * kr <= mech.h - hr.height - 2 * MARGIN:
                ratio, head = r, hr
                break
        self.ratio = ratio
        self.k = k = 1000.0 * ratio_factor(ratio) / self.per_m
        if head is None:
            head = viewport_header(mech, "Space diagram", None, unit, region="sweep", name="sweep space")
        top = mech.y + head.height
        self.ox = mech.x + mech.w / 2 - k * (lo_x + hi_x) / 2
        self.oy = top + (mech.bottom - top) / 2 + k * (lo_y + hi_y) / 2
        self.static += [Rectangle(0.0, 0.0, WIDTH, HEIGHT, "frame", "sweep frame"),
                        Line(MECH_W, 0.0, MECH_W, HEIGHT, "separator", "sweep separator"), *head.commands]

    def paper(self, p) -> tuple[float, float]:
        """Paper mm of a position in scene length units."""
        return self.ox + self.k * p[0], self.oy - self.k * p[1]

    def at(self, name: str, i: int | None = None) -> tuple[float, float]:
        p = self.pos[name][self.first if i is None else i]
        return self.paper(p) if p is not None else (self.ox, self.oy)

    def tag(self, cmd: Command, ident: str, cls: str = "sw-moving") -> None:
        self.ids[cmd.name] = (ident, cls)
        self.moving.append(cmd)
