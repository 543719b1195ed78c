"""Units at the edges: parse "500 mm/s", "120 rpm", "70 deg" to SI floats, and format SI values back in
the scene's own units.  pint does the conversions; its registry is built on first use, not at import.
"""

from __future__ import annotations

import functools
import math

import pint

# quantity kind -> (SI unit the engine uses, pint dimensionality it must have)
KINDS: dict[str, tuple[str, str]] = {
    "length": ("m", "[length]"),
    "velocity": ("m/s", "[length] / [time]"),
    "angular velocity": ("rad/s", "1 / [time]"),
    "angle": ("rad", ""),
}

DEFAULT_UNITS: dict[str, str] = {
    "length": "mm",
    "velocity": "mm/s",
    "angular velocity": "rad/s",
    "angle": "deg",
}


class UnitError(ValueError):
    """A value or unit that cannot be read; the message is one sentence without the key."""


@functools.cache
def registry() -> pint.UnitRegistry:
    return pint.UnitRegistry()


def _quantity(text: str) -> pint.Quantity:
    try:
        return registry().Quantity(text)
    except Exception as e:  # pint's parser raises assorted error types on garbage
        raise UnitError(f"{text!r} cannot be read as a number with a unit (e.g. \"50 mm\")") from e


def check_unit(unit: str, kind: str) -> str:
    """Validate that ``unit`` names a unit of ``kind``; returns it unchanged."""
    q = _quantity(f"1 {unit}")
    if not _compatible(q, kind):
        raise UnitError(f"{unit!r} is not a unit of {kind} (expected something like {DEFAULT_UNITS[kind]!r})")
    return unit


def _compatible(q: pint.Quantity, kind: str) -> bool:
    dim = KINDS[kind][1]
    return q.check(dim) if dim else q.dimensionless


def to_si(value: object, kind: str, default_unit: str) -> float:
    """A scene value -> SI float.  Plain numbers are in ``default_unit``; strings carry their unit."""
    if isinstance(value, bool):
        raise UnitError(f"{value!r} is not a number")
    if isinstance(value, (int, float)):
        q = registry().Quantity(float(value), default_unit)
    elif isinstance(value, str):
        q = _quantity(value.strip())
        if q.unitless:
            q = registry().Quantity(float(q.magnitude), default_unit)
    else:
        raise UnitError(f"{value!r} is not a number or a quantity like \"{'70 deg' if kind == 'angle' else '50 mm'}\"")
    if not _compatible(q, kind):
        raise UnitError(f"{value!r} is not a value of {kind} (expected a unit like {DEFAULT_UNITS[kind]!r})")
    si = KINDS[kind][0]
    out = float(q.to(si).magnitude)
    if not math.isfinite(out):
        raise UnitError(f"{value!r} is not a finite {kind}")
    return out


def from_si(value: float, kind: str, unit: str) -> float:
    return float(registry().Quantity(value, KINDS[kind][0]).to(unit).magnitude)


def unit_symbol(unit: str) -> str:
    """How a unit is printed on a sheet: mm/s stays mm/s, degree becomes deg."""
    return {"degree": "deg", "radian": "rad"}.get(unit, unit)


def format_value(value: float, kind: str, unit: str, digits: int = 4) -> str:
    v = from_si(value, kind, unit)
    return f"{_sig(v, digits)} {unit_symbol(unit)}"


def _sig(v: float, digits: int) -> str:
    if v == 0 or not math.isfinite(v):
        return f"{v:g}"
    mag = math.floor(math.log10(abs(v)))
    decimals = max(digits - 1 - mag, 0)
    if abs(v) >= 10 ** (digits + 2) or abs(v) < 1e-3:
        return f"{v:.{digits - 1}e}"
    return f"{v:.{decimals}f}"
