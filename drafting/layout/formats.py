"""How a sheet writes values: the unit of each quantity kind (from the scene's :class:`Units`), the
scales the drawing chose, and the paper length of a drawn vector.

:class:`SheetFormatter` is the value formatter of a sheet (``step.text(fmt)``): it writes every
:class:`~constructions.record.Value` in the scene's units, a "scale" value as the scale the drawing
chose for that diagram ("10 mm/s", read after "1 mm = "), and a "paper length" as millimetres on the
paper ("50 mm long").  A ``hook`` may rewrite any value (a blank lab sheet writes "____" for answers).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Callable, Mapping

from constructions.record import Value

from ..render.scales import number_text
from ..scene.units import registry

SI_UNITS: dict[str, str] = {
    "length": "m", "velocity": "m/s", "acceleration": "m/s^2", "angular velocity": "rad/s",
    "angular acceleration": "rad/s^2", "angle": "rad", "force": "N", "torque": "N*m", "mass": "kg",
    "time": "s", "moment of inertia": "kg*m^2",
}
"""The SI unit the engine works in, per quantity kind."""

FALLBACK_UNITS: dict[str, str] = {"force": "N", "torque": "N*m", "mass": "kg", "time": "s",
                                  "moment of inertia": "kg*m^2"}
"""Units for kinds a scene's units do not name (yet)."""

# display units per SI unit for the common spellings (no pint needed for these)
_KNOWN: dict[tuple[str, str], float] = {
    ("m", "m"): 1.0, ("m", "mm"): 1e3, ("m", "cm"): 1e2, ("m", "km"): 1e-3, ("m", "in"): 1 / 0.0254,
    ("m/s", "m/s"): 1.0, ("m/s", "mm/s"): 1e3, ("m/s", "cm/s"): 1e2, ("m/s", "m/min"): 60.0,
    ("m/s", "mm/min"): 6e4, ("m/s", "km/h"): 3.6,
    ("m/s^2", "m/s^2"): 1.0, ("m/s^2", "mm/s^2"): 1e3, ("m/s^2", "cm/s^2"): 1e2,
    ("N", "N"): 1.0, ("N", "kN"): 1e-3, ("N*m", "N*m"): 1.0, ("N*m", "N m"): 1.0,
    ("rad/s", "rad/s"): 1.0, ("rad/s", "rpm"): 60 / (2 * math.pi),
    ("rad/s^2", "rad/s^2"): 1.0, ("rad", "rad"): 1.0, ("rad", "deg"): 180 / math.pi,
    ("rad", "degree"): 180 / math.pi,
}


def _normal(unit: str) -> str:
    return unit.replace("\u00b2", "^2").replace("**2", "^2").replace(" ", "")


def unit_of(units, kind: str) -> str:
    """The unit ``units`` writes ``kind`` in (its own spelling), or a fallback for kinds it lacks."""
    try:
        return units.of(kind)
    except (KeyError, AttributeError):
        return FALLBACK_UNITS.get(kind, SI_UNITS.get(kind, ""))


def symbol_of(units, kind: str) -> str:
    """How the unit of ``kind`` is printed (mm/s, mm/s², deg)."""
    try:
        return units.symbol(kind)
    except (KeyError, AttributeError):
        u = unit_of(units, kind)
        return u.replace("^2", "\u00b2").replace("**2", "\u00b2").replace("*", " ")


@functools.lru_cache(maxsize=256)
def _per_si(si: str, unit: str) -> float:
    key = (_normal(si), _normal(unit))
    if key in _KNOWN:
        return _KNOWN[key]
    if not unit:
        return 1.0
    try:
        return float(registry().Quantity(1.0, si).to(unit.replace("\u00b2", "^2")).magnitude)
    except Exception as e:   # pint raises assorted errors for units of another dimension
        raise ValueError(f"the sheet unit {unit!r} cannot express a quantity in {si}") from e


def per_si(units, kind: str) -> float:
    """How many display units of ``kind`` make one SI unit (1000 for mm/s)."""
    si = SI_UNITS.get(kind)
    if si is None:
        return 1.0
    return _per_si(si, unit_of(units, kind))


def _sig(v: float, digits: int = 4) -> str:
    if v == 0 or not math.isfinite(v):
        return f"{v:g}"
    mag = math.floor(math.log10(abs(v)))
    if abs(v) >= 10 ** (digits + 2) or abs(v) < 1e-3:
        return f"{v:.{digits - 1}e}"
    return f"{v:.{max(digits - 1 - mag, 0)}f}"


def value_text(units, kind: str, value: float) -> str:
    """An SI value of ``kind`` in the scene's unit: "500.0 mm/s", "70.00 deg"."""
    if kind == "number":
        return f"{value:.4g}"
    try:
        return units.format(kind, value).replace("^2", "\u00b2")
    except (KeyError, AttributeError, ValueError):
        pass
    if kind not in SI_UNITS:
        return f"{value:.4g}"
    return f"{_sig(value * per_si(units, kind))} {symbol_of(units, kind)}".strip()


def paper_length_text(mm: float) -> str:
    """A length on paper: "50 mm long", "42.5 mm long"."""
    r = round(mm, 1)
    s = f"{r:.0f}" if abs(r - round(r)) < 1e-9 else f"{r:.1f}"
    return f"{s} mm long"


@dataclass(frozen=True)
class DiagramScale:
    """The scale the drawing chose for one diagram: SI units of ``quantity`` per paper mm, and how
    it is written (``per_mm`` display units of ``unit`` per mm)."""

    key: str
    quantity: str
    units_per_mm: float
    per_mm: float
    unit: str

    @property
    def text(self) -> str:
        return f"{number_text(self.per_mm)} {self.unit}".strip()


ValueHook = Callable[[Value, Callable[[Value], str]], str]
"""``hook(value, default)`` -> the text a sheet writes for ``value`` (``default(value)`` is the
worked-solution text); e.g. a lab sheet writes a blank for answers."""


DRAWN_NOTHING_MM = 1e-9
"""A value that its diagram would draw shorter than this (a nanometre of paper) is written as 0: what is left
of an exact zero after the arithmetic (a block's sliding acceleration of 8.674e-16 mm/s\u00b2) is not a
length anyone could measure off the polygon."""


@dataclass
class SheetFormatter:
    """The value formatter of a sheet: ``fmt(value)`` -> text (see the module docstring).

    ``scales`` maps diagram keys to the scale each diagram is drawn at; a "scale" or "paper length"
    value finds its diagram by ``of``: a diagram key ("force: link 3"), else the diagram of
    ``prefer`` (the step's own scale bar), else the first diagram of that quantity.  Before the scales
    are chosen (while the text is measured), ``probe`` writes the widest plausible text instead."""

    units: object
    scales: Mapping[str, DiagramScale] = field(default_factory=dict)
    hook: ValueHook | None = None
    probe: bool = False
    prefer: tuple[str, ...] = ()

    def scale_for(self, of: str) -> DiagramScale | None:
        if of in self.scales:
            return self.scales[of]
        for key in self.prefer:
            s = self.scales.get(key)
            if s is not None and s.quantity == of:
                return s
        return next((s for s in self.scales.values() if s.quantity == of), None)

    def default(self, v: Value) -> str:
        if v.kind == "scale":
            s = self.scale_for(v.of)
            if self.probe:
                return f"0.0005 {symbol_of(self.units, v.of)}"
            if s is not None:
                return s.text
            if v.value is not None:
                return f"{number_text(v.value * per_si(self.units, v.of))} {symbol_of(self.units, v.of)}"
            return f"(the {v.of} scale)"
        if v.kind == "paper length":
            s = self.scale_for(v.of)
            if self.probe:
                return "100.5 mm long"
            if s is not None and v.value is not None:
                return paper_length_text(abs(v.value) / s.units_per_mm)
            return value_text(self.units, v.of, abs(v.value)) if v.value is not None else ""
        if v.value is None:
            return ""
        s = self.scale_for(v.kind) if v.value != 0.0 else None
        if s is not None and s.units_per_mm > 0 and abs(v.value) / s.units_per_mm < DRAWN_NOTHING_MM:
            return value_text(self.units, v.kind, 0.0)     # a round-off's size (8.7e-16 mm/s2): nothing drawn
        return value_text(self.units, v.kind, v.value)

    def __call__(self, v: Value) -> str:
        if self.hook is not None:
            return self.hook(v, self.default)
        return self.default(v)

    def preferring(self, keys: tuple[str, ...]) -> "SheetFormatter":
        return SheetFormatter(self.units, self.scales, self.hook, self.probe, keys)
