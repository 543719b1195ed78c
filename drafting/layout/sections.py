"""The text of a sheet: the sections a construction's record is set in -- the given data, the vector
equations with their known/unknown marks, the numbered steps (a step's table under its words), the
results table and the notes -- each step's values written by the sheet's formatter."""

from __future__ import annotations

from typing import Sequence

from constructions.entities import ScaleBar
from constructions.record import Construction, Step

from .formats import SheetFormatter
from .items import MARK_NO, MARK_YES, EquationItem, Item, Paragraph, Section, TableItem

__all__ = ["text_sections", "step_formatter", "step_text"]


def step_formatter(fmt: SheetFormatter, step: Step) -> SheetFormatter:
    """The formatter of one step: its scale and paper-length values prefer the step's own diagrams."""
    keys = tuple(e.diagram.key for e in step.entities if isinstance(e, ScaleBar)) + \
        tuple(dict.fromkeys(e.diagram.key for e in step.entities))
    return fmt.preferring(keys) if keys else fmt


def step_text(step: Step, fmt: SheetFormatter) -> str:
    """A step's words with its values written by ``fmt`` (a step with no values is its words)."""
    words = getattr(step, "words", None)
    if words is None:                                  # a record without values apart
        return step.caption
    if not step.values:
        return words
    return step.text(step_formatter(fmt, step))


def text_sections(construction: Construction, results: Sequence, notes: Sequence[str],
              fmt: SheetFormatter, given: Sequence[str] = ()) -> list[Section]:
    secs: list[Section] = []
    if given:
        secs.append(Section("Given", tuple(
            Paragraph(t, label="\u2013", label_chars="\u2013", name=f"given {i + 1}") for i, t in enumerate(given))))
    eqs = construction.equations
    if eqs:
        items: list[Item] = [EquationItem(eq, name=f"equation {i + 1}") for i, eq in enumerate(eqs)]
        items.append(Paragraph(f"Marks over each vector: magnitude, then direction; "
                                 f"{MARK_YES} known, {MARK_NO} unknown.", name="equation legend"))
        secs.append(Section("Vector equations", tuple(items)))
    steps = [(t, s) for t, s in ((step_text(s, fmt).strip(), s) for s in construction.steps) if t]
    if steps:
        n = len(steps)
        items = []
        for i, (t, s) in enumerate(steps):
            table = getattr(s, "table_text", None) if getattr(s, "table", None) else None
            items.append(Paragraph(t, label=f"{i + 1}.", label_chars=f"{n}.", name=f"step {i + 1}",
                                   keep_with_next=table is not None))
            if table is not None:                            # the table the step sets out, under its words
                head, *rows = table(step_formatter(fmt, s))
                items.append(TableItem(head, tuple(rows), ("l",) + ("r",) * (len(head) - 1),
                                       name=f"step {i + 1} table"))
        secs.append(Section("Construction", tuple(items)))
    if results:
        has_note = any(r.note for r in results)
        header = ("Quantity", "Graphical", "Analytic", "Difference", "Note")
        rows = [(r.quantity, r.graphical, r.analytic, r.difference, r.note) for r in results]
        align = ("l", "r", "r", "r", "l")
        # a column with nothing in it is not printed (a problem sheet leaves only the answer's column)
        keep = [i for i in range(5) if i == 0 or any(row[i] for row in rows)]
        secs.append(Section("Results", (TableItem(
            tuple(header[i] for i in keep), tuple(tuple(row[i] for i in keep) for row in rows),
            tuple(align[i] for i in keep), wrap_last=has_note),)))
    if notes:
        secs.append(Section("Notes", tuple(
            Paragraph(t, label="\u2013", label_chars="\u2013", name=f"note {i + 1}") for i, t in enumerate(notes))))
    return secs
