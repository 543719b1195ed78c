"""What the step-through page and its sweep card share: a step's words as HTML, JSON that is safe inside a
``<script>`` element, and the pages' style sheets and scripts, kept as package data files beside this
module (``drafting/backends/html/*.css``, ``*.js``) and read with :mod:`importlib.resources`.
"""

from __future__ import annotations

import functools
import html
import json
from importlib.resources import files

from ..render.style import rich

def markup_html(text: str) -> str:
    """A step's words as HTML, set as the sheet sets them (:func:`~drafting.render.style.rich`): escaped,
    the notes' V_CB and A_CB^t, O4 and F14 with their sub- and superscripts, b' with its prime."""
    out = []
    for s in rich(text, 1.0):
        t = html.escape(s.text)
        out.append(f"<sub>{t}</sub>" if s.shift > 0 else f"<sup>{t}</sup>" if s.shift < 0 else t)
    return "".join(out)


def script_json(data, **options) -> str:
    """``data`` as JSON for a ``<script type="application/json">`` element: no ``</`` that could close it."""
    return json.dumps(data, ensure_ascii=False, **options).replace("</", "<\\/")


@functools.cache
def asset(name: str) -> str:
    """The text of ``drafting/backends/html/<name>`` (a style sheet or a script), on a line of its own
    where the page sets it inside its ``<style>`` or ``<script>`` element."""
    return "\n" + files(__package__).joinpath("html", name).read_text(encoding="utf-8")


__all__ = ["markup_html", "script_json", "asset"]
