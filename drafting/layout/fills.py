"""A fill: a page area's diagram panels arranged in rows, each panel at a rung of its scale ladder.

:func:`arrangements` lists the ways to put the panels in rows (stacked, side by side, the space diagram
over a row of polygons, rows of two), each panel given an equal share of its row's spare width;
:func:`fill` starts every panel at its smallest legible scale (rung) and, in turn, lets each climb one
rung while the rows still fit the area's height, so the diagrams grow together to fill the room (a
polygon whose construction fixed its scale has one rung).  :func:`quality` ranks what a fill drew.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from ..render.scales import ratio_factor
from .panel import Panel
from .panels import SpacePanel, VectorPanel


@dataclass
class Fill:
    """Panels arranged in ``rows`` inside an area ``w`` wide, each at a rung, with the rows' heights."""

    rows: tuple[tuple[Panel, ...], ...]
    widths: tuple[tuple[float, ...], ...]
    rungs: dict[str, int]
    heights: tuple[float, ...]
    w: float

    @property
    def used(self) -> float:
        return sum(self.heights)

    def quality(self) -> tuple:
        return quality([(p, self.rungs[p.key]) for row in self.rows for p in row])


def quality(placed: Sequence[tuple[Panel, int]]) -> tuple:
    """How good a set of panels at their rungs is: the space diagram up to true scale first (a sheet laid
    over a drawing, a ruler on the links), then the smallest polygon drawn at a scale the sheet chose
    (the answers are read off the polygons), then the space diagram enlarged beyond 1:1, then the total
    size of the polygons."""
    space = sum(ratio_factor(p.ratios[r]) for p, r in placed if isinstance(p, SpacePanel))
    free = [max(p.drawn_size(r)) for p, r in placed if isinstance(p, VectorPanel) and p.free]
    return (round(min(space, 1.0), 9), round(min(free), 6) if free else 0.0, round(space, 9),
            round(sum(free), 6))


def _row_widths(row: Sequence[Panel], w: float) -> tuple[float, ...] | None:
    mins = []
    for p in row:
        got = p.need(p.min_rung(), 10_000.0)
        if got is None:
            return None
        mins.append(max(got[0], p.min_width()))
    spare = w - sum(mins)
    if spare < -1e-9:
        return None
    return tuple(m + spare / len(row) for m in mins)


def fill(rows: Sequence[Sequence[Panel]], w: float, h: float, *, climb: bool = True) -> Fill | None:
    """Every panel at its smallest legible rung, then one rung each in turn while the rows fit ``h``;
    None when even the smallest rungs do not fit ``w`` x ``h``.  Without ``climb`` the polygons whose
    scale the sheet chooses stay at their smallest legible scale (leaving the room to text)."""
    rows = tuple(tuple(r) for r in rows)
    memo = rows[0][0].cache.fills if rows and rows[0] and hasattr(rows[0][0], "cache") else None
    key = (tuple(tuple(id(p) for p in r) for r in rows), round(w, 6), round(h, 6), climb)
    if memo is not None:
        if key not in memo:
            memo[key] = _fill(rows, w, h, climb)
        return memo[key]
    return _fill(rows, w, h, climb)


def smallest_fill(rows, w: float, h: float) -> tuple[list, dict[str, int], dict[str, float]] | None:
    """The rows' panel widths, and every panel at its smallest legible rung with the height it needs;
    None when that does not fit ``w`` x ``h`` (then no rung does)."""
    widths = []
    for row in rows:
        ws = _row_widths(row, w)
        if ws is None:
            return None
        widths.append(ws)
    rungs: dict[str, int] = {}
    needs: dict[str, float] = {}
    for row, ws in zip(rows, widths):
        for p, pw in zip(row, ws):
            r = p.min_rung()
            got = p.need(r, pw)
            if got is None:
                return None
            rungs[p.key], needs[p.key] = r, got[1]
    if sum(max(needs[p.key] for p in row) for row in rows) > h + 1e-9:
        return None
    return widths, rungs, needs


def _fill(rows, w: float, h: float, climb: bool) -> Fill | None:
    got = smallest_fill(rows, w, h)
    if got is None:
        return None
    widths, rungs, needs = got

    def heights() -> list[float]:
        return [max(needs[p.key] for p in row) for row in rows]
    order = sorted(((p, pw) for row, ws in zip(rows, widths) for p, pw in zip(row, ws)
                    if climb or not (isinstance(p, VectorPanel) and p.free)), key=lambda t: t[0].priority)
    if order:
        changed = True
        while changed:
            changed = False
            for p, pw in order:
                r = rungs[p.key] + 1
                if r >= p.rungs():
                    continue
                got = p.need(r, pw)
                if got is None:
                    continue
                old = needs[p.key]
                needs[p.key] = got[1]
                if sum(heights()) <= h + 1e-9:
                    rungs[p.key] = r
                    changed = True
                else:
                    needs[p.key] = old
    return Fill(rows, tuple(widths), rungs, tuple(heights()), w)


def arrangements(panels: Sequence[Panel]) -> list[tuple[tuple[Panel, ...], ...]]:
    """Ways to put the panels in rows, in order: stacked; the space diagram over a row of the others;
    all in one row; rows of two (the space diagram alone on top when it leads)."""
    ps = tuple(panels)
    n = len(ps)
    if n == 0:
        return [()]
    out: list[tuple[tuple[Panel, ...], ...]] = [tuple((p,) for p in ps)]
    lead = isinstance(ps[0], SpacePanel)
    if lead and n >= 3:
        out.append(((ps[0],), ps[1:]))
    if n >= 2:
        out.append((ps,))
    if n >= 4:
        out.append(tuple(ps[i:i + 2] for i in range(0, n, 2)))
        if lead:
            out.append(((ps[0],),) + tuple(ps[i:i + 2] for i in range(1, n, 2)))
    seen, uniq = set(), []
    for a in out:
        key = tuple(tuple(p.key for p in row) for row in a)
        if key not in seen:
            seen.add(key)
            uniq.append(a)
    return uniq


def min_width(arrangement) -> float:
    w = 0.0
    for row in arrangement:
        tot = 0.0
        for p in row:
            got = p.need(p.min_rung(), 10_000.0)
            tot += max(got[0] if got else 10_000.0, p.min_width())
        w = max(w, tot)
    return w
