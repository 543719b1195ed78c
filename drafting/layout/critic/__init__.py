"""The sheet critic: measures a laid-out :class:`~drafting.layout.sheet.Sheet` -- its drawing commands,
their owners, regions and scales, not the SVG text -- against what a sheet handed out unedited must be,
and returns what falls short as :class:`Finding` values.

    from drafting.layout.critic import criticise, tally
    findings = [f for sheet in sheets for f in criticise(sheet)]
    tally(findings)               # {"label-overlap": 0, "label-crossed": 3, ...}

The checks, each defined in its function's docstring:

    label-overlap     two diagram texts whose boxes share area (labels.label_overlaps)
    label-crossed     a diagram text struck by another entity's line (labels.crossed_labels)
    label-ambiguous   a label not clearly nearer its own entity than another of its kind (labels.ambiguous_labels)
    label-far         a label more than 8 mm from its own entity with no leader (labels.far_labels)
    short-arrow       a labelled arrow under 5 mm without a leader (labels.short_arrows)
    diagram-fill      a diagram filling < 60 % of its panel that a larger scale would fit (page.diagram_fill)
    blank-page        a frame more than 50 % blank (page.blank_page)
    lettering         a text's main run under 2.5 mm (page.small_lettering)
    title-cell        a title-block cell over 2 lines (page.title_cells)
"""

from __future__ import annotations

from typing import Callable, Iterable

from .labels import ambiguous_labels, crossed_labels, far_labels, label_overlaps, short_arrows
from .page import blank_fraction, blank_page, diagram_fill, small_lettering, title_cells
from .parts import Finding, owner, part

__all__ = ["CHECKS", "Finding", "criticise", "tally", "blank_fraction", "owner", "part"]

CHECKS: dict[str, Callable[..., list[Finding]]] = {
    "label-overlap": label_overlaps,
    "label-crossed": crossed_labels,
    "label-ambiguous": ambiguous_labels,
    "label-far": far_labels,
    "short-arrow": short_arrows,
    "diagram-fill": diagram_fill,
    "blank-page": blank_page,
    "lettering": small_lettering,
    "title-cell": title_cells,
}
"""Every check by its name, in the order findings are reported."""


def criticise(sheet, checks: Iterable[str] = CHECKS) -> list[Finding]:
    """The findings of ``checks`` (default: all) on one page, check by check."""
    return [f for name in checks for f in CHECKS[name](sheet)]


def tally(findings: Iterable[Finding]) -> dict[str, int]:
    """The number of findings of every check (0 for a check with none), in :data:`CHECKS` order."""
    out = dict.fromkeys(CHECKS, 0)
    for f in findings:
        out[f.check] += 1
    return out
