"""What the step-through page and its sweep card share: a step's words as HTML, JSON that is safe inside a
``<script>`` element, and the pages' style sheets and scripts, kept as package data files beside this
module (``drafting/backends/html/*.css``, ``*.js``) and read with :mod:`importlib.resources`.
"""

from __future__ import annotations

import functools
import html
import json
import re
from importlib.resources import files

_SUB = re.compile(r"_(\{[^}]*\}|[A-Za-z0-9]+)")
_SUP = re.compile(r"\^(\{[^}]*\}|[A-Za-z0-9]+)")


def markup_html(text: str) -> str:
    """A step's words as HTML: escaped, the notes' V_CB and A_CB^t written as sub- and superscripts."""
    def part(tag):
        return lambda m: f"<{tag}>{m.group(1).strip('{}')}</{tag}>"
    return _SUP.sub(part("sup"), _SUB.sub(part("sub"), html.escape(text)))


def script_json(data, **options) -> str:
    """``data`` as JSON for a ``<script type="application/json">`` element: no ``</`` that could close it."""
    return json.dumps(data, ensure_ascii=False, **options).replace("</", "<\\/")


@functools.cache
def asset(name: str) -> str:
    """The text of ``drafting/backends/html/<name>`` (a style sheet or a script), on a line of its own
    where the page sets it inside its ``<style>`` or ``<script>`` element."""
    return "\n" + files(__package__).joinpath("html", name).read_text(encoding="utf-8")


__all__ = ["markup_html", "script_json", "asset"]
