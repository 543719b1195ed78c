"""What the sheet critic reads off a :class:`~drafting.layout.sheet.Sheet`: who drew each command, the
diagrams' texts, each diagram's commands, and the findings it reports.

Every drawing command carries the name of the entity that drew it: "V_B" (the shaft), "V_B:head",
"V_B:label", "V_B:label bg", "guide C:rail:hatch".  The *owner* of a command is its name before the first
':' that is not followed by a space -- entity names may carry a namespace written "diagram: " ("links 3, 4:
P 1", "fbd link 2: h:text"), and that colon is part of the name.  What follows the owner is the
command's *part* ("label", "head", "rail:hatch"; "" for the entity's own geometry).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Sequence

from ...render.paper import Command, Rect, Text, command_points

_PART = re.compile(r":(?! )")

DIAGRAM_TEXT_PARTS = frozenset({"label", "text"})
"""The parts that are a diagram's lettering: an entity's label ("V_B:label") and a dimension's or note's
text ("h:text")."""

HEADER_PREFIXES = ("heading ", "scale bar ")
"""Names of a viewport's header: its heading and its scale bar (not the diagram's drawing)."""

PAGE_FURNITURE = frozenset({"frame", "separator"})


def owner(name: str) -> str:
    """The entity that drew a command named ``name`` (see the module docstring)."""
    return _PART.split(name, 1)[0]


def part(name: str) -> str:
    """What of its owner a command named ``name`` is ("label", "head", "" for the owner's own geometry)."""
    got = _PART.split(name, 1)
    return got[1] if len(got) > 1 else ""


@dataclass(frozen=True)
class Finding:
    """One thing the critic found on one page: which check, what (a sentence), where (a box, paper mm from
    the sheet's top-left corner, y down) and the figure measured (a length in mm, a ratio, a count)."""

    check: str
    page: tuple[int, int]
    what: str
    where: Rect
    value: float

    def line(self, source: str = "") -> str:
        """The finding in one line: ``source sheet n/m: check: what at (x, y) w x h mm``."""
        w = self.where
        head = f"{source} " if source else ""
        return (f"{head}sheet {self.page[0]}/{self.page[1]}: {self.check}: {self.what} "
                f"at ({w.x:.1f}, {w.y:.1f}) {w.w:.1f} x {w.h:.1f} mm")

    def to_json(self) -> dict:
        return {"check": self.check, "page": list(self.page), "what": self.what, "value": round(self.value, 4),
                "where_mm": [round(v, 2) for v in self.where]}


def diagram_texts(commands: Sequence[Command]) -> list[Text]:
    """The diagrams' labels, dimension texts and notes: texts in a viewport whose part is "label" or
    "text" (headings, scale-bar numbers and the text blocks are not)."""
    return [c for c in commands if type(c) is Text and c.region.startswith("viewport:")
            and part(c.name) in DIAGRAM_TEXT_PARTS]


def viewport_keys(regions) -> list[str]:
    """The keys of the page's viewports ("space", "velocity", "force: links 3, 4"), in region order."""
    return [r[len("viewport:"):] for r in regions if r.startswith("viewport:")]


def viewport_commands(commands: Sequence[Command], rect: Rect) -> tuple[list[Command], list[Command]]:
    """The commands of the viewport ``rect``: (its header, its drawing) -- every command lying within the
    rectangle (a text by its box), page furniture (frame, separators) left out."""
    header, drawing = [], []
    for c in commands:
        if c.name in PAGE_FURNITURE or not _within(c, rect):
            continue
        (header if c.name.startswith(HEADER_PREFIXES) else drawing).append(c)
    return header, drawing


def _within(c: Command, rect: Rect) -> bool:
    return all(rect.contains_point(x, y, 0.01) for x, y in command_points(c))
