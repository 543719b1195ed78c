"""Whether a document's steps read in order: a page whose steps run down its text column and then go on
in the room under the space diagram (a slot left of the column, read before it) prints steps 34-46 above
1-33 as a reader takes the page.  The page planner prefers, of documents with as many pages, one whose
steps do not."""

from __future__ import annotations

from .flow import FlowText, slot_page, slot_region


def steps_out_of_order(doc, sections: FlowText) -> int:
    """How many of ``doc``'s pages carry construction steps first in a text column and then in a slot the
    page gives back to a panel when empty (:attr:`PagePlan.reclaim`: the room under the space diagram)."""
    start = 0
    steps: range | None = None
    for sec, group in zip(sections.sections, sections.groups):
        if sec.heading == "Construction":
            steps = range(start, start + len(group))
        start += len(group)
    if steps is None:
        return 0
    placed = [doc.text[i] for i in steps if i < len(doc.text)]
    out = 0
    for n, pg in enumerate(doc.pages):
        optional = {name for name, _, _ in pg.reclaim}
        mine = [slot_region(s) for s in placed if slot_page(s) == str(n)]
        firsts = [i for i, r in enumerate(mine) if r not in optional]
        if firsts and any(r in optional for r in mine[firsts[0] + 1:]):
            out += 1
    return out
