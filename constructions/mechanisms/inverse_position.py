"""The inverse position problem: the crank angles that put a slider block at a given stroke position, or
a link at a given angle -- every one of them over a turn of the crank, on the assembly the scene chose.

The forward problem (the pose at a crank angle) is the construction's (:func:`.pose.locate`, dyad by
dyad); the inverse is found by running it: the quantity (the block's position along its guide, or the
link's angle) over one turn of the crank, sampled by the sweep (:func:`constructions.sweep.sweep`), then
every sign change of its difference from the target closed by bracketing on the construction itself
(Illinois' false position, to the last bit of the crank angle), and every sample where it only touches
the target (a limit position: the slider at a dead centre) refined as a minimum.  So any mechanism the
construction builds has its inverse -- a six-bar's ram as well as a slider-crank's piston.  The closed
forms of a plain slider-crank and four-bar (:mod:`constructions.analytic.inverse`, applied by
:func:`constructions.closed_forms.closed_form_inverse`) check it.

Positions: a block's position is measured along its fixed guide from the guide's ``through`` point, in
the guide's direction, or along the slot it runs in from the foot of the slotted link's first joint (a
hydraulic cylinder's length, pin to pin, when the barrel is pivoted at that joint); a link's angle is the direction from its fixed pivot to its other base joint (or,
for a link with no fixed pivot, from its first base joint to its second), CCW from +x, as the crank's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

import numpy as np

from ..errors import DegenerateInput
from ..formatting import Formatter, si_format
from ..geometry import Vec
from .assembly import PlanStep, assembly_plan
from .model import Mechanism, slide_line
from .pose import locate

TURN = 2 * math.pi
SAMPLES = 720
"""Crank angles sampled over the turn (every 0.5 deg) to bracket the solutions."""


@dataclass(frozen=True, slots=True)
class SliderAt:
    """Block ``block`` at ``position`` (m) along its fixed guide from the guide's point, or along its slot from
    the foot of the slotted link's first joint."""

    block: int
    position: float


@dataclass(frozen=True, slots=True)
class OutputAngle:
    """Link ``link`` at ``angle`` (rad, CCW from +x: its fixed pivot to its other base joint)."""

    link: int
    angle: float


Target = SliderAt | OutputAngle


@dataclass(frozen=True)
class InversePosition:
    """Every crank angle (rad, in [0, 2 pi), ascending) that puts the mechanism at ``target``.

    ``touching[i]`` is True where the quantity only touches the target there (a limit position: the two
    solutions of either side have met); ``reach`` lists the ranges (SI) the quantity covers over the turn,
    one per stretch of crank angles where the mechanism assembles -- what a "no position" sentence cites,
    so it is found (each end refined on the construction) only when there is no solution, else empty."""

    target: Target
    solutions: tuple[float, ...]
    touching: tuple[bool, ...]
    reach: tuple[tuple[float, float], ...]
    kind: str                     # "length" (a slider position) or "angle" (a link's angle)
    along: str = "its guide"      # what a block slides along: "its guide" or "the slot of link 3"

    def describe(self, fmt: Formatter = si_format) -> str:
        """One sentence: the solutions, or why there is none."""
        what = describe_target(self.target, fmt, self.along)
        if self.solutions:
            listed = ", ".join(fmt("angle", t) + (" (a limit position)" if touch else "")
                               for t, touch in zip(self.solutions, self.touching))
            many = "one crank angle puts" if len(self.solutions) == 1 else f"{len(self.solutions)} crank angles put"
            return f"{many.capitalize()} {what}: {listed}."
        if not self.reach:
            return f"No position: the mechanism assembles at no crank angle, so nothing puts {what}."
        spans = " and ".join(f"{fmt(self.kind, lo)} to {fmt(self.kind, hi)}" for lo, hi in self.reach)
        t = self.target
        if isinstance(t, SliderAt):
            moves, goal = f"block {t.block} travels only from {spans} along {self.along}", fmt("length", t.position)
        else:
            moves, goal = f"link {t.link} swings only from {spans}", fmt("angle", t.angle)
        return f"No position: over a turn of the crank {moves}, so no crank angle puts it at {goal}."


def describe_target(t: Target, fmt: Formatter = si_format, along: str = "its guide") -> str:
    """The target in words: "block 3 at 120 mm along its guide", "link 3 at 100 deg"."""
    if isinstance(t, SliderAt):
        return f"block {t.block} at {fmt('length', t.position)} along {along}"
    return f"link {t.link} at {fmt('angle', t.angle)}"


def quantity(m: Mechanism, target: Target, positions: Mapping[str, Vec]) -> float:
    """The block's position along its guide, or the link's angle (in (-pi, pi]), at ``positions``."""
    if isinstance(target, SliderAt):
        s = m.blocks()[target.block]
        line = slide_line(m, s, positions)
        return (positions[s.joint] - line.point).dot(line.direction)
    k = m.link(target.link)
    a = next((j for j in k.joints if j in m.ground), k.joints[0])
    return (positions[k.other(a)] - positions[a]).angle()


def check_target(m: Mechanism, target: Target) -> None:
    """DegenerateInput unless ``target`` names a slider block or a link other than the crank."""
    if isinstance(target, SliderAt):
        s = m.blocks().get(target.block)
        if s is None:
            raise DegenerateInput(f"there is no slider block {target.block}")
    elif target.link == m.crank:
        raise DegenerateInput(f"link {target.link} is the crank: give its angle itself")
    else:
        m.link(target.link)


def inverse_position(m: Mechanism, target: Target, *, plan: tuple[PlanStep, ...] | None = None,
                     samples: int = SAMPLES) -> InversePosition:
    """Every crank angle that puts ``m`` at ``target`` (module docstring), on the scene's assembly."""
    check_target(m, target)
    plan = assembly_plan(m) if plan is None else plan
    kind = "length" if isinstance(target, SliderAt) else "angle"
    goal = target.position if isinstance(target, SliderAt) else target.angle
    from ..sweep import sweep                   # the whole-turn machinery: loaded when a target is sought
    grid = TURN * np.arange(samples) / samples
    res = sweep(m, grid, 0.0, 0.0)
    values = np.full(samples, np.nan)
    for i in np.flatnonzero(np.asarray(res.assembles, dtype=bool)):
        values[i] = quantity(m, target, {n: Vec(float(x[i]), float(y[i])) for n, (x, y) in res.positions.items()})

    def diff(v: float) -> float:
        return v - goal if kind == "length" else math.remainder(v - goal, TURN)

    def residual(theta: float) -> float:
        v = _value(m, target, plan, theta)
        return diff(v) if math.isfinite(v) else math.nan

    r = np.array([diff(v) if math.isfinite(v) else math.nan for v in values])
    found: list[tuple[float, bool]] = []
    jump = math.pi if kind == "angle" else math.inf       # an angle's wrap from +pi to -pi is no root
    for i in range(samples):
        j = (i + 1) % samples
        a, b = r[i], r[j]
        if not (math.isfinite(a) and math.isfinite(b)):
            continue
        if a == 0.0:
            found.append((grid[i], False))
        elif a * b < 0.0 and abs(a - b) < jump:
            hi = grid[j] if j else TURN
            found.append((_false_position(residual, grid[i], hi, a, b), False))
        elif b != 0.0 and a * b > 0.0:
            p = r[i - 1]
            if math.isfinite(p) and p * a > 0.0 and abs(a) < abs(p) and abs(a) <= abs(b):
                t, v = _golden(lambda x: abs(residual(x)), grid[i] - TURN / samples, grid[i] + TURN / samples)
                if v <= (1e-9 * m.size if kind == "length" else 1e-9):
                    found.append((t, True))
    found = _merge(sorted((float(t) % TURN, touch) for t, touch in found))
    reach = () if found else _reach(values, kind, grid, lambda t: _value(m, target, plan, t))
    return InversePosition(target, tuple(t for t, _ in found), tuple(x for _, x in found), reach, kind,
                           _along(m, target))


def _along(m: Mechanism, target: Target) -> str:
    s = m.blocks().get(target.block) if isinstance(target, SliderAt) else None
    return f"the slot of link {s.on}" if s is not None and s.on is not None else "its guide"


def _value(m: Mechanism, target: Target, plan, theta: float) -> float:
    """The quantity on the construction at crank angle ``theta``; NaN where it does not assemble."""
    try:
        return quantity(m, target, locate(m, theta, plan).positions)
    except DegenerateInput:
        return math.nan


MERGE = 1e-6
"""Two solutions closer than this (rad) are one limit position, found twice from either side of it."""


def _merge(found: list[tuple[float, bool]]) -> list[tuple[float, bool]]:
    """The sorted solutions with any two closer than :data:`MERGE` (round the turn) made one limit position."""
    out: list[tuple[float, bool]] = []
    for t, touch in found:
        if out and t - out[-1][0] < MERGE:
            out[-1] = (0.5 * (out[-1][0] + t), True)
        else:
            out.append((t, touch))
    if len(out) > 1 and out[0][0] + TURN - out[-1][0] < MERGE:
        t = math.remainder(0.5 * (out[0][0] + out[-1][0] + TURN), TURN) % TURN
        out = [(t, True)] + out[1:-1]
    return out


def _false_position(f, a: float, b: float, fa: float, fb: float) -> float:
    """The root of ``f`` in [a, b] (fa, fb of opposite signs) by false position with Illinois' halving,
    to the last bit of the angle; bisection where f cannot be evaluated."""
    side = 0
    for _ in range(200):
        if b - a <= 4 * math.ulp(max(abs(a), abs(b), 1.0)):
            break
        c = (a * fb - b * fa) / (fb - fa)
        if not a < c < b:
            c = 0.5 * (a + b)
        fc = f(c)
        if not math.isfinite(fc):
            c = 0.5 * (a + b)
            fc = f(c)
            if not math.isfinite(fc):
                break
        if fc == 0.0:
            return c
        if fc * fb < 0.0:
            a, fa = b, fb
            b, fb = c, fc
            side = 0
        else:
            b, fb = c, fc
            if side == 1:
                fa *= 0.5
            side = 1
        if a > b:
            a, b, fa, fb = b, a, fb, fa
    return a if abs(fa) < abs(fb) else b


def _golden(f, a: float, b: float) -> tuple[float, float]:
    """(x, f(x)) at the minimum of the unimodal ``f`` on [a, b] by golden-section search."""
    g = (math.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(120):
        if b - a <= 4 * math.ulp(max(abs(a), abs(b), 1.0)):
            break                   # the bracket is a few ulps of the angle: no narrower one exists
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = f(d)
    x = 0.5 * (a + b)
    return x, f(x)


def _reach(values: np.ndarray, kind: str, grid: np.ndarray, value_at) -> tuple[tuple[float, float], ...]:
    """The ranges the quantity covers, one per stretch of assembling samples (angles unwrapped), each end
    refined on the construction (golden section about the sample where it is reached)."""
    n = values.size
    ok = np.isfinite(values)
    if not ok.any():
        return ()
    start = 0 if ok.all() else int(np.flatnonzero(~ok)[0])
    runs: list[list[int]] = []
    cur: list[int] = []
    for i in ((start + k) % n for k in range(n)):
        if ok[i]:
            cur.append(i)
        elif cur:
            runs.append(cur)
            cur = []
    if cur:
        runs.append(cur)
    step = TURN / n
    out = []
    for run in runs:
        v = values[run]
        u = np.unwrap(v) if kind == "angle" else v
        ends = []
        for sign, i in ((1.0, int(np.argmin(u))), (-1.0, int(np.argmax(u)))):
            t0, ref = float(grid[run[i]]), float(u[i])

            def f(t: float, ref=ref, sign=sign) -> float:
                q = value_at(t)
                if not math.isfinite(q):
                    return math.inf
                return sign * (ref + (math.remainder(q - ref, TURN) if kind == "angle" else q - ref))
            lo, hi = (t0 - step, t0 + step) if 0 < i < len(run) - 1 else (t0, t0)
            fx = _golden(f, lo, hi)[1] if hi > lo else sign * ref
            ends.append(sign * min(fx, sign * ref))        # never worse than the sample itself
        out.append((ends[0], ends[1]))
    return tuple(out)
