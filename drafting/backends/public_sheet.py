"""The sheet users hold: a page of drawing commands that shows and saves itself.

:class:`drafting.layout.sheet.Sheet` is a plain value -- paper, drawing commands and named regions -- that
knows nothing of files or SVG.  :class:`Sheet` here is the same value with the back ends at hand, the one
``study.sheets()`` hands out: ``sheet.svg()``, ``sheet.svg_inline()``, ``sheet.save("x.pdf")`` and
Jupyter's ``_repr_svg_``.  It has the layout sheet's fields, and its name, so it reads and prints as one.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from pathlib import Path

from ..layout import sheet as layout_sheet
from .files import save_sheet
from .svg import sheet_to_svg, svg_inline


@dataclass(frozen=True)
class Sheet(layout_sheet.Sheet):
    """A composed page (:class:`drafting.layout.sheet.Sheet`) that renders and saves itself."""

    @classmethod
    def of(cls, sheet: layout_sheet.Sheet) -> Sheet:
        """``sheet`` with its back ends at hand (the same fields)."""
        return cls(**{f.name: getattr(sheet, f.name) for f in fields(sheet)})

    def svg(self) -> str:
        """The page as an SVG document (true size in mm)."""
        return sheet_to_svg(self)

    def svg_inline(self, width: str = "100%") -> str:
        """The page as an SVG element that scales to ``width`` (for HTML and notebooks)."""
        return svg_inline(self, width)

    def save(self, path: Path | str, *, dpi: float | None = None) -> Path:
        """Write this page as SVG, PDF or PNG (the suffix decides), atomically; returns the Path."""
        return save_sheet(self, path, dpi=dpi)

    def _repr_svg_(self) -> str:
        return self.svg_inline()
