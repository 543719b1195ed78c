"""The slider over the crank angle on the step-through page of a swept scene (``analyses = ["sweep"]``).

One more card on the page, above the sheets: the mechanism drawn at an ISO 5455 scale in a panel of its
own, the cycle charts of the sweep beside it (output motion, angular velocities and accelerations, the
transmission angle with its 40-140 deg band), each with a cursor, and a readout of the charts' values at
the slider's angle in the scene's units.  A range slider (the arrow keys when it has focus, Home/End), a
play/pause button and a jump list of the positions the sweep names (limit positions, change points, the
transmission angle's extremes, where gaps begin) move the crank.

Every state is computed here, in Python, from the study's own sweep (one turn in steps of 1 deg,
:data:`drafting.families.linkage.family.SWEEP_STEPS`): the positions of every point in the scene's length unit,
the slider blocks' directions, the chart cursor and dot positions on paper, the readout text.  They
travel as JSON; the page's script only moves elements.  At a gap (the linkage cannot be assembled) only
the crank is drawn, greyed, with a note; nothing is borrowed from a neighbouring angle.

``#angle=150`` opens at crank angle 150 (scene's angle unit).  ``#selftest-sweep`` (after the page has
loaded) checks that an arrow key on the slider leaves the construction's steps alone, that play and pause
start and stop the crank, that at the first gap only the crank stands with the note, then moves the
slider a quarter turn through its input event and checks that every moved pin stands where the JSON
puts it, the first chart's cursor has moved and the readout changed; it writes the outcome and the
pins' SVG coordinates into the page title for a headless browser to read.
"""

from __future__ import annotations

import html
import json
import math
from dataclasses import dataclass

import numpy as np

from constructions.mechanisms.cycle import one_turn
from constructions.geometry import Vec
from constructions.mechanisms.model import Mechanism
from constructions.sweep import crank_points
from constructions.entities import Chart
from constructions.record import Construction

from ..layout.chart import AxisUnits, chart_with_axes
from ..render.drawing import PIN_R, DOT_R
from ..render.errors import LayoutError
from ..render.drawers import BLOCK_H, BLOCK_L, ground_symbol, hatching
from ..layout.formats import per_si, symbol_of
from .html_page import markup_html
from ..layout.header import viewport_header
from ..layout.wrap import text_at
from ..render.paper import Circle, Command, Line, Paper, Polygon, Polyline, Rect, Rectangle
from ..render.scales import ISO_5455, ratio_factor, ratio_text
from ..layout.sheet import Sheet
from ..render.style import LABEL, measure, rich
from .svg import sheet_to_svg

WIDTH, HEIGHT = 310.0, 150.0          # the card's drawing, mm
MECH_W = 120.0                        # the mechanism panel; the charts share the rest, two by two
MARGIN = 9.0                          # room around the swept mechanism for blocks, ground symbols, labels
CURSOR_DOT = 1.0
LABEL_OFFSET = (1.6, -1.8)

STYLE = """
#sweep { background: white; box-shadow: 0 0 3px #999; margin-bottom: 8px; padding: 8px 12px; }
#sweep h3 { margin: 0 0 8px; }
#sweep-controls { display: flex; align-items: center; gap: 12px; }
#sweep-controls button { font-size: 16px; padding: 4px 14px; min-width: 7em; }
#sweep-slider { flex: 1; }
#sweep-angle { font-size: 16px; min-width: 7.5em; font-weight: bold; }
#sweep-events { margin: 6px 0 0; font-size: 13px; color: #444; }
#sweep-events button { font-size: 13px; margin: 2px 4px 2px 0; cursor: pointer; }
#sweep-status { min-height: 1.4em; margin: 6px 0; font-size: 15px; }
#sweep.gap #sweep-status { color: #c00; font-weight: bold; }
#sweep.event #sweep-status { color: #c00; }
#sweep svg { box-shadow: none; margin-bottom: 4px; }
#sweep-readout { display: flex; flex-wrap: wrap; gap: 4px 22px; font-size: 15px; }
#sweep-readout .v { font-family: "DejaVu Sans Mono", monospace; }
#sweep.gap .sw-moving { opacity: 0.35; }
#sweep .sw-cursor { stroke: #d00; }
#sweep .sw-dot { fill: #d00; stroke: none; }
#sweep .sw-trace { stroke: #d00; }
"""

SCRIPT = """
(function () {
const D = JSON.parse(document.getElementById('sweep-data').textContent);
const $ = id => document.getElementById(id);
const card = $('sweep'), slider = $('sweep-slider'), play = $('sweep-play');
const f = v => (Math.round(v * 1000) / 1000).toString();
function P(name, i) {
  const p = D.pts[name][i];
  return p ? [D.ox + D.k * p[0], D.oy - D.k * p[1]] : null;
}
let cur = 0, timer = null;
function show(i) {
  cur = ((i % D.count) + D.count) % D.count;
  if (+slider.value !== cur) slider.value = cur;
  for (const l of D.links) {
    const el = $(l.id), ps = l.pts.map(n => P(n, cur)), on = ps.every(p => p);
    el.style.visibility = on ? '' : 'hidden';
    if (!on) continue;
    if (el.tagName === 'line') {
      el.setAttribute('x1', f(ps[0][0])); el.setAttribute('y1', f(ps[0][1]));
      el.setAttribute('x2', f(ps[1][0])); el.setAttribute('y2', f(ps[1][1]));
    } else el.setAttribute('points', ps.map(p => f(p[0]) + ',' + f(p[1])).join(' '));
  }
  for (const b of D.blocks) {
    const el = $(b.id), c = P(b.at, cur), a = b.dir[cur];
    el.style.visibility = (c && a !== null) ? '' : 'hidden';
    if (!c || a === null) continue;
    const u = [Math.cos(a), -Math.sin(a)], n = [-u[1], u[0]], pts = [];
    for (const [su, sn] of [[1, 1], [-1, 1], [-1, -1], [1, -1]])
      pts.push(f(c[0] + su * u[0] * b.l / 2 + sn * n[0] * b.h / 2) + ',' + f(c[1] + su * u[1] * b.l / 2 + sn * n[1] * b.h / 2));
    el.setAttribute('points', pts.join(' '));
  }
  for (const q of D.pins) {
    const el = $(q.id), c = P(q.at, cur);
    el.style.visibility = c ? '' : 'hidden';
    if (c) { el.setAttribute('cx', f(c[0])); el.setAttribute('cy', f(c[1])); }
  }
  for (const q of D.labels) {
    const el = $(q.id), c = P(q.at, cur);
    el.style.visibility = c ? '' : 'hidden';
    if (c) { el.setAttribute('x', f(c[0] + q.off[cur][0])); el.setAttribute('y', f(c[1] + q.off[cur][1])); }
  }
  for (const t of D.traces) {
    const pts = [];
    for (let j = t.from; j < t.to && j <= cur; j++) { const c = P(t.at, j); pts.push(f(c[0]) + ',' + f(c[1])); }
    $(t.id).setAttribute('points', pts.length > 1 ? pts.join(' ') : '');
  }
  for (const c of D.charts) {
    const el = $(c.id), x = c.x[cur];
    el.setAttribute('x1', f(x)); el.setAttribute('x2', f(x));
    for (const d of c.dots) {
      const dot = $(d.id), y = d.y[cur];
      dot.style.visibility = y === null ? 'hidden' : '';
      if (y !== null) { dot.setAttribute('cx', f(x)); dot.setAttribute('cy', f(y)); }
    }
  }
  D.readout[cur].forEach((v, j) => { $('sweep-v' + j).textContent = v; });
  $('sweep-angle').textContent = D.angle[cur];
  card.classList.toggle('gap', !D.ok[cur]);
  card.classList.toggle('event', D.ok[cur] && D.status[cur] !== '');
  $('sweep-status').textContent = D.status[cur];
}
slider.addEventListener('input', () => show(+slider.value));
slider.addEventListener('keydown', e => e.stopPropagation());   // the arrow keys move the crank, not the steps
function pause() { clearInterval(timer); timer = null; play.textContent = '\\u25b6 play'; }
play.onclick = () => {
  if (timer) { pause(); return; }
  timer = setInterval(() => show(cur + 1), 40);
  play.textContent = '\\u275a\\u275a pause';
};
document.querySelectorAll('#sweep-events button').forEach(b => b.onclick = () => { pause(); show(+b.dataset.i); });
const hash = location.hash;
const m = hash.match(/angle=(-?[0-9.]+)/);
let start = 0;
if (m) {
  const want = parseFloat(m[1]);
  let best = Infinity;
  D.value.forEach((v, i) => {
    const d = Math.abs(((v - want) % D.turn + 1.5 * D.turn) % D.turn - D.turn / 2);
    if (d < best) { best = d; start = i; }
  });
}
show(start);
if (hash.includes('selftest-sweep')) window.addEventListener('load', () => {
  const problems = [];
  // an arrow key on the slider moves the crank, never the construction's steps
  const steps = document.getElementById('count'), before_steps = steps ? steps.textContent : '';
  slider.dispatchEvent(new KeyboardEvent('keydown', {key: 'ArrowRight', bubbles: true}));
  if (steps && steps.textContent !== before_steps) problems.push('keys');
  // at a gap only the crank stands, greyed, with the note
  const gap = D.ok.indexOf(false);
  let gaps = 'none';
  if (gap >= 0) {
    show(gap);
    const drawn = D.links.filter(l => $(l.id).style.visibility !== 'hidden').map(l => l.pts.join(''));
    gaps = card.classList.contains('gap') && $('sweep-status').textContent.includes('cannot be assembled')
      && D.links.every(l => ($(l.id).style.visibility === 'hidden') === l.pts.some(n => !D.pts[n][gap]))
      ? 'ok:' + drawn.join('+') : 'FAILED';
    if (gaps === 'FAILED') problems.push('gap');
    show(start);
  }
  // play turns the crank on, pause stops it
  play.click();
  const playing = timer !== null && play.textContent.includes('pause');
  play.click();
  if (!playing || timer !== null || !play.textContent.includes('play')) problems.push('play');
  show(start);
  const before = D.readout[cur].join('|'), shown0 = $('sweep-v0').textContent;
  const target = (cur + Math.round(D.count / 4)) % D.count;
  slider.value = target;
  slider.dispatchEvent(new Event('input'));
  const where = [];
  for (const q of D.pins) {
    const el = $(q.id), c = P(q.at, target);
    if (!c) continue;
    const x = +el.getAttribute('cx'), y = +el.getAttribute('cy');
    if (Math.abs(x - c[0]) > 1e-3 || Math.abs(y - c[1]) > 1e-3) problems.push(q.at);
    where.push(q.at + '=' + el.getAttribute('cx') + ',' + el.getAttribute('cy'));
  }
  const cx = D.charts.length ? +$(D.charts[0].id).getAttribute('x1') : null;
  if (D.charts.length && Math.abs(cx - D.charts[0].x[target]) > 1e-3) problems.push('cursor');
  if (D.readout[cur].join('|') === before || $('sweep-v0').textContent === shown0) problems.push('readout');
  if (cur !== target || +slider.value !== target) problems.push('slider');
  document.title = 'selftest-sweep ' + (problems.length ? 'FAILED ' + problems.join(',') : 'ok') + ' i=' + cur
    + ' gaps=' + gaps + ' ' + where.join(' ') + ' cursor=' + cx + ' readout=' + $('sweep-v0').textContent;
});
})();
"""


@dataclass(frozen=True)
class SweepSection:
    """The card: its HTML (controls, SVG, readout, JSON, script), the JSON it carries and the drawing
    commands of its SVG (for tests)."""

    html: str
    data: dict
    commands: tuple[Command, ...]


def _hull_order(local: dict[str, Vec]) -> list[str]:
    """A plate's points in order round its centroid (its outline)."""
    cx = sum(p.x for p in local.values()) / len(local)
    cy = sum(p.y for p in local.values()) / len(local)
    return sorted(local, key=lambda n: math.atan2(local[n].y - cy, local[n].x - cx))


def _away_from(p: tuple[float, float], others: list[tuple[float, float]]) -> tuple[float, float]:
    """Of down, left, right and up (paper), the direction furthest in angle from the lines p -> others."""
    incident = [math.atan2(q[1] - p[1], q[0] - p[0]) for q in others if q != p]

    def gap(c: tuple[float, float]) -> float:
        a = math.atan2(c[1], c[0])
        return min((abs((a - b + math.pi) % (2 * math.pi) - math.pi) for b in incident), default=math.pi)
    best, best_gap = (0.0, 1.0), -1.0
    for c in ((0.0, 1.0), (-1.0, 0.0), (1.0, 0.0), (0.0, -1.0)):
        if gap(c) > best_gap + 1e-9:
            best, best_gap = c, gap(c)
    return best


LABEL_DIRECTIONS = tuple(-math.pi / 4 + j * math.pi / 4 for j in range(8))
"""Where a joint's name may stand (paper angles, y down), up-right first: the drafter's habit."""


def label_offset(spans, incident: list[float]) -> tuple[float, float]:
    """Where the name ``spans`` of a point starts (baseline, from the point, paper mm): centred on the
    direction furthest from the ``incident`` directions (paper angles of the lines leaving the point),
    just clear of its pin."""
    def gap(a: float) -> float:
        return min((abs((a - b + math.pi) % (2 * math.pi) - math.pi) for b in incident), default=math.pi)
    best = max(LABEL_DIRECTIONS, key=lambda a: (round(gap(a), 9), -LABEL_DIRECTIONS.index(a)))
    ext = measure(spans)
    d = (math.cos(best), math.sin(best))
    r = PIN_R + 0.7 + abs(d[0]) * ext.width / 2 + abs(d[1]) * ext.height / 2
    cx, cy = r * d[0], r * d[1]
    return round(cx - ext.width / 2, 3), round(cy - (ext.top + ext.bottom) / 2, 3)


def _sub_digits(n: int) -> str:
    return str(n).translate(str.maketrans("0123456789", "\u2080\u2081\u2082\u2083\u2084\u2085\u2086\u2087\u2088\u2089"))


class _Card:
    """Builds the card of one study: the states, the drawing, the readout and the named positions."""

    def __init__(self, study, s, rec: Construction) -> None:
        self.study, self.s, self.rec = study, s, rec
        self.m: Mechanism = study.scene.mechanism
        self.u = study.scene.units
        self.per_m = self.u.convert("length", 1.0)
        th = np.asarray(s.thetas, dtype=float)
        closed = th.size > 1 and abs(th[-1] - th[0] - 2 * math.pi) < 1e-9
        self.th, self.closed = th, closed
        self.count = th.size - 1 if closed else th.size               # the closing angle is the first again
        self.ok = np.asarray(s.assembles, dtype=bool)[:self.count]
        self.first = next((i for i in range(self.count) if self.ok[i]), 0)
        self.static: list[Command] = []
        self.moving: list[Command] = []
        self.ids: dict[str, tuple[str, str]] = {}
        self._states()
        self._scale()

    # -- the states -------------------------------------------------------------------------------------
    def _states(self) -> None:
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
            cp = crank_points(self.m, float(self.th[i]))
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

    # -- the mechanism ----------------------------------------------------------------------------------
    def guides(self) -> None:
        """Each fixed guide: its centre line and, for a block, rails along the block's whole travel."""
        for sl in self.m.slides:
            if sl.on is not None or sl.joint not in self.pos:
                continue
            d = (math.cos(sl.angle), -math.sin(sl.angle))
            nrm = (-d[1], d[0])
            g = self.paper((sl.through.x * self.per_m, sl.through.y * self.per_m))
            ts = [(q[0] - g[0]) * d[0] + (q[1] - g[1]) * d[1]
                  for q in (self.paper(p) for p in self.pos[sl.joint] if p is not None)]
            if not ts:
                continue
            a0, a1 = min(ts) - BLOCK_L / 2 - 4.0, max(ts) + BLOCK_L / 2 + 4.0
            self.static.append(Line(g[0] + a0 * d[0], g[1] + a0 * d[1], g[0] + a1 * d[0], g[1] + a1 * d[1], "centre",
                                    f"sweep guide {sl.joint}:centre line"))
            if sl.number is None:
                continue
            for sn in (1.0, -1.0):
                off = (nrm[0] * sn * BLOCK_H / 2, nrm[1] * sn * BLOCK_H / 2)
                p1 = (g[0] + a0 * d[0] + off[0], g[1] + a0 * d[1] + off[1])
                self.static.append(Line(*p1, g[0] + a1 * d[0] + off[0], g[1] + a1 * d[1] + off[1], "guide",
                                        f"sweep guide {sl.joint}:rail"))
                h = hatching(p1, d, a1 - a0, (nrm[0] * sn, nrm[1] * sn), f"sweep guide {sl.joint}:hatch")
                if h is not None:
                    self.static.append(h)

    def traces(self) -> list[dict]:
        """The coupler curve of each point fixed to a link (not a joint): the whole path thin, broken at
        gaps, and over it the part traced from the first angle to the slider's."""
        m, count = self.m, self.count
        self.traced = [a.name for a in m.attached if a.name in self.pos and a.name not in m.ground
                       and not any(a.name in lk.joints for lk in m.links)]
        out: list[dict] = []
        for name in self.traced:
            i = 0
            while i < count:
                if self.pos[name][i] is None:
                    i += 1
                    continue
                j = i
                while j < count and self.pos[name][j] is not None:
                    j += 1
                run = [self.paper(p) for p in self.pos[name][i:j]]
                if self.closed and i == 0 and j == count:
                    run.append(run[0])
                if len(run) >= 2:
                    self.static.append(Polyline(tuple(run), "path", f"sweep path of {name} {len(out) + 1}"))
                    tid = f"sw-trace-{len(out)}"
                    self.tag(Polyline(tuple(run[:1]) * 2, "series 4", f"sweep trace {len(out)}"), tid, "sw-trace")
                    out.append({"id": tid, "at": name, "from": i, "to": j})
                i = j
        return out

    def bodies(self) -> dict[str, list]:
        """Links (lines, or plates through all their points), slider blocks, pins, labels, fixed pivots."""
        m, pos = self.m, self.pos
        links, blocks, pins, labels = [], [], [], []
        for lk in m.links:
            local = m.local(lk.number)
            order = [x for x in (_hull_order(local) if len(local) > 2 else lk.joints) if x in pos]
            if len(order) < 2:
                continue
            lid = f"sw-link-{lk.number}"
            self.tag(Line(*self.at(order[0]), *self.at(order[1]), "link", f"sweep link {lk.number}") if len(order) == 2
                     else Polygon(tuple(self.at(x) for x in order), "link", f"sweep link {lk.number}"), lid)
            links.append({"id": lid, "pts": order})
        for sl in m.slides:
            if sl.number is None or sl.joint not in pos:
                continue
            dirs: list = []
            for i in range(self.count):
                if pos[sl.joint][i] is None:
                    dirs.append(None)
                elif sl.on is None:
                    dirs.append(sl.angle)
                else:                                    # a block on a slot turns with the slotted link
                    a, b = m.link(sl.on).joints
                    pa, pb = pos[a][i] if a in pos else None, pos[b][i] if b in pos else None
                    dirs.append(None if pa is None or pb is None else
                                math.atan2(pb[1] - pa[1], pb[0] - pa[0]) + sl.angle)
            bid = f"sw-block-{sl.number}"
            c0 = self.at(sl.joint)
            self.tag(Polygon((c0, c0, c0, c0), "block", f"sweep block {sl.number}"), bid)
            blocks.append({"id": bid, "at": sl.joint, "dir": dirs, "l": BLOCK_L, "h": BLOCK_H})
        for gname, gp in m.ground.items():
            p = self.paper((gp.x * self.per_m, gp.y * self.per_m))
            away = _away_from(p, [self.at(lk.other(gname)) for lk in m.links
                                  if gname in lk.joints and lk.other(gname) in pos])
            self.static += ground_symbol(p, away, f"sweep pivot {gname}")[0]
            spans = rich(gname, LABEL, pivot_digits=True)
            others = [self.at(lk.other(gname)) for lk in m.links if gname in lk.joints and lk.other(gname) in pos]
            incident = [math.atan2(q[1] - p[1], q[0] - p[0]) for q in others if q != p]
            dx, dy = label_offset(spans, incident + [math.atan2(away[1], away[0]) + t for t in (-0.6, 0.0, 0.6)])
            self.static.append(text_at(p[0] + dx, p[1] + dy, spans, style="label", region="sweep",
                                       name=f"sweep label {gname}"))
        joints = {j for lk in m.links for j in lk.joints} | {sl.joint for sl in m.slides}
        for name in pos:
            if name in m.ground or not (name in joints or name in self.traced):
                continue
            pid, lid = f"sw-pin-{name}", f"sw-label-{name}"
            self.tag(Circle(*self.at(name), PIN_R, "pin", f"sweep pin {name}") if name in joints
                     else Circle(*self.at(name), DOT_R, "dot", f"sweep pin {name}"), pid)
            pins.append({"id": pid, "at": name})
            spans = rich(name, LABEL, pivot_digits=True)
            offsets = [self._label_at(name, i, spans, blocks) for i in range(self.count)]
            x, y = self.at(name)
            dx, dy = offsets[self.first]
            self.tag(text_at(x + dx, y + dy, spans, style="label", region="sweep", name=f"sweep label {name}"), lid)
            labels.append({"id": lid, "at": name, "off": offsets})
        return {"links": links, "blocks": blocks, "pins": pins, "labels": labels}

    def _label_at(self, name: str, i: int, spans, blocks: list[dict]) -> tuple[float, float]:
        """The offset of ``name``'s label at slider angle ``i``: away from the links and blocks there."""
        p = self.pos[name][i]
        if p is None:
            return LABEL_OFFSET
        incident = []
        for lk in self.m.links:
            local = self.m.local(lk.number)
            if name in local:
                for other in local:
                    q = self.pos[other][i] if other in self.pos and other != name else None
                    if q is not None and (q[0], q[1]) != (p[0], p[1]):
                        incident.append(math.atan2(-(q[1] - p[1]), q[0] - p[0]))
        for b in blocks:
            if b["at"] == name and b["dir"][i] is not None:
                incident += [-b["dir"][i], math.pi - b["dir"][i]]
        return label_offset(spans, incident)

    # -- the charts and the readout -----------------------------------------------------------------------
    def charts(self) -> tuple[list[dict], list[str], list[list[str]]]:
        """The sweep's charts two by two beside the mechanism, each with a cursor and a dot on each series;
        the readout's headings and its text at every angle (scene units)."""
        u, th, count = self.u, self.th, self.count
        axes = AxisUnits(lambda kind, v: v * per_si(u, kind), lambda kind: symbol_of(u, kind))
        charts = [e for e in self.rec.entities() if isinstance(e, Chart)][:4]
        cw, ch = (WIDTH - MECH_W) / 2, HEIGHT / 2
        cursors: list[dict] = []
        heads = [f"\u03b8<sub>{self.m.crank}</sub>"]
        cols = [[u.format("angle", float(th[i]) % (2 * math.pi)) for i in range(count)]]
        # a chart runs over one turn from 0 (constructions.cycle.one_turn): where each slider angle is in it
        where: dict[int, int] = {}
        for j, i in enumerate(one_turn(tuple(float(t) for t in th))[0]):
            where.setdefault(i, j)
        for ci, chart in enumerate(charts):
            r = Rect(MECH_W + (ci % 2) * cw, (ci // 2) * ch, cw, ch)
            if ci % 2:
                self.static.append(Line(r.x, r.y, r.x, r.bottom, "separator", "sweep separator"))
            elif ci:
                self.static.append(Line(MECH_W, r.y, WIDTH, r.y, "separator", "sweep separator"))
            hd = viewport_header(r, chart.diagram.name, None, "", region="sweep", name=f"sweep {chart.name}")
            self.static += hd.commands
            cmds, at = chart_with_axes(chart, Rect(r.x + 2.0, r.y + hd.height, r.w - 4.0, r.h - hd.height - 1.5),
                                       axes, "sweep")
            self.static += cmds
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
            self.tag(Line(xs[0], at.top, xs[0], at.bottom, "series 4", f"sweep cursor {ci}"), cid, "sw-cursor")
            dots = []
            for si, ser in enumerate(chart.series):
                did = f"sw-dot-{ci}-{si}"
                ys = [round(at.y(axes.convert(ser.y_kind, float(ser.y[where[i]]))), 3)
                      if math.isfinite(ser.y[where[i]]) else None for i in range(count)]
                self.tag(Circle(xs[0], ys[0] if ys[0] is not None else at.bottom, CURSOR_DOT, "dot",
                                f"sweep dot {ci} {si}"), did, "sw-dot")
                dots.append({"id": did, "y": ys})
            cursors.append({"id": cid, "x": xs, "dots": dots})
        return cursors, heads, cols

    # -- what the sweep names -----------------------------------------------------------------------------
    def named(self) -> tuple[list[str], dict[int, list[str]]]:
        """The status line at every angle and the jump list: gaps, change points, and for a four-bar its
        limit positions and the transmission angle's extremes, each at its nearest slider angle."""
        u, th, count = self.u, self.th, self.count
        turn = 2 * math.pi
        step = float(th[1] - th[0]) if th.size > 1 else turn

        def angle(a: float) -> str:
            return u.format("angle", a % turn)

        def index_of(a: float) -> int:
            return int(round(((a - th[0]) % turn) / step)) % count if step > 0 else 0
        status = ["" for _ in range(count)]
        events: list[tuple[int, str]] = []
        for a, b in self.s.gaps():
            a, b = min(a, count), min(b, count)
            if a >= b:
                continue
            span = f"{angle(float(th[a]))} to {angle(float(th[b - 1]))}"
            for i in range(a, b):
                status[i] = (f"The linkage cannot be assembled at this crank angle (a gap, {span})"
                             + (": only the crank is drawn." if self.crank_names else "."))
            events.append((a, f"gap from {angle(float(th[a]))}"))
        named: list[tuple[float, str, str]] = []
        for a in self.s.change_points:
            named.append((a, f"change point at {angle(a)}", f"Change point at {angle(a)}: all the links lie in line "
                          f"and the two assemblies meet; the linkage keeps to its branch."))
        k = self.study.get("classification")
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

    # -- the whole ----------------------------------------------------------------------------------------
    def build(self) -> SweepSection:
        self.guides()
        traces = self.traces()
        parts = self.bodies()
        cursors, heads, cols = self.charts()
        status, merged = self.named()
        u, count = self.u, self.count
        data = {"count": count, "k": self.k, "ox": self.ox, "oy": self.oy, "scale": ratio_text(self.ratio),
                "turn": u.convert("angle", 2 * math.pi),
                "value": [u.convert("angle", float(self.th[i]) % (2 * math.pi)) for i in range(count)],
                "angle": [f"\u03b8{_sub_digits(self.m.crank)} = {t}" for t in cols[0]],
                "ok": [bool(x) for x in self.ok], "status": status, "pts": self.pos, **parts, "traces": traces,
                "charts": cursors, "readout": [[col[i] for col in cols] for i in range(count)]}
        commands = tuple(self.static + self.moving)

        def attrs(cmd: Command) -> dict[str, str]:
            if cmd.name in self.ids:
                ident, cls = self.ids[cmd.name]
                return {"id": ident, "class": cls}
            return {}
        svg = sheet_to_svg(Sheet(Paper("sweep", "landscape", WIDTH, HEIGHT), commands), attrs)
        dot = " \u00b7 "
        marks = "".join(f'<option value="{i}"></option>' for i in merged)
        jumps = "".join(f'<button data-i="{i}">{html.escape(dot.join(t))}</button>' for i, t in merged.items())
        readout = "".join(f'<span>{h} = <span class="v" id="sweep-v{j}"></span></span>' for j, h in enumerate(heads))
        payload = json.dumps(data, ensure_ascii=False, allow_nan=False).replace("</", "<\\/")
        body = (f'<div id="sweep"><h3>Over the cycle: turn the crank</h3>'
                f'<div id="sweep-controls"><button id="sweep-play">&#9654; play</button>'
                f'<input type="range" id="sweep-slider" min="0" max="{count - 1}" step="1" value="0" '
                f'list="sweep-marks" aria-label="crank angle"><span id="sweep-angle"></span></div>'
                f'<datalist id="sweep-marks">{marks}</datalist>'
                + (f'<div id="sweep-events">Named positions: {jumps}</div>' if merged else "")
                + f'<div id="sweep-status"></div>{svg}<div id="sweep-readout">{readout}</div>'
                f'<script type="application/json" id="sweep-data">{payload}</script>'
                f'<script>{SCRIPT}</script></div>')
        return SweepSection(body, data, commands)


def sweep_section(study) -> SweepSection | None:
    """The slider card of a solved study whose scene asked for the sweep; None for any other study (its
    page stays as it was)."""
    sw = study.computed("sweep")
    if sw is None or np.asarray(sw[0].thetas).size == 0:
        return None
    return _Card(study, *sw).build()


__all__ = ["SweepSection", "sweep_section", "STYLE"]
