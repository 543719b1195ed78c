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
import json
import re
from pathlib import Path

from .files import ExportError, prepare_folder, write_outputs
from ..render.paper import Command
from ..layout.sheet import step_text
from .svg import sheet_to_svg

STYLE = """
body { margin: 0; font-family: "DejaVu Sans", sans-serif; display: flex; height: 100vh; }
#sheets { flex: 3; overflow: auto; background: #eee; padding: 8px; }
#sheets svg { width: 100%; height: auto; background: white; margin-bottom: 8px; box-shadow: 0 0 3px #999; }
#panel { flex: 1; min-width: 320px; overflow: auto; padding: 12px; border-left: 1px solid #ccc; }
#controls button { font-size: 16px; padding: 4px 14px; }
#caption { font-size: 15px; margin: 12px 0; min-height: 3em; }
#equation { font-family: "DejaVu Sans Mono", monospace; margin-bottom: 12px; }
#steps li { cursor: pointer; margin: 2px 0; color: #666; }
#steps li.done { color: #000; }
#steps li.current { color: #c00; font-weight: bold; }
[data-e].todo { visibility: hidden; }
[data-e].current { stroke: #d00 !important; fill-opacity: 1; }
text[data-e].current { fill: #d00 !important; stroke: none !important; }
"""

SCRIPT = """
const STEPS = JSON.parse(document.getElementById('steps-data').textContent);
const first = {};
STEPS.forEach((s, i) => s.entities.forEach(e => { if (!(e in first)) first[e] = i; }));
const tagged = Array.from(document.querySelectorAll('[data-e]'));
let cur = 0;
function show(i) {
  cur = Math.max(0, Math.min(STEPS.length - 1, i));
  for (const el of tagged) {
    const k = first[el.getAttribute('data-e')];
    el.classList.toggle('todo', k !== undefined && k > cur);
    el.classList.toggle('current', k === cur);
  }
  document.querySelectorAll('#steps li').forEach((li, j) => {
    li.classList.toggle('current', j === cur);
    li.classList.toggle('done', j < cur);
  });
  document.getElementById('caption').innerHTML = (cur + 1) + '. ' + STEPS[cur].caption;   // escaped in Python
  document.getElementById('equation').innerHTML = STEPS[cur].equation || '';
  document.getElementById('count').textContent = (cur + 1) + ' / ' + STEPS.length;
  if (!location.hash.includes('selftest')) history.replaceState(null, '', '#step=' + (cur + 1));
}
function next() { show(cur + 1); }
function prev() { show(cur - 1); }
document.getElementById('next').onclick = next;
document.getElementById('prev').onclick = prev;
document.addEventListener('keydown', e => { if (e.key === 'ArrowRight') next(); if (e.key === 'ArrowLeft') prev(); });
document.querySelectorAll('#steps li').forEach((li, j) => li.onclick = () => show(j));
const m = location.hash.match(/step=(\\d+)/);
show(m ? parseInt(m[1], 10) - 1 : 0);
if (location.hash.includes('selftest')) {
  const target = m ? parseInt(m[1], 10) - 1 : 0;
  next(); next(); prev();
  const lit = document.querySelectorAll('[data-e].current').length;
  const hidden = document.querySelectorAll('[data-e].todo').length;
  const ok = cur === Math.min(target + 1, STEPS.length - 1);
  document.title = 'selftest ' + (ok ? 'ok' : 'FAILED') + ' step=' + (cur + 1) + ' lit=' + lit + ' hidden=' + hidden;
}
"""


_SUB = re.compile(r"_(\{[^}]*\}|[A-Za-z0-9]+)")
_SUP = re.compile(r"\^(\{[^}]*\}|[A-Za-z0-9]+)")


def markup_html(text: str) -> str:
    """A step's words as HTML: escaped, the notes' V_CB and A_CB^t written as sub- and superscripts."""
    def part(tag):
        return lambda m: f"<{tag}>{m.group(1).strip('{}')}</{tag}>"
    return _SUP.sub(part("sup"), _SUB.sub(part("sub"), html.escape(text)))


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


def page_html(study) -> str:
    """The step-through page of a solved study, as one HTML document."""
    from ..layout.formats import SheetFormatter
    from ..study.worked import sheets_for
    construction = study.construction
    sheets = sheets_for(study)
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
    data = json.dumps(steps, ensure_ascii=False).replace("</", "<\\/")
    title = html.escape(study.scene.title)
    from .html_sweep import STYLE as SWEEP_STYLE, sweep_section
    sweep = sweep_section(study)                    # None unless the scene asked for the sweep
    style, section = (STYLE, "") if sweep is None else (STYLE + SWEEP_STYLE, sweep.html)
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{title}</title>"
            f"<style>{style}</style></head><body>"
            f"<div id=\"sheets\">{section}{''.join(svgs)}</div>"
            f"<div id=\"panel\"><h3>{title}</h3><div id=\"controls\"><button id=\"prev\">&#9664; previous</button> "
            f"<span id=\"count\"></span> <button id=\"next\">next &#9654;</button></div>"
            f"<div id=\"caption\"></div><div id=\"equation\"></div><ol id=\"steps\">{items}</ol></div>"
            f"<script type=\"application/json\" id=\"steps-data\">{data}</script>"
            f"<script>{SCRIPT}</script></body></html>\n")


def write_page(study, out_dir: Path | str, stem: str) -> Path:
    """Write ``out_dir/stem.html`` atomically; raises ExportError naming the path."""
    out_dir = Path(out_dir)
    prepare_folder(out_dir)
    final = out_dir / f"{stem}.html"
    (written,) = write_outputs(out_dir, stem, [(final, lambda: page_html(study).encode("utf-8"))])
    return written


__all__ = ["page_html", "write_page", "entity_of", "ExportError"]
