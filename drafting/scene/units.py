"""Units at the edges: parse "500 mm/s", "120 rpm", "70 deg" to SI floats, and format SI values back in
the scene's own units.

A value is read as a number and a unit name, never as an expression: the number must match a strict
decimal pattern (sign, digits, optional fraction, optional exponent) and the unit a small grammar of unit
names joined by ``/``, ``*``, ``·``, a space or ``per``, each with an optional small integer power
(``^2``, ``**2``, ``^-1``).  Only then are the names looked up, one by one, in pint's registry (built
once, on first use), which gives each unit's factor and root units; the common names (mm, deg, rpm,
N ...) are pint's own figures kept in :mod:`.unit_table`, so a scene in them is read without loading
pint.  The root units must be exactly those of the key's kind: a percentage or ``dimensionless`` is not a
length and not an angle, ``Hz`` is not an angular velocity (use ``rad/s`` or ``rpm``), and ``50 mm rad`` is not a length.
"""

from __future__ import annotations

import functools
import math
import re

from . import limits
from .unit_table import KNOWN

# quantity kind -> (SI unit the engine uses, pint dimensionality it must have)
KINDS: dict[str, tuple[str, str]] = {
    "length": ("m", "[length]"),
    "velocity": ("m/s", "[length] / [time]"),
    "angular velocity": ("rad/s", "1 / [time]"),
    "angle": ("rad", ""),
    "acceleration": ("m/s^2", "[length] / [time] ** 2"),
    "angular acceleration": ("rad/s^2", "1 / [time] ** 2"),
    "force": ("N", "[mass] * [length] / [time] ** 2"),
    "torque": ("N m", "[mass] * [length] ** 2 / [time] ** 2"),
    "mass": ("kg", "[mass]"),
    "moment of inertia": ("kg m^2", "[mass] * [length] ** 2"),
    "stiffness": ("N/m", "[mass] / [time] ** 2"),
    "power": ("W", "[mass] * [length] ** 2 / [time] ** 3"),
    "pressure": ("Pa", "[mass] / [length] / [time] ** 2"),
    "ratio": ("", ""),              # a plain number (a contact ratio): no unit at all
}

DEFAULT_UNITS: dict[str, str] = {
    "length": "mm",
    "velocity": "mm/s",
    "angular velocity": "rad/s",
    "angle": "deg",
    "acceleration": "mm/s^2",
    "angular acceleration": "rad/s^2",
    "force": "N",
    "torque": "N m",
    "mass": "kg",
    "moment of inertia": "kg m^2",
    "stiffness": "N/mm",
    "power": "kW",
    "pressure": "MPa",
    "ratio": "",
}

_EXAMPLES = {"length": "50 mm", "velocity": "500 mm/s", "angular velocity": "10 rad/s", "angle": "70 deg",
             "acceleration": "2000 mm/s^2", "angular acceleration": "5 rad/s^2", "force": "100 N",
             "torque": "20 N m", "mass": "2.5 kg", "moment of inertia": "0.01 kg m^2",
             "stiffness": "2 N/mm", "power": "30 kW", "pressure": "2 MPa", "ratio": "1.6"}

# names pint does not know that people write
_ALIASES = {"rev": "revolution", "revs": "revolution", "\u00b0": "degree", "sec": "second"}

_NUMBER = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")
_DECIMAL_COMMA = re.compile(r"[+-]?\d*,\d")
_UNIT_TOKEN = re.compile(r"\s*(?:(?P<name>[A-Za-z_\u00b5\u03bc\u00b0\u2126%][A-Za-z_\u00b5\u03bc\u2126]*)"
                         r"|(?P<pow>\*\*|\^)|(?P<op>[*/\u00b7\u22c5])"
                         r"|(?P<int>[+-]?\d+))")
MAX_POWER = 4
MAX_FACTORS = 6
MAX_NAME = 40


class UnitError(ValueError):
    """A value or unit that cannot be read; the message is one sentence without the key."""


@functools.cache
def registry():
    """pint's unit registry, built once on first use.  pint keeps the definitions it has parsed in the
    user's cache folder (``cache_folder=":auto:"``, keyed by the definition files' contents): building
    the registry then takes ~0.1 s instead of ~0.5 s.  Where that folder cannot be used the registry is
    built from the definitions as before.  Its quantities print with the units' symbols (568.5 mm/s)."""
    import pint
    try:
        reg = pint.UnitRegistry(cache_folder=":auto:")
    except Exception:                   # an unwritable or broken cache: the definitions themselves
        reg = pint.UnitRegistry()
    reg.formatter.default_format = "~P"           # a Quantity prints with symbols: "568.5 mm/s"
    reg.formatter.default_sort_func = None        # in the order written: N·m, not m·N
    return reg


def _q(value: object) -> str:
    from .textsafe import quote
    return quote(value)


# -- reading a unit ------------------------------------------------------------------------------------

def _factors(unit: str) -> list[tuple[str, int]]:
    """``unit`` -> [(name, power)], by the strict grammar; raises UnitError."""
    out: list[tuple[str, int]] = []
    pos, sign, expect_name = 0, 1, True
    text = unit.strip()
    if not text:
        raise UnitError("an empty unit")
    while pos < len(text):
        m = _UNIT_TOKEN.match(text, pos)
        if not m:
            raise UnitError(f"{_q(unit)} is not a unit (write unit names such as mm, mm/s, rad/s, rpm or deg)")
        pos = m.end()
        if m["name"]:
            name = m["name"]
            if name == "per" and not expect_name and out:
                sign, expect_name = -1, True
                continue
            if len(name) > MAX_NAME:
                raise UnitError(f"{_q(unit)} is not a unit: {_q(name)} is too long for a unit name")
            power = 1
            p = _UNIT_TOKEN.match(text, pos)
            if p and p["pow"]:
                e = _UNIT_TOKEN.match(text, p.end())
                if not (e and e["int"]) or not (1 <= abs(int(e["int"])) <= MAX_POWER):
                    raise UnitError(f"{_q(unit)} is not a unit: a power must be a whole number from "
                                    f"-{MAX_POWER} to {MAX_POWER}, e.g. mm/s^2")
                power, pos = int(e["int"]), e.end()
            out.append((name, sign * power))
            if len(out) > MAX_FACTORS:
                raise UnitError(f"{_q(unit)} is not a unit: too many factors")
            sign, expect_name = 1, False
        elif m["op"]:
            if expect_name:
                raise UnitError(f"{_q(unit)} is not a unit (an operator needs a unit name on each side)")
            sign, expect_name = (-1 if m["op"] == "/" else 1), True
        else:
            raise UnitError(f"{_q(unit)} is not a unit: write a number and a unit name, e.g. \"50 mm\" "
                            f"(arithmetic is not read)")
    if expect_name:
        raise UnitError(f"{_q(unit)} is not a unit (it ends with an operator)")
    return out


@functools.lru_cache(maxsize=512)
def _root(unit: str) -> tuple[float, tuple[tuple[str, float], ...]]:
    """``unit`` -> (factor, root units) such that 1 unit = factor x root units."""
    factor = 1.0
    root: dict[str, float] = {}
    for name, power in _factors(unit):
        name = _ALIASES.get(name, name)
        f, r = KNOWN[name] if name in KNOWN else _pint_root(name)
        factor *= f ** power
        for k, v in r:
            root[k] = root.get(k, 0) + v * power
    return factor, tuple(sorted((k, v) for k, v in root.items() if v != 0))


def _pint_root(name: str) -> tuple[float, tuple[tuple[str, float], ...]]:
    """One unit name's factor and root units, from pint (a name not in :data:`unit_table.KNOWN`)."""
    reg = registry()
    try:
        canonical = reg.get_name(name)
        f, r = reg.get_root_units(canonical)
    except Exception:             # pint: UndefinedUnitError and friends
        raise UnitError(f"{_q(name)} is not a known unit name (e.g. mm, in, m/s, rad/s, rpm, "
                        f"deg)") from None
    return float(f), tuple(dict(r._units).items())


@functools.cache
def _kind_root(kind: str) -> tuple[float, tuple[tuple[str, float], ...]]:
    return _root(KINDS[kind][0])


def _ratio(unit: str, kind: str) -> tuple[float, float]:
    """(factor of ``unit``, factor of the SI unit of ``kind``), both to the same root units, so that
    SI = value * (f / kf) and value = SI * (kf / f) as pint computes them; raises UnitError when the
    unit is not of that kind."""
    if kind not in KINDS:
        raise UnitError(f"{kind!r} is not a kind of quantity ({', '.join(KINDS)})")
    if kind == "ratio":                 # a plain number: no unit, and no dimensionless unit either
        if unit.strip():
            raise UnitError(f"a ratio is a plain number, e.g. 1.6, without a unit ({_q(unit)} given)")
        return 1.0, 1.0
    f, root = _root(unit)
    kf, kroot = _kind_root(kind)
    if root != kroot:
        raise UnitError(f"{_q(unit)} is not a unit of {kind} (expected a unit like {DEFAULT_UNITS[kind]!r})")
    return f, kf


def check_unit(unit: str, kind: str) -> str:
    """Validate that ``unit`` names a unit of ``kind``; returns it unchanged."""
    if not isinstance(unit, str):
        raise UnitError(f"{_q(unit)} is not a unit name")
    _ratio(unit, kind)
    return unit


# -- reading a value --------------------------------------------------------------------------------------

def split_value(text: str) -> tuple[float, str | None]:
    """``"500 mm/s"`` -> (500.0, "mm/s"); ``"50"`` -> (50.0, None).  Never evaluates anything."""
    s = text.strip()
    m = _NUMBER.match(s)
    if not m:
        if _DECIMAL_COMMA.match(s):
            raise UnitError(f"{_q(text)} has a decimal comma; use a decimal point, e.g. \"60.5 mm\"")
        raise UnitError(f"{_q(text)} cannot be read as a number with a unit (e.g. \"50 mm\")")
    rest = s[m.end():]
    if rest.startswith(",") and rest[1:2].isdigit():
        raise UnitError(f"{_q(text)} has a decimal comma; use a decimal point, e.g. \"60.5 mm\" "
                        f"(and no thousands separators)")
    first = rest.lstrip()[:1]
    if first and (first in "*^/+-().," or first.isdigit()):
        raise UnitError(f"{_q(text)} is not a number with a unit: write a plain number and a unit name, "
                        f"e.g. \"50 mm\" (arithmetic is not read)")
    number = float(m.group())
    unit = rest.strip()
    return number, (unit or None)


def to_si(value: object, kind: str, default_unit: str) -> float:
    """A scene value -> SI float.  Plain numbers are in ``default_unit``; strings carry their unit.

    Raises :class:`UnitError` (one sentence, without the key) for anything else: expressions, decimal
    commas, units of another kind, numbers too large for a float, values outside :mod:`limits`."""
    if kind not in KINDS:
        raise UnitError(f"{kind!r} is not a kind of quantity ({', '.join(KINDS)})")
    if isinstance(value, bool):
        raise UnitError(f"{value!r} is not a number")
    if isinstance(value, (int, float)):
        try:
            number = float(value)
        except OverflowError:
            raise UnitError(f"{_q(value)} is too large to be {_a(kind)}") from None
        unit = default_unit
    elif isinstance(value, str):
        number, unit = split_value(value)
        unit = unit or default_unit
    else:
        example = _EXAMPLES.get(kind, "50 mm")
        raise UnitError(f"{_q(value)} is not a number or a quantity like \"{example}\"")
    if math.isnan(number):
        raise UnitError(f"{_q(value)} is not a number")
    if math.isinf(number):
        raise UnitError(f"{_q(value)} is too large to be {_a(kind)}")
    try:
        f, kf = _ratio(unit, kind)
    except UnitError as e:
        if unit is default_unit or isinstance(value, (int, float)):
            raise
        if "is not a unit of" in str(e):
            raise UnitError(f"{_q(value)} is not a value of {kind} (expected a unit like "
                            f"{DEFAULT_UNITS[kind]!r})") from None
        raise
    out = number * (f / kf)
    if not math.isfinite(out):
        raise UnitError(f"{_q(value)} is too large to be {_a(kind)}")
    problem = limits.magnitude_problem(kind, out)
    if problem:
        lo, hi = limits.MAGNITUDES[kind]
        bound = hi if problem == "too large" else lo
        try:
            shown = with_unit(f"{from_si(bound, kind, default_unit):g}", unit_symbol(default_unit))
        except UnitError:
            shown = f"{bound:g} {KINDS[kind][0]}"
        if problem == "too large":
            raise UnitError(f"{_q(value)} is too large: {_a(kind)} may be at most {shown}")
        raise UnitError(f"{_q(value)} is too small: a non-zero {kind} must be at least {shown} "
                        f"(write 0 for zero)")
    return out


def _a(kind: str) -> str:
    return ("an " if kind[0] in "aeiou" else "a ") + kind


def from_si(value: float, kind: str, unit: str) -> float:
    f, kf = _ratio(unit, kind)
    return float(value) * (kf / f)


def quantity(value: float, kind: str, unit: str):
    """An SI value of ``kind`` as a pint Quantity in ``unit`` (read by the strict grammar above, so a unit
    of another kind is a UnitError naming it); printed with the unit's symbols ("568.5 mm/s")."""
    reg = registry()
    pint_unit = reg.Unit("")
    for name, power in _factors(unit) if unit.strip() else ():
        pint_unit *= reg.Unit(_ALIASES.get(name, name)) ** power
    return reg.Quantity(from_si(value, kind, unit), pint_unit)


def unit_symbol(unit: str) -> str:
    """How a unit is printed on a sheet: mm/s stays mm/s, degree becomes the degree sign, a product is
    written with a space as in "N m" (lbf*in -> lbf in; a power ** -> ^)."""
    unit = {"degree": "\u00b0", "deg": "\u00b0", "radian": "rad"}.get(unit, unit)
    return " ".join(unit.replace("**", "^").replace("*", " ").split())


def with_unit(number: str, symbol: str) -> str:
    """A number and its printed unit: "50 mm", "70\u00b0" (the degree sign set close, ISO 80000-3), a
    ratio's bare number."""
    if not symbol:
        return number
    return f"{number}{symbol}" if symbol == "\u00b0" else f"{number} {symbol}"


def trimmed(number: str) -> str:
    """A fixed-point number without trailing zeros (ISO 129-1): "70.00" -> "70", "2.100" -> "2.1"."""
    if "." not in number or "e" in number or "E" in number:
        return number
    return number.rstrip("0").rstrip(".")


def format_value(value: float, kind: str, unit: str, digits: int = 4) -> str:
    """An SI value in ``unit`` to ``digits`` significant figures, trailing zeros dropped: "500 mm/s",
    "70\u00b0", "2.1 rad/s"."""
    v = from_si(value, kind, unit)
    return with_unit(trimmed(_sig(v, digits)), unit_symbol(unit))


def _sig(v: float, digits: int) -> str:
    if v == 0 or not math.isfinite(v):
        return f"{v:g}"
    mag = math.floor(math.log10(abs(v)))
    decimals = max(digits - 1 - mag, 0)
    if abs(v) >= 10 ** (digits + 2) or abs(v) < 1e-3:
        return f"{v:.{digits - 1}e}"
    return f"{v:.{decimals}f}"
