"""What a solved study becomes on paper: its worked-solution sheets, and the built-in example scene.

Takes a :class:`~drafting.study.study.Study` without importing it: the study hands itself here
(``Study.sheets``), so the two modules do not import each other."""

from __future__ import annotations

from pathlib import Path


def builtin_example() -> Path:
    """The scene ``drafting`` renders with no arguments: the notes' velocity Example 1, a file of the
    package (found beside its modules, as importlib.resources finds it in an installed package, without
    loading importlib.resources and zipfile: ~3 ms of a cold ``drafting``)."""
    return Path(__file__).parents[1] / "app" / "examples" / "notes-velocity-example-1.toml"


def sheets_for(study):
    """The sheets of a solved study: one, or as many pages as its diagrams need to stay legible."""
    from constructions.forces.dalembert import off_sheet
    from ..backends.public_sheet import Sheet
    from ..layout.sheet import ResultRow, SheetInfo, compose_sheets, sheet_date
    s = study.scene
    info = SheetInfo(title=s.title, drawing_number=s.drawing_number, paper=s.paper, orientation=s.orientation,
                     date=sheet_date(), units=s.units, notes=study.notes + study.warnings, scales=s.scales)
    rows = [ResultRow(q, g, a, d) for (q, g, a, d), c in zip(study.table().text, study.comparisons)
            if not off_sheet(c.name)]
    return tuple(Sheet.of(page) for page in compose_sheets(study.construction, info, rows))


def sheet_for(study):
    """The first sheet of a study (callers that want one page)."""
    return sheets_for(study)[0]
