"""A scene's text as the browser sends it -> its step-through page, or its one error sentence placed at the
line and key it names.

The text goes through the CLI's own path: :func:`drafting.scene.reader.parse_scene` (the size and nesting
limits first, then TOML, then the family's reader -- nothing in it is ever evaluated) and
:func:`drafting.app.solving.solve_study`.  A good scene gives a :class:`Drawn` (its page from
:func:`drafting.backends.html_page.page_html`, its sheets for the downloads, its warnings); a bad one a
:class:`Failed` with the sentence, the key and the 1-based line of the text it names (``line N`` in the
sentence, else the line where the key is set, else none).
"""

from __future__ import annotations

import functools
import re
import threading
from dataclasses import dataclass, field
from pathlib import Path

from ..app.solving import UserError, solve_study
from ..backends.cairo import sheet_to_png, sheets_to_pdf
from ..backends.files import PNG_DPI
from ..backends.html_page import page_html, page_parts
from ..backends.svg import sheet_to_svg
from ..render.errors import LayoutError
from ..scene.reader import SceneError, parse_scene
from ..study.study import Study
from ..scene.textsafe import shown_path

_LOCK = threading.Lock()        # one solve at a time: the app's threads share the engine's caches


@dataclass(frozen=True)
class Failed:
    error: str
    key: str = ""
    line: int | None = None


@dataclass
class Drawn:
    study: Study
    sheets: list
    whole: dict                     # the page's parts (html_page.page_parts)
    warnings: tuple[str, ...]
    results: list = field(default_factory=list)

    @property
    def parts(self) -> dict | None:
        """What a shown page of the scene takes in place; None for a page with a sweep (loaded anew)."""
        return None if self.whole["sweep"] is not None else {k: v for k, v in self.whole.items() if k != "sweep"}

    @functools.cached_property
    def page(self) -> str:
        """The whole step-through page, made when first asked for (a redraw in place never asks)."""
        with _LOCK:                 # (the engine's caches, as in draw)
            return page_html(self.study, self.sheets, self.whole)

    def download(self, fmt: str, index: int = 0) -> bytes:
        """The sheets as ``svg`` or ``png`` (sheet ``index``) or ``pdf`` (every sheet, one page each)."""
        if fmt == "pdf":
            return sheets_to_pdf(self.sheets)
        sheet = self.sheets[index]
        return sheet_to_svg(sheet).encode("utf-8") if fmt == "svg" else sheet_to_png(sheet, PNG_DPI)


def draw(text: str, path: Path | str) -> Drawn | Failed:
    """The scene ``text`` (its errors named as the file ``path``'s) drawn, or why it cannot be."""
    try:
        with _LOCK:
            try:
                scene = parse_scene(text, path)
            except SceneError as e:
                return Failed(str(e), e.key, line_of(text, str(e), e.key))
            study = solve_study(Study(scene))
            sheets = study.sheets()
            return Drawn(study, sheets, page_parts(study, sheets), tuple(study.warnings), study.table().text)
    except UserError as e:
        return Failed(str(e), "", line_of(text, str(e), ""))
    except LayoutError as e:
        return Failed(f"{shown_path(path)}: drawing.paper: {e}", "drawing.paper", line_of(text, "", "drawing.paper"))


_LINE = re.compile(r"\bline (\d+)\b")


def line_of(text: str, message: str, key: str) -> int | None:
    """The line the error is about: the one its sentence names, else where ``key`` is set in ``text``
    (``link[1].length``: the ``length =`` under the second ``[[link]]``; ``a.b``: the ``b =`` under
    ``[a]``), else the first line that sets the key's last name."""
    lines = text.splitlines()
    m = _LINE.search(message)
    if m and 1 <= int(m.group(1)) <= max(len(lines), 1):
        return int(m.group(1))
    parts = re.findall(r"([^.\[\]]+)(?:\[(\d+)\])?", key)
    if not parts:
        return None
    (table, index), leaf = parts[0], parts[-1][0].strip('"')
    setting = re.compile(rf'^\s*"?{re.escape(leaf)}"?\s*=')
    header = re.compile(r"^\s*\[\[?\s*([^\]]+?)\s*\]\]?")
    seen: dict[str, int] = {}
    head, fallback = "", None
    for i, ln in enumerate(lines, 1):
        h = header.match(ln)
        if h:
            head = h.group(1)
            seen[head] = seen.get(head, -1) + 1
            if len(parts) == 1 and head == table and seen[head] == int(index or 0):
                return i
            continue
        if setting.match(ln):
            fallback = fallback or i
            if len(parts) > 1 and head == table and seen.get(head, 0) == int(index or 0):
                return i
    return fallback


__all__ = ["draw", "Drawn", "Failed", "line_of"]
