"""Text flow: sections of items set into text slots in order at one lettering size, shrunk step by step
from 3.5 mm to no less than 2.5 mm until they fit (:func:`flow_shrinking`); the slots may lie on several
pages.  Where the slots and the diagram panels go is :mod:`drafting.layout.pages`' business.

Everything returned is drawing commands (:mod:`drafting.render.paper`) in paper mm, y down.
"""

from __future__ import annotations

import math
from typing import MutableMapping, Sequence

from ..render.paper import Command, Rect, translated
from .items import Heading, Item, Placed, Section, TooWide


LayoutCache = MutableMapping[tuple, "Placed | TooWide"]


def _or_too_wide(make):
    """``make()``, or the TooWide it raises (to be remembered, and raised again by :func:`_raised`)."""
    try:
        return make()
    except TooWide as e:
        return e


def _raised(got):
    """A remembered result: raised when it is a TooWide, else returned."""
    if isinstance(got, TooWide):
        raise got
    return got


def _remembered(cache: LayoutCache, key: tuple, make):
    """``make()`` remembered in ``cache`` under ``key``, a TooWide it raises included (raised again)."""
    got = cache.get(key)
    if got is None:
        got = cache[key] = _or_too_wide(make)
    return _raised(got)


def layout_item(item: Item, width: float, size: float, cache: LayoutCache | None = None, *,
                w: float | None = None) -> Placed:
    """``item.layout(width, size)``, remembered in ``cache`` (items are immutable): the same text is
    set once per width and size however many plans are tried.  ``w`` is ``round(width, 6)`` when the
    caller has it already."""
    if cache is None:
        return item.layout(width, size)
    return _remembered(cache, (item, round(width, 6) if w is None else w, size), lambda: item.layout(width, size))


def item_height(item: Item, width: float, size: float, cache: LayoutCache | None = None, *,
                w: float | None = None) -> float:
    """The height ``item`` takes at ``width`` and ``size`` (raises :class:`TooWide`), without making its
    commands when the item can; remembered in ``cache`` beside :func:`layout_item`'s results (``w`` as
    there)."""
    if cache is None:
        return item.height(width, size)
    if w is None:
        w = round(width, 6)
    got = cache.get((item, w, size))                      # set in full already
    if isinstance(got, Placed):
        return got.height
    if isinstance(got, TooWide):
        raise got
    return _remembered(cache, ("height", item, w, size), lambda: item.height(width, size))


class FlowText:
    """Sections made ready to flow many times (a page planner tries many plans): their items in order,
    each section's heading made once, and every item's height remembered per slot width, lettering
    size and kind of measure, in lists (no hashing of items on the way)."""

    def __init__(self, sections: Sequence[Section]) -> None:
        self.sections = tuple(sections)
        self.groups = [tuple([Heading(sec.heading), *sec.items]) if sec.heading else tuple(sec.items)
                       for sec in self.sections]
        self._heights: dict[tuple, list[list]] = {}

    def __len__(self) -> int:
        return len(self.sections)

    def __iter__(self):
        return iter(self.sections)

    def heights(self, w: float, size: float, plan: bool) -> list[list]:
        """Per section, per item: the height at width key ``w`` and ``size`` (a float or the TooWide
        raised), or None while unasked."""
        key = (w, size, plan)
        got = self._heights.get(key)
        if got is None:
            got = self._heights[key] = [[None] * len(g) for g in self.groups]
        return got


def flow(sections: Sequence[Section] | FlowText, slots: Sequence[tuple[str, Rect]], size: float,
         cache: LayoutCache | None = None, *, tagged: bool = False, plan: bool = False) -> list | None:
    """Set the sections into the slots in order at lettering ``size``; None when they do not fit.
    Each text command's region is the name of the slot it went into; with ``tagged`` the result is
    ``(slot name, command)`` pairs (a rule of a table has no region of its own).  With ``plan`` no
    command is made: the result is the name of the slot each item went into, in order (what a page
    planner needs to know of a trial).  A planner that flows the same sections many times passes them
    as one :class:`FlowText`."""
    if not sections:
        return []
    if not slots:
        return None
    text = sections if isinstance(sections, FlowText) else FlowText(sections)
    out: list[Command] = []
    si = 0
    name, slot = slots[si]
    y = slot.top
    section_gap = 1.0 * size
    item_gap = 0.35 * size
    used = False

    def next_slot() -> bool:
        nonlocal si, name, slot, y, used
        si += 1
        if si >= len(slots):
            return False
        name, slot = slots[si]
        y = slot.top
        used = False
        return True

    placements: list[tuple[str, float, float, Item, float]] = []
    measure_item = item_height if plan else (lambda it, wd, sz, c, w: layout_item(it, wd, sz, c, w=w).height)
    widths = [round(r.w, 6) for _, r in slots]
    tables = [text.heights(w, size, plan) for w in widths]

    def height_of(k: int, i: int, item: Item) -> float:
        row = tables[si][k]
        if row[i] is None:
            row[i] = _or_too_wide(lambda: measure_item(item, slot.w, size, cache, w=widths[si]))
        return _raised(row[i])

    for k, items in enumerate(text.groups):
        if used:
            y += section_gap
        i = 0
        while i < len(items):
            item = items[i]
            try:
                height = height_of(k, i, item)
                need = height
                if item.keep_with_next and i + 1 < len(items):
                    need += item_gap + height_of(k, i + 1, items[i + 1])
            except TooWide:
                height = None
                need = math.inf
            if height is None or y + need > slot.bottom + 1e-9:
                # too wide or too tall for what is left of this slot: go on in the next one
                if not next_slot():
                    return None
                continue
            placements.append((name, slot.x, y, item, slot.w))
            y += height + item_gap
            used = True
            i += 1
    if plan:
        return [name for name, _, _, _, _ in placements]
    # everything fits: now make the commands
    for name, x, y, item, w in placements:
        placed = layout_item(item, w, size, cache)      # (set in full already when measured so)
        region = slot_region(name)
        moved = [translated(c, x, y, region) for c in placed.commands]
        out.extend(((name, c) for c in moved) if tagged else moved)
    return out


# A document's text slot is named "<page>#<region>": the page's number and the region on that page (the
# commands set in it carry the region).  Made and read only here.

def page_slot(page: int, region: str) -> str:
    return f"{page}#{region}"


def slot_page(name: str) -> str:
    """The page number of a slot named by :func:`page_slot`, as text."""
    return name.partition("#")[0]


def slot_region(name: str) -> str:
    """The region of a slot named by :func:`page_slot` (a name without a page is its own region)."""
    return name.partition("#")[2] or name


TEXT_SIZES = (3.5, 3.25, 3.0, 2.75, 2.5)


def flow_shrinking(sections: Sequence[Section], slots: Sequence[tuple[str, Rect]], *,
                   sizes: Sequence[float] = TEXT_SIZES, cache: LayoutCache | None = None,
                   tagged: bool = False, plan: bool = False) -> tuple[list, float] | None:
    """The largest lettering size (3.5 down to 2.5) at which everything fits, and its commands (with
    ``plan``, the slots the items went into: see :func:`flow`)."""
    # (a lower bound of the height, set at the widest slot, used to skip sizes first: it cost more than it
    # saved -- each plan's slots have their own widths -- and never changed a sheet)
    text = sections if isinstance(sections, FlowText) else FlowText(sections)
    for size in sizes:
        out = flow(text, slots, size, cache, tagged=tagged, plan=plan)
        if out is not None:
            return out, size
    return None
