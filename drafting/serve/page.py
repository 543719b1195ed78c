"""The editor page of ``drafting serve``: the scene's text on the left (with its line numbers and, at the
line an error names, the error's sentence), the step-through page of its last good drawing on the right,
the results, warnings and downloads under the editor; a folder's scenes in a list above.  Its script and
style ship in ``drafting/serve/static/`` and are set inline: the page fetches nothing from elsewhere."""

from __future__ import annotations

import functools
import html
from importlib.resources import files

from ..backends.html_markup import script_json


@functools.cache
def static(name: str) -> str:
    """The text of ``drafting/serve/static/<name>``."""
    return files(__package__).joinpath("static", name).read_text(encoding="utf-8")


def editor_page(names: list[str], folder: bool) -> str:
    """The page for the served scenes ``names`` (``folder``: more may come and go; a list is shown)."""
    data = script_json({"scenes": names, "folder": folder})
    first = html.escape(names[0]) if names else "no scene"
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            f"<title>{first} - drafting serve</title><style>{static('app.css')}</style></head><body>"
            f"<div id=\"left\"><div id=\"bar\"><select id=\"scenes\" aria-label=\"Scene\""
            f"{'' if folder else ' hidden'}></select><strong id=\"name\"></strong> "
            f"<button id=\"save\" title=\"Save (Ctrl+S)\">Save</button> <span id=\"status\" aria-live=\"polite\">"
            f"</span></div><div id=\"notice\" role=\"alert\" hidden></div>"
            f"<div id=\"editor\"><pre id=\"gutter\" aria-hidden=\"true\"></pre><div id=\"mark\" hidden></div>"
            f"<textarea id=\"text\" spellcheck=\"false\" autocomplete=\"off\" aria-label=\"Scene text\"></textarea>"
            f"<div id=\"error\" role=\"alert\" hidden></div></div>"
            f"<div id=\"below\"><div id=\"downloads\"></div><ul id=\"warnings\"></ul><table id=\"results\"></table>"
            f"</div></div><div id=\"right\"><iframe id=\"view\" title=\"The sheets, step by step\"></iframe></div>"
            f"<script type=\"application/json\" id=\"serve-data\">{data}</script>"
            f"<script>{static('app.js')}</script></body></html>\n")


__all__ = ["editor_page", "static"]
