"""Whether a document's steps read in order: a page whose steps run down its text column and then go on
in the room under the space diagram (a slot left of the column, read before it) prints steps 34-46 above
1-33 as a reader takes the page.  The page planner prefers, of documents with as many pages, one whose
steps do not."""

from __future__ import annotations

from .flow import FlowText, page_slot, slot_page, slot_region


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


def reading_slots(pages, slots: list, used) -> list:
    """``slots`` (named "<page>#<region>", a page's text column first) in the order a reader takes them:
    a slot a page gives back to a panel when empty (:attr:`PagePlan.reclaim`, the room under the space
    diagram, left of the text column) that the text reached is read before the column to its right, so
    it is moved ahead of that page's other slots.  ``used`` holds the slots a flow in the given order
    reached; unchanged when no such slot was."""
    out = list(slots)
    for n, pg in enumerate(pages):
        for region, _, _ in pg.reclaim:
            name = page_slot(n, region)
            at = next((i for i, (s, _) in enumerate(out) if s == name), None)
            if name not in used or at is None:
                continue
            rect = out[at][1]
            first = next(i for i, (s, _) in enumerate(out) if slot_page(s) == str(n))
            if any(r.x >= rect.right - 1e-9 for _, r in out[first:at]):
                out.insert(first, out.pop(at))
    return out
