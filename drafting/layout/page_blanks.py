"""How much of a planned page is left blank: the page planner's measure, as the sheet critic measures a
page (:mod:`drafting.layout.critic.page`), taken before anything is drawn -- a document whose pages would
be mostly white is laid out again (:mod:`drafting.layout.pages`, whose ``Document`` -- its page plans,
the slot each item of text went into, the lettering size -- is measured here).
"""

from __future__ import annotations

from ..render.paper import Paper, Rect, Text, command_points
from .critic.geometry import covered_area
from .flow import FlowText, layout_item, slot_page
from .items import TooWide
from .page_plans import slots_of

MOST_BARE = 0.55
"""A page of a document with more of its frame than this left blank, as planned, is *bare* (the critic's
blank page is over half blank; the plan's measure, :func:`blank_shares`, counts text as the critic does
but a panel across its whole width, and runs up to 0.1 higher on the gallery): of two documents of as
many pages, the one with fewer bare pages is taken."""
TEXT_MARGIN = 2.0
"""The white each side of a block of text that reads as part of it (the critic's block margin), mm."""


def bare_pages(paper: Paper, doc, sections: FlowText, cache) -> int:
    """How many of ``doc``'s pages leave more than :data:`MOST_BARE` of the frame blank (see
    :func:`blank_shares`)."""
    return sum(1 for b in blank_shares(paper, doc, sections, cache) if b > MOST_BARE)


def blank_shares(paper: Paper, doc, sections: FlowText, cache) -> list[float]:
    """The share of the frame each of ``doc``'s pages leaves blank, as planned: the title block covers
    its rectangle; a panel its width from the top of its heading to the foot of its drawing (the room the
    drawing needs at its rung, centred in what the heading leaves); an item of text its height across
    its lines' boxes (:func:`text_cover`); the rest is blank."""
    F = paper.frame
    covered = [0.0] * doc.count
    for i, pg in enumerate(doc.pages):
        if pg.title_block is not None:
            covered[i] += pg.title_block.w * pg.title_block.h
        for p, r, rect in pg.panels:
            got = p.need(r, rect.w)
            h = rect.h if got is None else (rect.h + min(got[1], rect.h)) / 2
            covered[i] += rect.w * h
    if doc.text:
        slots = dict(slots_of(doc.pages))
        items = [item for group in sections.groups for item in group]
        for item, slot in zip(items, doc.text):
            r = slots[slot]
            try:
                covered[int(slot_page(slot))] += text_cover(item, r.w, doc.size, cache)
            except TooWide:             # (never placed so: the flow measured it)
                continue
    return [1.0 - c / (F.w * F.h) for c in covered]


def text_cover(item, width: float, size: float, cache) -> float:
    """The area ``item`` covers set ``width`` wide at ``size`` as the critic measures a page: the union of
    its lines' boxes (and rules) each grown by :data:`TEXT_MARGIN`, within its own height (the items of a
    slot abut: the margins between them are counted once), remembered in ``cache``."""
    key = ("text cover", item, round(width, 6), size)
    if key not in cache:
        placed = layout_item(item, width, size, cache)
        m = TEXT_MARGIN
        boxes = [(c.box if isinstance(c, Text) else Rect.bounding(command_points(c))).expanded(m)
                 for c in placed.commands if isinstance(c, Text) or c.style == "rule"]
        cache[key] = covered_area(boxes, Rect(-m, 0.0, width + 2 * m, placed.height))
    return cache[key]
