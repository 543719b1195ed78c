"""Packing blocks onto pages: diagram panels with minimum sizes and flowing text, on one or more sheets.

The blocks are the diagram panels of a construction (:mod:`drafting.layout.panels`: the space diagram at an
ISO 5455 scale, each vector polygon at its own scale, charts) and the text sections (vector equations,
numbered steps, results table, notes), which flow from slot to slot and page to page at one lettering
size between 3.5 and 2.5 mm.

A page is planned in three moves: an *arrangement* of its panels in rows, a *fill* that grows the
diagrams together to fill the room (:mod:`drafting.layout.fills`), and the text slots around them
(:mod:`drafting.layout.page_plans`).  Here the pages become a document.

The first strategy is the classic sheet (one page).  When the content cannot be set on one page legibly
(lettering at least 2.5 mm, every polygon at least ``POLYGON_MIN_MM`` large, the space diagram at an
ISO scale), the panels are split over pages (in order) and the text continues from page to page,
with pages of text only at the end when needed, the drawings kept together on as few pages as hold
them; every page has the title block with its sheet number n/m.  :class:`~drafting.render.errors.LayoutError` is raised only when one block alone cannot fit an empty
page.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Callable, Sequence

from ..render.errors import LayoutError
from ..render.paper import Paper
from ..render.scales import ratio_factor
from .flow import TEXT_SIZES, FlowText, flow, flow_shrinking, slot_page
from .fills import quality, smallest_fill
from .items import Section
from .page_blanks import bare_pages
from .page_plans import PagePlan, TbHeight, diagram_page, slots_of, text_page, text_page_options
from .panel import Panel
from .panels import SpacePanel, VectorPanel
from .reading_order import reading_slots, steps_out_of_order
from .stopwatch import timed

COMFORTABLE_LETTERING = 3.0
"""Lettering below this is taken only when nothing else fits."""
MAX_PAGES = 12


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


def _flow(sections, pages, cache) -> tuple[list, float] | None:
    """The text set into the pages' slots (remembered by the slots' geometry: many plans share it)."""
    if not sections:
        return [], TEXT_SIZES[0]
    slots = slots_of(pages)
    key = ("flow", tuple((n, round(r.x, 6), round(r.y, 6), round(r.w, 6), round(r.h, 6)) for n, r in slots))
    if key not in cache:
        got = flow_shrinking(sections, slots, cache=cache, plan=True)
        ordered = reading_slots(pages, slots, set(got[0])) if got else slots
        if ordered != slots:               # the text reached a slot read before the column: set it there first
            again = flow_shrinking(sections, ordered, cache=cache, plan=True)
            if again is not None and again[1] >= got[1] - 1e-9:
                got = again
        cache[key] = got
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


@timed("plan")
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
    # several pages, each with the same title block: planned with the widest block, then again with the
    # narrowest a page took (a text column narrower than the block narrows it) until all agree
    width = paper.title_block_max_width
    for _ in range(3):
        doc = _several_pages(plans, panels, sections, cache, prune)
        widths = {round(pg.title_block.w, 6) for pg in doc.pages if pg.title_block is not None}
        if len(widths) <= 1 or min(widths) >= width - 1e-6:
            break
        width = min(widths)
        plans = _GroupPlans(BlockPaper(paper.name, paper.orientation, paper.width, paper.height, width),
                            tb_height)
    return doc


def _several_pages(plans: "_GroupPlans", panels: list, sections: FlowText, cache, prune: bool) -> Document:
    """The best document of two or more pages (see :func:`plan_document`)."""
    paper = plans.paper
    # several pages: the panels in order over the pages; text on the first, all, the last or no
    # diagram page, and pages of text only after them as needed
    best: tuple | None = None
    n = len(panels)
    for m in range(1, max(n, 1) + 1):
        if best is not None and m > best[1].count and best[0][0] == 0:
            break                       # (a document read out of order may yet lose to one of more pages)
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
                # the steps read in order (worth another page); the fewest pages; no page left mostly
                # blank (the text beside the diagrams it speaks of, not a last page of a few lines); the
                # drawings on as few pages as hold them (a reader compares the polygons with the space
                # diagram); comfortable lettering, the largest diagrams, the largest lettering
                head = (-steps_out_of_order(doc, sections), -doc.count)
                if best is not None and head < best[0][:2]:
                    continue                # (it loses before its bare pages are measured)
                rest = (-sum(1 for pg in doc.pages if pg.panels), doc.size >= COMFORTABLE_LETTERING - 1e-9) + \
                    doc.quality() + (doc.size, -doc.empty_columns(), -m)
                if best is not None and head == best[0][:2] and best[0][2] == 0 and rest <= best[0][3:]:
                    continue                # (no bare page could make it win: the best has none)
                key = head + (-bare_pages(paper, doc, sections, cache),) + rest
                if best is None or key > best[0]:
                    best = (key, doc)
    if best is None:
        raise LayoutError(f"the content does not fit on {MAX_PAGES} sheets of {paper.name} {paper.orientation}")
    return best[1]


@dataclass(frozen=True, slots=True)
class BlockPaper(Paper):
    """A paper whose pages all take a title block ``block_width`` wide (one block for a document)."""

    block_width: float = 0.0

    @property
    def title_block_max_width(self) -> float:
        return self.block_width


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
    no empty column, no bare page, no page with its steps out of order."""
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
    return (0, -pages, 0, -m, True) + best_quality + (TEXT_SIZES[0], 0, -m)


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
        if smallest_fill(((p,),), F.w, F.h - tb_height(paper.title_block_max_width, [p])) is None:
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
