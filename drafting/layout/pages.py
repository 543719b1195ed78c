"""Packing blocks onto pages: diagram panels with minimum sizes and flowing text, on one or more sheets.

The blocks are the diagram panels of a construction (:mod:`drafting.layout.panels`: the space diagram at an
ISO 5455 scale, each vector polygon at its own scale, charts) and the text sections (vector equations,
numbered steps, results table, notes), which flow from slot to slot and page to page at one lettering
size between 3.5 and 2.5 mm.

A page is planned in three moves:

1. an *arrangement* of its panels in rows (stacked, side by side, the space diagram over a row of
   polygons, rows of two), each panel given an equal share of its row's spare width;
2. a *fill*: every panel starts at its smallest legible scale (rung) and, in turn, each climbs one rung
   while the rows still fit the area's height, so the diagrams grow together to fill the room (a polygon
   whose construction fixed its scale has one rung);
3. the text slots: the text column (landscape), the room under the diagrams (portrait), the leftover
   of the diagram column.

The first strategy is the classic sheet: landscape, diagrams in a column on the left, the text column
on the right over the title block, the space diagram on top with a text slot under it when it leaves
room; portrait, diagrams on top and text below.  When the content cannot be set on one page legibly
(lettering at least 2.5 mm, every polygon at least ``POLYGON_MIN_MM`` large, the space diagram at an
ISO scale), the panels are split over pages (in order) and the text continues from page to page,
with pages of text only at the end when needed, the drawings kept together on as few pages as hold
them; every page has the title block with its sheet number n/m.  :class:`~drafting.render.errors.LayoutError` is raised only when one block alone cannot fit an empty
page.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import Callable, Sequence

from .flow import flow, flow_shrinking, FlowText, page_slot, slot_page, TEXT_SIZES
from .items import Section
from ..render.errors import LayoutError
from ..render.paper import Paper, Rect
from ..render.scales import ratio_factor
from .panels import Panel, SpacePanel, VectorPanel

TEXT_COL_MIN = 120.0
SPACE_MIN_H = 40.0
LEFTOVER_MIN_H = 30.0
GUTTER = 3.0
COMFORTABLE_LETTERING = 3.0
"""Lettering below this is taken only when nothing else fits."""
MAX_PAGES = 12

Sep = tuple[float, float, float, float]


# ---- a fill: panels in rows, each at a rung ---------------------------------------------------------

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


def _smallest(rows, w: float, h: float) -> tuple[list, dict[str, int], dict[str, float]] | None:
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
    got = _smallest(rows, w, h)
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


# ---- pages --------------------------------------------------------------------------------------

@dataclass
class PagePlan:
    """Where everything on one page goes: panels (key -> panel, rung, rect), text slots, the title
    block (sized for the probe scale text), separators, and slots that go back to a panel when the
    text leaves them empty."""

    panels: list[tuple[Panel, int, Rect]] = field(default_factory=list)
    text_slots: list[tuple[str, Rect]] = field(default_factory=list)
    title_block: Rect | None = None
    separators: list[Sep] = field(default_factory=list)
    reclaim: list[tuple[str, dict[str, Rect], Sep]] = field(default_factory=list)
    kind: str = "diagrams"           # "diagrams", "text"

    def quality(self) -> tuple:
        return quality([(p, r) for p, r, _ in self.panels])


TbHeight = Callable[[float, Sequence[Panel]], float]


def _place_rows(fl: Fill, x: float, top: float, bottom: float, *, from_bottom: bool, space_top: bool,
                leftover_slot: bool, plan: PagePlan, slot_name: str) -> None:
    """Put the fill's rows into the column [x, x + fl.w] between ``top`` and ``bottom``.

    ``space_top``: the first row (the space diagram) at the top, the others from the bottom up, the
    leftover between them (a text slot when ``leftover_slot`` and it is tall enough, else the space
    row's).  Otherwise the rows from the bottom up (``from_bottom``) or from the top down."""
    w = fl.w
    rows = list(zip(fl.rows, fl.widths, fl.heights))
    leftover = (bottom - top) - fl.used
    seps = plan.separators

    def put(row, ws, y, hgt) -> None:
        xx = x
        for i, (p, pw) in enumerate(zip(row, ws)):
            plan.panels.append((p, fl.rungs[p.key], Rect(xx, y, pw, hgt)))
            if i:
                seps.append((xx, y, xx, y + hgt))
            xx += pw

    if space_top and rows:
        first, rest = rows[0], rows[1:]
        y = bottom
        for row, ws, hgt in reversed(rest):
            y -= hgt
            put(row, ws, y, hgt)
            if y > top + 1e-9:
                seps.append((x, y, x + w, y))
        low = y
        space_h = first[2]
        if leftover_slot and leftover >= LEFTOVER_MIN_H:
            put(first[0], first[1], top, space_h)
            sep = (x, top + space_h, x + w, top + space_h)
            plan.text_slots.append((slot_name, Rect.from_edges(x + GUTTER, top + space_h + GUTTER, x + w - GUTTER,
                                                               low - GUTTER)))
            whole = Rect.from_edges(x, top, x + w, low)
            plan.reclaim.append((slot_name, {first[0][0].key: whole}, sep))
        else:
            put(first[0], first[1], top, low - top)
        return
    if from_bottom:
        slot = leftover_slot and leftover >= LEFTOVER_MIN_H
        if not slot and rows:                 # no text above them: the top row takes the leftover
            rows[0] = (rows[0][0], rows[0][1], rows[0][2] + leftover)
        y = bottom
        for i in range(len(rows) - 1, -1, -1):
            row, ws, hgt = rows[i]
            y -= hgt
            put(row, ws, y, hgt)
            if y > top + 1e-6 and not (i == 0 and slot):
                seps.append((x, y, x + w, y))
        if slot:
            plan.text_slots.append((slot_name, Rect.from_edges(x + GUTTER, top + GUTTER, x + w - GUTTER, y - GUTTER)))
            # unused, the slot goes to the top row's panels
            n_top = len(rows[0][0])
            tops = {p.key: Rect.from_edges(r.x, top, r.right, r.bottom) for p, _, r in plan.panels[-n_top:]}
            plan.reclaim.append((slot_name, tops, (x, y, x + w, y)))
    else:
        y = top
        for i, (row, ws, hgt) in enumerate(rows):
            if i:
                seps.append((x, y, x + w, y))
            put(row, ws, y, hgt)
            y += hgt


def _best_fill(arrs, w: float, h: float, *, climb: bool) -> Fill | None:
    best = None
    for a in arrs:
        fl = fill(a, w, h, climb=climb)
        if fl is None:
            continue
        key = fl.quality() + (h - fl.used,)
        if best is None or key > best[0]:
            best = (key, fl)
    return None if best is None else best[1]


def landscape_text_page(paper: Paper, panels: Sequence[Panel], tb_height: TbHeight, *, text_width: float | None,
                        climb: bool) -> PagePlan | None:
    """The classic landscape sheet: diagrams in a column on the left, text and the title block on the
    right.  ``text_width`` asks for a text column that wide (at least TEXT_COL_MIN); by default half the
    frame, at most the title block's width."""
    F = paper.frame
    if not panels:
        return text_page(paper, panels, tb_height)
    pref = min(paper.title_block_max_width, 0.5 * F.w) if text_width is None else text_width
    best = None
    for a in arrangements(panels):
        need_w = max(min_width(a), 100.0 if isinstance(panels[0], SpacePanel) else 0.0)
        wt = max(TEXT_COL_MIN, min(pref, F.w - need_w))
        if F.w - wt < need_w - 1e-9:
            continue
        fl = fill(a, F.w - wt, F.h, climb=climb)
        if fl is None:
            continue
        key = fl.quality() + (F.h - fl.used, wt)
        if best is None or key > best[0]:
            best = (key, fl, wt)
    if best is None:
        return None
    _, fl, wt = best
    xd = F.right - wt
    tbw = min(paper.title_block_max_width, wt)
    h_tb = tb_height(tbw, panels)
    plan = PagePlan(kind="diagrams")
    plan.title_block = Rect(F.right - tbw, F.bottom - h_tb, tbw, h_tb)
    plan.separators.append((xd, F.top, xd, F.bottom))
    plan.text_slots.append(("text:0", Rect.from_edges(xd + GUTTER, F.top + GUTTER, F.right - GUTTER,
                                                       plan.title_block.top - GUTTER)))
    lead = isinstance(fl.rows[0][0], SpacePanel) and len(fl.rows[0]) == 1
    _place_rows(fl, F.x, F.top, F.bottom, from_bottom=True, space_top=lead, leftover_slot=True, plan=plan,
                slot_name="text:1")
    return plan


def portrait_text_page(paper: Paper, panels: Sequence[Panel], tb_height: TbHeight, *, share: float,
                       climb: bool) -> PagePlan | None:
    """Portrait: the diagrams across the top (at most ``share`` of the height above the title block),
    the text below them and beside the title block."""
    F = paper.frame
    if not panels:
        return text_page(paper, panels, tb_height)
    tbw = paper.title_block_max_width
    h_tb = tb_height(tbw, panels)
    tb = Rect(F.right - tbw, F.bottom - h_tb, tbw, h_tb)
    fl = _best_fill(arrangements(panels), F.w, share * (F.h - h_tb), climb=climb)
    if fl is None:
        return None
    plan = PagePlan(kind="diagrams", title_block=tb)
    # polygons in the last row narrowed to what they need: the room beside them takes text
    last, beside = fl.rows[-1], None
    if not any(isinstance(p, SpacePanel) for p in last):
        ws = []
        for p in last:
            got = p.need(fl.rungs[p.key], 10_000.0)
            w = max(got[0], p.min_width()) if got else None
            again = p.need(fl.rungs[p.key], w) if w else None
            if again is None or again[1] > fl.heights[-1] + 1e-9:
                break
            ws.append(w)
        else:
            if F.w - sum(ws) >= 80.0:
                fl = Fill(fl.rows, fl.widths[:-1] + (tuple(ws),), fl.rungs, fl.heights, fl.w)
                y0 = F.top + sum(fl.heights[:-1])
                beside = Rect.from_edges(F.x + sum(ws), y0, F.right, y0 + fl.heights[-1])
    _place_rows(fl, F.x, F.top, F.top + fl.used, from_bottom=False, space_top=False, leftover_slot=False,
                plan=plan, slot_name="")
    y_end = F.top + fl.used
    plan.separators.append((F.x, y_end, F.right, y_end))
    if beside is not None:
        plan.separators.append((beside.x, beside.y, beside.x, beside.bottom))
        plan.text_slots.append(("text:0", beside.inset(GUTTER)))
    if tb.top - y_end > 20.0:
        plan.text_slots.append((f"text:{len(plan.text_slots)}", Rect.from_edges(
            F.x + GUTTER, y_end + GUTTER, F.right - GUTTER, tb.top - GUTTER)))
    if tb.left - F.left >= 60.0:
        plan.text_slots.append((f"text:{len(plan.text_slots)}", Rect.from_edges(
            F.x + GUTTER, max(tb.top, y_end) + GUTTER, tb.left - GUTTER, F.bottom - GUTTER)))
    return plan


def diagram_page(paper: Paper, panels: Sequence[Panel], tb_height: TbHeight) -> PagePlan | None:
    """A page of diagrams only: rows across the frame above the title block's band, or two columns --
    one the frame's full height, one over the title block -- whichever draws the diagrams larger."""
    F = paper.frame
    best: tuple | None = None
    tbw = paper.title_block_max_width
    h_tb = tb_height(tbw, panels)
    fl = _best_fill(arrangements(panels), F.w, F.h - h_tb, climb=True)
    if fl is not None:
        best = (fl.quality() + (F.h - h_tb - fl.used,), [(fl, F.x, F.top, F.h - h_tb)], tbw, h_tb)
    if paper.orientation == "landscape" and len(panels) >= 2:
        for wt in dict.fromkeys((min(tbw, 0.5 * F.w), TEXT_COL_MIN)):
            h2 = tb_height(wt, panels)
            for k in range(1, len(panels)):
                left = _best_fill(arrangements(panels[:k]), F.w - wt, F.h, climb=True)
                right = _best_fill(arrangements(panels[k:]), wt, F.h - h2, climb=True) if left else None
                if left is None or right is None:
                    continue
                q = quality([(p, f.rungs[p.key]) for f in (left, right) for row in f.rows for p in row])
                key = q + (F.h - left.used + F.h - h2 - right.used,)
                if best is None or key > best[0]:
                    best = (key, [(left, F.x, F.top, F.h), (right, F.right - wt, F.top, F.h - h2)], wt, h2)
    if best is None:
        return None
    _, cols, tbw, h_tb = best
    plan = PagePlan(kind="diagrams", title_block=Rect(F.right - tbw, F.bottom - h_tb, tbw, h_tb))
    for i, (fl, x, top, h) in enumerate(cols):
        # spread what is left over the rows, so the panels share the room
        extra = (h - fl.used) / len(fl.rows)
        fl = Fill(fl.rows, fl.widths, fl.rungs, tuple(v + extra for v in fl.heights), fl.w)
        _place_rows(fl, x, top, top + h, from_bottom=False, space_top=False, leftover_slot=False, plan=plan,
                    slot_name="")
        if i:
            plan.separators.append((x, F.top, x, F.bottom))
    if len(cols) == 1:
        plan.separators.append((F.x, F.bottom - h_tb, plan.title_block.left, F.bottom - h_tb))
    return plan


def text_page(paper: Paper, panels: Sequence[Panel], tb_height: TbHeight) -> PagePlan:
    """A page of text: two columns on landscape (the right one over the title block), one on portrait
    (and beside the title block when there is room)."""
    F = paper.frame
    tbw = paper.title_block_max_width
    h_tb = tb_height(tbw, ())
    tb = Rect(F.right - tbw, F.bottom - h_tb, tbw, h_tb)
    plan = PagePlan(kind="text", title_block=tb)
    if paper.orientation == "landscape":
        xm = F.x + F.w / 2
        plan.text_slots.append(("text:0", Rect.from_edges(F.x + GUTTER, F.top + GUTTER, xm - GUTTER,
                                                           (F.bottom if tb.left >= xm else tb.top) - GUTTER)))
        plan.text_slots.append(("text:1", Rect.from_edges(xm + GUTTER, F.top + GUTTER, F.right - GUTTER,
                                                           tb.top - GUTTER)))
        plan.separators.append((xm, F.top, xm, F.bottom if tb.left >= xm else tb.top))
    else:
        plan.text_slots.append(("text:0", Rect.from_edges(F.x + GUTTER, F.top + GUTTER, F.right - GUTTER,
                                                           tb.top - GUTTER)))
        if tb.left - F.left >= 60.0:
            plan.text_slots.append(("text:1", Rect.from_edges(F.x + GUTTER, tb.top + GUTTER, tb.left - GUTTER,
                                                               F.bottom - GUTTER)))
    return plan


def text_page_options(paper: Paper, panels: Sequence[Panel], tb_height: TbHeight) -> list[PagePlan]:
    """The plans of a page with diagrams and text, in order of preference (the classic sheet first)."""
    out: list[PagePlan | None] = []
    for climb in (False, True):
        if paper.orientation == "landscape":
            out.append(landscape_text_page(paper, panels, tb_height, text_width=None, climb=climb))
            out.append(landscape_text_page(paper, panels, tb_height, text_width=TEXT_COL_MIN, climb=climb))
        else:
            for share in (0.45, 0.6, 0.75, 0.9):
                out.append(portrait_text_page(paper, panels, tb_height, share=share, climb=climb))
    uniq: list[PagePlan] = []
    seen = set()
    for p in out:
        if p is None:
            continue
        key = (tuple((q.key, r, tuple(round(v, 6) for v in (rc.x, rc.y, rc.w, rc.h))) for q, r, rc in p.panels),
               tuple((n, tuple(round(v, 6) for v in (rc.x, rc.y, rc.w, rc.h))) for n, rc in p.text_slots))
        if key not in seen:
            seen.add(key)
            uniq.append(p)
    return uniq


# ---- documents: pages with the text flowed through them --------------------------------------------

@dataclass
class Document:
    pages: list[PagePlan]
    text: list                       # the slot ("<page>#<slot>") each placed item went into
    size: float

    @property
    def count(self) -> int:
        return len(self.pages)

    def quality(self) -> tuple:
        return quality([(p, r) for pg in self.pages for p, r, _ in pg.panels])

    def empty_columns(self) -> int:
        """Pages whose text slots the text never reached (room left blank)."""
        used = {slot_page(slot) for slot in self.text}
        return sum(1 for i, pg in enumerate(self.pages) if pg.text_slots and str(i) not in used)


def slots_of(pages: Sequence[PagePlan]) -> list[tuple[str, Rect]]:
    return [(page_slot(i, name), r) for i, pg in enumerate(pages) for name, r in pg.text_slots
            if r.w > 20 and r.h > 10]


def _flow(sections, pages, cache) -> tuple[list, float] | None:
    """The text set into the pages' slots (remembered by the slots' geometry: many plans share it)."""
    if not sections:
        return [], TEXT_SIZES[0]
    slots = slots_of(pages)
    key = ("flow", tuple((n, round(r.x, 6), round(r.y, 6), round(r.w, 6), round(r.h, 6)) for n, r in slots))
    if key not in cache:
        cache[key] = flow_shrinking(sections, slots, cache=cache, plan=True)
    return cache[key]


def _pick(plans: Sequence[PagePlan], document: Callable[[PagePlan], "Document | None"], *,
          prune: bool = True) -> Document | None:
    """The classic rule over the one-page ``plans`` (``document(plan)`` flows the text into a plan: None
    when it does not fit): the first plan the text fits sets the lettering size; another is taken when
    it keeps that size, or keeps comfortable lettering (3 mm) while drawing the space diagram (when
    reduced) or the polygons larger; of those, the largest space scale, then the largest polygons, then
    lettering.  None when the text fits no plan.

    Plans are flowed only as far as the choice needs: where the sheet chooses a polygon's scale, a plan
    that keeps comfortable lettering is taken whatever the first one's size, so the plans of the best
    drawings are flowed first and, when one of them keeps 3 mm, the others are never flowed (a plan
    whose drawings are smaller cannot win).  Otherwise (or without ``prune``: the test's reference) every
    plan is flowed."""
    docs: dict[int, Document | None] = {}

    def doc(i: int) -> Document | None:
        if i not in docs:
            docs[i] = document(plans[i])
        return docs[i]
    free = bool(plans) and any(isinstance(p, VectorPanel) and p.free for p, _, _ in plans[0].panels)
    if free and prune:
        # the plans of the best drawings (their order kept among them)
        top = max(pl.quality() for pl in plans)
        best = [i for i, pl in enumerate(plans) if pl.quality() == top]
        comfortable = [i for i in best if doc(i) is not None and doc(i).size >= COMFORTABLE_LETTERING - 1e-9]
        if comfortable:
            return doc(max(comfortable, key=lambda i: doc(i).size))     # the first of the largest
    options = [d for d in (doc(i) for i in range(len(plans))) if d is not None]
    if not options:
        return None
    first = options[0]
    ref = first.size
    reduced = any(isinstance(p, SpacePanel) and ratio_factor(p.ratios[r]) < 1.0
                  for pg in first.pages for p, r, _ in pg.panels)

    def acceptable(o: Document) -> bool:
        return o is first or o.size >= ref - 1e-9 or ((reduced or free) and o.size >= COMFORTABLE_LETTERING - 1e-9)
    return max((o for o in options if acceptable(o)), key=lambda o: o.quality() + (o.size,))


def _compositions(n: int, m: int):
    """Ways to cut n items in order into m non-empty groups: the group sizes."""
    for cuts in itertools.combinations(range(1, n), m - 1):
        bounds = (0,) + cuts + (n,)
        yield [bounds[i + 1] - bounds[i] for i in range(m)]


def plan_document(paper: Paper, panels: Sequence[Panel], sections, tb_height: TbHeight, *,
                  cache: dict | None = None, what: str = "", prune: bool = True) -> Document:
    """The pages for ``panels`` and the text ``sections``: one page when it can be set legibly, else
    the fewest pages (see the module docstring).

    Of the several-page documents, one is flowed only when it could beat the best so far: its key
    can be bounded before its text is set -- at least as many pages as groups (one more when no
    diagram page takes text), its drawings no larger than its groups' largest plans draw them,
    lettering no larger than the largest size.  (``prune=False`` flows every one: the test's
    reference.)"""
    panels = list(panels)
    cache = {} if cache is None else cache
    sections = FlowText(sections)             # flowed once per plan tried: made ready once
    plans = _GroupPlans(paper, tb_height)
    # one page
    def one_page(plan: PagePlan) -> Document | None:
        got = _flow(sections, [plan], cache)
        return None if got is None else Document([plan], got[0], got[1])
    picked = _pick(plans.with_text(panels), one_page)
    if picked is not None:
        return picked
    _check_blocks(paper, panels, sections, tb_height, cache)
    # several pages: the panels in order over the pages; text on the first, all, the last or no
    # diagram page, and pages of text only after them as needed
    best: tuple | None = None
    n = len(panels)
    for m in range(1, max(n, 1) + 1):
        if best is not None and m > best[1].count:
            break
        for sizes in (_compositions(n, m) if n else [[]]):
            groups, i = [], 0
            for s in sizes:
                groups.append(panels[i:i + s])
                i += s
            for mode in ("first", "all", "last", "none"):
                if mode != "first" and m == 1 and mode != "none":
                    continue
                if prune and best is not None:
                    bound = _best_possible(plans, groups, mode, bool(sections))
                    if bound is None or bound <= best[0]:
                        continue
                doc = _document(plans, groups, mode, sections, cache)
                if doc is None:
                    continue
                # fewest pages; then the drawings kept together on as few pages as hold them (a reader
                # compares the polygons with the space diagram), then comfortable lettering, the largest
                # diagrams, the largest lettering
                drawing_pages = sum(1 for pg in doc.pages if pg.panels)
                key = (-doc.count, -drawing_pages, doc.size >= COMFORTABLE_LETTERING - 1e-9) + doc.quality() + (
                    doc.size, -doc.empty_columns(), -m)
                if best is None or key > best[0]:
                    best = (key, doc)
    if best is None:
        raise LayoutError(f"the content does not fit on {MAX_PAGES} sheets of {paper.name} {paper.orientation}")
    return best[1]


class _GroupPlans:
    """The page plans of a group of panels, with text (:func:`text_page_options`) and without
    (:func:`diagram_page`), each made once per document: the several-page search meets the same group
    in many cuts and text modes.  (Plans are not changed once made.)"""

    def __init__(self, paper: Paper, tb_height: TbHeight) -> None:
        self.paper, self.tb_height = paper, tb_height
        self._memo: dict[tuple, object] = {}

    def _get(self, make, panels: Sequence[Panel]):
        key = (make, tuple(map(id, panels)))
        if key not in self._memo:
            self._memo[key] = make(self.paper, panels, self.tb_height)
        return self._memo[key]

    def with_text(self, panels: Sequence[Panel]) -> list[PagePlan]:
        return self._get(text_page_options, panels)

    def diagrams(self, panels: Sequence[Panel]) -> PagePlan | None:
        return self._get(diagram_page, panels)


def _text_on(groups, mode: str) -> list[bool]:
    m = len(groups)
    return [mode == "all" or (mode == "first" and i == 0) or (mode == "last" and i == m - 1) for i in range(m)]


def _best_possible(plans: _GroupPlans, groups, mode: str, has_text: bool) -> tuple | None:
    """No document of ``groups`` in ``mode`` has a key above this (see plan_document), or None when
    some group has no plan at all.  Each of its components bounds the real key's: the pages (at least
    the groups, one more for text when no group takes it), every group a drawing page, comfortable
    lettering, each panel at the largest scale any plan of its group draws it, the largest lettering,
    no empty column."""
    m = len(groups)
    scales: dict[int, float] = {}
    sizes: dict[int, float] = {}
    for g, wt in zip(groups, _text_on(groups, mode)):
        options = [p for p in ((plans.with_text(g) if wt else []) + [plans.diagrams(g)]) if p is not None]
        if wt and not plans.with_text(g):
            return None
        if not options:
            return None
        for plan in options:
            for p, r, _ in plan.panels:
                if isinstance(p, SpacePanel):
                    scales[id(p)] = max(scales.get(id(p), 0.0), ratio_factor(p.ratios[r]))
                elif isinstance(p, VectorPanel) and p.free:
                    sizes[id(p)] = max(sizes.get(id(p), 0.0), max(p.drawn_size(r)))
    space, free = sum(scales.values()), list(sizes.values())
    best_quality = (round(min(space, 1.0), 9), round(min(free), 6) if free else 0.0, round(space, 9),
                    round(sum(free), 6))
    pages = m + (1 if has_text and mode == "none" else 0)
    return (-pages, -m, True) + best_quality + (TEXT_SIZES[0], 0, -m)


def _document(plans: _GroupPlans, groups, mode, sections, cache) -> Document | None:
    paper, tb_height = plans.paper, plans.tb_height
    pages: list[PagePlan] = []
    with_text = _text_on(groups, mode)
    choices: list[list[PagePlan]] = []
    for g, wt in zip(groups, with_text):
        if wt:
            opts = plans.with_text(g)
        else:
            p = plans.diagrams(g)
            opts = [p] if p is not None else []
        if not opts:
            return None
        choices.append(opts)
    if not sections:
        pages = [max(c, key=lambda p: p.quality()) for c in choices]
        return Document(pages, [], TEXT_SIZES[0])
    pages = [c[0] for c in choices]
    extra = 0
    while True:
        trial = pages + [text_page(paper, (), tb_height) for _ in range(extra)]
        got = _flow(sections, trial, cache)
        if got is not None:
            break
        extra += 1
        if len(trial) >= MAX_PAGES:
            return None
    pages = trial
    size = got[1]
    # each page in turn takes its plan with the largest diagrams that keeps the lettering size
    for i, opts in enumerate(choices):
        for o in sorted(opts[1:], key=lambda p: p.quality(), reverse=True):
            if o.quality() <= pages[i].quality():
                break
            cand = pages[:i] + [o] + pages[i + 1:]
            g2 = _flow(sections, cand, cache)
            if g2 is not None and g2[1] >= size - 1e-9:
                pages, got = cand, g2
                break
    # a diagram page whose text slots stayed empty draws its diagrams over the whole page instead
    used = {slot_page(slot) for slot in got[0]}
    for i, g in enumerate(groups):
        if str(i) not in used and pages[i].text_slots:
            alt = plans.diagrams(g)
            if alt is not None and alt.quality() >= pages[i].quality():
                cand = pages[:i] + [alt] + pages[i + 1:]
                g2 = _flow(sections, cand, cache)
                if g2 is not None and g2[1] >= got[1] - 1e-9:
                    pages, got = cand, g2
    return Document(pages, got[0], got[1])


def _check_blocks(paper, panels, sections, tb_height, cache) -> None:
    """LayoutError when a single block cannot fit an empty page."""
    F = paper.frame
    for p in panels:
        # as diagram_page([p]) is None, without climbing the scales: one panel has one arrangement,
        # and a page of it fails only when its smallest legible rung does
        if _smallest(((p,),), F.w, F.h - tb_height(paper.title_block_max_width, [p])) is None:
            r = p.min_rung()
            got = p.need(r, 10_000.0)
            size = f" ({got[0]:.0f} x {got[1]:.0f} mm)" if got else ""
            raise LayoutError(f"the {getattr(p, 'title', p.key).lower()} does not fit an empty {paper.name} "
                              f"{paper.orientation} sheet even at its smallest legible scale{size}; "
                              + ("use A3" if paper.name == "A4" else "draw it at a coarser scale"))
    if sections:
        tp = text_page(paper, (), tb_height)
        slots = [(n, r) for n, r in tp.text_slots if r.w > 20 and r.h > 10]
        for sec in sections:
            for item in sec.items:
                if flow([Section("", (item,))], slots[:1], TEXT_SIZES[-1], cache, plan=True) is None:
                    raise LayoutError(f"a text block ({type(item).__name__}) does not fit an empty "
                                      f"{paper.name} {paper.orientation} sheet even with 2.5 mm lettering")
