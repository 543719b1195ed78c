"""A study's results table: named rows of numbers in the scene's units, printable, and ready for CSV or pandas.

    table = study.table()
    print(table)                          # the table the sheet prints: quantity, graphical, analytic, difference
    table.rows[0].graphical, table.rows[0].unit      # 568.5, 'mm/s' (a vector's magnitude; .graphical_angle)
    table.to_csv()                        # the same rows as CSV (what `drafting solve --csv` writes)
    pandas.DataFrame(table.rows)          # one column per field of :class:`Row`

A :class:`Row` holds numbers, not text: a vector as its magnitude, components and direction (degrees CCW from
+x), a rate or torque signed (CCW positive), each in the unit its ``unit`` field names; None where there is no
value (no analytic model).  ``table.text`` keeps the sheet's own cells ("568.5 mm/s at 180.0\u00b0").
"""

from __future__ import annotations

import csv
import io
import re
from typing import Iterator, NamedTuple, Sequence

from constructions.check import Comparison
from constructions.geometry import Vec

from ..scene.units import DEFAULT_UNITS, KINDS, from_si, with_unit
from ..scene.unitset import Units, direction_deg

CSV_HEADER = ("quantity", "kind", "unit", "graphical", "graphical x", "graphical y", "graphical angle (deg)",
              "analytic", "analytic x", "analytic y", "analytic angle (deg)", "difference", "agrees")
TEXT_HEADER = ("quantity", "graphical", "analytic", "difference")


class Row(NamedTuple):
    """One result in the scene's units (the fields of :data:`CSV_HEADER`, in its order)."""

    quantity: str                       # the result's name, as study.results is keyed ("omega_2")
    kind: str                           # "velocity", "angular velocity", ...
    unit: str                           # the scene's unit of every number in the row ("mm/s")
    graphical: float                    # read off the construction: a vector's magnitude, a rate signed
    graphical_x: float | None
    graphical_y: float | None
    graphical_angle: float | None       # degrees CCW from +x, for a vector
    analytic: float | None
    analytic_x: float | None
    analytic_y: float | None
    analytic_angle: float | None
    difference: float | None            # |graphical - analytic|
    agrees: bool | None


class TextRow(NamedTuple):
    """One result as the sheet's results table prints it."""

    quantity: str
    graphical: str
    analytic: str
    difference: str


_RATE_KINDS = frozenset({"angular velocity", "angular acceleration", "torque"})
"""Scalar kinds that turn one way or the other (written with CCW / CW)."""

_GREEK = {"alpha": "\u03b1", "beta": "\u03b2", "gamma": "\u03b3", "delta": "\u03b4", "theta": "\u03b8",
          "mu": "\u03bc", "rho": "\u03c1", "phi": "\u03c6", "psi": "\u03c8", "omega": "\u03c9"}
_GREEK_WORD = re.compile(r"^(" + "|".join(_GREEK) + r")(?=_|'|$)")


def display_name(name: str) -> str:
    """A result's name as a sheet sets it: omega_2 -> ω_2, phi' -> φ', phi_max -> φ_max (the rest of the
    name is the notes' markup already)."""
    return _GREEK_WORD.sub(lambda m: _GREEK[m[1]], name)


def value_text(u: Units, c: Comparison, value: Vec | float | None) -> str:
    """A value of result ``c`` as the sheet writes it: "568.5 mm/s at 180.0\u00b0", "2.1 rad/s CW", "n/a"."""
    if value is None:
        return "n/a"
    if isinstance(value, Vec):
        return f"{u.format(c.kind, value.norm())} at {direction_deg(value):.1f}\u00b0"
    if c.kind not in _RATE_KINDS:          # a length, an angle, a force magnitude: no sense of turning
        return u.format(c.kind, value) if value < 0 else u.format(c.kind, abs(value))
    sense = "CCW" if value > 0 else "CW" if value < 0 else ""
    return f"{u.format(c.kind, abs(value))} {sense}".strip()


def difference_text(u: Units, c: Comparison) -> str:
    if c.difference is None:
        return "n/a"
    return with_unit(f"{u.convert(c.kind, c.difference):.1e}", u.symbol(c.kind))


def _cells(u: Units, kind: str, v: Vec | float | None) -> tuple[float | None, ...]:
    if v is None:
        return None, None, None, None
    if isinstance(v, Vec):
        return u.convert(kind, v.norm()), u.convert(kind, v.x), u.convert(kind, v.y), direction_deg(v)
    return u.convert(kind, v), None, None, None


def row_of(u: Units, c: Comparison) -> Row:
    """The row of result ``c`` in the units ``u``."""
    diff = None if c.difference is None else u.convert(c.kind, c.difference)
    return Row(c.name, c.kind, u.symbol(c.kind), *_cells(u, c.kind, c.graphical), *_cells(u, c.kind, c.analytic),
               diff, c.agrees)


def _json_value(kind: str, v: Vec | float | None, convert) -> object:
    if v is None:
        return None
    if isinstance(v, Vec):
        return {"x": convert(kind, v.x), "y": convert(kind, v.y), "magnitude": convert(kind, v.norm()),
                "angle_deg": direction_deg(v)}
    return convert(kind, v)


def scene_unit(units: Units, kind: str) -> str:
    """The scene's unit of ``kind``, or the default where a scene cannot set one (a power)."""
    try:
        return units.of(kind)
    except KeyError:
        return DEFAULT_UNITS[kind]


def json_values(u: Units, c: Comparison) -> dict[str, object]:
    """The values of result ``c`` for ``solve --json``: graphical, analytic and difference in the scene's unit
    (``unit``), and the same in SI under ``si`` (a vector as x, y, magnitude and angle_deg)."""
    unit, si_unit = scene_unit(u, c.kind), KINDS[c.kind][0]
    out: dict[str, object] = {"kind": c.kind, "unit": unit}
    si: dict[str, object] = {"unit": si_unit}
    for into, to in ((out, unit), (si, si_unit)):
        def convert(kind: str, v: float, to: str = to) -> float:
            return from_si(v, kind, to) if to else float(v)
        for field in ("graphical", "analytic", "difference"):
            into[field] = _json_value(c.kind, getattr(c, field), convert)
    out["si"] = si
    return out


def _csv_cell(v: object) -> str:
    if v is None:
        return ""
    if isinstance(v, bool):
        return "yes" if v else "no"
    return repr(v) if isinstance(v, float) else str(v)


class Table(Sequence[Row]):
    """The results table of a study: a sequence of :class:`Row` (``.rows``), ``.text`` the sheet's cells,
    ``str(table)`` aligned text, :meth:`to_csv`, :meth:`records`."""

    def __init__(self, rows: Sequence[Row], text: Sequence[TextRow]) -> None:
        self.rows: list[Row] = list(rows)
        self.text: list[TextRow] = list(text)

    @classmethod
    def of(cls, units: Units, comparisons: Sequence[Comparison]) -> "Table":
        return cls([row_of(units, c) for c in comparisons],
                   [TextRow(display_name(c.name), value_text(units, c, c.graphical), value_text(units, c, c.analytic),
                            difference_text(units, c)) for c in comparisons])

    def __len__(self) -> int:
        return len(self.rows)

    def __getitem__(self, i):            # an index or a slice of rows
        return self.rows[i]

    def __iter__(self) -> Iterator[Row]:
        return iter(self.rows)

    def records(self) -> list[dict[str, object]]:
        """The rows as dicts (field -> value), e.g. for ``json.dumps`` or ``pandas.DataFrame``."""
        return [r._asdict() for r in self.rows]

    def to_csv(self) -> str:
        """The rows as CSV: a header naming each column (:data:`CSV_HEADER`), each row's unit in its ``unit``
        column, empty cells where there is no value, agreement as yes / no."""
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(CSV_HEADER)
        for r in self.rows:
            w.writerow([_csv_cell(v) for v in r])
        return buf.getvalue()

    def lines(self) -> list[str]:
        """The text rows aligned under a header and a rule of dashes (no lines when there are no rows)."""
        if not self.text:
            return []
        rows = [TEXT_HEADER, *self.text]
        widths = [max(len(r[i]) for r in rows) for i in range(4)]
        out = []
        for k, r in enumerate(rows):
            out.append("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip())
            if k == 0:
                out.append("  ".join("-" * w for w in widths))
        return out

    def __str__(self) -> str:
        return "\n".join(self.lines())

    def __repr__(self) -> str:
        return f"<Table of {len(self.rows)} results: {', '.join(r.quantity for r in self.rows[:6])}" \
               f"{', ...' if len(self.rows) > 6 else ''}>"
