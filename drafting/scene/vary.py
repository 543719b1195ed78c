"""Parameter ranges in a scene (``[vary]``) and the variants drawn from them: what every family that can
vary shares (the family reads its own keys: :attr:`drafting.families.registry.Family.vary`, e.g.
:mod:`drafting.families.linkage.vary`).

A range is ``[from, to]`` or ``{ from, to, step }``; plain numbers are in the scene's ``[units]``.  A variant
takes each value on the grid ``from + k step`` (k = 0, 1, ...; never beyond ``to``), so the numbers on a sheet
are round; without a step, the step is the largest of 1, 2, 5 x 10^n units of ``from`` that divides the
range into at least 20 parts (30 .. 150 deg: 5 deg).

Variant ``i`` of seed ``S`` draws its values with ``numpy.random.default_rng([S, i])``, in the order the
keys are written: the same seed and index always give the same values, whatever else the batch does.  A
draw that cannot be assembled (or sits at a singular position) is drawn again from the same generator;
the batch says so.

Every problem with ``[vary]`` is one :class:`~drafting.scene.reader.SceneError` sentence naming the file and
the key, and is found when the scene is read (``render`` and ``solve`` read the scene's own values and
check its ranges).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from decimal import Decimal
from typing import Any

from ..render.scales import nice_floor
from .reader import SceneError
from .units import UnitError, from_si, split_value, to_si, unit_symbol, with_unit

STEPS_AT_LEAST = 20
MAX_STEPS = 10_000_000


@dataclass(frozen=True)
class Range:
    """One varied value: its ``[vary]`` key, where it goes in the scene, its kind, and the grid
    ``low + k step`` (k = 0 .. count - 1) in ``unit``."""

    key: str
    where: tuple            # ("input", "angle"), ("link", index in [[link]], "length"), ("load", index, "force"),
                            # ("mass", index in [[mass]], "mass") or ("frame", pivot name, 0 for x | 1 for y)
    kind: str
    unit: str
    low: Decimal
    step: Decimal
    count: int

    def value(self, k: int) -> Decimal:
        return self.low + self.step * k

    def text(self, k: int) -> str:
        """The value as the scene file would write it ("35 deg")."""
        return f"{_plain(self.value(k))} {self.unit}"

    @property
    def header(self) -> str:
        """A CSV column header with the unit: "crank_angle (deg)"."""
        return f"{self.key} ({unit_symbol(self.unit)})"


def _plain(d: Decimal) -> str:
    s = format(d.normalize(), "f")
    return s if s != "-0" else "0"


def fail(path, key: str, problem: str) -> SceneError:
    return SceneError(path, key, problem)


def read_range(path, full: str, where: tuple, kind: str, spec, units, key_name: str) -> Range:
    if isinstance(spec, list):
        if len(spec) != 2:
            raise fail(path, full, "must be a range [from, to], e.g. [\"30 deg\", \"150 deg\"]")
        lo_raw, hi_raw, step_raw = spec[0], spec[1], None
    elif isinstance(spec, dict):
        unknown = sorted(set(spec) - {"from", "to", "step"})
        if unknown:
            raise fail(path, f"{full}.{unknown[0]}", "unknown key; a range has from, to and step")
        if "from" not in spec or "to" not in spec:
            raise fail(path, f"{full}.{'from' if 'from' not in spec else 'to'}", "is missing")
        lo_raw, hi_raw, step_raw = spec["from"], spec["to"], spec.get("step")
    else:
        raise fail(path, full, "must be a range [from, to] or { from = ..., to = ..., step = ... }")
    default_unit = units.of(kind)
    unit = default_unit
    if isinstance(lo_raw, str):
        try:
            unit = split_value(lo_raw)[1] or default_unit
        except UnitError as e:
            raise fail(path, full, str(e)) from None

    def si(raw, what):
        try:
            return to_si(raw, kind, default_unit)
        except UnitError as e:
            raise fail(path, f"{full}" + (f".{what}" if isinstance(spec, dict) else ""), str(e)) from None
    lo, hi = si(lo_raw, "from"), si(hi_raw, "to")
    if not hi > lo:
        raise fail(path, full, f"the range must go up: from {_shown(lo, kind, unit)} to {_shown(hi, kind, unit)}")
    lo_u = Decimal(f"{from_si(lo, kind, unit):.12g}")      # 12 digits: the round trip through SI
    hi_u = Decimal(f"{from_si(hi, kind, unit):.12g}")
    span = hi_u - lo_u
    if step_raw is None:
        step = Decimal(f"{nice_floor(float(span) / STEPS_AT_LEAST):.12g}")   # the largest 1-2-5 x 10^n
    else:
        st = si(step_raw, "step")
        if not st > 0:
            raise fail(path, f"{full}.step", "must be positive")
        step = Decimal(f"{from_si(st, kind, unit):.12g}")
        if step > span:
            raise fail(path, f"{full}.step", f"{_shown(st, kind, unit)} is larger than the range "
                                             f"({with_unit(_plain(span), unit_symbol(unit))})")
    count = int(span / step) + 1
    if count > MAX_STEPS:
        raise fail(path, f"{full}.step", f"makes {count} values; at most {MAX_STEPS} are allowed")
    return Range(key_name, where, kind, unit, lo_u, step, count)


def _shown(si: float, kind: str, unit: str) -> str:
    return with_unit(f"{from_si(si, kind, unit):g}", unit_symbol(unit))


# ---- variants ----------------------------------------------------------------------------------------

def draw(ranges, rng) -> list[int]:
    """One draw: a grid index per range, in the ranges' order."""
    return [int(rng.integers(0, r.count)) for r in ranges]


def variant_data(data: dict[str, Any], ranges, ks, index: int) -> dict[str, Any]:
    """The scene's data with the drawn values written in, its ``[vary]`` removed and its drawing number
    marked with the variant (TOM-V-001-007)."""
    out = copy.deepcopy(data)
    out.pop("vary", None)
    for r, k in zip(ranges, ks):
        if r.where[0] == "input":
            out.setdefault("input", {})[r.where[1]] = r.text(k)
        else:             # ("link", i, "length"), ("load", i, "force"), ("mass", i, "mass") or ("frame", pivot, 0 | 1)
            out[r.where[0]][r.where[1]][r.where[2]] = r.text(k)
    drawing = out.setdefault("drawing", {})
    if isinstance(drawing, dict):
        drawing["number"] = f"{drawing.get('number', 'TOM-000')}-{index:03d}"
    return out
