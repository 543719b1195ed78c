"""A lazy study of one scene: only the analyses the scene asks for (and what they need) are ever built.

The analyses come from the scene's family (:mod:`drafting.families.registry`) as a dependency chain: asking for
"acceleration" runs "position" and "velocity" first; asking for "velocity" builds nothing for
accelerations.  ``Study.ran`` lists what has been computed so far (e.g. "position", "velocity",
"analytic check"); the JSON output carries it, so a test can see what a scene cost.
"""

from __future__ import annotations

from functools import cached_property
from typing import Any, Mapping

from constructions.check import Comparison, compare
from constructions.geometry import Vec
from constructions.quantities import key as quantity_key
from constructions.record import Construction

from ..families.registry import Family, family
from ..scene.reader import Scene, SceneError
from .results import Result
from .table import CSV_HEADER, Table, difference_text, display_name, json_values, value_text

__all__ = ["Study", "results_csv", "display_name", "CSV_HEADER"]


class Study:
    """The lazy study of ``scene``.  ``options`` are what a caller hands an analysis beyond the scene (the
    crank angles and progress callback of ``drafting sweep``: :attr:`Family.sweeps`)."""

    def __init__(self, scene: Scene, options: Mapping[str, Any] | None = None) -> None:
        self.scene = scene
        self.family: Family = family(scene.kind)
        self.options: Mapping[str, Any] = dict(options or {})
        self.ran: list[str] = []
        self._results: dict[str, Any] = {}

    # -- the registry ---------------------------------------------------------------------------------
    @cached_property
    def needed(self) -> tuple[str, ...]:
        """The analyses the scene asks for and everything they require, in dependency order."""
        out: list[str] = []

        def visit(name: str) -> None:
            for r in self.family.analyses[name].requires:
                visit(r)
            if name not in out:
                out.append(name)
        for a in self.scene.analyses:
            visit(a)
        return tuple(out)

    def asked(self, name: str) -> bool:
        return name in self.needed

    def get(self, name: str) -> Any:
        """The result of analysis ``name``, computed (with what it requires) on first use."""
        if name in self._results:
            return self._results[name]
        a = self.family.analyses[name]
        for r in a.requires:
            self.get(r)
        result = a.run(self)
        self._results[name] = result
        label = a.label or a.name
        if label not in self.ran:
            self.ran.append(label)
        return result

    def computed(self, name: str) -> Any:
        """The result of ``name`` if it has been computed so far -- asked for, or needed by an analysis
        that decided at run time (a force analysis asks for accelerations only when bodies have mass)."""
        if self.asked(name):
            return self.get(name)
        return self._results.get(name)

    def result(self, name: str) -> Any:
        """The result of ``name`` if the scene calls for it, else None (nothing is computed)."""
        return self.get(name) if self.asked(name) else None

    def __getattr__(self, name: str) -> Any:
        # study.position / study.velocity / study.acceleration ...: the family's analyses by name
        fam = self.__dict__.get("family")
        if fam is not None and name in fam.analyses:
            return self.result(name)
        raise AttributeError(name)

    def check(self) -> "Study":
        """Run the family's checks of the scene (:attr:`Family.checks`): SceneError where it is wrong."""
        for name in self.family.checks:
            self.get(name)
        return self

    def run(self) -> "Study":
        """Run every analysis the scene calls for, the family's checks first (errors propagate as
        SceneError or ConstructionError)."""
        self.check()
        for name in self.needed:
            self.get(name)
        self.comparisons
        return self

    # -- what every family offers -----------------------------------------------------------------------
    @property
    def construction(self) -> Construction:
        return self.family.construction(self)

    @property
    def warnings(self) -> tuple[str, ...]:
        return self.family.warnings(self)

    @property
    def notes(self) -> tuple[str, ...]:
        """What the family says about the scene besides its warnings (e.g. the linkage's class)."""
        return self.family.notes(self)

    @cached_property
    def comparisons(self) -> list[Comparison]:
        measured = self.family.measured(self)
        if not measured:
            return []
        rows = compare(measured, self.family.analytic(self), self.family.scales(self))
        if self.scene.find is not None:
            have = {quantity_key(r.name) for r in rows}
            unknown = [f for f in self.scene.find if quantity_key(f) not in have]
            if unknown:
                names = ", ".join(display_name(r.name) for r in rows[:24]) + (", ..." if len(rows) > 24 else "")
                raise SceneError(self.scene.path, "ask.find", f"{unknown[0]!r} is not a quantity this scene "
                                                              f"measures; it measures {names}")
            wanted = {quantity_key(f) for f in self.scene.find}
            rows = [r for r in rows if quantity_key(r.name) in wanted]
        return rows

    @property
    def model(self) -> str | None:
        """The analytic model the results were checked against, or None."""
        return self.family.model_name(self)

    @property
    def results(self) -> dict[str, Result]:
        """Every compared quantity by name ("V_C", "omega_2", "F_32"): ``.graphical`` read off the
        construction, ``.analytic``, ``.difference``, ``.agrees`` (SI values; vectors as Vec, rates CCW
        positive), each convertible: ``.graphical.to("mm/s")``, ``.graphical.in_scene_units()``
        (:mod:`drafting.study.results`).  :meth:`table` has the same rows in the scene's units."""
        return {c.name: Result(c, self.scene.units) for c in self.comparisons}

    def sheets(self) -> list:
        """The worked sheets (:class:`~drafting.backends.public_sheet.Sheet`, one per page): ``sheet.save("x.pdf")``."""
        from .worked import sheets_for
        return list(sheets_for(self))

    def _repr_html_(self) -> str:
        """Jupyter: the title, the results table in the scene's units and the first sheet, inline."""
        from html import escape
        rows = "".join(f"<tr><td>{escape(q)}</td><td>{escape(g)}</td><td>{escape(a)}</td><td>{escape(d)}</td></tr>"
                       for q, g, a, d in self.table().text)
        head = "<tr><th>quantity</th><th>graphical</th><th>analytic</th><th>difference</th></tr>"
        table = f"<table>{head}{rows}</table>" if rows else ""
        words = "".join(f"<li>{escape(w)}</li>" for w in self.notes + self.warnings)
        sheets = self.sheets()
        more = f"<p>{len(sheets)} sheets; the first:</p>" if len(sheets) > 1 else ""
        return (f"<div><h4>{escape(self.scene.title)}</h4>{table}"
                + (f"<ul>{words}</ul>" if words else "") + more + sheets[0].svg_inline() + "</div>")

    def disagreements(self) -> list[Comparison]:
        return [c for c in self.comparisons if c.agrees is False]

    # -- presentation of values in the scene's units -------------------------------------------------
    def value_text(self, c: Comparison, value: Vec | float | None) -> str:
        return value_text(self.scene.units, c, value)

    def difference_text(self, c: Comparison) -> str:
        return difference_text(self.scene.units, c)

    def table(self) -> Table:
        """The results in the scene's units: named :class:`~drafting.study.table.Row` s of numbers (``.rows``),
        ``print``-able, ``.to_csv()``, ``.records()``; ``.text`` the sheet's own cells."""
        return Table.of(self.scene.units, self.comparisons)

    def to_json(self) -> dict[str, Any]:
        """Machine-readable results in the scene's units, and the list of analyses that ran."""
        u = self.scene.units
        out: dict[str, Any] = {"scene": str(self.scene.path), "kind": self.scene.kind, "title": self.scene.title,
                               "units": u.as_dict(),
                               "units_note": "values are in the scene's units (units); each check row gives its "
                                             "unit and, under si, the same values in SI"}
        out.update(self.family.json(self))
        if self.comparisons:
            out["check"] = {
                "model": self.model,
                "tolerance_relative": min(c.tolerance for c in self.comparisons),
                "agrees": (not self.disagreements()) if self.model else None,
                "rows": [{"quantity": c.name, "relative_difference": c.relative, "tolerance": c.tolerance,
                          "agrees": c.agrees, **json_values(u, c)} for c in self.comparisons]}
        out["notes"] = list(self.notes)
        out["warnings"] = list(self.warnings)
        out["analyses"] = list(self.ran)
        return out


def results_csv(study: "Study") -> str:
    """The results table as CSV in the scene's units (:meth:`~drafting.study.table.Table.to_csv`)."""
    return study.table().to_csv()
