"""A self-contained HTML page per scene: the construction step by step.

The page holds the scene's sheets as inline SVG, every drawn element tagged with the entity it draws
(``data-e``), and the steps (caption in the scene's units, equation, the entities each adds).  Previous /
next (buttons, the arrow keys, or a click on a step) walk through them: what the current step adds is
highlighted, what earlier steps drew stays, what later steps draw is hidden; the title block, frames and
scale bars always show.  ``#step=N`` opens at step N.  No network, no external file: it opens from a
file path.  ``#selftest`` walks forward and back once and writes the outcome into the page title, so a
headless browser can check the page works (the test suite does, in Chromium).
"""

from __future__ import annotations

import html
from pathlib import Path
from typing import Callable, Sequence

from .files import ExportError
from .html_markup import asset, markup_html, script_json
from .html_sweep import sweep_section
from ..render.paper import Command
from ..layout.formats import SheetFormatter
from ..layout.sheet import Sheet, step_text
from .svg import sheet_to_svg


def entity_of(command_name: str, names: set[str]) -> str | None:
    """The entity a drawing command draws: its name is the entity's, or the entity's followed by ':'."""
    if command_name in names:
        return command_name
    head = command_name
    while ":" in head:
        head = head.rsplit(":", 1)[0]
        if head in names:
            return head
    return None


def page_html(study, sheets: Sequence[Sheet]) -> str:
    """The step-through page of a solved study whose sheets are ``sheets``, as one HTML document."""
    construction = study.construction
    fmt = SheetFormatter(study.scene.units, {k: v for sh in sheets for k, v in sh.diagram_scales.items()})
    steps = [{"caption": markup_html(step_text(st, fmt)),
              "equation": markup_html(st.equation.text(marks=False)) if st.equation else "",
              "entities": [e.name for e in st.entities]} for st in construction.steps]
    names = {e for st in steps for e in st["entities"]}

    def attrs(c: Command) -> dict[str, str]:
        e = entity_of(c.name, names)
        return {"data-e": e} if e is not None else {}
    svgs = [sheet_to_svg(sh, attrs) for sh in sheets]
    items = "".join(f"<li>{s['caption']}</li>" for s in steps)
    data = script_json(steps)
    title = html.escape(study.scene.title)
    sweep = sweep_section(study)                    # None unless the scene asked for the sweep
    style, section = (asset("page.css"), "") if sweep is None else (asset("page.css") + asset("sweep.css"),
                                                                    sweep.html)
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{title}</title>"
            f"<style>{style}</style></head><body>"
            f"<div id=\"sheets\">{section}{''.join(svgs)}</div>"
            f"<div id=\"panel\"><h3>{title}</h3><div id=\"controls\"><button id=\"prev\">&#9664; previous</button> "
            f"<span id=\"count\"></span> <button id=\"next\">next &#9654;</button></div>"
            f"<div id=\"caption\"></div><div id=\"equation\"></div><ol id=\"steps\">{items}</ol></div>"
            f"<script type=\"application/json\" id=\"steps-data\">{data}</script>"
            f"<script>{asset('page.js')}</script></body></html>\n")


def page_plan(study, sheets: Sequence[Sheet], out_dir: Path | str, stem: str) -> list[tuple[Path, Callable[[], bytes]]]:
    """The ``(final path, produce)`` pair of the page, ``out_dir/stem.html``: to go to one
    :func:`~drafting.backends.files.write_outputs` call with the sheets' own plan, so that the page and
    the sheets of one render are written together or not at all."""
    return [(Path(out_dir) / f"{stem}.html", lambda: page_html(study, sheets).encode("utf-8"))]


__all__ = ["page_html", "page_plan", "entity_of", "ExportError"]
