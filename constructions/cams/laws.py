"""Follower motion laws and motion programs: displacement s and its derivatives against the cam angle.

Every law is written on the normalised rise ``u = (theta - theta_i) / beta`` in [0, 1] as ``f(u)`` with
``f(0) = 0`` and ``f(1) = 1``; a rise of lift ``h`` over ``beta`` is ``s = s_i + h f(u)``, a return is
``s = s_i - h f(u)`` (the notes' ``h f((theta_e - theta)/beta)`` is the same curve, since every law here
is odd about its middle: ``f(1 - u) = 1 - f(u)``).  Derivatives by the chain rule:
``ds/dtheta = h f'(u) / beta``, ``d2s/dtheta2 = h f''(u) / beta^2``, ``d3s/dtheta3 = h f'''(u) / beta^3``;
with the cam turning at a steady ``omega`` (rad/s), ``v = omega s'``, ``a = omega^2 s''``,
``j = omega^3 s'''``.

The laws and their derivatives (derived here, checked against numerical derivatives in the tests):

- uniform:         f = u;  f' = 1;  f'' = f''' = 0 inside, but f' jumps at both ends (infinite acceleration);
- parabolic:       f = 2u^2 (u < 1/2), 1 - 2(1-u)^2;  f' = 4u, 4(1-u);  f'' = +4, -4;  f''' = 0 (f'' jumps
                   at both ends and in the middle: infinite jerk three times);
- simple harmonic: f = (1 - cos pi u)/2;  f' = (pi/2) sin pi u;  f'' = (pi^2/2) cos pi u;
                   f''' = -(pi^3/2) sin pi u.  So a = (h/2)(pi/beta)^2 omega^2 cos(pi u) and
                   j = -(h/2)(pi/beta)^3 omega^3 sin(pi u); the notes write (L/2)(pi L omega / 2 beta)^2
                   and ^3, which fails a dimension check (and the jerk's sign);
- cycloidal:       f = u - sin(2 pi u)/(2 pi);  f' = 1 - cos 2 pi u;  f'' = 2 pi sin 2 pi u;
                   f''' = 4 pi^2 cos 2 pi u (finite jerk jumps at the ends);
- 3-4-5:           f = 10u^3 - 15u^4 + 6u^5;  f' = 30u^2(1-u)^2;  f'' = 60u(1 - 3u + 2u^2);
                   f''' = 60 - 360u + 360u^2;
- 4-5-6-7:         f = 35u^4 - 84u^5 + 70u^6 - 20u^7;  f' = 140u^3(1-u)^3;
                   f'' = 420u^2 - 1680u^3 + 2100u^4 - 840u^5;  f''' = 840u - 5040u^2 + 8400u^3 - 4200u^4.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..tolerance import CLOSING_REL, JOIN_JUMP_REL, START_SNAP, TURN_REL

PI = math.pi
TAU = 2.0 * math.pi

UNIFORM = "uniform"
PARABOLIC = "parabolic"
HARMONIC = "simple harmonic"
CYCLOIDAL = "cycloidal"
POLY345 = "3-4-5 polynomial"
POLY4567 = "4-5-6-7 polynomial"
LAWS = (UNIFORM, PARABOLIC, HARMONIC, CYCLOIDAL, POLY345, POLY4567)
ALIASES = {"shm": HARMONIC, "harmonic": HARMONIC, "simple harmonic motion": HARMONIC, "uniform velocity": UNIFORM,
           "constant velocity": UNIFORM, "parabola": PARABOLIC, "constant acceleration": PARABOLIC,
           "cycloid": CYCLOIDAL, "3-4-5": POLY345, "345": POLY345, "4-5-6-7": POLY4567, "4567": POLY4567}

DWELL, RISE, RETURN = "dwell", "rise", "return"
SEGMENT_KINDS = (DWELL, RISE, RETURN)


def law_name(name: str) -> str:
    """The law a scene names ("SHM", "cycloidal", "3-4-5" ...), spelled as in :data:`LAWS`."""
    n = " ".join(str(name).strip().lower().split())
    if n in LAWS:
        return n
    if n in ALIASES:
        return ALIASES[n]
    raise ValueError(f"{name!r} is not a motion law; choose from {', '.join(LAWS)}")


def _uniform(u):
    z = np.zeros_like(u)
    return u, np.ones_like(u), z, z


def _parabolic(u):
    first = u < 0.5
    w = 1.0 - u
    f = np.where(first, 2 * u * u, 1 - 2 * w * w)
    f1 = np.where(first, 4 * u, 4 * w)
    f2 = np.where(first, 4.0, -4.0)
    return f, f1, f2, np.zeros_like(u)


def _harmonic(u):
    c, s = np.cos(PI * u), np.sin(PI * u)
    return (1 - c) / 2, PI / 2 * s, PI ** 2 / 2 * c, -PI ** 3 / 2 * s


def _cycloidal(u):
    c, s = np.cos(TAU * u), np.sin(TAU * u)
    return u - s / TAU, 1 - c, TAU * s, TAU ** 2 * c


def _poly345(u):
    return (10 * u ** 3 - 15 * u ** 4 + 6 * u ** 5, 30 * u ** 2 - 60 * u ** 3 + 30 * u ** 4,
            60 * u - 180 * u ** 2 + 120 * u ** 3, 60 - 360 * u + 360 * u ** 2)


def _poly4567(u):
    return (35 * u ** 4 - 84 * u ** 5 + 70 * u ** 6 - 20 * u ** 7,
            140 * u ** 3 - 420 * u ** 4 + 420 * u ** 5 - 140 * u ** 6,
            420 * u ** 2 - 1680 * u ** 3 + 2100 * u ** 4 - 840 * u ** 5,
            840 * u - 5040 * u ** 2 + 8400 * u ** 3 - 4200 * u ** 4)


NORMALISED: dict[str, Callable] = {UNIFORM: _uniform, PARABOLIC: _parabolic, HARMONIC: _harmonic,
                                   CYCLOIDAL: _cycloidal, POLY345: _poly345, POLY4567: _poly4567}
"""law -> f(u) returning (f, f', f'', f''') on an array of u in [0, 1]."""

def _low(law: str, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(f, f') alone: what a profile's points need (the same formulas as above, fewer operations)."""
    if law == HARMONIC:
        x = PI * u
        return 0.5 - 0.5 * np.cos(x), (PI / 2) * np.sin(x)
    if law == CYCLOIDAL:
        x = TAU * u
        return u - np.sin(x) / TAU, 1.0 - np.cos(x)
    if law == POLY345:
        u2 = u * u
        return u2 * u * (10.0 + u * (-15.0 + 6.0 * u)), u2 * (30.0 + u * (-60.0 + 30.0 * u))
    if law == POLY4567:
        u3 = u * u * u
        return (u3 * u * (35.0 + u * (-84.0 + u * (70.0 - 20.0 * u))),
                u3 * (140.0 + u * (-420.0 + u * (420.0 - 140.0 * u))))
    f = NORMALISED[law](u)
    return f[0], f[1]


def normalised_low(law: str, u) -> tuple[np.ndarray, np.ndarray]:
    """(f, f') of ``law`` at ``u`` (array-like in [0, 1])."""
    return _low(law, np.asarray(u, dtype=float))


END_SLOPES = {UNIFORM: {0.0: 1.0, 1.0: 1.0}, PARABOLIC: {0.0: 0.0, 0.5: 2.0, 1.0: 0.0}}
"""f'(u) exactly at a law's ends and inner joins where it is not 0 (every other law starts and ends at rest)."""


def end_slope(law: str, u: float) -> float:
    """f'(u) of ``law`` at one of its ends or inner joins (u = 0, 1/2 for a parabola, 1): exact, no arrays."""
    return END_SLOPES.get(law, {}).get(u, 0.0)


INNER_JOINS = {PARABOLIC: (0.5,)}
"""Points inside a law where a derivative jumps (the parabolas meet at the middle: f'' from +4 to -4)."""


def normalised(law: str, u) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(f, f', f'', f''') of ``law`` at ``u`` (array-like in [0, 1])."""
    return NORMALISED[law](np.asarray(u, dtype=float))


@dataclass(frozen=True, slots=True)
class Segment:
    """One part of a motion program: a dwell, or a rise/return of ``lift`` (SI, positive) by ``law``
    over the cam angle ``beta`` (rad)."""

    kind: str
    beta: float
    lift: float = 0.0
    law: str = HARMONIC

    def __post_init__(self) -> None:
        if self.kind not in SEGMENT_KINDS:
            raise ValueError(f"{self.kind!r} is not a segment ({', '.join(SEGMENT_KINDS)})")
        if not (self.beta > 0 and math.isfinite(self.beta)):
            raise ValueError(f"a {self.kind} needs a positive cam angle, not {self.beta!r}")
        if self.kind != DWELL:
            if self.law not in LAWS:
                raise ValueError(f"{self.law!r} is not a motion law")
            if not (self.lift > 0 and math.isfinite(self.lift)):
                raise ValueError(f"a {self.kind} needs a positive lift, not {self.lift!r}")

    @property
    def sign(self) -> int:
        return {DWELL: 0, RISE: 1, RETURN: -1}[self.kind]

    def describe(self) -> str:
        return "dwell" if self.kind == DWELL else f"{self.law} {self.kind}"


@dataclass(frozen=True, slots=True)
class Join:
    """Where two pieces of the program meet (or a law's own inner join): at cam angle ``theta``, the
    jumps of s' (rad^-1 scaled: SI length per rad), s'' and s''' from the left to the right, and what
    they mean."""

    theta: float
    before: str
    after: str
    jumps: tuple[float, float, float]
    consequence: str          # "", "infinite acceleration", "infinite jerk", "finite jump in jerk"

    @property
    def continuous(self) -> bool:
        return not self.consequence


class Program:
    """A motion program: segments laid end to end from cam angle 0 through one turn, starting at zero
    lift; the segments' angles must add up to 360 deg and the lifts must bring the follower back.

    ``s(theta)`` and ``derivatives(theta)`` take any array of cam angles (taken modulo one turn) and
    return SI lengths per radian^k; at a join the later segment's value is taken (the earlier one's at
    360 deg itself is the start's)."""

    def __init__(self, segments, *, closing_tolerance: float = CLOSING_REL) -> None:
        self.segments = tuple(segments)
        if not self.segments:
            raise ValueError("a motion program needs at least one segment")
        total = sum(s.beta for s in self.segments)
        if abs(total - TAU) > TURN_REL * TAU:
            raise ValueError(f"the segments cover {math.degrees(total):.6g} deg; they must cover one turn (360 deg)")
        starts = np.cumsum([0.0] + [s.beta for s in self.segments[:-1]])
        self.starts = tuple(float(a) for a in starts)
        self._snapped = np.asarray(self.starts) - START_SNAP * TAU     # the starts _index looks a cam angle up in
        lifts = [0.0]
        for s in self.segments:
            lifts.append(lifts[-1] + s.sign * s.lift)
            if lifts[-1] < -closing_tolerance * max(1.0, max(x.lift for x in self.segments)):
                raise ValueError(f"the {s.describe()} starting at {math.degrees(self.starts[len(lifts) - 2]):.6g} deg "
                                 f"takes the follower below zero lift")
        self.levels = tuple(lifts)          # s at the start of each segment, and at the end
        h = max(lifts)
        if h <= 0:
            raise ValueError("the program never lifts the follower")
        if abs(lifts[-1]) > closing_tolerance * h:
            raise ValueError(f"the program ends at a lift of {lifts[-1]:.6g} m, not back at zero; the returns "
                             f"must take back what the rises lift")
        self.levels = tuple(lifts[:-1]) + (0.0,)
        self.lift = h

    # -- evaluation ----------------------------------------------------------------------------------------
    def _index(self, theta: np.ndarray) -> np.ndarray:
        # a cam angle within rounding of a segment's start belongs to that segment (a station at 150 deg
        # built as 10 x 15 deg must not read the end of the segment before as 3e-14 above zero lift)
        idx = np.searchsorted(self._snapped, theta, side="right") - 1
        return np.minimum(np.maximum(idx, 0), len(self.segments) - 1)     # np.clip's, without its wrapper

    def derivatives(self, theta) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(s, s', s'', s''') at ``theta`` (rad): SI length, length/rad, length/rad^2, length/rad^3."""
        th = np.mod(np.asarray(theta, dtype=float), TAU)
        th = np.where(th >= TAU, 0.0, th)
        idx = self._index(th)
        out = [np.zeros(th.shape) for _ in range(4)]
        for i, seg in enumerate(self.segments):
            m = idx == i
            if not m.any():
                continue
            out[0][m] = self.levels[i]
            if seg.kind == DWELL:
                continue
            # np.clip's result without its wrapper (a NaN stays NaN either way)
            u = np.minimum(np.maximum((th[m] - self.starts[i]) / seg.beta, 0.0), 1.0)
            f = normalised(seg.law, u)
            k = seg.sign * seg.lift
            out[0][m] = self.levels[i] + k * f[0]
            for n in (1, 2, 3):
                out[n][m] = k * f[n] / seg.beta ** n
        return out[0], out[1], out[2], out[3]

    def s(self, theta) -> np.ndarray:
        return self.derivatives(theta)[0]

    def one_sided(self, i: int, u: float) -> tuple[float, float, float, float]:
        """(s, s', s'', s''') of segment ``i`` at its own normalised ``u`` (0 its start, 1 its end)."""
        seg = self.segments[i]
        if seg.kind == DWELL:
            return float(self.levels[i]), 0.0, 0.0, 0.0
        f = normalised(seg.law, np.array([u]))
        k = seg.sign * seg.lift
        return (float(self.levels[i] + k * f[0][0]),) + tuple(float(k * f[n][0] / seg.beta ** n) for n in (1, 2, 3))

    def end_velocity(self, i: int, u: float) -> float:
        """s' of segment ``i`` exactly at one of its ends or inner joins (u = 0, 1/2 for a parabola, 1):
        :func:`end_slope` scaled, no arrays."""
        seg = self.segments[i]
        return 0.0 if seg.kind == DWELL else seg.sign * seg.lift * end_slope(seg.law, u) / seg.beta

    def with_speed(self, theta, omega: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(s, v, a, j) in SI with the cam turning steadily at ``omega`` (rad/s; its magnitude counts)."""
        s, d1, d2, d3 = self.derivatives(theta)
        w = abs(omega)
        return s, d1 * w, d2 * w ** 2, d3 * w ** 3

    # -- joins ----------------------------------------------------------------------------------------------
    def joins(self, rel: float = JOIN_JUMP_REL) -> tuple[Join, ...]:
        """Every join between segments (including 360 deg back to 0) and every law's inner join, with
        the jumps of s', s'' and s''' across it and their consequence for the follower."""
        n = len(self.segments)
        out: list[Join] = []
        for i in range(n):
            seg = self.segments[i]
            for uj in INNER_JOINS.get(seg.law, ()) if seg.kind != DWELL else ():
                a = self._jump(self._law_side(i, uj, -1), self._law_side(i, uj, +1), rel)
                out.append(Join(self.starts[i] + uj * seg.beta, seg.describe(), seg.describe(), *a))
            j = (i + 1) % n
            left = self.one_sided(i, 1.0)
            right = self.one_sided(j, 0.0)
            a = self._jump(left, right, rel)
            theta = self.starts[j] if j else TAU
            out.append(Join(theta if j else 0.0, seg.describe(), self.segments[j].describe(), *a))
        out.sort(key=lambda x: x.theta)
        return tuple(out)

    def _law_side(self, i: int, u: float, side: int):
        seg = self.segments[i]
        k = seg.sign * seg.lift
        # the law's pieces on either side of an inner join: evaluate just inside each piece's formula
        if seg.law == PARABOLIC:
            if side < 0:
                f = (2 * u * u, 4 * u, 4.0, 0.0)
            else:
                w = 1 - u
                f = (1 - 2 * w * w, 4 * w, -4.0, 0.0)
        else:
            f = tuple(float(x[0]) for x in normalised(seg.law, np.array([u])))
        return (self.levels[i] + k * f[0],) + tuple(k * f[n] / seg.beta ** n for n in (1, 2, 3))

    def _jump(self, left, right, rel):
        scale = [self.lift * (TAU / min(s.beta for s in self.segments)) ** n for n in range(4)]
        d = tuple(right[n] - left[n] for n in (1, 2, 3))
        big = [abs(d[n - 1]) > rel * scale[n] for n in (1, 2, 3)]
        if big[0]:
            c = "infinite acceleration"
        elif big[1]:
            c = "infinite jerk"
        elif big[2]:
            c = "finite jump in jerk"
        else:
            c = ""
        return d, c


def segments_from_angles(parts) -> list[Segment]:
    """Segments from (kind, start, end, lift, law) with angles in rad (a helper for tests and the notes'
    examples, which give each segment by its start and end)."""
    out = []
    for kind, a, b, lift, law in parts:
        out.append(Segment(kind, b - a, lift, law))
    return out


__all__ = ["LAWS", "UNIFORM", "PARABOLIC", "HARMONIC", "CYCLOIDAL", "POLY345", "POLY4567", "DWELL", "RISE",
           "RETURN", "Segment", "Program", "Join", "normalised", "normalised_low", "end_slope", "law_name", "segments_from_angles"]
