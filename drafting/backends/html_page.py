"""A self-contained HTML page per scene: the construction step by step.

The page holds the scene's sheets as inline SVG -- the same documents as the SVG files, every drawn
entity a group with the same id, class and ``data-entity`` (:mod:`drafting.backends.svg`) -- and the
steps: caption in the scene's units, equation, and the ids of what each step adds (its entities and, on
the sheet, its own words).  Previous / next (buttons, the arrow keys, or a click on a step) walk through
them: what the current step adds is drawn in colour, what earlier steps drew stays, and everything of a
later step is hidden -- its entities and their labels and values, its words on the sheet and in the list;
the results table and the notes (read off the finished construction) show with the last step.  The
title block, frames, headings, scale bars and the vector equations always show.  The sheets fit the
window's width and zoom (the buttons, ``+`` ``-`` ``0``, or Ctrl with the wheel).  ``#step=N`` opens at
step N.  No network, no external file: it opens from a file path.  ``#selftest`` walks forward and back
once and writes the outcome into the page title, so a headless browser can check the page works (the
test suite does, in Chromium).
"""

from __future__ import annotations

import html
from pathlib import Path
from typing import Callable, Sequence

from .files import ExportError
from .html_markup import asset, markup_html, script_json
from .html_sweep import sweep_section
from ..layout.formats import SheetFormatter
from ..layout.parts import Ids, entity_of, part_of
from ..layout.sections import step_text
from ..layout.sheet import Sheet
from .svg import sheet_to_svg

#: What the sheet shows only with the last step: read off the finished construction.
_AT_THE_END = frozenset(("table", "note"))
_AT_THE_END_HEADINGS = frozenset(("heading Results", "heading Notes"))


def _shown_at_the_end(sheets: Sequence[Sheet], ids: Ids) -> list[str]:
    """The ids of the sheets' results table and notes (with their headings)."""
    out: dict[str, None] = {}
    for sh in sheets:
        for c in sh.commands:
            p = part_of(c.name, sh.entities)
            if p.owner not in sh.entities and (p.kind in _AT_THE_END or p.owner in _AT_THE_END_HEADINGS):
                out[ids(p.owner)] = None
    return list(out)


def page_parts(study, sheets: Sequence[Sheet]) -> dict:
    """What changes between two drawings of one scene's page: the sheets' SVG (each in its group), the
    step list and its data (JSON), whether it has a sweep section, its title -- as :func:`page_html`
    sets them in the page (``drafting serve`` puts a redrawn scene's parts in place of the shown ones)."""
    construction = study.construction
    fmt = SheetFormatter(study.scene.units, {k: v for sh in sheets for k, v in sh.diagram_scales.items()})
    ids = Ids(sheets[0].entities if sheets else {})
    svgs = [f'<div class="sheet" role="group" aria-label="Sheet {i + 1} of {len(sheets)}">'
            f"{sheet_to_svg(sh, ids=ids)}</div>" for i, sh in enumerate(sheets)]
    steps, words = [], 0
    for st in construction.steps:
        text = step_text(st, fmt)
        own = [ids(e.name) for e in st.entities]
        if text.strip():                             # the sheet numbers the steps that have words
            words += 1
            own.append(ids(f"step {words}"))
            if getattr(st, "table", ()):             # the table the step sets out, shown with it
                own.append(ids(f"step {words} table"))
        steps.append({"caption": markup_html(text),
                      "equation": markup_html(st.equation.text(marks=False)) if st.equation else "", "ids": own})
    items = "".join(f"<li>{s['caption']}</li>" for s in steps)
    data = script_json({"steps": steps, "end": _shown_at_the_end(sheets, ids)})
    sweep = sweep_section(study)                    # None unless the scene asked for the sweep
    return {"sheets": "".join(svgs), "items": items, "data": data, "title": html.escape(study.scene.title),
            "sweep": sweep}


def page_html(study, sheets: Sequence[Sheet], parts: dict | None = None) -> str:
    """The step-through page of a solved study whose sheets are ``sheets``, as one HTML document (from
    its :func:`page_parts` when given)."""
    parts = page_parts(study, sheets) if parts is None else parts
    sweep, title, items, data = parts["sweep"], parts["title"], parts["items"], parts["data"]
    style, section = (asset("page.css"), "") if sweep is None else (asset("page.css") + asset("sweep.css"),
                                                                    sweep.html)
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>{title}</title>"
            f"<style>{style}</style></head><body>"
            f"<div id=\"sheets\" tabindex=\"0\" aria-label=\"Sheets\">{section}{parts['sheets']}</div>"
            f"<div id=\"panel\"><h3>{title}</h3><div id=\"controls\"><button id=\"prev\">&#9664; previous</button> "
            f"<span id=\"count\" aria-live=\"polite\"></span> <button id=\"next\">next &#9654;</button></div>"
            f"<div id=\"zoom\" role=\"group\" aria-label=\"Zoom\"><button id=\"zoom-out\" title=\"Zoom out (-)\" "
            f"aria-label=\"Zoom out\">&minus;</button> <button id=\"zoom-fit\" title=\"Fit the width (0)\">fit width"
            f"</button> <button id=\"zoom-in\" title=\"Zoom in (+)\" aria-label=\"Zoom in\">+</button> "
            f"<span id=\"zoom-level\" aria-live=\"polite\">100 %</span></div>"
            f"<div id=\"caption\" aria-live=\"polite\"></div><div id=\"equation\"></div><ol id=\"steps\">{items}</ol></div>"
            f"<script type=\"application/json\" id=\"steps-data\">{data}</script>"
            f"<script>{asset('page.js')}</script></body></html>\n")


def page_plan(study, sheets: Sequence[Sheet], out_dir: Path | str, stem: str) -> list[tuple[Path, Callable[[], bytes]]]:
    """The ``(final path, produce)`` pair of the page, ``out_dir/stem.html``: to go to one
    :func:`~drafting.backends.files.write_outputs` call with the sheets' own plan, so that the page and
    the sheets of one render are written together or not at all."""
    return [(Path(out_dir) / f"{stem}.html", lambda: page_html(study, sheets).encode("utf-8"))]


__all__ = ["page_html", "page_parts", "page_plan", "entity_of", "ExportError"]
