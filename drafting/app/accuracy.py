"""The tolerance of a value worked out from readings: the error propagated from the readings it comes from.

A worked sheet states how it works a value out, in the words of its answer step, with the readings as the
step's values: "Measure V_CB = $m0 ...; ω_2 = V_CB/BC = $w0" (a rate: a reading over a length of the space
diagram), "T_2 = resultant × perpendicular distance h from O2 = $r × $h = $t" (a torque: a force times an
arm).  :func:`derivations` finds each such value in the Study's record and propagates, to first order,
``|d f| = sum |df/dx_i| tol_i`` from the readings' own tolerances:

- a reading off a polygon (velocity, acceleration, force) is good to 1 mm at that polygon's scale;
- a length off the space diagram (the L of ω = V/L, the arm h of a torque) is good to 1 mm at the space
  diagram's scale: drawn to half a millimetre and read to half a millimetre, as any length on paper.

So ω = V/L is good to ``tol_V / L + |ω| tol_L / L`` and T = F h to ``h tol_F + F tol_h``: a small rate is
marked at its own readings' accuracy, not at a share of the largest rate on the sheet.  A value the record
does not work out this way has no derivation here (the caller falls back).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Mapping

from constructions.record import StepKind

PAPER_MM = 1.0
"""A length on paper is drawn and read to this (mm): half a millimetre each."""

_SYMBOL = r"([^\s=;,()]+)"
_READ = re.compile(_SYMBOL + r" = \$(\w+)")                                   # "V_CB = $m0"
_RATIO = re.compile(_SYMBOL + r" = " + _SYMBOL + r"/" + _SYMBOL + r" = \$(\w+)")  # "ω_2 = V_CB/BC = $w0"
_PRODUCT = re.compile(_SYMBOL + r" = [^;]*?= \$(\w+) × \$(\w+) = \$(\w+)")     # "T_2 = ... = $r × $h = $t"


@dataclass(frozen=True)
class Reading:
    """One reading a derived value comes from: its symbol, SI magnitude, tolerance and how that was found."""

    symbol: str
    kind: str
    value: float
    tolerance: float
    basis: str


@dataclass(frozen=True)
class Derived:
    """A value worked out from readings: its tolerance (SI) and the readings it was propagated from."""

    tolerance: float
    readings: tuple[Reading, ...]


def reading_tolerance(kind: str, scales: Mapping[str, object], diagram: str = "") -> tuple[float, str] | None:
    """1 mm on paper at the scale of the diagram ``kind`` is read off (``diagram``'s own when named, else
    the coarsest of that quantity; a length off the space diagram) and the words saying so, or None."""
    s = scales.get(diagram) if diagram else None
    if s is None:
        ofkind = [d for d in scales.values() if d.quantity == kind]
        if kind == "length" and "space" in scales:
            ofkind = [scales["space"]]
        if not ofkind:
            return None
        s = max(ofkind, key=lambda d: d.units_per_mm)
    kind_word = "diagram" if s.quantity == "length" else "polygon"
    where = "the space diagram" if s.key == "space" else \
        f"the {s.quantity} {kind_word} ({s.key.split(':', 1)[1].strip()})" if ":" in s.key else f"the {s.quantity} {kind_word}"
    return PAPER_MM * s.units_per_mm, f"1 mm on {where} at 1 mm = {s.text}"


def derivations(construction, scales: Mapping[str, object]) -> dict[str, Derived]:
    """Display symbol ("ω_2", "T_2") -> how it was worked out, for every ratio and product an answer step
    of ``construction`` states."""
    out: dict[str, Derived] = {}
    for st in construction.steps:
        if st.kind is not StepKind.ANSWER:
            continue
        vals = dict(st.values)
        for clause in st.words.split(";"):
            _ratio(clause, vals, st.words, scales, out)
            _product(clause, vals, scales, out)
    return out


def _ratio(clause, vals, words, scales, out) -> None:
    m = _RATIO.search(clause)
    if not m or m[4] not in vals:
        return
    name, num, den, res = m[1], m[2], m[3], vals[m[4]]
    read = {s: vals[k] for s, k in _READ.findall(words) if k in vals}
    if num not in read or res.value is None or read[num].value is None or res.value == 0:
        return
    top = abs(read[num].value)
    length = top / abs(res.value)                    # the length the step divides by: V = ω L
    t_num = reading_tolerance(read[num].kind, scales)
    t_len = reading_tolerance("length", scales)
    if t_num is None or t_len is None or length == 0:
        return
    tol = t_num[0] / length + abs(res.value) * t_len[0] / length
    out[name] = Derived(tol, (Reading(num, read[num].kind, top, *t_num), Reading(den, "length", length, *t_len)))


def _product(clause, vals, scales, out) -> None:
    m = _PRODUCT.search(clause)
    if not m or not all(k in vals for k in m.groups()[1:]):
        return
    a, b = vals[m[2]], vals[m[3]]
    if a.value is None or b.value is None:
        return
    ta, tb = reading_tolerance(a.kind, scales), reading_tolerance(b.kind, scales)
    if ta is None or tb is None:
        return
    tol = abs(b.value) * ta[0] + abs(a.value) * tb[0]
    names = ("F" if a.kind == "force" else m[2], "h" if b.kind == "length" else m[3])
    out[m[1]] = Derived(tol, (Reading(names[0], a.kind, abs(a.value), *ta),
                             Reading(names[1], b.kind, abs(b.value), *tb)))
