"""Answers at drawing accuracy: the tolerance a hand construction is marked at, the answer key's items,
and ``drafting check SCENE --answers FILE`` marking a student's values item by item.

Drawing accuracy (the tolerance of a pencil, not of the engine's 1e-9 check):

- A line is drawn to half a millimetre and read off to half a millimetre, so a length measured on paper
  is good to :data:`PAPER_MM` = 1 mm.  A magnitude read off a diagram (a velocity, acceleration or force
  off its polygon, a length off the space diagram) is accepted within 1 mm at the scale the worked sheet
  draws that diagram at (1 mm = 10 mm/s: within 10 mm/s).  A value that names the diagram it is read off
  (a gear pair's path of contact, off the detail at the pitch point) is marked at that diagram's scale;
  otherwise, with several diagrams of its kind (force polygons of several links), the coarsest counts.
- A direction is accepted within the angle 1 mm subtends at the tip of the vector as drawn, and never
  less than :data:`DIRECTION_MIN_DEG` (1 degree, a protractor's reading).
- A value worked out from readings (an angular velocity is V_CB / BC, an angular acceleration A^t / L, a
  torque a force times an arm) is accepted within the error propagated to first order from the readings
  it comes from, each at its own drawing accuracy (:mod:`drafting.app.accuracy`: a polygon reading 1 mm at
  its polygon's scale, a length off the space diagram 1 mm at the space diagram's scale), found in the
  answer step that works it out.  A small rate is so marked as tightly as its own readings allow.  A value
  the record works out otherwise (a gear train's speeds from tooth numbers, a ratio) is accepted within
  :data:`DERIVED_REL` = 2 % of itself (2 % of the largest of its kind when it is zero).  An angle is
  accepted within 1 degree.
- A rate's sense (CW / CCW) must be right: "2.1 rad/s cw" or a signed "-2.1 rad/s".

An answers file is CSV (``name,value`` rows, an optional header, the value with its unit: ``V_C,568
mm/s at 180 deg``, ``omega_2,2.1 rad/s cw``) or TOML (``V_C = "568 mm/s at 180 deg"``); a plain number is
in the scene's unit of that quantity.  Every problem with the file is one sentence naming the file and the
item (:class:`AnswersError`).
"""

from __future__ import annotations

import csv
import io
import math
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Mapping, Sequence

from constructions.geometry import Vec
from constructions.quantities import key as quantity_key

from .accuracy import PAPER_MM, derivations, reading_tolerance
from ..scene import limits
from ..scene.reader import read_input_text
from ..scene.textsafe import cut, one_line, printable
from ..scene.units import UnitError, to_si

DIRECTION_MIN_DEG = 1.0
"""A direction is never asked closer than this (degrees)."""
DERIVED_REL = 0.02
"""A value worked out other than from readings: 2 % of itself."""
ANGLE_TOL_DEG = 1.0
"""An angle measured with a protractor."""
MAX_ANSWERS_BYTES = 64 * 1024

RATE_KINDS = frozenset({"angular velocity", "angular acceleration", "torque"})
DIAGRAM_KIND = {"length": "length", "velocity": "velocity", "acceleration": "acceleration", "force": "force"}


class AnswersError(Exception):
    """A bad answers file: one sentence naming the file and the item."""

    def __init__(self, path: Path | str, item: str, problem: str) -> None:
        where = cut(printable(str(path)), 120)
        text = f"{where}: {cut(printable(item), 60)}: {problem}" if item else f"{where}: {problem}"
        super().__init__(one_line(text))


@dataclass(frozen=True)
class KeyItem:
    """One answer of a key: the expected value (SI; a Vec for a vector, signed CCW + for a rate), how the
    sheet prints it, and the tolerance it is marked at (SI, and degrees for a direction)."""

    name: str            # as the engine names it: "V_C", "omega_2"
    shown: str           # as the key prints it: "V_C", "ω_2"
    kind: str
    value: Vec | float
    text: str            # "568.5 mm/s at 180.0°", "2.100 rad/s CW"
    magnitude_text: str  # "568.5 mm/s", "2.100 rad/s"
    tolerance: float
    tolerance_text: str  # "± 10.00 mm/s, ± 1.0°"
    direction_tolerance: float | None = None   # degrees, vectors only
    analytic: str = ""
    basis: str = ""      # how the tolerance was found: "1 mm on the velocity polygon at 1 mm = 10 mm/s"

    @property
    def number_text(self) -> str:
        """The printed number alone ("568.5")."""
        return self.magnitude_text.split(" ", 1)[0]

    @property
    def direction(self) -> float | None:
        if isinstance(self.value, Vec):
            from ..scene.unitset import direction_deg
            return direction_deg(self.value)
        return None


def tolerances(study, comparisons, scales: Mapping[str, object]) -> dict[str, tuple[float, float | None, str]]:
    """Each comparison's tolerance at drawing accuracy: name -> (SI tolerance, direction tolerance in
    degrees or None, how the tolerance was found).  ``scales`` are the worked sheets' diagram scales (key ->
    DiagramScale)."""
    from ..study.study import display_name
    u = study.scene.units
    coarsest: dict[str, object] = {}
    for s in scales.values():
        if s.quantity not in coarsest or s.units_per_mm > coarsest[s.quantity].units_per_mm:
            coarsest[s.quantity] = s
    largest: dict[str, float] = {}
    for c in comparisons:
        v = _expected(c)
        if v is not None:
            largest[c.kind] = max(largest.get(c.kind, 0.0), _magnitude(v))
    derived = derivations(study.construction, scales)
    out: dict[str, tuple[float, float | None, str]] = {}
    for c in comparisons:
        v = _expected(c)
        if v is None:
            continue
        mag = _magnitude(v)
        own = scales.get(c.diagram) if c.diagram else None
        scale = own if own is not None else coarsest.get(DIAGRAM_KIND.get(c.kind, ""))
        upm = scale.units_per_mm if scale is not None else None
        d = derived.get(display_name(c.name))
        if c.kind == "angle":
            tol, basis = math.radians(ANGLE_TOL_DEG), f"{ANGLE_TOL_DEG:g} deg with a protractor"
        elif upm is not None:
            tol, basis = PAPER_MM * upm, reading_tolerance(c.kind, scales, scale.key)[1]
        elif d is not None:
            tol = d.tolerance
            basis = "propagated from " + " and ".join(
                f"{r.symbol} \u00b1 {u.format(r.kind, r.tolerance)} ({r.basis})" for r in d.readings)
        elif mag > 0:
            tol, basis = DERIVED_REL * mag, f"{DERIVED_REL:.0%} of the value (worked out, not read off a diagram)"
        else:
            tol = DERIVED_REL * largest.get(c.kind, 0.0)
            basis = f"{DERIVED_REL:.0%} of the largest {c.kind} of the key (the value is zero)"
        dtol = None
        if isinstance(v, Vec) and mag > tol:           # a vector within its tolerance of zero has no direction
            paper = mag / upm if upm else 50.0          # no diagram of its kind: as a 50 mm vector
            dtol = max(DIRECTION_MIN_DEG, math.degrees(math.atan2(PAPER_MM, paper)))
        out[c.name] = (tol, dtol, basis)
    return out


def _expected(c):
    return c.graphical if c.graphical is not None else c.analytic


def _magnitude(v) -> float:
    return v.norm() if isinstance(v, Vec) else abs(float(v))


def key_items(study, scales: Mapping[str, object]) -> list[KeyItem]:
    """The answer key of a solved study: every compared quantity with its value as the worked sheet prints
    it and the tolerance it is marked at."""
    from ..study.study import display_name
    u = study.scene.units
    comps = [c for c in study.comparisons if _expected(c) is not None and "(" not in c.name]
    # "T_2 (virtual work)", "V_C (instant centres)": the same answer checked another way, not another answer
    tols = tolerances(study, comps, scales)
    items = []
    for c in comps:
        v = _expected(c)
        text = study.value_text(c, v)
        tol, dtol, basis = tols[c.name]
        mag = u.format(c.kind, _magnitude(v))
        tol_text = f"\u00b1 {u.format(c.kind, tol)}" if c.kind != "angle" else f"\u00b1 {ANGLE_TOL_DEG:g}\u00b0"
        if dtol is not None:
            tol_text += f", \u00b1 {dtol:.1f}\u00b0"
        items.append(KeyItem(c.name, display_name(c.name), c.kind, v, text, mag, tol, tol_text, dtol,
                             study.value_text(c, c.analytic) if c.analytic is not None else "", basis))
    return items


# ---- a student's answers -------------------------------------------------------------------------------

@dataclass(frozen=True)
class Answer:
    name: str            # as written in the file
    raw: str
    magnitude: float     # SI, signed for a rate when a sense or sign is given
    direction: float | None   # degrees
    sense: int | None    # +1 CCW, -1 CW, None not said


_SENSE = re.compile(r"\s+(counter-clockwise|anticlockwise|anti-clockwise|clockwise|ccw|cw)\s*$", re.I)
_AT = re.compile(r"\s+at\s+", re.I)


def parse_answer(path, name: str, raw, kind: str, unit: str) -> Answer:
    """One value of an answers file for a quantity of ``kind`` (plain numbers in ``unit``)."""
    if isinstance(raw, bool) or not isinstance(raw, (str, int, float)):
        raise AnswersError(path, name, f"{cut(printable(repr(raw)), 40)} is not a value like \"568 mm/s\"")
    if isinstance(raw, (int, float)):
        try:
            return Answer(name, repr(raw), to_si(raw, kind, unit), None, None)
        except UnitError as e:
            raise AnswersError(path, name, str(e)) from None
    text = raw.strip().replace("\u00b0", " deg")
    if not text:
        raise AnswersError(path, name, "has no value")
    sense = None
    m = _SENSE.search(text)
    if m:
        word = m.group(1).lower()
        sense = -1 if word in ("clockwise", "cw") else 1
        text = text[:m.start()]
    direction = None
    parts = _AT.split(text, maxsplit=1)
    if len(parts) == 2:
        text = parts[0]
        try:
            direction = math.degrees(to_si(parts[1].strip(), "angle", "deg"))
        except UnitError as e:
            raise AnswersError(path, name, f"the direction {e}") from None
    try:
        value = to_si(text.strip(), kind, unit)
    except UnitError as e:
        raise AnswersError(path, name, str(e)) from None
    return Answer(name, raw.strip(), value, direction, sense)


def read_answers(path: Path | str) -> list[tuple[str, object]]:
    """``(name, value)`` pairs of an answers file: CSV, or TOML when the suffix is .toml."""
    path = Path(path)
    text = read_input_text(path, MAX_ANSWERS_BYTES, "answers file", AnswersError)
    if path.suffix.lower() == ".toml":
        try:
            limits.check_text(text, "an answers file")   # nesting and number sizes, before the TOML reader, as for scenes
        except limits.LimitError as e:
            raise AnswersError(path, e.key, e.problem) from None
        try:
            t = tomllib.loads(text)
        except tomllib.TOMLDecodeError as e:
            raise AnswersError(path, "", f"is not valid TOML ({e})") from None
        return list(t.items())
    pairs: list[tuple[str, object]] = []
    reader = csv.reader(io.StringIO(text))
    rows = iter(reader)
    while True:
        try:
            row = next(rows)
        except StopIteration:
            break
        except csv.Error as e:              # a stray carriage return inside a field, a NUL ...
            raise AnswersError(path, f"line {reader.line_num}", f"is not a CSV row ({e})") from None
        i = reader.line_num
        cells = [c.strip() for c in row]
        if not cells or not any(cells) or cells[0].startswith("#"):
            continue
        if i == 1 and cells[0].lower() in ("name", "quantity", "item"):
            continue
        if len(cells) < 2 or not cells[1]:
            raise AnswersError(path, f"line {i}", "needs a name and a value, e.g. V_C,568 mm/s")
        if len(cells) > 3 and any(cells[3:]):
            raise AnswersError(path, f"line {i}", f"has {len(cells)} fields; a row is a name, a value and an "
                                                  f"optional direction or sense, e.g. V_C,568 mm/s,180")
        value = cells[1]
        if len(cells) >= 3 and cells[2]:          # a direction (or a sense) in a third column
            extra = cells[2]
            value = f"{value} {extra}" if _SENSE.search(" " + extra) else f"{value} at {extra}"
        pairs.append((cells[0], value))
    return pairs


@dataclass(frozen=True)
class Mark:
    item: KeyItem
    verdict: str          # "right", "wrong", "missing"
    given: str = ""
    why: str = ""

    def line(self, width: int) -> str:
        expected = f"expected {self.item.text} ({self.item.tolerance_text})"
        given = f"{self.given}: " if self.given else ""
        why = f" -- {self.why}" if self.why else ""
        return f"  {self.item.shown.ljust(width)}  {self.verdict.ljust(7)}  {given}{expected}{why}"


def _angle_diff(a: float, b: float) -> float:
    d = (a - b) % 360.0
    return min(d, 360.0 - d)


def mark_one(item: KeyItem, ans: Answer, units) -> Mark:
    v = item.value
    shown = ans.raw
    if isinstance(v, Vec):
        off = abs(abs(ans.magnitude) - v.norm())
        if off > item.tolerance:
            return Mark(item, "wrong", shown, f"magnitude off by {units.format(item.kind, off)}")
        if v.norm() <= item.tolerance:                 # a vector of (near) zero length has no direction to mark
            return Mark(item, "right", shown)
        if ans.direction is None:
            return Mark(item, "wrong", shown, "no direction given (write e.g. \"at 180 deg\")")
        dd = _angle_diff(ans.direction, item.direction)
        if dd > (item.direction_tolerance or DIRECTION_MIN_DEG):
            return Mark(item, "wrong", shown, f"direction off by {dd:.1f}\u00b0")
        return Mark(item, "right", shown)
    expected = float(v)
    given = ans.magnitude
    if item.kind in RATE_KINDS:
        if ans.sense is not None:
            given = ans.sense * abs(given)
        if expected != 0 and abs(given) > item.tolerance and (given > 0) != (expected > 0):
            return Mark(item, "wrong", shown, f"the sense is {'CW' if expected < 0 else 'CCW'}")
    elif ans.sense is not None:
        return Mark(item, "wrong", shown, f"a {item.kind} has no sense of turning")
    off = abs(given - expected) if item.kind in RATE_KINDS else abs(abs(given) - abs(expected))
    if off > item.tolerance:
        return Mark(item, "wrong", shown, f"off by {units.format(item.kind, off)}")
    return Mark(item, "right", shown)


def mark(items: Sequence[KeyItem], pairs: Iterable[tuple[str, object]], path, units) -> tuple[list[Mark], list[str]]:
    """Mark ``pairs`` (name, value) against the key ``items``: one Mark per key item, in the key's order,
    and the names of the file that are not quantities of the scene.  A name is the key's own, or one
    spelled loosely ("vcb" for V_CB) where that fits one item only: where it fits several (PB and p_b of
    a gear pair) the file must write the name as the key does."""
    exact = {i.name: i for i in items}
    loose: dict[str, list[KeyItem]] = {}
    for i in items:
        loose.setdefault(quantity_key(i.name), []).append(i)
    got: dict[str, Answer] = {}
    unknown: list[str] = []
    for name, raw in pairs:
        if not isinstance(name, str) or not name.strip():
            raise AnswersError(path, str(name), "is not a quantity name")
        nm = name.strip()
        item = exact.get(nm)
        if item is None:
            fits = loose.get(quantity_key(nm), [])
            if len(fits) > 1:
                raise AnswersError(path, nm, f"could be {' or '.join(f.name for f in fits)}; write the name as "
                                             f"the key does")
            item = fits[0] if fits else None
        if item is None:
            unknown.append(nm)
            continue
        if item.name in got:
            raise AnswersError(path, name, "is answered twice")
        got[item.name] = parse_answer(path, nm, raw, item.kind, units.of(item.kind))
    marks = []
    for i in items:
        a = got.get(i.name)
        marks.append(Mark(i, "missing") if a is None else mark_one(i, a, units))
    return marks, unknown
