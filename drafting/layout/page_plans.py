"""Page plans: where the panels, the text slots and the title block go on one page.

The first strategy is the classic sheet: landscape, diagrams in a column on the left, the text column
on the right over the title block, the space diagram on top with a text slot under it when it leaves
room (:func:`landscape_text_page`); portrait, diagrams on top and text below
(:func:`portrait_text_page`).  A page may also hold diagrams only (:func:`diagram_page`) or text only
(:func:`text_page`).  The text slots are the text column (landscape), the room under the diagrams
(portrait) and the leftover of the diagram column.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Sequence

from ..render.paper import TITLE_BLOCK_MAX_WIDTH, Paper, Rect
from ..render.scales import ratio_factor
from .fills import Fill, arrangements, fill, min_width, quality
from .flow import page_slot
from .panel import Panel
from .panels import SpacePanel

TEXT_COL_MIN = 120.0
SPACE_MIN_H = 40.0
LEFTOVER_MIN_H = 30.0
GUTTER = 3.0

Sep = tuple[float, float, float, float]


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


def widest_column(paper: Paper) -> float:
    """The widest right-hand column a page gives text or diagrams over the title block: as wide as the
    widest title block (the block itself may be narrower: ``paper.title_block_max_width``, one width
    for a document's pages)."""
    return min(TITLE_BLOCK_MAX_WIDTH, paper.frame.w)


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


def _best_fill(arrs, w: float, h: float, *, climb: bool, room: bool = True) -> Fill | None:
    """The arrangement whose fill draws the diagrams largest; of those, the one that leaves the most
    height (``room``: for text under it) or the least (a page of diagrams only, which shares what is left
    among its rows: two charts one over the other in a tall column, not side by side stretched tall)."""
    best = None
    for a in arrs:
        fl = fill(a, w, h, climb=climb)
        if fl is None:
            continue
        key = fl.quality() + ((h - fl.used) if room else -(h - fl.used),)
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
    pref = min(widest_column(paper), 0.5 * F.w) if text_width is None else text_width
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
    fl = _best_fill(arrangements(panels), F.w, F.h - h_tb, climb=True, room=False)
    if fl is not None:
        best = (fl.quality() + (F.h - h_tb - fl.used,), [(fl, F.x, F.top, F.h - h_tb)], tbw, h_tb)
    if paper.orientation == "landscape" and len(panels) >= 2:
        # the right column half the frame, the narrowest a title block takes, or as wide as the left
        # column's drawings leave it (a tall mechanism keeps a narrow column, the polygons get the rest);
        # the title block under it at most as wide
        narrowest_left = min(min(min_width(a) for a in arrangements(panels[:k])) for k in range(1, len(panels)))
        col = widest_column(paper)
        true_scale = _true_scale_width(panels[0])
        widths = (min(col, 0.5 * F.w), TEXT_COL_MIN, min(col, F.w - narrowest_left)) + (
            () if true_scale is None else (F.w - true_scale,))
        for wt in dict.fromkeys(w for w in widths if w >= TEXT_COL_MIN):
            h2 = tb_height(min(tbw, wt), panels)
            for k in range(1, len(panels)):
                left = _best_fill(arrangements(panels[:k]), F.w - wt, F.h, climb=True, room=False)
                right = _best_fill(arrangements(panels[k:]), wt, F.h - h2, climb=True, room=False) if left else None
                if left is None or right is None:
                    continue
                q = quality([(p, f.rungs[p.key]) for f in (left, right) for row in f.rows for p in row])
                key = q + (F.h - left.used + F.h - h2 - right.used,)
                if best is None or key > best[0]:
                    best = (key, [(left, F.x, F.top, F.h), (right, F.right - wt, F.top, F.h - h2)], min(tbw, wt),
                            h2)
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


def _true_scale_width(p: Panel) -> float | None:
    """The width a space diagram's panel needs at the largest ISO scale up to 1:1 (a column that narrow
    leaves the rest of the page to the polygons); None for another panel or one no such scale draws."""
    if not isinstance(p, SpacePanel):
        return None
    rungs = [r for r in range(p.rungs()) if ratio_factor(p.ratios[r]) <= 1.0 + 1e-12]
    got = p.need(max(rungs), 10_000.0) if rungs else None
    return None if got is None else max(got[0], p.min_width())


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


def slots_of(pages: Sequence[PagePlan]) -> list[tuple[str, Rect]]:
    """The text slots of ``pages`` worth setting text in (over 20 x 10 mm), each named by its page
    (:func:`~drafting.layout.flow.page_slot`)."""
    return [(page_slot(i, name), r) for i, pg in enumerate(pages) for name, r in pg.text_slots
            if r.w > 20 and r.h > 10]


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
