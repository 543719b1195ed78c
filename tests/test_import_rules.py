"""Who may import whom, read from the source (imports inside functions too): the engine never imports
drafting/, and drafting never solves -- only study/ and families/ call the engine's solvers.  The drawing
rooms (render/, layout/, backends/) import of constructions/ only the record and the data types it is made
of (geometry, and the tolerance the drawing's one geometric helper is given); scene/ the model's data types
it reads a scene into; app/ the errors and values it reports (and the sweep's thread setting, one thread in
its pool workers).  Every number and point they draw or print
comes from the Study's record and results.  And drafting's rooms import only down their floors
(render < scene < layout < backends < study < families < app = serve)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

ROOM_IMPORTS = {
    "render": {"constructions.entities", "constructions.geometry", "constructions.tolerance"},
    "layout": {"constructions.entities", "constructions.geometry", "constructions.record"},
    "backends": {"constructions.entities", "constructions.geometry"},
    "scene": {"constructions.forces.effects", "constructions.forces.inertia", "constructions.geometry",
              "constructions.mechanisms.model"},
    "app": {"constructions.entities", "constructions.errors", "constructions.geometry", "constructions.quantities",
            "constructions.record", "constructions.sweep_threads"},
    "serve": set(),
}
"""Each room that does not solve and exactly the constructions modules it imports."""

SOLVING_ROOMS = {"study", "families"}
"""The rooms that run the engine's analyses."""

BENCH_HARNESS = {"drafting/app/bench_sweep.py": {"constructions.geometry", "constructions.mechanisms.model",
                                                 "constructions.sweep_kernels"}}
"""``drafting bench`` times the engine's own sweep kernels: the one file outside the solving rooms that calls
a solver, to time it, drawing nothing."""

DATA_TYPES = {"constructions.record", "constructions.entities", "constructions.forces.effects",
              "constructions.forces.inertia", "constructions.mechanisms.model", "constructions.geometry", "constructions.quantities", "constructions.formatting",
              "constructions.errors", "constructions.dimensions", "constructions.tolerance",
              "constructions.sweep_threads"}
"""The engine's modules that hold data types and names, no solver: all a drawing room may ever import (and
the sweep's thread setting, the standard library only)."""


def imported_modules(folder: Path) -> dict[str, set[str]]:
    """Every absolute module each .py file under ``folder`` imports, at any depth of its code."""
    out: dict[str, set[str]] = {}
    for path in sorted(folder.rglob("*.py")):
        mods: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                package = ROOT.joinpath(*node.module.split("."))
                submodules = {f"{node.module}.{a.name}" for a in node.names
                              if (package / f"{a.name}.py").exists() or (package / a.name).is_dir()}
                mods |= submodules or {node.module}
            elif isinstance(node, ast.Import):
                mods |= {a.name for a in node.names}
        out[str(path.relative_to(ROOT))] = mods
    return out


def test_constructions_never_imports_drafting():
    wrong = {f: sorted(m for m in mods if m == "drafting" or m.startswith("drafting."))
             for f, mods in imported_modules(ROOT / "constructions").items()}
    assert {f: m for f, m in wrong.items() if m} == {}


def _engine(mods: set[str]) -> set[str]:
    return {m for m in mods if m == "constructions" or m.startswith("constructions.")}


@pytest.mark.parametrize("room", sorted(ROOM_IMPORTS))
def test_the_rooms_that_do_not_solve_import_no_solver(room):
    """A room outside study/ and families/ imports exactly its listed constructions modules, every one a
    data type (the bench harness apart)."""
    assert ROOM_IMPORTS[room] <= DATA_TYPES
    by_file = {f: mods for f, mods in imported_modules(ROOT / "drafting" / room).items() if f not in BENCH_HARNESS}
    engine = {m for mods in by_file.values() for m in _engine(mods)}
    assert engine == ROOM_IMPORTS[room], {f: sorted(_engine(mods)) for f, mods in by_file.items() if _engine(mods)}


def test_every_room_is_ruled_and_the_top_imports_no_engine():
    """Each folder of drafting/ is a ruled room; api.py and entry.py reach the engine only through them;
    the bench harness imports what it is listed with."""
    rooms = {p.name for p in (ROOT / "drafting").iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    assert rooms == set(ROOM_IMPORTS) | SOLVING_ROOMS
    top = {f: _engine(m) for f, m in imported_modules(ROOT / "drafting").items() if f.count("/") == 1}
    assert {f: m for f, m in top.items() if m} == {}
    harness = imported_modules(ROOT / "drafting" / "app")
    assert {f: _engine(harness[f]) for f in BENCH_HARNESS} == BENCH_HARNESS


FLOORS = {"render": 0, "scene": 1, "layout": 2, "backends": 3, "study": 4, "families": 5, "app": 6, "serve": 6}
"""drafting's rooms, lowest first: a module imports from its own room or a lower one (api.py and entry.py,
on top, from any).  The one exception is families/registry.py, which imports nothing and which scene/
(reading a scene's kind) and study/ (its analyses) look families up in."""


def test_the_rooms_import_down_the_floors_only():
    top = max(FLOORS.values()) + 1
    upward = []
    for path in sorted((ROOT / "drafting").rglob("*.py")):
        parts = path.relative_to(ROOT).with_suffix("").parts
        room = FLOORS.get(parts[1], top) if len(parts) > 2 else top
        package = parts[:-1]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level:
                base = package[: len(package) - node.level + 1] + tuple((node.module or "").split(".") if node.module else ())
                targets = [base] if node.module else [base + (a.name,) for a in node.names]
            elif isinstance(node, (ast.Import, ast.ImportFrom)):
                names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""]
                targets = [tuple(n.split(".")) for n in names]
            else:
                continue
            for t in targets:
                if t[0] != "drafting" or len(t) < 2 or t[:3] == ("drafting", "families", "registry"):
                    continue
                if FLOORS.get(t[1], top) > room:
                    upward.append(f"{'/'.join(parts)} -> {'.'.join(t)}")
    assert upward == []
