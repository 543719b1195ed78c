"""Who may import whom, read from the source (imports inside functions too): the engine never imports
drafting/, and drafting's drawing rooms -- render/, layout/, backends/ -- never solve: of constructions/
they import only the record and the data types it is made of (geometry, and the tolerance the drawing's
one geometric helper is given), never a solver; every number and point they draw comes from the Study's
record and results."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

DRAWING_ROOMS = {
    "render": {"constructions.entities", "constructions.geometry", "constructions.tolerance"},
    "layout": {"constructions.entities", "constructions.geometry", "constructions.record"},
    "backends": {"constructions.entities", "constructions.geometry"},
}
"""Each drawing room and exactly the constructions modules it imports."""

DATA_TYPES = {"constructions.record", "constructions.entities", "constructions.geometry", "constructions.quantities", "constructions.formatting",
              "constructions.errors", "constructions.dimensions", "constructions.tolerance"}
"""The engine's modules that hold data types and names, no solver: all a drawing room may ever import."""


def imported_modules(folder: Path) -> dict[str, set[str]]:
    """Every absolute module each .py file under ``folder`` imports, at any depth of its code."""
    out: dict[str, set[str]] = {}
    for path in sorted(folder.rglob("*.py")):
        mods: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                mods.add(node.module)
                mods |= {f"{node.module}.{a.name}" for a in node.names if node.module == "constructions"}
            elif isinstance(node, ast.Import):
                mods |= {a.name for a in node.names}
        out[str(path.relative_to(ROOT))] = mods
    return out


def test_constructions_never_imports_drafting():
    wrong = {f: sorted(m for m in mods if m == "drafting" or m.startswith("drafting."))
             for f, mods in imported_modules(ROOT / "constructions").items()}
    assert {f: m for f, m in wrong.items() if m} == {}


@pytest.mark.parametrize("room", sorted(DRAWING_ROOMS))
def test_the_drawing_rooms_import_no_solver(room):
    """A drawing room imports exactly its listed constructions modules, every one a data type."""
    assert DRAWING_ROOMS[room] <= DATA_TYPES
    by_file = imported_modules(ROOT / "drafting" / room)
    engine = {m for mods in by_file.values() for m in mods if m == "constructions" or m.startswith("constructions.")}
    assert engine == DRAWING_ROOMS[room], {f: sorted(m for m in mods if m.startswith("constructions"))
                                           for f, mods in by_file.items()}
