"""The largest velocity, acceleration, jerk and pressure angle of a cam, per segment and over the turn, with
the cam angles where they occur: exact, and as read at the drawn stations.

Velocity, acceleration and jerk: exact, from each law's closed form.  A rise or return of lift ``h`` over
``beta`` has ``|s^(n)| = h |f^(n)(u)| / beta^n`` (:mod:`.laws`), so its largest is ``h max|f^(n)| /
beta^n`` at the ``u`` where ``|f^(n)|`` peaks on [0, 1] -- found on paper, where ``f^(n+1) = 0`` or at an
end (:data:`PEAKS`):

- simple harmonic: f' = pi/2 at u = 1/2; f'' = pi^2/2 at u = 0 and 1; f''' = pi^3/2 at u = 1/2;
- cycloidal: f' = 2 at 1/2; f'' = 2 pi at 1/4 and 3/4; f''' = 4 pi^2 at 0, 1/2 and 1;
- 3-4-5: f' = 15/8 at 1/2; f'' = 10 sqrt(3)/3 at (3 -+ sqrt 3)/6; f''' = 60 at 0 and 1;
- 4-5-6-7: f' = 35/16 at 1/2; f'' at (5 -+ sqrt 5)/10 (f''' = 840 u (1 - u)(1 - 5u + 5u^2) = 0); f''' = 52.5
  at 1/2 (f'''' = 840 (1 - 2u)(1 - 10u + 10u^2): the inner roots give 42);
- parabolic: f' = 2 at 1/2; |f''| = 4 throughout; f''' = 0;  uniform: f' = 1 throughout, f'' = f''' = 0.

The values are the laws' own formulas evaluated at those ``u`` (to rounding).  Where the velocity jumps at
a join (uniform motion) the acceleration there is infinite, and where the acceleration jumps the jerk is
(:meth:`.laws.Program.joins`): :func:`unbounded` names those cam angles; the maxima are the laws' finite
values between the joins.  A dwell's v, a, j are 0.

The pressure angle: no closed form in general (it mixes s, s' and the follower's geometry), so it is
searched on every piece of the program (:func:`.search.piece_extrema`): the value to rounding, the cam angle
to about 1e-8 rad (flat at the peak, the curve cannot place it closer in floating point).  Measured against
the radial roller's closed form for simple harmonic motion, ``tan phi_max = (pi h / 2 beta) / sqrt(d0 (d0 +
h))`` at ``cos(pi u) = (h/2) / (d0 + h/2)``: the value within 2.4e-16 relative, the angle within 6e-9 rad
over four cams (the tests hold them to 1e-12 and 1e-7 rad).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .envelope import evaluate
from .follower import FLAT, Follower
from .laws import CYCLOIDAL, DWELL, HARMONIC, PARABOLIC, POLY345, POLY4567, UNIFORM, Program, normalised
from .search import piece_bounds, piece_extrema
from .stations import StationTable

_R3, _R5, _R15 = math.sqrt(3.0), math.sqrt(5.0), math.sqrt(15.0)
PEAKS: dict[str, tuple[tuple[float, ...] | None, ...]] = {
    HARMONIC: ((0.5,), (0.0, 1.0), (0.5,)),
    CYCLOIDAL: ((0.5,), (0.25, 0.75), (0.0, 0.5, 1.0)),
    POLY345: ((0.5,), ((3 - _R3) / 6, (3 + _R3) / 6), (0.0, 0.5, 1.0)),
    POLY4567: ((0.5,), ((5 - _R5) / 10, (5 + _R5) / 10), ((5 - _R15) / 10, 0.5, (5 + _R15) / 10)),
    PARABOLIC: ((0.5,), None, None),
    UNIFORM: (None, None, None),
}
"""law -> for f', f'', f''': the u in [0, 1] where |f^(n)| may peak (its critical points and the ends that
count), or None where |f^(n)| is the same throughout the segment."""

TIE_REL = 1e-12
"""Peaks within this fraction of the largest count as equal (the law's symmetric peaks, equal segments)."""

QUANTITIES = ("v", "a", "j")


@dataclass(frozen=True)
class Peak:
    """The largest magnitude ``value`` (SI) of a quantity and the cam angles ``at`` (rad) where it occurs;
    ``throughout``: the value holds over the whole span ``at = (start, end)`` (a dwell, uniform motion's
    velocity, a parabola's acceleration), or over each of several spans, ``at = (start, end, start, end ...)``."""

    value: float
    at: tuple[float, ...]
    throughout: bool = False


def law_peak(law: str, n: int) -> tuple[float, tuple[float, ...] | None]:
    """``(max |f^(n)|, the u where it occurs)`` of a law on [0, 1] (``None`` for u: the same throughout)."""
    cand = PEAKS[law][n - 1]
    if cand is None:
        return float(abs(normalised(law, np.array([0.25]))[n][0])), None
    vals = np.abs(normalised(law, np.array(cand))[n])
    top = float(np.max(vals))
    return top, tuple(u for u, v in zip(cand, vals) if v >= top * (1 - TIE_REL))


def segment_peak(program: Program, i: int, n: int, omega: float | None) -> Peak:
    """The largest ``|d^n s / dt^n|`` (``omega`` None: per radian) of segment ``i``, exact."""
    seg, start = program.segments[i], program.starts[i]
    w = abs(omega) if omega else 1.0
    if seg.kind == DWELL:
        return Peak(0.0, (start, start + seg.beta), True)
    top, us = law_peak(seg.law, n)
    value = seg.lift * top / seg.beta ** n * w ** n
    if us is None:
        return Peak(value, (start, start + seg.beta), True)
    return Peak(value, tuple(start + u * seg.beta for u in us))


def overall(peaks: list[Peak]) -> Peak:
    """The largest of several segments' peaks, with every cam angle where it occurs."""
    top = max(p.value for p in peaks)
    if top == 0:
        return Peak(0.0, (peaks[0].at[0], peaks[-1].at[-1]), True)
    best = [p for p in peaks if p.value >= top * (1 - TIE_REL)]
    if len(best) == 1:
        return best[0]
    if all(p.throughout for p in best):                  # several spans: their (start, end) pairs in turn
        return Peak(top, tuple(a for p in best for a in p.at), True)
    return Peak(top, tuple(a for p in best for a in (p.at if not p.throughout else p.at[:1])))


def motion_maxima(program: Program, omega: float | None) -> dict[str, list[Peak]]:
    """``{"v": [...], "a": [...], "j": [...]}``: each segment's exact peak (``omega`` None: s', s'', s''')."""
    return {q: [segment_peak(program, i, n, omega) for i in range(len(program.segments))]
            for n, q in enumerate(QUANTITIES, 1)}


def pressure_maxima(program: Program, f: Follower) -> list[Peak] | None:
    """Each segment's largest |pressure angle| and where (searched: see the module's notes; a dwell's holds
    throughout it); None for a flat face square to its axis (always 0)."""
    if f.kind == FLAT:
        return None
    found = piece_extrema(program, lambda x: evaluate(program, f, x),
                          [(lambda e: np.abs(e.pressure_angle), True)])[0]
    ends = [start + seg.beta for start, seg in zip(program.starts, program.segments)]
    best: list[tuple[float, float] | None] = [None] * len(program.segments)
    for (lo, hi), (t, v, _) in zip(piece_bounds(program), found):
        i = min(int(np.searchsorted(ends, 0.5 * (lo + hi))), len(ends) - 1)
        if best[i] is None or v > best[i][1]:
            best[i] = (t, v)
    return [Peak(v, (start, start + seg.beta), True) if seg.kind == DWELL else Peak(v, (t,))
            for (t, v), start, seg in zip(best, program.starts, program.segments)]


def unbounded(program: Program) -> dict[str, tuple[float, ...]]:
    """The cam angles where a = infinite (the velocity jumps) and where j = infinite (the velocity or the
    acceleration jumps): ``{"a": (...), "j": (...)}``."""
    out: dict[str, list[float]] = {"a": [], "j": []}
    for jn in program.joins():
        if jn.consequence == "infinite acceleration":
            out["a"].append(jn.theta)
            out["j"].append(jn.theta)
        elif jn.consequence == "infinite jerk":
            out["j"].append(jn.theta)
    return {k: tuple(v) for k, v in out.items()}


@dataclass(frozen=True)
class StationPeak:
    """The largest magnitude read at the drawn stations: ``value`` at station ``index``, cam angle ``at``."""

    value: float
    at: float
    index: int


def station_peaks(table: StationTable) -> dict[str, StationPeak]:
    """The largest |v|, |a|, |j| and |pressure angle| among the stations (the first station where it is
    largest)."""
    cols = {"v": table.v, "a": table.a, "j": table.j, "pressure_angle": table.pressure_angle}
    out = {}
    for name, col in cols.items():
        k = int(np.argmax(np.abs(col)))
        out[name] = StationPeak(float(abs(col[k])), float(table.theta[k]), k)
    return out


__all__ = ["PEAKS", "Peak", "StationPeak", "law_peak", "segment_peak", "overall", "motion_maxima",
           "pressure_maxima", "unbounded", "station_peaks"]
